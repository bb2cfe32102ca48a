// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// CPRDepthImageFilter against analytic cases (docs/design.md "View" and "Depth"). Unless a test says otherwise the view
// looks along v = LPS +y (theta = 0, up = +z), so a point (x, y, z) lands in column x + (W-1)/2 and row -z + (H-1)/2 at
// depth y, with C at the origin and 1 mm pixels.

#include "itkCPRCenterlineRasterizer.h"
#include "itkCPRDepthImageFilter.h"
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

struct DepthMap
{
  unsigned int               Width;
  unsigned int               Height;
  std::vector<float>         Depth;
  std::vector<unsigned char> Fixed;
  std::vector<uint32_t>      Owner;

  float
  DepthAt(unsigned int column, unsigned int row) const
  {
    return Depth[row * Width + column];
  }
  uint32_t
  OwnerAt(unsigned int column, unsigned int row) const
  {
    return Owner[row * Width + column];
  }
  bool
  FixedAt(unsigned int column, unsigned int row) const
  {
    return Fixed[row * Width + column] != 0;
  }
};

DepthMap
Compute(const itk::CenterlineTree &       tree,
        const itk::CPRViewSpecification & view,
        itk::CPRDepthMode                 mode = itk::CPRDepthMode::Scanline,
        bool                              fixLumen = true)
{
  auto filter = FilterType::New();
  filter->SetCenterlineTree(tree);
  filter->SetViewSpecification(view);
  filter->SetMode(mode);
  filter->SetFixLumen(fixLumen);
  filter->Update();
  const auto size = filter->GetDepthOutput()->GetLargestPossibleRegion().GetSize();
  return { static_cast<unsigned int>(size[0]),
           static_cast<unsigned int>(size[1]),
           vr::test::PixelsOf(filter->GetDepthOutput()),
           vr::test::PixelsOf(filter->GetFixedMaskOutput()),
           vr::test::PixelsOf(filter->GetOwnerLabelOutput()) };
}
} // namespace

TEST(CPRDepthImageFilter, TiltedStraightVesselHasExactDepthOnItsPixelsAndConstantRows)
{
  // x = 0 is column 10 of 21; z from 15 to -15 covers rows 5..35 of 41; depth y runs from -10 to 10.
  itk::CenterlineTree tree;
  tree.AddBranch(Branch(3, { P(0, -10, 15), P(0, 10, -15) }));
  const DepthMap map = Compute(tree, View(21, 41));
  for (unsigned int row = 5; row <= 35; ++row)
  {
    const double expected = -10.0 + 20.0 * (row - 5.0) / 30.0; // y at z = 20 - row
    EXPECT_EQ(map.OwnerAt(10, row), 3u) << "row " << row;
    EXPECT_TRUE(map.FixedAt(10, row)) << "row " << row;
    EXPECT_NEAR(map.DepthAt(10, row), expected, 1e-5) << "row " << row;
    for (unsigned int column = 0; column < 21; ++column)
    {
      EXPECT_EQ(map.DepthAt(column, row), map.DepthAt(10, row)) << "row " << row << " column " << column;
      EXPECT_EQ(map.FixedAt(column, row), column == 10) << "row " << row << " column " << column;
    }
  }
}

TEST(CPRDepthImageFilter, RowsBeyondAVesselEndCopyTheNearestRowWithACenterlinePixel)
{
  itk::CenterlineTree tree;
  tree.AddBranch(Branch(1, { P(0, -10, 15), P(0, 10, -15) })); // rows 5..35 of 41
  const DepthMap map = Compute(tree, View(21, 41));
  for (unsigned int column = 0; column < 21; ++column)
  {
    for (unsigned int row = 0; row < 5; ++row)
    {
      EXPECT_EQ(map.DepthAt(column, row), map.DepthAt(column, 5));
      EXPECT_EQ(map.OwnerAt(column, row), 1u);
      EXPECT_FALSE(map.FixedAt(column, row));
    }
    for (unsigned int row = 36; row < 41; ++row)
    {
      EXPECT_EQ(map.DepthAt(column, row), map.DepthAt(column, 35));
      EXPECT_FALSE(map.FixedAt(column, row));
    }
  }
  EXPECT_FLOAT_EQ(map.DepthAt(0, 0), -10.0f);
  EXPECT_FLOAT_EQ(map.DepthAt(0, 40), 10.0f);
}

