// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// CPRResampleImageFilter against analytic cases (docs/design.md "Resampling"): X = B(i, j) + d(i, j) v.

#include "itkCPRVectorHelpers.h"
#include "itkCPRResampleImageFilter.h"
#include "itkImageRegionIteratorWithIndex.h"
#include "vrTestImages.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace
{
using VolumeType = itk::Image<float, 3>;
using DepthType = itk::Image<float, 2>;
using FilterType = itk::CPRResampleImageFilter<VolumeType, DepthType, DepthType>;
using PointType = itk::Point<double, 3>;

using vr::test::P;

/** A volume of the given grid whose voxels hold f(physical point of the voxel). */
VolumeType::Pointer
MakeVolume(const itk::Size<3> &                             size,
           const itk::Vector<double, 3> &                   spacing,
           const PointType &                                origin,
           const VolumeType::DirectionType &                direction,
           const std::function<double(const PointType &)> & f)
{
  auto volume = VolumeType::New();
  volume->SetRegions(size);
  volume->SetSpacing(spacing);
  volume->SetOrigin(origin);
  volume->SetDirection(direction);
  volume->Allocate();
  for (itk::ImageRegionIteratorWithIndex<VolumeType> it(volume, volume->GetBufferedRegion()); !it.IsAtEnd(); ++it)
  {
    PointType point;
    volume->TransformIndexToPhysicalPoint(it.GetIndex(), point);
    it.Set(static_cast<float>(f(point)));
  }
  return volume;
}

VolumeType::DirectionType
Identity()
{
  VolumeType::DirectionType direction;
  direction.SetIdentity();
  return direction;
}

/** A depth image on \a view, filled by depth(i, j). */
DepthType::Pointer
MakeDepth(const itk::CPRViewGeometry & view, const std::function<double(int, int)> & depth)
{
  auto image = DepthType::New();
  view.ConfigureImage(image.GetPointer());
  image->Allocate();
  for (itk::ImageRegionIteratorWithIndex<DepthType> it(image, image->GetBufferedRegion()); !it.IsAtEnd(); ++it)
  {
    it.Set(static_cast<float>(depth(it.GetIndex()[0], it.GetIndex()[1])));
  }
  return image;
}

itk::CPRViewGeometry
MakeView(double angle, const PointType & center, unsigned int width, unsigned int height, double sx, double sy)
{
  itk::Size<2> size = { { width, height } };
  return itk::CPRViewGeometry(itk::detail::MakeVector3(0, 0, 1), angle, center, size, itk::detail::MakeVector2(sx, sy));
}

double
Linear(const PointType & p)
{
  return 3.0 * p[0] - 2.0 * p[1] + 0.5 * p[2] + 7.0;
}
} // namespace

TEST(CPRResampleImageFilter, LinearVolumeGivesTheAnalyticValueEverywhere)
{
  // Volume covers [-20, 20]^3 at 1 mm; the surface stays well inside it. Linear interpolation is exact for a
  // linear function, so each pixel equals f(B(i, j) + d(i, j) v).
  const auto volume =
    MakeVolume({ { 41, 41, 41 } }, itk::detail::MakeVector3(1, 1, 1), P(-20, -20, -20), Identity(), Linear);
  const auto view = MakeView(35.0, P(1, -2, 0.5), 24, 30, 0.7, 0.9);
  const auto depth = MakeDepth(view, [](int i, int j) { return 0.3 * i - 0.2 * j + 1.0; });
  auto       filter = FilterType::New();
  filter->SetVolume(volume);
  filter->SetDepth(depth);
  filter->Update(); // the view comes from the depth image's metadata
  const auto cpr = vr::test::PixelsOf(filter->GetOutput());
  for (int j = 0; j < 30; ++j)
  {
    for (int i = 0; i < 24; ++i)
    {
      const double expected = Linear(view.SurfacePoint(i, j, 0.3 * i - 0.2 * j + 1.0));
      EXPECT_NEAR(cpr[j * 24 + i], expected, 2e-3) << "pixel " << i << "," << j;
    }
  }
  EXPECT_EQ(filter->GetOutput()->GetSpacing(), depth->GetSpacing());
  EXPECT_TRUE(itk::CPRViewGeometry::DictionaryHasView(filter->GetOutput()->GetMetaDataDictionary()));
}

