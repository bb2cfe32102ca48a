// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// CenterlineExtractionFilter on shapes made in code whose axis and radius are known exactly (issue 15, item 1):
// straight and curved tubes, a Y bifurcation, a tube in an oblique, anisotropic volume; then the label rules,
// components, root points and every bad input.

#include "itkCenterlineExtractionFilter.h"
#include "itkCenterlineForeground.h"
#include "itkImageRegionIteratorWithIndex.h"
#include "itkSignedMaurerDistanceMapImageFilter.h"

#include "PlainCenterlineExtraction.h"

#include "vrTestImages.h"
#include "vrTestSegmentations.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>
#include <sstream>

namespace
{
using vr::test::LabelMap;
using vr::test::P;
using vr::test::PointType;
using FilterType = itk::CenterlineExtractionFilter<LabelMap>;
using VectorType = itk::Vector<double, 3>;

VectorType
V(double x, double y, double z)
{
  VectorType v;
  v[0] = x;
  v[1] = y;
  v[2] = z;
  return v;
}

itk::Matrix<double, 3, 3>
Identity()
{
  itk::Matrix<double, 3, 3> identity;
  identity.SetIdentity();
  return identity;
}

itk::CenterlineTree
Extract(const LabelMap * image, const std::function<void(FilterType *)> & configure = {})
{
  auto filter = FilterType::New();
  filter->SetInput(image);
  if (configure)
  {
    configure(filter);
  }
  filter->Update();
  return filter->GetCenterlineTree();
}

/** How an extracted tree compares with the true one: distances of its points to the true axes, radius errors,
 * and how much of the true axes it covers. */
struct Comparison
{
  double      MaximumDistance{ 0.0 };
  double      MedianDistance{ 0.0 };
  double      MaximumRadiusError{ 0.0 };
  double      MedianRadiusError{ 0.0 };
  double      MeanRadiusError{ 0.0 };
  double      CoveredFraction{ 0.0 };
  std::size_t Points{ 0 };
  std::size_t InOverlaps{ 0 };
};

/** Compares \a extracted with \a truth. Points within 1.5 radii of two or more true axes are left out of the distance
 * and radius figures: where tubes overlap (around a bifurcation) their union has no single axis, and the centerline
 * leaves the union's middle for each branch's over about a radius. Coverage: the fraction
 * of truth points farther than \a endMargin mm from their branch's ends that lie within \a coverDistance mm of the
 * extracted tree. */
Comparison
Compare(const itk::CenterlineTree & extracted,
        const itk::CenterlineTree & truth,
        double                      endMargin = 0.0,
        double                      coverDistance = 1.0)
{
  Comparison          comparison;
  std::vector<double> distances;
  std::vector<double> radiusErrors;
  double              signedSum = 0.0;
  for (const auto & branch : extracted.GetBranches())
  {
    for (std::size_t k = 0; k < branch.Points.size(); ++k)
    {
      const PointType & point = branch.Points[k];
      std::size_t       inside = 0;
      for (const auto & tube : truth.GetBranches())
      {
        const auto nearest = vr::test::NearestPointOnPolyline(point, tube.Points, tube.Radii);
        inside += nearest.Distance <= 1.5 * nearest.Radius ? 1 : 0;
      }
      if (inside >= 2)
      {
        ++comparison.InOverlaps;
        continue;
      }
      const auto nearest = vr::test::NearestPointOnTree(point, truth);
      distances.push_back(nearest.Nearest.Distance);
      radiusErrors.push_back(std::abs(branch.Radii[k] - nearest.Nearest.Radius));
      signedSum += branch.Radii[k] - nearest.Nearest.Radius;
    }
  }
  comparison.Points = distances.size();
  comparison.MaximumDistance = *std::max_element(distances.begin(), distances.end());
  comparison.MedianDistance = vr::test::Quantile(distances, 0.5);
  comparison.MaximumRadiusError = *std::max_element(radiusErrors.begin(), radiusErrors.end());
  comparison.MedianRadiusError = vr::test::Quantile(radiusErrors, 0.5);
  comparison.MeanRadiusError = signedSum / static_cast<double>(radiusErrors.size());
  std::size_t considered = 0;
  std::size_t covered = 0;
  for (const auto & branch : truth.GetBranches())
  {
    const double length = vr::test::PolylineLength(branch.Points);
    double       arc = 0.0;
    for (std::size_t k = 0; k < branch.Points.size(); ++k)
    {
      arc += k == 0 ? 0.0 : branch.Points[k - 1].EuclideanDistanceTo(branch.Points[k]);
      if (arc < endMargin || arc > length - endMargin)
      {
        continue;
      }
      ++considered;
      covered += vr::test::NearestPointOnTree(branch.Points[k], extracted).Nearest.Distance <= coverDistance ? 1 : 0;
    }
  }
  comparison.CoveredFraction = considered ? static_cast<double>(covered) / static_cast<double>(considered) : 0.0;
  return comparison;
}

std::ostream &
operator<<(std::ostream & os, const Comparison & c)
{
  return os << c.Points << " points (" << c.InOverlaps << " more at bifurcations): distance to the true axis median "
            << c.MedianDistance << " max " << c.MaximumDistance << " mm; radius error median " << c.MedianRadiusError
            << " max " << c.MaximumRadiusError << " mean (signed) " << c.MeanRadiusError << " mm; "
            << 100.0 * c.CoveredFraction << " % of the axis covered";
}

// ---------------------------------------------------------------------------------------------------------------
// Item 1: analytic shapes.

TEST(CenterlineExtractionFilter, StraightObliqueTubeGivesOneBranchOnItsAxisWithItsRadius)
{
  constexpr double    radius = 4.0;
  auto                image = vr::test::MakeLabelMap({ { 64, 64, 80 } }, V(1, 1, 1), P(0, 0, 0), Identity());
  itk::CenterlineTree truth;
  truth.AddBranch(
    vr::test::TubeBranch(1, vr::test::SegmentPoints(P(12.3, 15.6, 10.2), P(50.1, 44.7, 68.4), 0.5), radius));
  vr::test::DrawTubes(image, truth);

  const itk::CenterlineTree tree = Extract(image);
  const Comparison          c = Compare(tree, truth, 1.5 * radius);
  std::cout << "straight tube, r = 4 voxels: " << tree.GetNumberOfBranches() << " branches; " << c << std::endl;
  ASSERT_EQ(tree.GetNumberOfBranches(), 1u);
  EXPECT_LT(c.MaximumDistance, 0.5);
  EXPECT_LT(c.MaximumRadiusError, 0.5);
  EXPECT_GT(c.CoveredFraction, 0.99);
  // Points about every half voxel.
  const auto & points = tree.GetBranches()[0].Points;
  for (std::size_t k = 1; k < points.size(); ++k)
  {
    EXPECT_NEAR(points[k - 1].EuclideanDistanceTo(points[k]), 0.5, 0.05);
  }
}

TEST(CenterlineExtractionFilter, CurvedTubeGivesOneBranchOnItsAxisWithItsRadius)
{
  constexpr double radius = 3.0;
  auto             image = vr::test::MakeLabelMap({ { 72, 72, 40 } }, V(1, 1, 1), P(0, 0, 0), Identity());
  VectorType       u = V(1, 0, 0.2);
  u.Normalize();
  VectorType v = V(0, 1, 0.3);
  v.Normalize();
  itk::CenterlineTree truth;
  truth.AddBranch(vr::test::TubeBranch(1, vr::test::ArcPoints(P(8.4, 8.1, 12.3), 50.0, u, v, 5.0, 85.0, 0.25), radius));
  vr::test::DrawTubes(image, truth);

  const itk::CenterlineTree tree = Extract(image);
  const Comparison          c = Compare(tree, truth, 1.5 * radius);
  std::cout << "curved tube, r = 3 voxels, curvature radius 50: " << tree.GetNumberOfBranches() << " branches; " << c
            << std::endl;
  ASSERT_EQ(tree.GetNumberOfBranches(), 1u);
  EXPECT_LT(c.MaximumDistance, 0.5);
  EXPECT_LT(c.MaximumRadiusError, 0.5);
  EXPECT_GT(c.CoveredFraction, 0.99);
}

/** A Y: a trunk of radius 5 dividing into daughters of radius 3.5 and 3. */
itk::CenterlineTree
YTree()
{
  itk::CenterlineTree tree;
  tree.AddBranch(vr::test::TubeBranch(1, vr::test::SegmentPoints(P(32.2, 31.7, 6.4), P(32.2, 31.7, 36.0), 0.5), 5.0));
  tree.AddBranch(vr::test::TubeBranch(2, vr::test::SegmentPoints(P(32.2, 31.7, 36.0), P(12.5, 38.3, 72.6), 0.5), 3.5));
  tree.AddBranch(vr::test::TubeBranch(3, vr::test::SegmentPoints(P(32.2, 31.7, 36.0), P(51.8, 24.9, 70.1), 0.5), 3.0));
  return tree;
}

TEST(CenterlineExtractionFilter, YBifurcationGivesExactlyThreeBranchesRootedAtTheTrunk)
{
  auto                      image = vr::test::MakeLabelMap({ { 64, 64, 80 } }, V(1, 1, 1), P(0, 0, 0), Identity());
  const itk::CenterlineTree truth = YTree();
  vr::test::DrawTubes(image, truth);

  auto filter = FilterType::New();
  filter->SetInput(image);
  filter->Update();
  const itk::CenterlineTree & tree = filter->GetCenterlineTree();
  const PointType             junction = P(32.2, 31.7, 36.0);
  const Comparison            c = Compare(tree, truth, 1.5 * 5.0);
  std::cout << "Y bifurcation: " << tree.GetNumberOfBranches() << " branches; " << c << std::endl;
  ASSERT_EQ(tree.GetNumberOfBranches(), 3u);
  EXPECT_LT(c.MaximumDistance, 0.5);
  EXPECT_LT(c.MaximumRadiusError, 0.5);
  EXPECT_GT(c.CoveredFraction, 0.99);
  // Rooted at the trunk's free end (the end of largest radius); both daughters start where the trunk ends.
  const auto & branches = tree.GetBranches();
  EXPECT_LT(branches[0].Points.front().EuclideanDistanceTo(P(32.2, 31.7, 6.4)), 5.0) << branches[0].Points.front();
  EXPECT_EQ(filter->GetParentBranchIds(), (std::vector<int>{ 0, 1, 1 }));
  EXPECT_EQ(branches[1].Points.front(), branches[0].Points.back());
  EXPECT_EQ(branches[2].Points.front(), branches[0].Points.back());
  EXPECT_LT(branches[0].Points.back().EuclideanDistanceTo(junction), 2.0) << branches[0].Points.back();
  // Larger child first: branch 2 is the radius-3.5 daughter.
  EXPECT_LT(vr::test::NearestPointOnTree(branches[1].Points.back(), truth).Branch, 2u);
}

TEST(CenterlineExtractionFilter, TubeInAnObliqueAnisotropicVolumeIsMeasuredInPhysicalSpace)
{
  // Voxels 0.6 x 0.8 x 1.4 mm, axes rotated by 35 degrees: every length must be physical.
  constexpr double radius = 3.0;
  const auto       direction = vr::test::RotationMatrix(1, 2, 3, 35.0);
  auto             image = vr::test::MakeLabelMap({ { 90, 70, 36 } }, V(0.6, 0.8, 1.4), P(-20.0, 10.0, 5.0), direction);
  // An arc through the middle of the volume, in physical space.
  PointType center;
  image->TransformContinuousIndexToPhysicalPoint(
    itk::ContinuousIndex<double, 3>(std::array<double, 3>{ 45.0, 35.0, 18.0 }.data()), center);
  VectorType u = direction * V(1, 0.1, 0);
  u.Normalize();
  VectorType v = direction * V(0, 1, 0.15);
  v.Normalize();
  itk::CenterlineTree truth;
  truth.AddBranch(
    vr::test::TubeBranch(1, vr::test::ArcPoints(center - u * 40.0, 40.0, u, v, -30.0, 30.0, 0.25), radius));
  vr::test::DrawTubes(image, truth);

  const itk::CenterlineTree tree = Extract(image);
  const Comparison          c = Compare(tree, truth, 1.5 * radius);
  std::cout << "oblique anisotropic volume (0.6 x 0.8 x 1.4 mm, rotated 35 degrees), r = 3 mm: "
            << tree.GetNumberOfBranches() << " branches; " << c << std::endl;
  ASSERT_EQ(tree.GetNumberOfBranches(), 1u);
  EXPECT_LT(c.MaximumDistance, 0.5 * 0.6);
  EXPECT_LT(c.MaximumRadiusError, 0.5 * 0.6);
  EXPECT_GT(c.CoveredFraction, 0.99);
}
} // namespace

