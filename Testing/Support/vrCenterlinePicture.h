// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrCenterlinePicture_h
#define vrCenterlinePicture_h

#include "itkCenterlineTree.h"
#include "itkImage.h"

#include <string>

namespace vr::test
{
/** Writes a PNG for looking at an extraction: the segmentation's foreground projected along the LPS axis on which it
 * is thinnest (grey: how many voxels lie behind a pixel), with the centerline points drawn over it in one colour per
 * branch, a white square where a branch starts, and a \a reference tree, when given, as thicker white lines beneath.
 * Rows run along the axis of largest extent; 1600 rows. */
void
WriteCenterlinePicture(const itk::Image<unsigned char, 3> * segmentation,
                       const itk::CenterlineTree &          tree,
                       const std::string &                  path,
                       const itk::CenterlineTree *          reference = nullptr);
} // namespace vr::test

#endif
