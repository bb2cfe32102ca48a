// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The merge of a centerline file's polylines into branches, on the ITK side alone: hand-made paths whose branches are
// known, and the one polyline resampler against values worked out by hand.
#include "itkCenterlinePolylineMerge.h"

#include <gtest/gtest.h>

#include <array>

namespace
{
using itk::CenterlinePolyline;
using PointType = CenterlinePolyline::PointType;

PointType
P(double x, double y, double z)
{
  PointType point;
  point[0] = x;
  point[1] = y;
  point[2] = z;
  return point;
}

CenterlinePolyline
Line(std::size_t source, std::vector<PointType> points, std::vector<double> radii = {})
{
  CenterlinePolyline polyline;
  polyline.Source = source;
  polyline.Points = std::move(points);
  polyline.Radii = std::move(radii);
  return polyline;
}

TEST(CenterlinePolylineMerge, TwoPathsSharingATrunkGiveTheTrunkAndEachPathsOwnPart)
{
  // Path 1: (0,0,0) .. (0,0,3) then left to (-2,0,5); path 2 repeats the trunk (within 1 um) then goes right.
  const std::vector<CenterlinePolyline> paths = {
    Line(0, { P(0, 0, 0), P(0, 0, 1), P(0, 0, 2), P(0, 0, 3), P(-1, 0, 4), P(-2, 0, 5) }, { 5, 5, 5, 5, 3, 3 }),
    Line(1, { P(0, 0, 0), P(0, 0, 1.0000004), P(0, 0, 2), P(0, 0, 3), P(1, 0, 4), P(2, 0, 5) }, { 5, 5, 5, 4.5, 2, 2 }),
  };
  std::size_t merged = 0;
  const auto  branches = itk::MergeOverlappingPaths(paths, 1e-3, merged);
  ASSERT_EQ(branches.size(), 3u);
  EXPECT_EQ(merged, 4u); // the second path's four trunk points
  // The first path is cut where the second leaves it: trunk (0..3), then its left part from (0,0,3).
  EXPECT_EQ(branches[0].Polyline.Points, (std::vector<PointType>{ P(0, 0, 0), P(0, 0, 1), P(0, 0, 2), P(0, 0, 3) }));
  EXPECT_EQ(branches[1].Polyline.Points, (std::vector<PointType>{ P(0, 0, 3), P(-1, 0, 4), P(-2, 0, 5) }));
  EXPECT_EQ(branches[2].Polyline.Points, (std::vector<PointType>{ P(0, 0, 3), P(1, 0, 4), P(2, 0, 5) }));
  EXPECT_EQ(branches[0].Polyline.Source, 0u);
  EXPECT_EQ(branches[1].Polyline.Source, 0u);
  EXPECT_EQ(branches[2].Polyline.Source, 1u);
  EXPECT_FALSE(branches[0].Whole);
  EXPECT_FALSE(branches[2].Whole);
  // The right branch starts at the shared point but with its own path's radius there (4.5, not the trunk's 5).
  EXPECT_EQ(branches[2].Polyline.Radii, (std::vector<double>{ 4.5, 2, 2 }));
}

TEST(CenterlinePolylineMerge, PathsThatOnlyTouchAtTheirEndsStayWholeBranches)
{
  const std::vector<CenterlinePolyline> paths = {
    Line(3, { P(0, 0, 0), P(0, 0, 1) }),
    Line(4, { P(0, 0, 1), P(1, 0, 1), P(2, 0, 1) }),
  };
  std::size_t merged = 0;
  const auto  branches = itk::MergeOverlappingPaths(paths, 1e-3, merged);
  ASSERT_EQ(branches.size(), 2u);
  EXPECT_EQ(merged, 1u);
  EXPECT_TRUE(branches[0].Whole);
  EXPECT_TRUE(branches[1].Whole);
  EXPECT_EQ(branches[1].Polyline.Points.front(), P(0, 0, 1));
  EXPECT_TRUE(branches[1].Polyline.Radii.empty());
}

TEST(CenterlinePolylineMerge, AZeroToleranceMergesOnlyEqualPoints)
{
  const std::vector<CenterlinePolyline> paths = {
    Line(0, { P(0, 0, 0), P(0, 0, 1), P(0, 0, 2) }),
    Line(1, { P(0, 0, 0), P(0, 0, 1.000001), P(0, 0, 2) }),
  };
  std::size_t merged = 0;
  const auto  branches = itk::MergeOverlappingPaths(paths, 0.0, merged);
  // (0,0,0) and (0,0,2) repeat exactly; the middle point of path 2 is new: it becomes a branch of its own between
  // the two shared points, and the first path is cut at neither end (they are its ends).
  EXPECT_EQ(merged, 2u);
  ASSERT_EQ(branches.size(), 2u);
  EXPECT_EQ(branches[1].Polyline.Points, (std::vector<PointType>{ P(0, 0, 0), P(0, 0, 1.000001), P(0, 0, 2) }));
}

TEST(CenterlinePolylineMerge, CoordinatesFarBeyondAnyGridStillMergeByTheirTrueDistance)
{
  // A hostile file's points at +-1e160 mm (found by fuzzing: the neighbourhood grid's cell index overflowed). The
  // repeated points still merge, the far ones stay apart, and the answer is the one the same paths give near 0.
  const double far = 1e160;
  const std::vector<CenterlinePolyline> paths = {
    Line(0, { P(far, 0, 0), P(far, 0, 1), P(-far, 0, 2) }),
    Line(1, { P(far, 0, 0), P(far, 0, 1), P(0, -far, 3) }),
  };
  std::size_t merged = 0;
  const auto  branches = itk::MergeOverlappingPaths(paths, 1e-3, merged);
  EXPECT_EQ(merged, 2u);
  ASSERT_EQ(branches.size(), 3u);
  EXPECT_EQ(branches[0].Polyline.Points, (std::vector<PointType>{ P(far, 0, 0), P(far, 0, 1) }));
  EXPECT_EQ(branches[1].Polyline.Points, (std::vector<PointType>{ P(far, 0, 1), P(-far, 0, 2) }));
  EXPECT_EQ(branches[2].Polyline.Points, (std::vector<PointType>{ P(far, 0, 1), P(0, -far, 3) }));
}

TEST(CenterlinePolylineMerge, TheResamplerPlacesEqualArcStepsWithTheEndsKept)
{
  // An L of arm lengths 3 and 1 (length 4), resampled to 5 points: one every 1 mm along the arc.
  const std::vector<std::array<double, 3>> points = { { 0, 0, 0 }, { 3, 0, 0 }, { 3, 1, 0 } };
  const std::vector<double>                radii = { 1, 4, 2 };
  std::vector<std::array<double, 3>>       resampled;
  std::vector<double>                      resampledRadii;
  itk::ResamplePolylineEvenly(points, radii, 5, resampled, resampledRadii);
  const std::vector<std::array<double, 3>> expected = {
    { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 }, { 3, 0, 0 }, { 3, 1, 0 }
  };
  ASSERT_EQ(resampled.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k)
  {
    for (unsigned int axis = 0; axis < 3; ++axis)
    {
      EXPECT_NEAR(resampled[k][axis], expected[k][axis], 1e-12) << "point " << k;
    }
  }
  EXPECT_EQ(resampled.front(), points.front());
  EXPECT_EQ(resampled.back(), points.back());
  // Radii linear along each segment: 1 -> 4 over 3 mm, so 2 and 3 at 1 and 2 mm; then 4 -> 2.
  const std::vector<double> expectedRadii = { 1, 2, 3, 4, 2 };
  for (std::size_t k = 0; k < expectedRadii.size(); ++k)
  {
    EXPECT_NEAR(resampledRadii[k], expectedRadii[k], 1e-12) << "radius " << k;
  }
  // One point asked: the first; one point given: repeated.
  itk::ResamplePolylineEvenly(points, radii, 1, resampled, resampledRadii);
  EXPECT_EQ(resampled, (std::vector<std::array<double, 3>>{ points.front() }));
  itk::ResamplePolylineEvenly(std::vector<std::array<double, 3>>{ { 1, 2, 3 } }, {}, 3, resampled, resampledRadii);
  EXPECT_EQ(resampled.size(), 3u);
  EXPECT_TRUE(resampledRadii.empty());
}

TEST(CenterlinePolylineMerge, BranchGroupsAverageTheirTractsByRadiusSquaredAndTakeTheBlankedBifurcation)
{
  // Two paths through a trunk group 0 (two tracts, radii 1 and 3 along x = 0 and x = 4), a blanked bifurcation
  // tract each (group 9), then each path's own group (1 and 2).
  const std::vector<CenterlinePolyline> tracts = {
    Line(0, { P(0, 0, 0), P(0, 0, 2) }, { 1, 1 }),  // path 0, trunk
    Line(1, { P(0, 0, 2), P(0, 0, 3) }, { 1, 1 }),  // path 0, blanked
    Line(2, { P(0, 0, 3), P(-1, 0, 4) }, { 1, 1 }), // path 0, left
    Line(3, { P(4, 0, 0), P(4, 0, 2) }, { 3, 3 }),  // path 1, trunk
    Line(4, { P(4, 0, 2), P(4, 0, 3) }, { 3, 3 }),  // path 1, blanked
    Line(5, { P(4, 0, 3), P(5, 0, 4) }, { 3, 3 }),  // path 1, right
  };
  const std::vector<itk::CenterlineTractLabels> labels = {
    { 0, false, 0, 0 }, { 9, true, 0, 1 }, { 1, false, 0, 2 },
    { 0, false, 1, 0 }, { 9, true, 1, 1 }, { 2, false, 1, 2 },
  };
  std::size_t merged = 0;
  const auto  branches = itk::MergeBranchGroups(tracts, labels, 1e-3, merged);
  ASSERT_EQ(branches.size(), 3u); // groups 0, 1, 2; the blanked group 9 is no branch
  // The trunk: weights 1 and 9, so x = (1 * 0 + 9 * 4) / 10 = 3.6; radius the plain mean 2.
  ASSERT_EQ(branches[0].Polyline.Points.size(), 2u);
  EXPECT_DOUBLE_EQ(branches[0].Polyline.Points[0][0], 3.6);
  EXPECT_DOUBLE_EQ(branches[0].Polyline.Radii[0], 2.0);
  EXPECT_EQ(branches[0].Polyline.Source, 0u);
  // The left branch starts at the trunk's end, then runs through the blanked tract (0,0,2)-(0,0,3) to (-1,0,4).
  const auto & left = branches[1].Polyline;
  ASSERT_EQ(left.Points.size(), 4u);
  EXPECT_DOUBLE_EQ(left.Points[0][0], 3.6);
  EXPECT_EQ(left.Points[1], P(0, 0, 2));
  EXPECT_EQ(left.Points[2], P(0, 0, 3));
  EXPECT_EQ(left.Points[3], P(-1, 0, 4));
  EXPECT_EQ(left.Source, 2u);
  EXPECT_FALSE(branches[1].Whole);
  // 12 input points, 2 + 4 + 4 out.
  EXPECT_EQ(merged, 2u);
}
} // namespace