namespace
{
class TubeRadiusTest : public ::testing::TestWithParam<double>
{
};

TEST_P(TubeRadiusTest, StraightTubeOfAnyRadiusIsOneBranchOnItsAxis)
{
  const double radius = GetParam();
  const int    n = static_cast<int>(8 * radius + 30);
  auto         image =
    vr::test::MakeLabelMap({ { static_cast<unsigned>(n), static_cast<unsigned>(n), static_cast<unsigned>(2 * n) } },
                           V(1, 1, 1),
                           P(0, 0, 0),
                           Identity());
  itk::CenterlineTree truth;
  truth.AddBranch(vr::test::TubeBranch(
    1,
    vr::test::SegmentPoints(
      P(radius + 3.3, radius + 4.1, radius + 2.7), P(n - radius - 3.6, n - radius - 5.2, 2 * n - radius - 3.1), 0.5),
    radius));
  vr::test::DrawTubes(image, truth);
  const itk::CenterlineTree tree = Extract(image);
  const Comparison          c = Compare(tree, truth, 1.5 * radius);
  std::cout << "straight tube, r = " << radius << " voxels: " << tree.GetNumberOfBranches() << " branches; " << c
            << std::endl;
  ASSERT_EQ(tree.GetNumberOfBranches(), 1u);
  EXPECT_LT(c.MaximumDistance, 0.5);
  EXPECT_LT(c.MaximumRadiusError, 0.5);
  EXPECT_GT(c.CoveredFraction, 0.99);
}

INSTANTIATE_TEST_SUITE_P(Radii, TubeRadiusTest, ::testing::Values(1.5, 2.0, 2.5, 3.5, 6.0, 9.0));
} // namespace

