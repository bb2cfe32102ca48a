// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrGreyImage.h"

#include "vrWindowLevel.h"

namespace vr
{
namespace
{
QImage
Grey(const float * pixels, int width, int height, double window, double level)
{
  QImage image(width, height, QImage::Format_Grayscale8);
  for (int row = 0; row < height; ++row)
  {
    WindowLevelToBytes(pixels + static_cast<std::size_t>(row) * width, width, window, level, image.scanLine(row));
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
