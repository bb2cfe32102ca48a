// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrIntensityWindow.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace vr
{
std::string
IntensityUnitOf(VolumeNode * volume)
{
  // Air in CT is about -1000 HU; no other modality stores intensities this far below 0.
  constexpr double AirBound = -500.0;
  vtkImageData *   image = volume != nullptr ? volume->GetImageData() : nullptr;
  if (image == nullptr || image->GetPointData()->GetScalars() == nullptr)
  {
    return std::string();
  }
  double range[2];
  image->GetScalarRange(range);
  // The stored values' range as intensities (a CT stored as unsigned integers has its air in the intercept).
  const itk::CPRIntensityRescale & rescale = volume->GetIntensityRescale();
  const double                     lowest = std::min(rescale.Apply(range[0]), rescale.Apply(range[1]));
  return lowest <= AirBound ? "HU" : std::string();
}

void
PercentileWindowOf(VolumeNode * volume, double & window, double & level)
{
  window = 0.0;
  level = 0.0;
  vtkImageData * image = volume != nullptr ? volume->GetImageData() : nullptr;
  vtkDataArray * scalars = image != nullptr ? image->GetPointData()->GetScalars() : nullptr;
  if (scalars == nullptr || scalars->GetNumberOfTuples() == 0)
  {
    return;
  }
  constexpr vtkIdType MaximumSamples = vtkIdType{ 1 } << 22;
  const vtkIdType     count = scalars->GetNumberOfTuples();
  const vtkIdType     stride = std::max<vtkIdType>(1, (count + MaximumSamples - 1) / MaximumSamples);
  std::vector<double> samples;
  samples.reserve(static_cast<std::size_t>(count / stride + 1));
  for (vtkIdType k = 0; k < count; k += stride)
  {
    const double value = scalars->GetComponent(k, 0);
    if (std::isfinite(value))
    {
      samples.push_back(value);
    }
  }
  if (samples.empty())
  {
    return;
  }
  // The value at rank q (n - 1), rounded to the nearest rank.
  auto percentile = [&samples](double q)
  {
    const auto rank = static_cast<std::size_t>(std::lround(q * static_cast<double>(samples.size() - 1)));
    std::nth_element(samples.begin(), samples.begin() + static_cast<std::ptrdiff_t>(rank), samples.end());
    return samples[rank];
  };
  // The rescale is monotonic: the percentiles of the intensities are those of the stored values, rescaled.
  const itk::CPRIntensityRescale & rescale = volume->GetIntensityRescale();
  const double                     first = rescale.Apply(percentile(0.01));
  const double                     last = rescale.Apply(percentile(0.99));
  const double                     low = std::min(first, last);
  const double                     high = std::max(first, last);
  window = std::max(high - low, 1.0);
  level = 0.5 * (low + high);
}

void
DefaultWindowOf(VolumeNode * volume, double & window, double & level)
{
  if (IntensityUnitOf(volume) == "HU")
  {
    window = CTAWindow;
    level = CTALevel;
    return;
  }
  PercentileWindowOf(volume, window, level);
}
} // namespace vr