namespace
{
TEST(CenterlineExtractionFilter, BumpsOnTheWallMakeNoSpur)
{
  // The Y with 60 bumps (balls of radius 1 to 2 voxels centred on its wall), as a real segmentation's surface has.
  auto                      image = vr::test::MakeLabelMap({ { 64, 64, 80 } }, V(1, 1, 1), P(0, 0, 0), Identity());
  const itk::CenterlineTree truth = YTree();
  vr::test::DrawTubes(image, truth);
  std::mt19937                           random(7);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  itk::CenterlineTree                    bumps;
  for (int k = 0; k < 60; ++k)
  {
    const auto & branch = truth.GetBranches()[k % 3];
    const auto & a = branch.Points.front();
    const auto & b = branch.Points.back();
    VectorType   axis = b - a;
    axis.Normalize();
    VectorType side = CrossProduct(axis, V(uniform(random) - 0.5, uniform(random) - 0.5, uniform(random) - 0.5));
    side.Normalize();
    const PointType center = a + (b - a) * (0.1 + 0.8 * uniform(random)) + side * branch.Radii[0];
    bumps.AddBranch(vr::test::TubeBranch(k + 1, { center, center }, 1.0 + uniform(random)));
  }
  vr::test::DrawTubes(image, bumps);

  auto filter = FilterType::New();
  filter->SetInput(image);
  filter->Update();
  const itk::CenterlineTree & tree = filter->GetCenterlineTree();
  const Comparison            c = Compare(tree, truth, 1.5 * 5.0);
  std::cout << "Y with 60 bumps: " << tree.GetNumberOfBranches() << " branches; " << c << std::endl;
  EXPECT_EQ(tree.GetNumberOfBranches(), 3u);
  EXPECT_LT(c.MaximumDistance, 1.0);
  EXPECT_GT(c.CoveredFraction, 0.99);
}

/** A tree of three generations: a trunk, two daughters, and two granddaughters on the larger daughter, which
 * continues past them: five sections when split at the junctions... */
itk::CenterlineTree
ThreeGenerationTree()
{
  itk::CenterlineTree tree;
  tree.AddBranch(vr::test::TubeBranch(1, vr::test::SegmentPoints(P(40.3, 40.2, 5.5), P(40.3, 40.2, 30.0), 0.5), 5.0));
  tree.AddBranch(vr::test::TubeBranch(2, vr::test::SegmentPoints(P(40.3, 40.2, 30.0), P(20.4, 45.1, 60.0), 0.5), 3.5));
  tree.AddBranch(vr::test::TubeBranch(3, vr::test::SegmentPoints(P(20.4, 45.1, 60.0), P(10.2, 47.3, 92.4), 0.5), 3.0));
  tree.AddBranch(vr::test::TubeBranch(4, vr::test::SegmentPoints(P(20.4, 45.1, 60.0), P(33.1, 60.8, 90.2), 0.5), 2.5));
  tree.AddBranch(vr::test::TubeBranch(5, vr::test::SegmentPoints(P(40.3, 40.2, 30.0), P(65.2, 28.4, 85.0), 0.5), 3.0));
  // A side branch leaving the last one in the middle: that daughter is split there, six sections in all.
  tree.AddBranch(vr::test::TubeBranch(6, vr::test::SegmentPoints(P(52.75, 34.3, 57.5), P(70.3, 58.7, 70.1), 0.5), 2.0));
  return tree;
}

TEST(CenterlineExtractionFilter, ThreeGenerationsWithASideBranchGiveExactlyTheirSections)
{
  auto                      image = vr::test::MakeLabelMap({ { 80, 72, 100 } }, V(1, 1, 1), P(0, 0, 0), Identity());
  const itk::CenterlineTree truth = ThreeGenerationTree();
  vr::test::DrawTubes(image, truth);
  auto filter = FilterType::New();
  filter->SetInput(image);
  filter->Update();
  const itk::CenterlineTree & tree = filter->GetCenterlineTree();
  const Comparison            c = Compare(tree, truth, 1.5 * 5.0);
  std::cout << "three generations and a side branch: " << tree.GetNumberOfBranches() << " branches; " << c << std::endl;
  EXPECT_EQ(tree.GetNumberOfBranches(), 7u);
  EXPECT_LT(c.MaximumDistance, 0.5);
  EXPECT_LT(c.MaximumRadiusError, 0.5);
  EXPECT_GT(c.CoveredFraction, 0.99);
}
} // namespace

