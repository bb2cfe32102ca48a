// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// CPRDepthImageFilter's Visibility mode (docs/design.md "Depth") against hand-worked and analytic cases, a brute-force
// nearest footprint pixel, and the tube ray caster of the tests (PlainTubeRayCaster). Unless a test says otherwise the
// view looks along v = LPS +y (theta = 0, up = +z): a point (x, y, z) lands in column x + (W-1)/2 and row
// -z + (H-1)/2 at depth y, with C at the origin.

#include "PlainTubeRayCaster.h"
#include "itkCPRDepthImageFilter.h"
#include "itkCPROcclusionProfile.h"
#include "itkCPRVectorHelpers.h"
#include "vrTestImages.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace
{
using FilterType = itk::CPRDepthImageFilter<itk::Image<float, 2>>;
using PointType = itk::Point<double, 3>;
using vr::test::Branch;
using vr::test::P;
using vr::test::View;

/** A straight branch from a to b sampled every mm, with a constant radius (none when radius is 0). */
itk::CenterlineBranch
Straight(int id, const PointType & a, const PointType & b, double radius)
{
  itk::CenterlineBranch branch;
  branch.Id = id;
  const auto steps = static_cast<int>(std::ceil(a.EuclideanDistanceTo(b)));
  for (int k = 0; k <= steps; ++k)
  {
    const double t = static_cast<double>(k) / steps;
    branch.Points.push_back(a + t * (b - a));
    if (radius > 0.0)
    {
      branch.Radii.push_back(radius);
    }
  }
  return branch;
}

struct Visibility
{
  unsigned int                         Width;
  unsigned int                         Height;
  std::vector<float>                   Depth;
  std::vector<unsigned char>           Fixed;
  std::vector<uint32_t>                Owner;
  std::vector<uint32_t>                Hidden;
  std::vector<itk::CPRBranchOcclusion> Occlusion;
  itk::CPRViewGeometry                 View;

  std::size_t
  Index(unsigned int column, unsigned int row) const
  {
    return static_cast<std::size_t>(row) * Width + column;
  }
  double
  HiddenLength(int id) const
  {
    for (const auto & entry : Occlusion)
    {
      if (entry.BranchId == id)
      {
        return entry.HiddenLength;
      }
    }
    ADD_FAILURE() << "no occlusion entry for branch " << id;
    return std::numeric_limits<double>::quiet_NaN();
  }
};

Visibility
Compute(const itk::CenterlineTree &       tree,
        const itk::CPRViewSpecification & view,
        bool                              fixLumen = true,
        FilterType *                      reuse = nullptr)
{
  FilterType::Pointer filter = reuse != nullptr ? FilterType::Pointer(reuse) : FilterType::New();
  filter->SetCenterlineTree(tree);
  filter->SetViewSpecification(view);
  filter->SetMode(itk::CPRDepthMode::Visibility);
  filter->SetFixLumen(fixLumen);
  filter->Update();
  const auto size = filter->GetDepthOutput()->GetLargestPossibleRegion().GetSize();
  return { static_cast<unsigned int>(size[0]),
           static_cast<unsigned int>(size[1]),
           vr::test::PixelsOf(filter->GetDepthOutput()),
           vr::test::PixelsOf(filter->GetFixedMaskOutput()),
           vr::test::PixelsOf(filter->GetOwnerLabelOutput()),
           vr::test::PixelsOf(filter->GetHiddenLabelOutput()),
           filter->GetBranchOcclusions(),
           filter->GetView() };
}
} // namespace

