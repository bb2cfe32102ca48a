// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrTestNifti_h
#define vrTestNifti_h

#include "itkSize.h"

#include <vector>

namespace vr::test
{
/** The 352 bytes of a NIfTI-1 single-file header (.nii) written field by field from NIfTI-1's layout (nifti1.h), in
 * either byte order, for voxels of \a datatype (NIFTI_TYPE_*) and \a bitpix following it at byte 352: dimensions
 * \a size, spacing in mm, scl_slope and scl_inter, a qform (code 1) with an offset of (-10, 20, 30) mm. Written by
 * hand so that the tests control what ITK's writer would not (big-endian files, scl fields). */
std::vector<unsigned char>
Nifti1Header(const itk::Size<3> & size,
             short                datatype,
             short                bitpix,
             const double         spacing[3],
             float                slope,
             float                intercept,
             bool                 bigEndian);
} // namespace vr::test

#endif
