// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrImageTypes_h
#define vrImageTypes_h

#include "itkImage.h"

#include <cstdint>

/** \file vrImageTypes.h
 * \brief The ITK image types the platform side passes between its layers.
 * \ingroup VesselReformation
 */
namespace vr
{
/** A CT volume, in LPS (origin, spacing and direction honoured), intensities as float (HU for CT). */
using VolumeImageType = itk::Image<float, 3>;
/** A 3D label map or vessel mask (0 = background), in LPS like the volumes: a segmentation's vessels. */
using LabelMapVolumeType = itk::Image<unsigned char, 3>;
/** A 2D image on a CPR view: depth (mm) or CPR intensity; the view travels in its metadata dictionary. */
using DepthImageType = itk::Image<float, 2>;
/** The fixed mask on a CPR view: 1 = fixed, 0 = free. */
using MaskImageType = itk::Image<unsigned char, 2>;
/** The owner labels on a CPR view: the id of the branch owning each pixel, 0 = none. */
using LabelImageType = itk::Image<uint32_t, 2>;
} // namespace vr

#endif