TEST(CPRVisibilityDepth, TheTubeInFrontOwnsItsWholeFootprintAndHidesTheOneBehind)
{
  // A horizontal tube (branch 1, z = 0, radius 3, depth -10) in front of a vertical one (branch 2, x = 0, radius 2,
  // depth +10). 1 mm pixels, 41 x 61: x = 0 is column 20, z = 0 is row 30.
  itk::CenterlineTree tree;
  tree.AddBranch(Straight(1, P(-20, -10, 0), P(20, -10, 0), 3.0));
  tree.AddBranch(Straight(2, P(0, 10, 25), P(0, 10, -25), 2.0));
  const Visibility map = Compute(tree, View(41, 61));
  for (unsigned int row = 0; row < 61; ++row)
  {
    for (unsigned int column = 0; column < 41; ++column)
    {
      const double      x = column - 20.0;
      const double      z = 30.0 - row;
      const bool        inFront = std::abs(z) <= 3.0;
      const bool        behind = std::hypot(x, std::max(0.0, std::abs(z) - 25.0)) <= 2.0; // with its round ends
      const std::size_t k = map.Index(column, row);
      if (inFront)
      {
        EXPECT_EQ(map.Owner[k], 1u) << column << "," << row;
        EXPECT_FLOAT_EQ(map.Depth[k], -10.0f) << column << "," << row;
        EXPECT_EQ(map.Fixed[k], 1) << column << "," << row;
        EXPECT_EQ(map.Hidden[k], behind ? 2u : 0u) << column << "," << row;
      }
      else if (behind)
      {
        EXPECT_EQ(map.Owner[k], 2u) << column << "," << row;
        EXPECT_FLOAT_EQ(map.Depth[k], 10.0f) << column << "," << row;
        EXPECT_EQ(map.Fixed[k], 1) << column << "," << row;
        EXPECT_EQ(map.Hidden[k], 0u) << column << "," << row;
      }
      else
      {
        EXPECT_EQ(map.Fixed[k], 0) << column << "," << row;
        EXPECT_EQ(map.Hidden[k], 0u) << column << "," << row;
      }
    }
  }
  // The vertical centerline under the horizontal footprint (rows 27..33) is hidden: 7 pixels of 1 mm, the exact
  // answer being the footprint's 6 mm plus what the pixel grid adds at its two edges.
  EXPECT_NEAR(map.HiddenLength(2), 6.0, 1.0);
  EXPECT_EQ(map.HiddenLength(1), 0.0);
  // Without lumen fixing only the visible centerline pixels are fixed: the vertical one is not, under branch 1.
  const Visibility bare = Compute(tree, View(41, 61), false);
  EXPECT_EQ(bare.Fixed[bare.Index(20, 30)], 1) << "branch 1's centerline";
  EXPECT_EQ(bare.Fixed[bare.Index(20, 29)], 0) << "branch 2's centerline under branch 1";
  EXPECT_EQ(bare.Fixed[bare.Index(20, 20)], 1) << "branch 2's centerline in the open";
  EXPECT_EQ(bare.Fixed[bare.Index(22, 20)], 0) << "branch 2's lumen";
}

TEST(CPRVisibilityDepth, TheFootprintIsTheRadiusInMillimetresWithTheDepthOfTheClosestPoint)
{
  // A vessel tilted in depth (y from -8 to 8 as z goes 15 -> -15) with a radius growing from 2 to 5 mm, on 0.8 x 1.2 mm
  // pixels: every pixel within the radius at its closest point, and only those, is footprint (fixed), its depth the
  // centerline's there (or, on the centerline pixels, the rasteriser's: the same within float rounding).
  itk::CenterlineTree tree;
  tree.AddBranch(Branch(7, { P(1, -8, 15), P(1, 8, -15) }, { 2.0, 5.0 }));
  const Visibility map = Compute(tree, View(31, 41, 0.8, 1.2));
  for (unsigned int row = 0; row < 41; ++row)
  {
    for (unsigned int column = 0; column < 31; ++column)
    {
      const double x = (column - 15.0) * 0.8;
      const double z = (20.0 - row) * 1.2;
      // Closest point on the segment (x = 1, z from 15 to -15) in the image plane.
      const double      t = std::clamp((15.0 - z) / 30.0, 0.0, 1.0);
      const double      dz = z - (15.0 - 30.0 * t);
      const double      distance = std::hypot(x - 1.0, dz);
      const double      radius = 2.0 + 3.0 * t;
      const std::size_t k = map.Index(column, row);
      if (std::abs(distance - radius) < 1e-6)
      {
        continue; // on the edge: rounding decides
      }
      EXPECT_EQ(map.Fixed[k] != 0, distance <= radius) << column << "," << row;
      if (distance <= radius)
      {
        EXPECT_EQ(map.Owner[k], 7u);
        EXPECT_NEAR(map.Depth[k], -8.0 + 16.0 * t, 1e-5) << column << "," << row;
      }
    }
  }
}

