// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrClinicalVolume.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace vr::test
{
namespace
{
template<typename TPixel>
TPixel
Stored(double value)
{
  if constexpr (std::is_integral_v<TPixel>)
  {
    const double rounded = std::round(value);
    return static_cast<TPixel>(std::clamp(rounded,
                                          static_cast<double>(std::numeric_limits<TPixel>::lowest()),
                                          static_cast<double>(std::numeric_limits<TPixel>::max())));
  }
  else
  {
    return static_cast<TPixel>(value);
  }
}
} // namespace

template<typename TPixel>
typename itk::Image<TPixel, 3>::Pointer
MakeClinicalVolume(itk::CTAPhantomKind                 kind,
                   const itk::Size<3> &                size,
                   double                              intercept,
                   const std::function<void(double)> & progress)
{
  using PhantomImage = itk::Image<float, 3>;
  if (size[0] < 2 || size[1] < 2 || size[2] < 2)
  {
    throw std::invalid_argument("a clinical volume needs at least 2 voxels along each axis");
  }
  // The phantom's field of view (mm), from its grid at 1 mm.
  auto reference = itk::MakeCTAPhantom(kind, 1.0);
  reference.Source->UpdateOutputInformation();
  const auto   referenceSize = reference.Source->GetOutput()->GetLargestPossibleRegion().GetSize();
  const double pixel = std::max(static_cast<double>(referenceSize[0]) / static_cast<double>(size[0]),
                                static_cast<double>(referenceSize[1]) / static_cast<double>(size[1]));

  // Drawn at the slices' pixel spacing: its columns and rows are the output's, centred.
  auto phantom = itk::MakeCTAPhantom(kind, pixel);
  phantom.Source->UpdateOutputInformation();
  PhantomImage *            drawn = phantom.Source->GetOutput();
  const auto                drawnSize = drawn->GetLargestPossibleRegion().GetSize();
  const auto                drawnOrigin = drawn->GetOrigin();
  const itk::IndexValueType shiftX =
    (static_cast<itk::IndexValueType>(size[0]) - static_cast<itk::IndexValueType>(drawnSize[0])) / 2;
  const itk::IndexValueType shiftY =
    (static_cast<itk::IndexValueType>(size[1]) - static_cast<itk::IndexValueType>(drawnSize[1])) / 2;
  const double length = static_cast<double>(drawnSize[2]) * pixel;
  const double sliceSpacing = length / static_cast<double>(size[2]);
  const double bottom = drawnOrigin[2] - 0.5 * pixel;

  using OutputImage = itk::Image<TPixel, 3>;
  auto                             volume = OutputImage::New();
  typename OutputImage::RegionType region;
  region.SetSize(size);
  volume->SetRegions(region);
  typename OutputImage::SpacingType spacing;
  spacing[0] = pixel;
  spacing[1] = pixel;
  spacing[2] = sliceSpacing;
  volume->SetSpacing(spacing);
  typename OutputImage::PointType origin;
  origin[0] = drawnOrigin[0] - static_cast<double>(shiftX) * pixel;
  origin[1] = drawnOrigin[1] - static_cast<double>(shiftY) * pixel;
  origin[2] = bottom + 0.5 * sliceSpacing;
  volume->SetOrigin(origin);
  volume->Allocate();

  const std::size_t   sliceVoxels = static_cast<std::size_t>(size[0]) * size[1];
  const TPixel        air = Stored<TPixel>(-1000.0 - intercept);
  constexpr long      SlabSlices = 16;
  long                slabStart = -1;
  long                slabEnd = -1;
  std::vector<double> slice(static_cast<std::size_t>(drawnSize[0]) * drawnSize[1]);
  for (itk::SizeValueType k = 0; k < size[2]; ++k)
  {
    // The drawn slices around this one (continuous index t along the drawn z axis).
    const double z = origin[2] + static_cast<double>(k) * sliceSpacing;
    const double t = std::clamp((z - drawnOrigin[2]) / pixel, 0.0, static_cast<double>(drawnSize[2] - 1));
    const long   below = std::min(static_cast<long>(std::floor(t)), static_cast<long>(drawnSize[2]) - 1);
    const long   above = std::min(below + 1, static_cast<long>(drawnSize[2]) - 1);
    const double fraction = t - static_cast<double>(below);
    if (below < slabStart || above >= slabEnd)
    {
      slabStart = below;
      slabEnd = std::min(below + SlabSlices, static_cast<long>(drawnSize[2]));
      PhantomImage::RegionType slab = drawn->GetLargestPossibleRegion();
      slab.SetIndex(2, slabStart);
      slab.SetSize(2, static_cast<itk::SizeValueType>(slabEnd - slabStart));
      drawn->SetRequestedRegion(slab);
      phantom.Source->Update();
    }
    const float * lower = drawn->GetBufferPointer() + (below - slabStart) * static_cast<long>(slice.size());
    const float * upper = drawn->GetBufferPointer() + (above - slabStart) * static_cast<long>(slice.size());
    TPixel *      target = volume->GetBufferPointer() + k * sliceVoxels;
    std::fill(target, target + sliceVoxels, air);
    for (itk::SizeValueType j = 0; j < drawnSize[1]; ++j)
    {
      const itk::IndexValueType y = static_cast<itk::IndexValueType>(j) + shiftY;
      if (y < 0 || y >= static_cast<itk::IndexValueType>(size[1]))
      {
        continue;
      }
      for (itk::SizeValueType i = 0; i < drawnSize[0]; ++i)
      {
        const itk::IndexValueType x = static_cast<itk::IndexValueType>(i) + shiftX;
        if (x < 0 || x >= static_cast<itk::IndexValueType>(size[0]))
        {
          continue;
        }
        const std::size_t at = j * drawnSize[0] + i;
        const double      value = lower[at] + (upper[at] - lower[at]) * fraction;
        target[static_cast<std::size_t>(y) * size[0] + static_cast<std::size_t>(x)] = Stored<TPixel>(value - intercept);
      }
    }
    if (progress && k % 64 == 0)
    {
      progress(static_cast<double>(k) / static_cast<double>(size[2]));
    }
  }
  if (progress)
  {
    progress(1.0);
  }
  return volume;
}

template itk::Image<short, 3>::Pointer
MakeClinicalVolume<short>(itk::CTAPhantomKind, const itk::Size<3> &, double, const std::function<void(double)> &);
template itk::Image<unsigned short, 3>::Pointer
MakeClinicalVolume<unsigned short>(itk::CTAPhantomKind,
                                   const itk::Size<3> &,
                                   double,
                                   const std::function<void(double)> &);
template itk::Image<float, 3>::Pointer
MakeClinicalVolume<float>(itk::CTAPhantomKind, const itk::Size<3> &, double, const std::function<void(double)> &);
template itk::Image<double, 3>::Pointer
MakeClinicalVolume<double>(itk::CTAPhantomKind, const itk::Size<3> &, double, const std::function<void(double)> &);
} // namespace vr::test
