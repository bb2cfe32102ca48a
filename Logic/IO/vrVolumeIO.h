// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrVolumeIO_h
#define vrVolumeIO_h

#include "vrImageTypes.h"

#include <string>

namespace vr
{
/** Reads a scalar volume (LPS, origin/spacing/direction kept) as float: NRRD, NIfTI, MetaImage, or a DICOM
 * series when \a path is a folder (the series with the most files). Throws vr::InputError naming the file and
 * what is wrong (missing, unreadable header, not 3D, not scalar, empty folder). */
VolumeImageType::Pointer
ReadVolume(const std::string & path);

/** Writes a volume atomically, format from the extension. */
void
WriteVolume(const VolumeImageType * volume, const std::string & path);
} // namespace vr

#endif