TEST(CPRVisibilityDepth, PixelsOutsideEveryFootprintTakeTheNearestFootprintPixel)
{
  // Random tubes on an anisotropic grid; the brute force compares every free pixel with every footprint pixel (the
  // fixed ones, all branches having radii) in mm, ties to the smaller depth, then the smaller id.
  std::mt19937                           generator(38);
  std::uniform_real_distribution<double> coordinate(-20.0, 20.0);
  std::uniform_real_distribution<double> radius(0.4, 3.0);
  for (int trial = 0; trial < 5; ++trial)
  {
    itk::CenterlineTree tree;
    for (int id = 1; id <= 4; ++id)
    {
      std::vector<PointType> points;
      std::vector<double>    radii;
      for (int k = 0; k < 3; ++k)
      {
        points.push_back(P(coordinate(generator), std::round(coordinate(generator)), coordinate(generator)));
        radii.push_back(radius(generator));
      }
      tree.AddBranch(Branch(id, points, radii));
    }
    const Visibility map = Compute(tree, View(37, 29, 1.0, 1.5));
    std::size_t      free = 0;
    for (unsigned int row = 0; row < map.Height; ++row)
    {
      for (unsigned int column = 0; column < map.Width; ++column)
      {
        const std::size_t k = map.Index(column, row);
        if (map.Fixed[k])
        {
          continue;
        }
        ++free;
        double   bestDistance = std::numeric_limits<double>::infinity();
        float    bestDepth = 0.0f;
        uint32_t bestOwner = 0;
        for (unsigned int r = 0; r < map.Height; ++r)
        {
          for (unsigned int c = 0; c < map.Width; ++c)
          {
            const std::size_t s = map.Index(c, r);
            if (!map.Fixed[s])
            {
              continue;
            }
            const double dx = (static_cast<double>(c) - column) * 1.0;
            const double dy = (static_cast<double>(r) - row) * 1.5;
            const double distance = dx * dx + dy * dy;
            if (bestOwner == 0 || distance < bestDistance ||
                (distance == bestDistance &&
                 (map.Depth[s] < bestDepth || (map.Depth[s] == bestDepth && map.Owner[s] < bestOwner))))
            {
              bestDistance = distance;
              bestDepth = map.Depth[s];
              bestOwner = map.Owner[s];
            }
          }
        }
        EXPECT_EQ(map.Owner[k], bestOwner) << "trial " << trial << " pixel " << column << "," << row;
        EXPECT_EQ(map.Depth[k], bestDepth) << "trial " << trial << " pixel " << column << "," << row;
        EXPECT_EQ(map.Hidden[k], 0u);
      }
    }
    EXPECT_GT(free, 100u);
  }
}

TEST(CPRVisibilityDepth, WithoutRadiiTheFootprintIsTheCenterlineAndOnlyCrossingsHide)
{
  // The two tubes of the first test without radii: each centerline is its own footprint; the crossing pixel shows the
  // nearer one and hides the other; every other pixel takes the nearest centerline pixel, as Nearest mode does.
  itk::CenterlineTree tree;
  tree.AddBranch(Straight(1, P(-20, -10, 0), P(20, -10, 0), 0.0));
  tree.AddBranch(Straight(2, P(0, 10, 25), P(0, 10, -25), 0.0));
  const Visibility  map = Compute(tree, View(41, 61));
  const std::size_t crossing = map.Index(20, 30);
  EXPECT_EQ(map.Owner[crossing], 1u);
  EXPECT_EQ(map.Hidden[crossing], 2u);
  EXPECT_FLOAT_EQ(map.Depth[crossing], -10.0f);
  std::size_t fixed = 0;
  for (std::size_t k = 0; k < map.Fixed.size(); ++k)
  {
    fixed += map.Fixed[k];
    EXPECT_TRUE(std::isfinite(map.Depth[k]));
    EXPECT_NE(map.Owner[k], 0u);
    if (k != crossing)
    {
      EXPECT_EQ(map.Hidden[k], 0u) << k;
    }
  }
  EXPECT_EQ(fixed, 41u + 51u - 1u) << "both centerlines, the crossing once";
  EXPECT_GT(map.HiddenLength(2), 0.0);
  EXPECT_LE(map.HiddenLength(2), 1.5) << "about one pixel of branch 2 at the crossing";
  EXPECT_EQ(map.HiddenLength(1), 0.0);
}