TEST(CPRResampleImageFilter, NonIdentityDirectionIsSampledAtTheRightPlace)
{
  // A rotated, flipped, offset grid: the voxel holding f at index k lies at origin + direction * (spacing * k).
  // If the filter ignored the direction the values would be f at other points.
  VolumeType::DirectionType direction;
  direction.Fill(0.0);
  direction[0][1] = -1.0; // i runs along +y, j along -x, k along -z (a 90 degree turn and a flip)
  direction[1][0] = 1.0;
  direction[2][2] = -1.0;
  const auto volume =
    MakeVolume({ { 30, 36, 24 } }, itk::detail::MakeVector3(1.2, 1.0, 1.5), P(15, -20, 17), direction, Linear);
  // The grid spans x in [-20, 15], y in [-20, 14.8] and z in [-17.5, 17]; stay inside it.
  const auto view = MakeView(-20.0, P(-3, -2, 0), 16, 18, 1.0, 1.0);
  const auto depth = MakeDepth(view, [](int i, int j) { return 0.25 * (i - j); });
  auto       filter = FilterType::New();
  filter->SetVolume(volume);
  filter->SetDepth(depth);
  filter->Update();
  const auto cpr = vr::test::PixelsOf(filter->GetOutput());
  for (int j = 0; j < 18; ++j)
  {
    for (int i = 0; i < 16; ++i)
    {
      EXPECT_NEAR(cpr[j * 16 + i], Linear(view.SurfacePoint(i, j, 0.25 * (i - j))), 2e-3) << i << "," << j;
    }
  }
}

TEST(CPRResampleImageFilter, PointsOutsideTheVolumeGetTheDefaultValue)
{
  const auto volume = MakeVolume({ { 10, 10, 10 } },
                                 itk::detail::MakeVector3(1, 1, 1),
                                 P(0, 0, 0),
                                 Identity(),
                                 [](const PointType & p) { return 100.0 + p[0]; });
  const auto view = MakeView(0.0, P(4.5, 4.5, 4.5), 4, 4, 1.0, 1.0);
  // Row 0 reaches 100 mm behind the volume; the rest stays on its middle.
  const auto depth = MakeDepth(view, [](int, int j) { return j == 0 ? 100.0 : 0.0; });
  auto       filter = FilterType::New();
  filter->SetVolume(volume);
  filter->SetDepth(depth);
  filter->Update();
  auto cpr = vr::test::PixelsOf(filter->GetOutput());
  EXPECT_FLOAT_EQ(cpr[0], 100.0f) << "default: the volume's minimum";
  EXPECT_FLOAT_EQ(cpr[4 + 1], 100.0f + 4.0f) << "inside: column 1 lies at x = 4";

  filter->SetDefaultValue(-1024.0f);
  filter->Update();
  cpr = vr::test::PixelsOf(filter->GetOutput());
  EXPECT_FLOAT_EQ(cpr[3], -1024.0f);
}

namespace
{
// One bright voxel of 1000 at index (10, 10, 10) of a 21^3 volume at 1 mm; the surface passes 2 mm in front of
// it (d = -2 along v = +y) at the pixel that lines up with it in x and z.
struct BrightVoxel
{
  VolumeType::Pointer  Volume;
  itk::CPRViewGeometry View;
  DepthType::Pointer   Depth;
};

BrightVoxel
MakeBrightVoxel()
{
  BrightVoxel case_;
  case_.Volume =
    MakeVolume({ { 21, 21, 21 } },
               itk::detail::MakeVector3(1, 1, 1),
               P(0, 0, 0),
               Identity(),
               [](const PointType & p) { return (p[0] == 10.0 && p[1] == 10.0 && p[2] == 10.0) ? 1000.0 : 0.0; });
  case_.View = MakeView(0.0, P(10, 10, 10), 5, 5, 1.0, 1.0); // pixel (2, 2) lines up with x = 10, z = 10
  case_.Depth = MakeDepth(case_.View, [](int, int) { return -2.0; });
  return case_;
}

float
CentrePixel(const BrightVoxel & case_, double slabThickness, itk::CPRSlabMode mode)
{
  auto filter = FilterType::New();
  filter->SetVolume(case_.Volume);
  filter->SetDepth(case_.Depth);
  filter->SetSlabThickness(slabThickness);
  filter->SetSlabMode(mode);
  filter->Update();
  return vr::test::PixelsOf(filter->GetOutput())[2 * 5 + 2];
}
} // namespace

