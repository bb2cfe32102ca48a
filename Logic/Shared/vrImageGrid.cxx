// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrImageGrid.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace vr::detail
{
void
PhysicalBounds(const itk::ImageBase<3> * image, itk::Point<double, 3> & low, itk::Point<double, 3> & high)
{
  const auto region = image->GetLargestPossibleRegion();
  low.Fill(std::numeric_limits<double>::infinity());
  high.Fill(-std::numeric_limits<double>::infinity());
  for (unsigned int corner = 0; corner < 8; ++corner)
  {
    itk::Index<3> index;
    for (unsigned int axis = 0; axis < 3; ++axis)
    {
      index[axis] =
        region.GetIndex(axis) + ((corner >> axis) & 1 ? static_cast<itk::IndexValueType>(region.GetSize(axis)) - 1 : 0);
    }
    itk::Point<double, 3> point;
    image->TransformIndexToPhysicalPoint(index, point);
    for (unsigned int axis = 0; axis < 3; ++axis)
    {
      low[axis] = std::min(low[axis], point[axis]);
      high[axis] = std::max(high[axis], point[axis]);
    }
  }
}

bool
SameGrid(const itk::ImageBase<3> * a, const itk::ImageBase<3> * b)
{
  if (a->GetLargestPossibleRegion() != b->GetLargestPossibleRegion())
  {
    return false;
  }
  for (unsigned int i = 0; i < 3; ++i)
  {
    if (std::abs(a->GetSpacing()[i] - b->GetSpacing()[i]) > 1e-6 * a->GetSpacing()[i] ||
        std::abs(a->GetOrigin()[i] - b->GetOrigin()[i]) > 1e-3)
    {
      return false;
    }
    for (unsigned int j = 0; j < 3; ++j)
    {
      if (std::abs(a->GetDirection()(i, j) - b->GetDirection()(i, j)) > 1e-6)
      {
        return false;
      }
    }
  }
  return true;
}

std::string
DescribeGrid(const itk::ImageBase<3> * image)
{
  std::ostringstream    text;
  const auto            size = image->GetLargestPossibleRegion().GetSize();
  const auto            spacing = image->GetSpacing();
  itk::Point<double, 3> low;
  itk::Point<double, 3> high;
  PhysicalBounds(image, low, high);
  text << size[0] << " x " << size[1] << " x " << size[2] << " voxels of " << spacing[0] << " x " << spacing[1] << " x "
       << spacing[2] << " mm spanning LPS " << low << " to " << high;
  return text.str();
}
} // namespace vr::detail