TEST(CPRVisibilityDepth, BranchesThatCoincideInProjectionShowTheNearestAndHideTheRest)
{
  // Four tubes along the same line of the image at depths 30, -5, 12, 50 (and a fifth, an exact copy of the
  // second): one is visible, the next lumen wholly behind it is the hidden label, nothing is NaN.
  itk::CenterlineTree tree;
  const double        depths[] = { 30.0, -5.0, 12.0, 50.0, -5.0 };
  for (int id = 1; id <= 5; ++id)
  {
    tree.AddBranch(Straight(id, P(0, depths[id - 1], 20), P(0, depths[id - 1], -20), 2.5));
  }
  const Visibility map = Compute(tree, View(21, 51));
  for (unsigned int row = 5; row <= 45; ++row)
  {
    for (unsigned int column = 8; column <= 12; ++column)
    {
      const std::size_t k = map.Index(column, row);
      EXPECT_EQ(map.Owner[k], 2u) << "the nearest, of the two copies the smaller id";
      EXPECT_FLOAT_EQ(map.Depth[k], -5.0f);
      EXPECT_EQ(map.Hidden[k], 3u) << "the next lumen behind; the copy of 2 is the same lumen";
    }
  }
  for (const float depth : map.Depth)
  {
    EXPECT_TRUE(std::isfinite(depth));
  }
  EXPECT_EQ(map.HiddenLength(2), 0.0);
  EXPECT_EQ(map.HiddenLength(5), 0.0) << "a copy of the visible vessel is not hidden by it";
  for (const int id : { 1, 3, 4 })
  {
    EXPECT_NEAR(map.HiddenLength(id), 40.0, 1e-9) << "branch " << id;
  }
}

TEST(CPRVisibilityDepth, ABranchLeavingItsParentIsNotHiddenByIt)
{
  // A child leaving a parent tube (radius 8) sideways from inside its lumen, and one leaving it backwards (away from
  // the viewer) and then turning sideways behind it: the first is never behind the parent's lumen; the second is where
  // its sideways part runs behind the parent's footprint.
  itk::CenterlineTree tree;
  tree.AddBranch(Straight(1, P(0, 0, 30), P(0, 0, -30), 8.0));
  tree.AddBranch(Straight(2, P(0, 0, 10), P(25, 3, 10), 3.0));
  itk::CenterlineBranch backwards = Straight(3, P(0, 0, -10), P(4, 30, -10), 2.0);
  const auto            sideways = Straight(3, P(4, 30, -10), P(25, 33, -10), 2.0);
  backwards.Points.insert(backwards.Points.end(), sideways.Points.begin() + 1, sideways.Points.end());
  backwards.Radii.insert(backwards.Radii.end(), sideways.Radii.begin() + 1, sideways.Radii.end());
  tree.AddBranch(backwards);
  const Visibility map = Compute(tree, View(61, 71));
  EXPECT_EQ(map.HiddenLength(1), 0.0);
  EXPECT_EQ(map.HiddenLength(2), 0.0);
  // The part running back (depth 0 to 30 over 4 mm of the image) is the vessel seen nearly end-on and counts as
  // visible; the sideways part (depth 30 to 33, radius 2, front behind the parent's back at depth 8) is hidden where
  // it lies within the parent's footprint, x from 4 to 8: 4 mm, and up to half a pixel more at the footprint's edge.
  EXPECT_NEAR(map.HiddenLength(3), 4.3, 0.6);
  for (unsigned int column = 0; column < map.Width; ++column)
  {
    EXPECT_NE(map.Hidden[map.Index(column, 25)], 2u) << "no dashed stretch where the child leaves sideways";
  }
}