TEST(CPRResampleImageFilter, SlabMaximumFindsABrightVoxelTheSurfaceMisses)
{
  const auto case_ = MakeBrightVoxel();
  EXPECT_FLOAT_EQ(CentrePixel(case_, 0.0, itk::CPRSlabMode::MIP), 0.0f) << "the surface alone misses it";
  EXPECT_FLOAT_EQ(CentrePixel(case_, 2.0, itk::CPRSlabMode::MIP), 0.0f) << "1 mm half slab: still misses";
  EXPECT_FLOAT_EQ(CentrePixel(case_, 6.0, itk::CPRSlabMode::MIP), 1000.0f) << "3 mm half slab reaches it";
  EXPECT_FLOAT_EQ(CentrePixel(case_, 6.0, itk::CPRSlabMode::MinIP), 0.0f);
  // 13 samples 0.5 mm apart from -5 to +1 mm around the voxel; linear interpolation gives 500, 1000, 500 at
  // -0.5, 0, 0.5 and 0 elsewhere: mean 2000 / 13.
  EXPECT_NEAR(CentrePixel(case_, 6.0, itk::CPRSlabMode::Mean), 2000.0 / 13.0, 1e-3);
}

TEST(CPRResampleImageFilter, NearestAndCubicInterpolation)
{
  const auto volume =
    MakeVolume({ { 41, 41, 41 } }, itk::detail::MakeVector3(1, 1, 1), P(-20, -20, -20), Identity(), Linear);
  const auto view = MakeView(0.0, P(0, 0, 0), 9, 9, 1.0, 1.0);
  // Nearest at depths that land 0.3 mm off a voxel centre returns the voxel's own value.
  const auto depth = MakeDepth(view, [](int, int) { return 2.3; });
  auto       filter = FilterType::New();
  filter->SetVolume(volume);
  filter->SetDepth(depth);
  filter->SetInterpolation(itk::CPRInterpolationMode::Nearest);
  filter->Update();
  auto cpr = vr::test::PixelsOf(filter->GetOutput());
  for (int j = 0; j < 9; ++j)
  {
    for (int i = 0; i < 9; ++i)
    {
      EXPECT_FLOAT_EQ(cpr[j * 9 + i], Linear(view.SurfacePoint(i, j, 2.0))) << i << "," << j;
    }
  }
  // A cubic B-spline reproduces a linear function away from the borders.
  filter->SetInterpolation(itk::CPRInterpolationMode::Cubic);
  filter->Update();
  cpr = vr::test::PixelsOf(filter->GetOutput());
  for (int j = 0; j < 9; ++j)
  {
    for (int i = 0; i < 9; ++i)
    {
      EXPECT_NEAR(cpr[j * 9 + i], Linear(view.SurfacePoint(i, j, 2.3)), 1e-2) << i << "," << j;
    }
  }
}

TEST(CPRResampleImageFilter, RejectsBadInput)
{
  const auto volume = MakeVolume({ { 5, 5, 5 } }, itk::detail::MakeVector3(1, 1, 1), P(0, 0, 0), Identity(), Linear);
  auto       bare = vr::test::MakeDepthImage(3, 3, std::vector<float>(9, 0.0f));
  auto       filter = FilterType::New();
  filter->SetVolume(volume);
  filter->SetDepth(bare);
  EXPECT_THROW(filter->Update(), itk::ExceptionObject) << "no view anywhere";

  filter->SetView(MakeView(0.0, P(2, 2, 2), 4, 3, 1.0, 1.0));
  try
  {
    filter->Update();
    ADD_FAILURE() << "no exception for a view of another size";
  }
  catch (const itk::ExceptionObject & error)
  {
    EXPECT_NE(std::string(error.GetDescription()).find("size"), std::string::npos) << error.GetDescription();
  }

  filter->SetView(MakeView(0.0, P(2, 2, 2), 3, 3, 1.0, 1.0));
  filter->SetSlabThickness(-1.0);
  try
  {
    filter->Update();
    ADD_FAILURE() << "no exception for a negative slab";
  }
  catch (const itk::ExceptionObject & error)
  {
    EXPECT_NE(std::string(error.GetDescription()).find("SlabThickness"), std::string::npos) << error.GetDescription();
  }
}
