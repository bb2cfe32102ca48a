// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrGreyImage.h"

#include <algorithm>
#include <cmath>

namespace vr
{
namespace
{
QImage
Grey(const float * pixels, int width, int height, double window, double level)
{
  QImage       image(width, height, QImage::Format_Grayscale8);
  const double low = level - 0.5 * window;
  const double scale = 255.0 / std::max(window, 1e-6);
  for (int row = 0; row < height; ++row)
  {
    uchar *       line = image.scanLine(row);
    const float * values = pixels + static_cast<std::size_t>(row) * width;
    for (int column = 0; column < width; ++column)
    {
      const double value = std::isfinite(values[column]) ? (values[column] - low) * scale : 0.0;
      line[column] = static_cast<uchar>(std::clamp(value, 0.0, 255.0));
    }
  }
  return image;
}
} // namespace

QImage
GreyImage(const DepthImageType * image, double window, double level)
{
  if (image == nullptr)
  {
    return QImage();
  }
  const auto size = image->GetLargestPossibleRegion().GetSize();
  return Grey(image->GetBufferPointer(), static_cast<int>(size[0]), static_cast<int>(size[1]), window, level);
}

QImage
GreySlice(const VolumeImageType * stack, unsigned int index, double window, double level)
{
  if (stack == nullptr || index >= stack->GetLargestPossibleRegion().GetSize()[2])
  {
    return QImage();
  }
  const auto        size = stack->GetLargestPossibleRegion().GetSize();
  const std::size_t slice = static_cast<std::size_t>(size[0]) * size[1];
  return Grey(
    stack->GetBufferPointer() + index * slice, static_cast<int>(size[0]), static_cast<int>(size[1]), window, level);
}
} // namespace vr