TEST(CPRVisibilityDepth, AVesselLoopingBehindItselfHidesItsFarPart)
{
  // One branch: down at depth -20, across at the bottom, and back up at depth +20 behind its first part (an aortic
  // arch seen from the side): the far part is hidden behind the near one and labelled with the same id.
  itk::CenterlineTree   tree;
  itk::CenterlineBranch loop = Straight(1, P(0, -20, 20), P(0, -20, -20), 4.0);
  const auto            bottom = Straight(1, P(0, -20, -20), P(0, 20, -20), 4.0);
  const auto            back = Straight(1, P(0, 20, -20), P(0, 20, 20), 4.0);
  for (const auto * part : { &bottom, &back })
  {
    loop.Points.insert(loop.Points.end(), part->Points.begin() + 1, part->Points.end());
    loop.Radii.insert(loop.Radii.end(), part->Radii.begin() + 1, part->Radii.end());
  }
  tree.AddBranch(loop);
  const Visibility  map = Compute(tree, View(21, 61));
  const std::size_t k = map.Index(10, 30);
  EXPECT_EQ(map.Owner[k], 1u);
  EXPECT_FLOAT_EQ(map.Depth[k], -20.0f) << "the near part, not the far one";
  EXPECT_EQ(map.Hidden[k], 1u);
  // The far part is hidden all along its 40 mm; the bottom, which runs along v, is the vessel seen end-on and never
  // counts as hidden (its self-occlusion tolerance is infinite).
  EXPECT_NEAR(map.HiddenLength(1), 40.0, 1.0);
}

TEST(CPRVisibilityDepth, ReusedFilterEqualsANewOneAtAnotherAngle)
{
  std::mt19937                           generator(7);
  std::uniform_real_distribution<double> coordinate(-25.0, 25.0);
  itk::CenterlineTree                    tree;
  for (int id = 1; id <= 6; ++id)
  {
    tree.AddBranch(Branch(id,
                          { P(coordinate(generator), coordinate(generator), coordinate(generator)),
                            P(coordinate(generator), coordinate(generator), coordinate(generator)) },
                          { 2.0 + id * 0.3, 1.5 }));
  }
  auto reused = FilterType::New();
  Compute(tree, View(64, 48, 1.0, 1.0, 0.0), true, reused);
  const Visibility again = Compute(tree, View(64, 48, 1.0, 1.0, 57.0), true, reused);
  const Visibility fresh = Compute(tree, View(64, 48, 1.0, 1.0, 57.0));
  EXPECT_EQ(again.Depth, fresh.Depth);
  EXPECT_EQ(again.Owner, fresh.Owner);
  EXPECT_EQ(again.Fixed, fresh.Fixed);
  EXPECT_EQ(again.Hidden, fresh.Hidden);
  ASSERT_EQ(again.Occlusion.size(), fresh.Occlusion.size());
  for (std::size_t b = 0; b < again.Occlusion.size(); ++b)
  {
    EXPECT_EQ(again.Occlusion[b].HiddenLength, fresh.Occlusion[b].HiddenLength);
  }
  // The other modes leave the hidden labels at 0 and report no occlusion.
  reused->SetMode(itk::CPRDepthMode::Scanline);
  reused->Update();
  for (const uint32_t label : vr::test::PixelsOf(reused->GetHiddenLabelOutput()))
  {
    ASSERT_EQ(label, 0u);
  }
  EXPECT_TRUE(reused->GetBranchOcclusions().empty());
}