// ---------------------------------------------------------------------------------------------------------------
// The parts: the distance transform against ITK's, the plain reference against the filter.

namespace
{
TEST(CenterlineForeground, DistanceIsITKsMaurerDistanceToTheBackground)
{
  // Random overlapping balls in an anisotropic grid with a background margin.
  auto         image = vr::test::MakeLabelMap({ { 42, 37, 31 } }, V(0.7, 1.1, 1.6), P(-3, 4, 2), Identity());
  std::mt19937 random(11);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  itk::CenterlineTree                    balls;
  for (int k = 0; k < 25; ++k)
  {
    const PointType center = P(-3 + 0.7 * (6 + 30 * uniform(random)),
                               4 + 1.1 * (6 + 25 * uniform(random)),
                               2 + 1.6 * (5 + 20 * uniform(random)));
    balls.AddBranch(
      vr::test::TubeBranch(k + 1, { center, center + V(3 * uniform(random), 0, 2) }, 1.0 + 5.0 * uniform(random)));
  }
  vr::test::DrawTubes(image, balls);
  // DrawTubes may reach the edge: clear a one-voxel margin, as the filter's crop has.
  const auto size = image->GetLargestPossibleRegion().GetSize();
  for (itk::ImageRegionIteratorWithIndex<LabelMap> it(image, image->GetLargestPossibleRegion()); !it.IsAtEnd(); ++it)
  {
    const auto index = it.GetIndex();
    for (unsigned int axis = 0; axis < 3; ++axis)
    {
      if (index[axis] == 0 || index[axis] + 1 == static_cast<long>(size[axis]))
      {
        it.Set(0);
      }
    }
  }

  const auto foreground = itk::detail::MakeCenterlineForeground(image);
  auto       maurer = itk::SignedMaurerDistanceMapImageFilter<LabelMap, itk::Image<float, 3>>::New();
  maurer->SetInput(image);
  maurer->SetBackgroundValue(1); // the background as the object: the foreground gets its distance to it
  maurer->SetInsideIsPositive(false);
  maurer->SetSquaredDistance(false);
  maurer->SetUseImageSpacing(true);
  maurer->Update();
  ASSERT_GT(foreground.Size(), 1000u);
  double largest = 0.0;
  double worst = 0.0;
  for (uint32_t voxel = 0; voxel < foreground.Size(); ++voxel)
  {
    const double expected = maurer->GetOutput()->GetPixel(foreground.IndexOf(voxel));
    largest = std::max(largest, expected);
    worst = std::max(worst, std::abs(foreground.Distance[voxel] - expected));
  }
  std::cout << foreground.Size() << " foreground voxels, largest distance " << largest
            << " mm; largest difference from ITK's Maurer map " << worst << " mm" << std::endl;
  EXPECT_GT(largest, 4.0);
  EXPECT_LT(worst, 1e-4);
}

TEST(PlainCenterlineExtraction, FindsTheFiltersTree)
{
  // The benchmark's reference must do the same job: on a 96^3 branching tree, the same branches, points near.
  itk::Size<3> size;
  size.Fill(96);
  auto image = vr::test::MakeLabelMap(size, V(1, 1, 1), P(0, 0, 0), Identity());
  vr::test::DrawTubes(image, vr::test::MakeBranchingTree(96, 3));
  const itk::CenterlineTree filtered = Extract(image);
  const itk::CenterlineTree plain = vr::test::PlainCenterlineExtraction(image);
  std::vector<double>       distances;
  for (const auto & branch : plain.GetBranches())
  {
    for (const auto & point : branch.Points)
    {
      distances.push_back(vr::test::NearestPointOnTree(point, filtered).Nearest.Distance);
    }
  }
  std::cout << "branching tree: the filter finds " << filtered.GetNumberOfBranches()
            << " branches, the plain reference " << plain.GetNumberOfBranches() << "; its voxel points lie "
            << vr::test::Quantile(distances, 0.5) << " mm (median), " << vr::test::Quantile(distances, 0.95)
            << " mm (95 %) from the filter's" << std::endl;
  EXPECT_EQ(filtered.GetNumberOfBranches(), 15u);
  EXPECT_EQ(plain.GetNumberOfBranches(), 15u);
  EXPECT_LT(vr::test::Quantile(distances, 0.95), 1.0);
}

// ---------------------------------------------------------------------------------------------------------------
// Labels, components, roots.

/** Two disjoint tubes, labels 3 and 5, and a Y made of labels 7 (trunk) and 8 (daughters) that touch. */
LabelMap::Pointer
LabelledScene()
{
  auto                image = vr::test::MakeLabelMap({ { 80, 64, 70 } }, V(1, 1, 1), P(0, 0, 0), Identity());
  itk::CenterlineTree a;
  a.AddBranch(vr::test::TubeBranch(1, vr::test::SegmentPoints(P(8, 8, 5), P(8, 10, 60), 0.5), 3.0));
  vr::test::DrawTubes(image, a, 3);
  itk::CenterlineTree b;
  b.AddBranch(vr::test::TubeBranch(1, vr::test::SegmentPoints(P(20, 55, 5), P(22, 55, 40), 0.5), 2.5));
  vr::test::DrawTubes(image, b, 5);
  itk::CenterlineTree trunk;
  trunk.AddBranch(vr::test::TubeBranch(1, vr::test::SegmentPoints(P(50, 30, 4), P(50, 30, 30), 0.5), 4.5));
  vr::test::DrawTubes(image, trunk, 7);
  itk::CenterlineTree daughters;
  daughters.AddBranch(vr::test::TubeBranch(1, vr::test::SegmentPoints(P(50, 30, 30), P(35, 36, 64), 0.5), 3.0));
  daughters.AddBranch(vr::test::TubeBranch(2, vr::test::SegmentPoints(P(50, 30, 30), P(68, 24, 63), 0.5), 3.0));
  vr::test::DrawTubes(image, daughters, 8);
  return image;
}

TEST(CenterlineExtractionFilter, ChosenLabelsCombineAndComponentsGetATreeEach)
{
  const auto image = LabelledScene();
  // Every non-zero voxel: three components, 1 + 1 + 3 branches, the largest (the Y) first.
  auto filter = FilterType::New();
  filter->SetInput(image);
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfComponents(), 3u);
  EXPECT_EQ(filter->GetNumberOfComponentsWithoutCenterline(), 0u);
  EXPECT_EQ(filter->GetCenterlineTree().GetNumberOfBranches(), 5u);
  EXPECT_EQ(filter->GetParentBranchIds(), (std::vector<int>{ 0, 1, 1, 0, 0 }));
  std::vector<int> ids;
  for (const auto & branch : filter->GetCenterlineTree().GetBranches())
  {
    ids.push_back(branch.Id);
  }
  EXPECT_EQ(ids, (std::vector<int>{ 1, 2, 3, 4, 5 }));
  EXPECT_NEAR(filter->GetCenterlineTree().GetBranches()[0].Points.front()[0], 50.0, 1.0);

