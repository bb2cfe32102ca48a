// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// CPRResampleImageFilter samples linearly straight from the volume's buffer and keeps the volume's minimum
// between updates. Neither may change a result: these tests compare it, bit for bit, with the straightforward
// evaluation through ITK's own LinearInterpolateImageFunction and MinimumMaximumImageCalculator.
#include "itkCPRVectorHelpers.h"
#include "vrTestImages.h"

#include "itkCPRDepthImageFilter.h"
#include "itkCPRResampleImageFilter.h"
#include "itkLinearInterpolateImageFunction.h"
#include "itkMinimumMaximumImageCalculator.h"
#include "itkRunoffPhantomImageSource.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace
{
using vr::test::DepthImage;
using vr::test::VolumeImage;
using ResampleFilter = itk::CPRResampleImageFilter<VolumeImage, DepthImage>;

/** The CPR image as docs/design.md "Resampling" defines it, one pixel and one slab sample at a time through ITK's
 * interpolator; outside the volume, its minimum. */
std::vector<float>
ReferenceCPR(const VolumeImage *          volume,
             const DepthImage *           depth,
             const itk::CPRViewGeometry & view,
             const std::vector<double> &  slabOffsets,
             itk::CPRSlabMode             slabMode)
{
  auto interpolator = itk::LinearInterpolateImageFunction<VolumeImage, double>::New();
  interpolator->SetInputImage(volume);
  auto calculator = itk::MinimumMaximumImageCalculator<VolumeImage>::New();
  calculator->SetImage(volume);
  calculator->SetRegion(volume->GetBufferedRegion());
  calculator->ComputeMinimum();
  const float outside = calculator->GetMinimum();

  using ContinuousIndex = itk::ContinuousIndex<double, 3>;
  ContinuousIndex atCenter, atColumn, atRow, atDepth;
  volume->TransformPhysicalPointToContinuousIndex(view.GetCenter(), atCenter);
  volume->TransformPhysicalPointToContinuousIndex(view.GetCenter() + view.GetU() * view.GetSpacing()[0], atColumn);
  volume->TransformPhysicalPointToContinuousIndex(view.GetCenter() - view.GetUp() * view.GetSpacing()[1], atRow);
  volume->TransformPhysicalPointToContinuousIndex(view.GetCenter() + view.GetV(), atDepth);
  const itk::Vector<double, 3> perColumn = atColumn - atCenter;
  const itk::Vector<double, 3> perRow = atRow - atCenter;
  const itk::Vector<double, 3> perMillimetre = atDepth - atCenter;

  const auto         size = view.GetSize();
  const double       centerColumn = 0.5 * (size[0] - 1.0);
  const double       centerRow = 0.5 * (size[1] - 1.0);
  std::vector<float> result(size[0] * size[1]);
  for (itk::IndexValueType row = 0; row < static_cast<itk::IndexValueType>(size[1]); ++row)
  {
    for (itk::IndexValueType column = 0; column < static_cast<itk::IndexValueType>(size[0]); ++column)
    {
      const std::size_t            k = static_cast<std::size_t>(row) * size[0] + column;
      const double                 d = depth->GetBufferPointer()[k];
      const itk::Vector<double, 3> surface = atCenter.GetVectorFromOrigin() + perColumn * (column - centerColumn) +
                                             perRow * (row - centerRow) + perMillimetre * d;
      std::vector<double> values;
      for (const double offset : slabOffsets)
      {
        ContinuousIndex sample;
        for (unsigned int axis = 0; axis < 3; ++axis)
        {
          sample[axis] = surface[axis] + perMillimetre[axis] * offset;
        }
        if (interpolator->IsInsideBuffer(sample))
        {
          values.push_back(interpolator->EvaluateAtContinuousIndex(sample));
        }
      }
      if (values.empty())
      {
        result[k] = outside;
      }
      else if (slabOffsets.size() > 1 && slabMode == itk::CPRSlabMode::Mean)
      {
        double sum = 0.0;
        for (const double value : values)
        {
          sum += value;
        }
        result[k] = static_cast<float>(sum / values.size());
      }
      else if (slabMode == itk::CPRSlabMode::MinIP)
      {
        result[k] = static_cast<float>(*std::min_element(values.begin(), values.end()));
      }
      else
      {
        result[k] = static_cast<float>(*std::max_element(values.begin(), values.end()));
      }
    }
  }
  return result;
}

/** A small random volume with unequal spacing, an oblique direction and a buffered region that does not start
 * at index 0, so that every term of the index arithmetic matters. */
VolumeImage::Pointer
MakeObliqueRandomVolume()
{
  auto                    volume = VolumeImage::New();
  VolumeImage::RegionType region;
  region.SetIndex({ { 2, -3, 1 } });
  region.SetSize({ { 23, 17, 11 } });
  volume->SetRegions(region);
  volume->SetSpacing(itk::detail::MakeVector3(0.7, 1.1, 1.3));
  VolumeImage::PointType origin;
  origin[0] = -4.0;
  origin[1] = 3.0;
  origin[2] = 2.5;
  volume->SetOrigin(origin);
  VolumeImage::DirectionType direction;
  const double               c = std::cos(0.4);
  const double               s = std::sin(0.4);
  direction(0, 0) = c;
  direction(0, 1) = -s;
  direction(0, 2) = 0.0;
  direction(1, 0) = s;
  direction(1, 1) = c;
  direction(1, 2) = 0.0;
  direction(2, 0) = 0.0;
  direction(2, 1) = 0.0;
  direction(2, 2) = 1.0;
  volume->SetDirection(direction);
  volume->Allocate();
  std::mt19937                          generator(17);
  std::uniform_real_distribution<float> values(-500.0f, 1500.0f);
  std::generate_n(volume->GetBufferPointer(), region.GetNumberOfPixels(), [&] { return values(generator); });
  return volume;
}

float
MinimumOf(const VolumeImage * volume)
{
  return *std::min_element(volume->GetBufferPointer(),
                           volume->GetBufferPointer() + volume->GetBufferedRegion().GetNumberOfPixels());
}

/** The physical point at continuous index (13, 5, 6): inside the oblique volume, off its centre. */
itk::Point<double, 3>
PointInsideObliqueVolume(const VolumeImage * volume)
{
  itk::ContinuousIndex<double, 3> index;
  index[0] = 13.0;
  index[1] = 5.0;
  index[2] = 6.0;
  itk::Point<double, 3> point;
  volume->TransformContinuousIndexToPhysicalPoint(index, point);
  return point;
}

std::vector<double>
SlabOffsets(double thickness, double smallestSpacing)
{
  if (thickness <= 0.0)
  {
    return { 0.0 };
  }
  const double        step = 0.5 * smallestSpacing;
  const std::size_t   intervals = static_cast<std::size_t>(std::ceil(thickness / step - 1e-9));
  std::vector<double> offsets(intervals + 1);
  for (std::size_t k = 0; k <= intervals; ++k)
  {
    offsets[k] = -0.5 * thickness + thickness * static_cast<double>(k) / intervals;
  }
  return offsets;
}
} // namespace

