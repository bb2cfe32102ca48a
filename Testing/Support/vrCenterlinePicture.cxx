// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCenterlinePicture.h"

#include "itkImageFileWriter.h"
#include "itkImageRegionConstIteratorWithIndex.h"
#include "itkPNGImageIO.h"
#include "itkRGBPixel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace vr::test
{
void
WriteCenterlinePicture(const itk::Image<unsigned char, 3> * segmentation,
                       const itk::CenterlineTree &          tree,
                       const std::string &                  path,
                       const itk::CenterlineTree *          reference)
{
  using PointType = itk::Point<double, 3>;
  // The physical bounds of the foreground.
  std::array<double, 3> low;
  std::array<double, 3> high;
  low.fill(std::numeric_limits<double>::infinity());
  high.fill(-std::numeric_limits<double>::infinity());
  std::vector<PointType> voxels;
  for (itk::ImageRegionConstIteratorWithIndex<itk::Image<unsigned char, 3>> it(segmentation,
                                                                               segmentation->GetBufferedRegion());
       !it.IsAtEnd();
       ++it)
  {
    if (it.Get() == 0)
    {
      continue;
    }
    PointType point;
    segmentation->TransformIndexToPhysicalPoint(it.GetIndex(), point);
    voxels.push_back(point);
    for (unsigned int axis = 0; axis < 3; ++axis)
    {
      low[axis] = std::min(low[axis], point[axis]);
      high[axis] = std::max(high[axis], point[axis]);
    }
  }
  const auto &       spacing = segmentation->GetSpacing();
  std::array<int, 3> order{ 0, 1, 2 };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return high[a] - low[a] > high[b] - low[b]; });
  // 1600 pixels down, whatever the segmentation's size.
  const double       extent = high[order[0]] - low[order[0]] + 10.0;
  const double       pixel = extent / 1600.0;
  const int          rowAxis = order[0];    // down the picture
  const int          columnAxis = order[1]; // across
  const double       margin = 5.0;
  const unsigned int width = static_cast<unsigned int>((high[columnAxis] - low[columnAxis] + 2 * margin) / pixel) + 1;
  const unsigned int height = static_cast<unsigned int>((high[rowAxis] - low[rowAxis] + 2 * margin) / pixel) + 1;
  std::vector<unsigned> counts(static_cast<std::size_t>(width) * height, 0);
  const auto            pixelOf = [&](const PointType & point, long & column, long & row)
  {
    column = std::lround((point[columnAxis] - low[columnAxis] + margin) / pixel);
    row = std::lround((high[rowAxis] + margin - point[rowAxis]) / pixel);
    return column >= 0 && row >= 0 && column < static_cast<long>(width) && row < static_cast<long>(height);
  };
  // Each voxel covers its footprint (about its spacing) in the picture.
  const long footprint =
    std::max(0L, std::lround(0.5 * std::min(spacing[0], std::min(spacing[1], spacing[2])) / pixel));
  for (const auto & point : voxels)
  {
    long column = 0;
    long row = 0;
    pixelOf(point, column, row);
    for (long r = row - footprint; r <= row + footprint; ++r)
    {
      for (long c = column - footprint; c <= column + footprint; ++c)
      {
        if (r >= 0 && c >= 0 && r < static_cast<long>(height) && c < static_cast<long>(width))
        {
          ++counts[static_cast<std::size_t>(r) * width + static_cast<std::size_t>(c)];
        }
      }
    }
  }
  const unsigned most = std::max(1u, *std::max_element(counts.begin(), counts.end()));

  using RGBImage = itk::Image<itk::RGBPixel<unsigned char>, 2>;
  auto               image = RGBImage::New();
  RGBImage::SizeType size;
  size[0] = width;
  size[1] = height;
  image->SetRegions(RGBImage::RegionType(size));
  image->Allocate();
  for (std::size_t k = 0; k < counts.size(); ++k)
  {
    const auto grey = static_cast<unsigned char>(counts[k] == 0 ? 0 : 60 + (170 * counts[k]) / most);
    image->GetBufferPointer()[k].Set(grey, grey, grey);
  }
  static const std::array<std::array<unsigned char, 3>, 8> colours = { { { 255, 60, 60 },
                                                                         { 60, 200, 255 },
                                                                         { 255, 200, 0 },
                                                                         { 80, 255, 80 },
                                                                         { 255, 80, 255 },
                                                                         { 255, 140, 0 },
                                                                         { 0, 255, 200 },
                                                                         { 160, 120, 255 } } };
  const auto dot = [&](const PointType & point, const std::array<unsigned char, 3> & colour, int size)
  {
    long column = 0;
    long row = 0;
    pixelOf(point, column, row);
    for (long r = row - size; r <= row + size; ++r)
    {
      for (long c = column - size; c <= column + size; ++c)
      {
        if (r >= 0 && c >= 0 && r < static_cast<long>(height) && c < static_cast<long>(width))
        {
          image->GetBufferPointer()[static_cast<std::size_t>(r) * width + static_cast<std::size_t>(c)].Set(
            colour[0], colour[1], colour[2]);
        }
      }
    }
  };
  if (reference != nullptr)
  {
    for (const auto & branch : reference->GetBranches())
    {
      for (const auto & point : branch.Points)
      {
        dot(point, { 255, 255, 255 }, 2);
      }
    }
  }
  for (const auto & branch : tree.GetBranches())
  {
    for (const auto & point : branch.Points)
    {
      dot(point, colours[static_cast<std::size_t>(branch.Id - 1) % colours.size()], 1);
    }
  }
  for (const auto & branch : tree.GetBranches())
  {
    dot(branch.Points.front(), { 255, 255, 255 }, 4);
  }
  auto writer = itk::ImageFileWriter<RGBImage>::New();
  writer->SetImageIO(itk::PNGImageIO::New());
  writer->SetInput(image);
  writer->SetFileName(path);
  writer->Update();
}
} // namespace vr::test