  // Labels 7 and 8 only: the Y, whose two labels touch, is one tree of three branches.
  filter->SetForegroundLabels({ 8, 7 });
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfComponents(), 1u);
  EXPECT_EQ(filter->GetCenterlineTree().GetNumberOfBranches(), 3u);
  // Label 8 alone: the daughters, joined at their shared end, make a V: one bent branch (the trunk is gone).
  filter->SetForegroundLabels({ 8 });
  filter->Update();
  EXPECT_EQ(filter->GetCenterlineTree().GetNumberOfBranches(), 1u);
  for (const auto & branch : filter->GetCenterlineTree().GetBranches())
  {
    for (const auto & point : branch.Points)
    {
      EXPECT_GT(point[2], 26.0) << "a point on the trunk, which label 8 does not hold";
    }
  }
  // Labels 3 and 5: the two tubes.
  filter->SetForegroundLabels({ 3, 5 });
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfComponents(), 2u);
  EXPECT_EQ(filter->GetCenterlineTree().GetNumberOfBranches(), 2u);
}

TEST(CenterlineExtractionFilter, RootPointChoosesTheEndAndSpecksHaveNoCenterline)
{
  auto                image = vr::test::MakeLabelMap({ { 40, 40, 70 } }, V(1, 1, 1), P(0, 0, 0), Identity());
  itk::CenterlineTree tube;
  // Wider at the top: by default the tree is rooted there.
  itk::CenterlineBranch branch =
    vr::test::TubeBranch(1, vr::test::SegmentPoints(P(20, 20, 5), P(20, 21, 60), 0.5), 3.0);
  for (std::size_t k = 0; k < branch.Radii.size(); ++k)
  {
    branch.Radii[k] = 2.5 + 2.0 * static_cast<double>(k) / static_cast<double>(branch.Radii.size() - 1);
  }
  tube.AddBranch(branch);
  vr::test::DrawTubes(image, tube);
  // A speck and a ball: no centerline, counted.
  image->SetPixel({ { 4, 4, 4 } }, 1);
  itk::CenterlineTree ball;
  ball.AddBranch(vr::test::TubeBranch(1, { P(8, 30, 30), P(8, 30, 30) }, 4.0));
  vr::test::DrawTubes(image, ball);

  auto filter = FilterType::New();
  filter->SetInput(image);
  filter->Update();
  ASSERT_EQ(filter->GetCenterlineTree().GetNumberOfBranches(), 1u);
  EXPECT_GT(filter->GetCenterlineTree().GetBranches()[0].Points.front()[2], 50.0) << "rooted at the wide end";
  EXPECT_EQ(filter->GetNumberOfComponents(), 3u);
  EXPECT_EQ(filter->GetNumberOfComponentsWithoutCenterline(), 2u);

  // A root point near the narrow end (LPS, mm) turns the tree around.
  filter->SetRootPoints({ P(20, 20, 3) });
  filter->Update();
  ASSERT_EQ(filter->GetCenterlineTree().GetNumberOfBranches(), 1u);
  const auto & points = filter->GetCenterlineTree().GetBranches()[0].Points;
  EXPECT_LT(points.front()[2], 10.0);
  EXPECT_GT(points.back()[2], 50.0);
}