TEST(PlainTubeRayCaster, MeetsAStraightTubeWhereTheCircleSays)
{
  // The oracle itself: a tube along x at depth 4 and z = 0, radius 3. The ray of the pixel at z = 2 enters at
  // 4 - sqrt(9 - 4); the ray at z = 3.5 misses; a tapered tube meets the ray where its radius there says.
  itk::CenterlineTree tree;
  tree.AddBranch(Branch(1, { P(-10, 4, 0), P(10, 4, 0) }, { 3.0, 3.0 }));
  const auto view = itk::CPRViewGeometry::Resolve(View(21, 21), tree, nullptr);
  const auto hit = vr::test::CrossTubes(tree, view, 10.0, 8.0); // z = 2
  ASSERT_EQ(hit.size(), 1u);
  EXPECT_NEAR(hit[0].Entry, 4.0 - std::sqrt(5.0), 1e-9);
  EXPECT_NEAR(hit[0].Exit, 4.0 + std::sqrt(5.0), 1e-9);
  EXPECT_TRUE(vr::test::CrossTubes(tree, view, 10.0, 6.5).empty()); // z = 3.5
  const auto hits = vr::test::CastTubeRays(tree, view);
  EXPECT_EQ(hits.At(10, 10), 1u);
  EXPECT_EQ(hits.At(10, 6), 0u);
  EXPECT_EQ(hits.At(0, 13), 1u); // z = -3: on the surface

  itk::CenterlineTree tapered;
  tapered.AddBranch(Branch(2, { P(-10, 0, 0), P(10, 0, 0) }, { 1.0, 5.0 })); // r(x) = 3 + 0.2 x along the axis
  const auto crossings = vr::test::CrossTubes(tapered, view, 15.0, 7.0);     // x = 5, z = 3: r = 4 near there
  ASSERT_EQ(crossings.size(), 1u);
  // Inside where y^2 + 9 <= (3 + 0.2 x*)^2 with x* the nearest axis point, here x* = 5: |y| <= sqrt(16 - 9).
  EXPECT_NEAR(crossings[0].Entry, -std::sqrt(7.0), 1e-9);
  EXPECT_TRUE(vr::test::IsCenterlinePointHidden(tree, view, P(0, 20, 0), 1.0));
  EXPECT_FALSE(vr::test::IsCenterlinePointHidden(tree, view, P(0, 6, 0), 1.0)) << "inside the tube's lumen";
}

TEST(CPROcclusionProfile, TwoParallelTubesHideEachOtherExactlyWhereTheirFootprintsOverlap)
{
  // Two tubes along z (50 mm, radius 10), 40 mm apart along x. Turning about z, the one behind lies in the other's
  // footprint while their projected separation 40 |cos(theta)| is at most 10 mm, theta from 75.5 to 104.5 degrees,
  // and there it is wholly behind (depth separation 40 sin(theta) >= 38.7 mm > 20): all 50 mm of it hidden; elsewhere
  // nothing. Pixels of 0.05 mm, far finer than the radius: the tubes reach over many buckets of heights.
  itk::CenterlineTree tree;
  tree.AddBranch(Straight(1, P(0, 0, 0), P(0, 0, 50), 10.0));
  tree.AddBranch(Straight(2, P(40, 0, 0), P(40, 0, 50), 10.0));
  itk::Vector<double, 3> up;
  up[0] = 0.0;
  up[1] = 0.0;
  up[2] = 1.0;
  itk::Size<2>                   size{ { 100, 100 } };
  const itk::CPRViewGeometry     view(up, 0.0, P(20, 0, 25), size, itk::detail::MakeVector2(0.05, 0.05));
  const itk::CPROcclusionProfile profile = itk::ComputeCPROcclusionProfile(tree, view);
  ASSERT_EQ(profile.HiddenLength.size(), 180u);
  EXPECT_NEAR(profile.TreeLength, 100.0, 1e-9);
  for (unsigned int angle = 0; angle < 180; ++angle)
  {
    const double expected = angle >= 76 && angle <= 104 ? 50.0 : 0.0;
    EXPECT_NEAR(profile.HiddenLength[angle], expected, 1e-6) << angle << " degrees";
  }
  EXPECT_EQ(profile.LeastOccludedAngle(), 0u);
  EXPECT_EQ(profile.MostOccludedAngle(), 76u);
  EXPECT_NEAR(profile.HiddenFraction(90), 0.5, 1e-9);
}
