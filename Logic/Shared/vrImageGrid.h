// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrImageGrid_h
#define vrImageGrid_h

#include "itkImageBase.h"

#include <string>

/** Comparing and describing the voxel grids of 3D images (a segmentation against a volume, masks against each other).
 */
namespace vr::detail
{
/** The LPS bounding box of an image's voxel centres. */
void
PhysicalBounds(const itk::ImageBase<3> * image, itk::Point<double, 3> & low, itk::Point<double, 3> & high);

/** Whether two images share a grid: size, spacing, origin and direction (to round-off). */
bool
SameGrid(const itk::ImageBase<3> * a, const itk::ImageBase<3> * b);

/** Size, spacing and LPS extent of an image's grid, for messages. */
std::string
DescribeGrid(const itk::ImageBase<3> * image);
} // namespace vr::detail

#endif