// A view larger than the volume: pixels outside, on the half-voxel borders and inside, with and without slabs.
TEST(CPRResampleImageFilterFastPath, LinearSamplingEqualsITKInterpolatorBitForBit)
{
  const auto                 volume = MakeObliqueRandomVolume();
  const itk::CPRViewGeometry view(itk::detail::MakeVector3(0.1, 0.2, 1.0),
                                  33.0,
                                  PointInsideObliqueVolume(volume),
                                  { { 27, 23 } },
                                  itk::detail::MakeVector2(0.9, 0.8));
  const auto                 depth = vr::test::MakeRandomDepthImage(27, 23, -4.0f, 4.0f, 3);
  view.ConfigureImage(depth.GetPointer());

  struct Slab
  {
    double           Thickness;
    itk::CPRSlabMode Mode;
  };
  for (const Slab slab : { Slab{ 0.0, itk::CPRSlabMode::MIP },
                           Slab{ 3.0, itk::CPRSlabMode::MIP },
                           Slab{ 2.0, itk::CPRSlabMode::MinIP },
                           Slab{ 4.0, itk::CPRSlabMode::Mean } })
  {
    SCOPED_TRACE("slab " + std::to_string(slab.Thickness) + " mm");
    auto filter = ResampleFilter::New();
    filter->SetVolume(volume);
    filter->SetDepth(depth);
    filter->SetSlabThickness(slab.Thickness);
    filter->SetSlabMode(slab.Mode);
    filter->Update();
    const auto reference = ReferenceCPR(volume, depth, view, SlabOffsets(slab.Thickness, 0.7), slab.Mode);
    const auto fast = vr::test::PixelsOf(filter->GetOutput());
    ASSERT_EQ(fast.size(), reference.size());
    std::size_t different = 0;
    for (std::size_t k = 0; k < fast.size(); ++k)
    {
      different += (fast[k] != reference[k]) ? 1 : 0;
    }
    EXPECT_EQ(different, 0u) << "of " << fast.size() << " pixels";
    // The view is meant to reach outside the volume: some pixels must take the minimum, most not.
    const auto outside = std::count(fast.begin(), fast.end(), MinimumOf(volume));
    EXPECT_GT(outside, 0);
    EXPECT_LT(outside, static_cast<long>(fast.size()) / 2);
  }
}

