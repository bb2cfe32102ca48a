// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrImageIO_h
#define vrImageIO_h

#include "itkVector.h"
#include "vrImageTypes.h"

#include <string>

namespace vr
{
/** Writes a 2D output (NRRD or any ITK format by extension) atomically, with its metadata dictionary (the CPR
 * view, as CPR_* key/value pairs in NRRD). Throws vr::InputError naming the path. */
void
WriteImage2D(const DepthImageType * image, const std::string & path);
void
WriteImage2D(const MaskImageType * image, const std::string & path);
void
WriteImage2D(const LabelImageType * image, const std::string & path);
/** A 2D image of LPS points (a single-vessel CPR's pixel positions), as a 3-component vector image. */
void
WriteImage2D(const itk::Image<itk::Vector<float, 3>, 2> * image, const std::string & path);

/** Reads a 2D depth image (and its metadata) or a mask; throws vr::InputError naming the file. A 3D file with a
 * single slice counts as 2D. The mask may be stored with any scalar pixel type: non-zero pixels become 1 (fixed),
 * zero 0, a non-finite one is an error naming the pixel. */
DepthImageType::Pointer
ReadDepthImage(const std::string & path);
MaskImageType::Pointer
ReadMaskImage(const std::string & path);

/** Writes an 8-bit PNG of \a image through window/level: vr::WindowLevelToByte, as the views show it. */
void
WriteWindowedPNG(const DepthImageType * image, double window, double level, const std::string & path);
/** Writes an 8-bit grey image as a PNG, atomically, read back before it is published (a full disk leaves nothing).
 * Throws vr::InputError naming the path. */
void
WriteGreyPNG(const MaskImageType * image, const std::string & path);
// Grey = round(255 (v - level + window/2) / window) clamped to [0, 255]; NaN gives 0. Throws vr::InputError
// naming the window or level when window is not > 0 or either is not finite. Row 0 of the image is the PNG's top.

} // namespace vr

#endif