TEST(CPRDepthImageFilter, TwoParallelVesselsSplitEachRowAtTheMiddleColumn)
{
  // Columns 5 (depth 3) and 15 (depth -4) of 21. Column 10 is 5 pixels from both: the tie goes to the vessel
  // nearer the viewer (depth -4).
  itk::CenterlineTree tree;
  tree.AddBranch(Branch(1, { P(-5, 3, 15), P(-5, 3, -15) }));
  tree.AddBranch(Branch(2, { P(5, -4, 15), P(5, -4, -15) }));
  const DepthMap map = Compute(tree, View(21, 41));
  for (unsigned int row = 0; row < 41; ++row)
  {
    for (unsigned int column = 0; column < 21; ++column)
    {
      const bool left = column < 10;
      EXPECT_EQ(map.DepthAt(column, row), left ? 3.0f : -4.0f) << column << "," << row;
      EXPECT_EQ(map.OwnerAt(column, row), left ? 1u : 2u) << column << "," << row;
    }
  }
}

TEST(CPRDepthImageFilter, WhereVesselsCrossInProjectionTheNearerOneOwnsThePixel)
{
  // A horizontal vessel (along x at z = 0, row 20) and a vertical one (along z at x = 0, column 10) cross at
  // pixel (10, 20). Try both depth orders.
  for (const double horizontalDepth : { 5.0, -5.0 })
  {
    itk::CenterlineTree tree;
    tree.AddBranch(Branch(1, { P(-10, horizontalDepth, 0), P(10, horizontalDepth, 0) }));
    tree.AddBranch(Branch(2, { P(0, -horizontalDepth, 20), P(0, -horizontalDepth, -20) }));
    const DepthMap map = Compute(tree, View(21, 41));
    const bool     horizontalIsNearer = horizontalDepth < 0.0;
    EXPECT_EQ(map.OwnerAt(10, 20), horizontalIsNearer ? 1u : 2u);
    EXPECT_EQ(map.DepthAt(10, 20), static_cast<float>(horizontalIsNearer ? horizontalDepth : -horizontalDepth));
    EXPECT_EQ(map.OwnerAt(9, 20), 1u);
    EXPECT_EQ(map.OwnerAt(10, 19), 2u);
  }
}

TEST(CPRDepthImageFilter, NearestModeEqualsABruteForceVoronoiAssignment)
{
  // Random polylines on a small anisotropic grid; the brute force compares every pixel with every centerline
  // pixel in mm, ties to the smaller depth, then the smaller branch id (docs/design.md "Depth").
  std::mt19937                           generator(5);
  std::uniform_real_distribution<double> coordinate(-14.0, 14.0);
  std::uniform_real_distribution<double> radius(0.5, 3.0);
  for (int trial = 0; trial < 4; ++trial)
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
    const auto     view = View(23, 17, 1.0, 1.5);
    const DepthMap map = Compute(tree, view, itk::CPRDepthMode::Nearest, true);
    const auto     pixels = itk::detail::RasterizeCenterlines(tree, itk::CPRViewGeometry::Resolve(view, tree, nullptr));
    ASSERT_GT(pixels.CountCenterlinePixels(), 10u);
    for (unsigned int row = 0; row < 17; ++row)
    {
      for (unsigned int column = 0; column < 23; ++column)
      {
        double      bestDistance = std::numeric_limits<double>::infinity();
        double      bestDepth = 0.0;
        uint32_t    bestOwner = 0;
        std::size_t bestIndex = 0;
        for (unsigned int r = 0; r < 17; ++r)
        {
          for (unsigned int c = 0; c < 23; ++c)
          {
            const std::size_t k = r * 23 + c;
            if (!pixels.IsCenterline(k))
            {
              continue;
            }
            const double dx = (static_cast<double>(c) - column) * 1.0;
            const double dy = (static_cast<double>(r) - row) * 1.5;
            const double distance = dx * dx + dy * dy;
            const bool   better =
              bestOwner == 0 || distance < bestDistance ||
              (distance == bestDistance &&
               (pixels.Depth[k] < bestDepth || (pixels.Depth[k] == bestDepth && pixels.Owner[k] < bestOwner)));
            if (better)
            {
              bestDistance = distance;
              bestDepth = pixels.Depth[k];
              bestOwner = pixels.Owner[k];
              bestIndex = k;
            }
          }
        }
        EXPECT_EQ(map.OwnerAt(column, row), bestOwner) << "trial " << trial << " pixel " << column << "," << row;
        EXPECT_EQ(map.DepthAt(column, row), static_cast<float>(bestDepth)) << "pixel " << column << "," << row;
        const bool withinLumen = std::sqrt(bestDistance) <= pixels.Radius[bestIndex];
        EXPECT_EQ(map.FixedAt(column, row), withinLumen) << "pixel " << column << "," << row;
      }
    }
  }
}