TEST(CenterlineExtractionFilter, RerunsOnlyWhenTheSegmentationOrAParameterChanges)
{
  const auto image = LabelledScene();
  auto       filter = FilterType::New();
  filter->SetInput(image);
  filter->Update();
  const auto firstTime = filter->GetOutput()->GetMTime();
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetMTime(), firstTime) << "ran again without a change";
  filter->SetForegroundLabels({});
  filter->SetRootPoints({});
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetMTime(), firstTime) << "setting the same values is no change";
  image->Modified();
  filter->Update();
  EXPECT_GT(filter->GetOutput()->GetMTime(), firstTime);
  const auto secondTime = filter->GetOutput()->GetMTime();
  filter->SetMinimumBranchLength(1.0);
  filter->Update();
  EXPECT_GT(filter->GetOutput()->GetMTime(), secondTime);
}

TEST(CenterlineExtractionFilter, MinimumBranchLengthDropsShortTerminalBranches)
{
  auto                      image = vr::test::MakeLabelMap({ { 80, 72, 100 } }, V(1, 1, 1), P(0, 0, 0), Identity());
  const itk::CenterlineTree truth = ThreeGenerationTree();
  vr::test::DrawTubes(image, truth);
  auto filter = FilterType::New();
  filter->SetInput(image);
  // The side branch (id 6 of the truth) is about 30 mm long from its parent's axis, every other terminal branch
  // at least 33 mm: at 32 mm only the side branch goes, and the daughter it left is one branch again.
  filter->SetMinimumBranchLength(32.0);
  filter->Update();
  EXPECT_EQ(filter->GetCenterlineTree().GetNumberOfBranches(), 5u);
}