// The phantom at its design angle, then rotated, with one filter kept across the updates as the module does.
TEST(CPRResampleImageFilterFastPath, PhantomAtSeveralAnglesEqualsITKInterpolator)
{
  auto phantom = itk::RunoffPhantomImageSource::New();
  phantom->SetScale(0.3);
  phantom->Update();
  auto depth = itk::CPRDepthImageFilter<DepthImage>::New();
  depth->SetCenterlineTree(phantom->GetCenterlineTree());
  depth->SetReferenceVolume(phantom->GetOutput());
  auto resample = ResampleFilter::New();
  resample->SetVolume(phantom->GetOutput());
  resample->SetDepth(depth->GetOutput());
  for (const double angle : { 30.0, 75.0, -20.0 })
  {
    SCOPED_TRACE("angle " + std::to_string(angle));
    itk::CPRViewSpecification specification;
    specification.AngleInDegrees = angle;
    specification.ImageSize[0] = 96;
    specification.ImageSize[1] = 160;
    depth->SetViewSpecification(specification);
    resample->Update();
    const auto reference =
      ReferenceCPR(phantom->GetOutput(), depth->GetOutput(), depth->GetView(), { 0.0 }, itk::CPRSlabMode::MIP);
    EXPECT_TRUE(vr::test::PixelsOf(resample->GetOutput()) == reference);
  }
}

// The kept minimum must follow a changed volume: a new darkest voxel becomes the value outside.
TEST(CPRResampleImageFilterFastPath, KeptMinimumFollowsAChangedVolume)
{
  const auto                 volume = MakeObliqueRandomVolume();
  const itk::CPRViewGeometry view(itk::detail::MakeVector3(0.0, 0.0, 1.0),
                                  0.0,
                                  PointInsideObliqueVolume(volume),
                                  { { 5, 5 } },
                                  itk::detail::MakeVector2(1.0, 1.0));
  // Every sample 1 m away along v: all outside.
  auto depth = vr::test::MakeDepthImage(5, 5, std::vector<float>(25, 1000.0f));
  view.ConfigureImage(depth.GetPointer());
  auto filter = ResampleFilter::New();
  filter->SetVolume(volume);
  filter->SetDepth(depth);
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetBufferPointer()[12], MinimumOf(volume));

  volume->GetBufferPointer()[100] = -3000.0f;
  volume->Modified();
  filter->Update();
  EXPECT_EQ(filter->GetOutput()->GetBufferPointer()[12], -3000.0f);
}