TEST(CPRDepthImageFilter, LumenFixingFixesExactlyThePixelsWithinTheRadius)
{
  // A vertical vessel at column 10 with a 3.4 mm lumen, 0.8 mm columns: |i - 10| * 0.8 <= 3.4 means columns 6..14.
  itk::CenterlineTree tree;
  tree.AddBranch(Branch(1, { P(0, 2, 15), P(0, 2, -15) }, { 3.4, 3.4 }));
  const DepthMap scanline = Compute(tree, View(21, 41, 0.8, 1.0));
  for (unsigned int row = 5; row <= 35; ++row)
  {
    for (unsigned int column = 0; column < 21; ++column)
    {
      EXPECT_EQ(scanline.FixedAt(column, row), column >= 6 && column <= 14) << column << "," << row;
    }
  }
  // Rows beyond the vessel's end have no centerline pixel of their own: nothing fixed in scanline mode.
  EXPECT_FALSE(scanline.FixedAt(10, 2));

  // Without lumen fixing only the centerline column is fixed.
  const DepthMap bare = Compute(tree, View(21, 41, 0.8, 1.0), itk::CPRDepthMode::Scanline, false);
  for (unsigned int column = 0; column < 21; ++column)
  {
    EXPECT_EQ(bare.FixedAt(column, 20), column == 10);
  }

  // Nearest mode fixes a 2D neighbourhood: beyond the top end (row 5) it is a half disc of radius 3.4 mm.
  const DepthMap nearest = Compute(tree, View(21, 41, 0.8, 1.0), itk::CPRDepthMode::Nearest);
  for (unsigned int row = 0; row < 5; ++row)
  {
    for (unsigned int column = 0; column < 21; ++column)
    {
      const double dx = (column - 10.0) * 0.8;
      const double dy = (5.0 - row) * 1.0;
      EXPECT_EQ(nearest.FixedAt(column, row), std::sqrt(dx * dx + dy * dy) <= 3.4) << column << "," << row;
    }
  }
}

TEST(CPRDepthImageFilter, RotatingByNinetyDegreesMapsAKnownPointToItsPixel)
{
  // At theta = 90 about up = +z the view looks along v = (-1, 0, 0) with screen-right u = (0, 1, 0). The point
  // C + (7, -4, 3) then lies at column -4 + (W-1)/2, row -3 + (H-1)/2 and depth -7.
  itk::CenterlineTree tree;
  tree.AddBranch(Branch(4, { P(7, -4, 3) }));
  tree.AddBranch(Branch(5, { P(0, 8, -10), P(0, 8, -11) })); // keeps the rows below filled
  const DepthMap map = Compute(tree, View(21, 41, 1.0, 1.0, 90.0));
  EXPECT_EQ(map.OwnerAt(6, 17), 4u);
  EXPECT_NEAR(map.DepthAt(6, 17), -7.0, 1e-5);
  EXPECT_TRUE(map.FixedAt(6, 17));
  EXPECT_EQ(map.OwnerAt(18, 30), 5u);
  EXPECT_NEAR(map.DepthAt(18, 30), 0.0, 1e-9); // cos(90 degrees) is not exactly 0 in floating point
}

TEST(CPRDepthImageFilter, OutputsCarryTheViewAndItsSpacing)
{
  itk::CenterlineTree tree;
  tree.AddBranch(Branch(1, { P(0, 0, 5), P(0, 0, -5) }));
  auto filter = FilterType::New();
  filter->SetCenterlineTree(tree);
  filter->SetViewSpecification(View(9, 13, 0.5, 0.75, 20.0));
  filter->Update();
  for (const itk::ImageBase<2> * image : { static_cast<const itk::ImageBase<2> *>(filter->GetDepthOutput()),
                                           static_cast<const itk::ImageBase<2> *>(filter->GetFixedMaskOutput()),
                                           static_cast<const itk::ImageBase<2> *>(filter->GetOwnerLabelOutput()) })
  {
    EXPECT_DOUBLE_EQ(image->GetSpacing()[0], 0.5);
    EXPECT_DOUBLE_EQ(image->GetSpacing()[1], 0.75);
    const auto view = itk::CPRViewGeometry::ReadFromDictionary(image->GetMetaDataDictionary());
    EXPECT_EQ(view, filter->GetView());
    EXPECT_DOUBLE_EQ(view.GetAngleInDegrees(), 20.0);
  }
}

TEST(CPRDepthImageFilter, RejectsAnEmptyTreeAndATreeOutsideTheImage)
{
  auto filter = FilterType::New();
  filter->SetViewSpecification(View(9, 9));
  EXPECT_THROW(filter->Update(), itk::ExceptionObject);

  itk::CenterlineTree far;
  far.AddBranch(Branch(1, { P(500, 0, 500), P(600, 0, 500) }));
  filter->SetCenterlineTree(far);
  try
  {
    filter->Update();
    ADD_FAILURE() << "no exception";
  }
  catch (const itk::ExceptionObject & error)
  {
    EXPECT_NE(std::string(error.GetDescription()).find("no centerline point projects into"), std::string::npos)
      << error.GetDescription();
  }
}