// ---------------------------------------------------------------------------------------------------------------
// Bad input: an exception that names the value.

std::string
ErrorOf(const std::function<void()> & action)
{
  try
  {
    action();
  }
  catch (const itk::ExceptionObject & exception)
  {
    std::cout << "  message: " << exception.GetDescription() << std::endl;
    return exception.GetDescription();
  }
  ADD_FAILURE() << "no exception";
  return "";
}

TEST(CenterlineExtractionFilter, EmptyMaskAndMissingLabelsAreClearErrors)
{
  auto empty = vr::test::MakeLabelMap({ { 10, 10, 10 } }, V(1, 1, 1), P(0, 0, 0), Identity());
  auto filter = FilterType::New();
  filter->SetInput(empty);
  EXPECT_NE(ErrorOf([&] { filter->Update(); }).find("no foreground: every voxel is 0"), std::string::npos);

  const auto scene = LabelledScene();
  filter->SetInput(scene);
  filter->SetForegroundLabels({ 4, 9 });
  const std::string message = ErrorOf([&] { filter->Update(); });
  EXPECT_NE(message.find("no voxel with label 4, 9"), std::string::npos);
  EXPECT_NE(message.find("its values are 0 3 5 7 8"), std::string::npos);

  // A level set read as a label map: many values, given as a range.
  auto floats = itk::Image<float, 3>::New();
  floats->SetRegions(itk::Image<float, 3>::RegionType({ { 0, 0, 0 } }, { { 20, 20, 20 } }));
  floats->Allocate();
  for (std::size_t k = 0; k < 8000; ++k)
  {
    floats->GetBufferPointer()[k] = -2.5f + 0.001f * static_cast<float>(k);
  }
  auto floatFilter = itk::CenterlineExtractionFilter<itk::Image<float, 3>>::New();
  floatFilter->SetInput(floats);
  floatFilter->SetForegroundLabels({ 1.0f });
  EXPECT_NE(ErrorOf([&] { floatFilter->Update(); }).find("its values range from -2.5 to 5.499"), std::string::npos);
}

