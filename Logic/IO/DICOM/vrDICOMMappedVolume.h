// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrDICOMMappedVolume_h
#define vrDICOMMappedVolume_h

#include "vrStoredVolume.h"

#include <string>

/** The caller's side of the DICOM reader process's hand-over (vrDICOMVolumeHandOver.h). Internal (namespace
 * vr::detail): the IO library's DICOM series reader only. */
namespace vr::detail
{
/** The volume the reader process left in the file \a descriptor (the caller's memfd, the child ended with exit
 * status 0): its header and its size checked against each other, then the file mapped and the mapping made the
 * image's buffer, without a copy. The image's pixel container owns the mapping: it is unmapped when the last
 * reference to the buffer goes (the image, a volume node's array reading it). The descriptor may be closed after.
 *
 * The voxels are in the series' stored type (8- or 16-bit integers, Rescale the files' one slope and intercept) or in
 * float with the identity rescale (docs/dicom-series.md "Values").
 * Throws vr::InputError "<where>: the DICOM reader process handed over ..." naming what is wrong: a file cut short
 * (its bytes and the volume's), a header the child did not finish, a header that contradicts itself. */
StoredVolume
ReceiveDICOMVolume(int descriptor, const std::string & where);
} // namespace vr::detail

#endif
