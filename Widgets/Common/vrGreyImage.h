// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrGreyImage_h
#define vrGreyImage_h

#include "vrImageTypes.h"

#include <QImage>

namespace vr
{
/** The CPR image \a image through window and level as an 8-bit grey QImage, row 0 at the top (the logic's row 0):
 * display only, the values are the logic's. Each grey is vr::WindowLevelToByte's, as in a saved PNG.
 * \ingroup VesselReformation
 */
QImage
GreyImage(const DepthImageType * image, double window, double level);

/** Slice \a index (along the third axis) of \a stack through window and level, as GreyImage(). */
QImage
GreySlice(const VolumeImageType * stack, unsigned int index, double window, double level);
} // namespace vr

#endif