TEST(CenterlineExtractionFilter, SegmentationWithoutAnElongatedComponentIsAClearError)
{
  auto                image = vr::test::MakeLabelMap({ { 30, 30, 30 } }, V(1, 1, 1), P(0, 0, 0), Identity());
  itk::CenterlineTree ball;
  ball.AddBranch(vr::test::TubeBranch(1, { P(15, 15, 15), P(15, 15, 15) }, 6.0));
  vr::test::DrawTubes(image, ball);
  auto filter = FilterType::New();
  filter->SetInput(image);
  const std::string message = ErrorOf([&] { filter->Update(); });
  EXPECT_NE(message.find("CenterlineExtractionFilter(0x"), std::string::npos);
  EXPECT_NE(message.find("no centerline"), std::string::npos);
  EXPECT_NE(message.find("longer than it is wide"), std::string::npos);
}

TEST(CenterlineExtractionFilter, BadParametersAndRootPointsNameTheValue)
{
  const auto image = LabelledScene();
  const auto expectError = [&](const std::function<void(FilterType *)> & configure, const std::string & part)
  {
    auto filter = FilterType::New();
    filter->SetInput(image);
    configure(filter);
    const std::string message = ErrorOf([&] { filter->Update(); });
    EXPECT_NE(message.find(part), std::string::npos) << message;
  };
  expectError([](FilterType * f) { f->SetMinimumBranchLength(-1.0); }, "MinimumBranchLength = -1 mm is invalid");
  expectError([](FilterType * f) { f->SetMinimumBranchLength(std::nan("")); }, "MinimumBranchLength = nan mm");
  expectError([](FilterType * f) { f->SetSpurRadiusRatio(-0.5); }, "SpurRadiusRatio = -0.5 is invalid");
  expectError([](FilterType * f) { f->SetInvalidationScale(0.5); }, "InvalidationScale = 0.5 is invalid");
  expectError([](FilterType * f) { f->SetPointSpacing(-2.0); }, "PointSpacing = -2 mm is invalid");
  expectError([](FilterType * f) { f->SetRootPointTolerance(0.0); }, "RootPointTolerance = 0 mm is invalid");
  expectError([](FilterType * f) { f->SetRootPoints({ P(std::nan(""), 0, 0) }); }, "RootPoints[0]");
  // A root point far from every vessel (the wrong frame, typically).
  expectError([](FilterType * f) { f->SetRootPoints({ P(-50, -30, 35) }); }, "from the nearest foreground voxel");
  // Two root points in one component.
  expectError(
    [](FilterType * f) {
      f->SetRootPoints({ P(50, 30, 5), P(36, 36, 62) });
    },
    "in the same connected component as an earlier root point");
  // No input.
  auto filter = FilterType::New();
  EXPECT_FALSE(ErrorOf([&] { filter->Update(); }).empty());
}

TEST(CenterlineExtractionFilter, PrintSelfPrintsEveryParameter)
{
  auto filter = FilterType::New();
  filter->SetForegroundLabels({ 2, 3 });
  filter->SetRootPoints({ P(1, 2, 3) });
  filter->SetMinimumBranchLength(4.5);
  filter->SetSpurRadiusRatio(1.25);
  filter->SetInvalidationScale(2.5);
  filter->SetPointSpacing(0.75);
  filter->SetRootPointTolerance(7.0);
  std::ostringstream text;
  filter->Print(text);
  for (const char * part : { "ForegroundLabels: 2 3",
                             "RootPoints (LPS, mm): [1, 2, 3]",
                             "RootPointTolerance (mm): 7",
                             "MinimumBranchLength (mm): 4.5",
                             "SpurRadiusRatio: 1.25",
                             "InvalidationScale: 2.5",
                             "PointSpacing (mm): 0.75",
                             "NumberOfComponents: 0",
                             "NumberOfComponentsWithoutCenterline: 0",
                             "ParentBranchIds: 0 branches" })
  {
    EXPECT_NE(text.str().find(part), std::string::npos) << part << " not in\n" << text.str();
  }
}
} // namespace
