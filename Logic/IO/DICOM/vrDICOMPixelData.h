// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// One file's pixels, read with GDCM, checked against the file's own attributes (the length of plain pixel data,
// compressed or plain as its transfer syntax says) and rescaled with its own slope and intercept, in double, into a
// float slice. Internal (namespace vr::detail): the DICOM reader process only, where GDCM may abort.
#ifndef vrDICOMPixelData_h
#define vrDICOMPixelData_h

#include "vrDICOMSeriesGroups.h"

#include <string>

namespace vr::detail
{
/** Reads the pixels of \a file, one of the set \a layout describes, as \a slope * stored + \a intercept.
 * \param slice receives Columns x Rows values, row by row (the file's order): room for them.
 * \return empty, or why the file cannot be read, naming it: it cannot be parsed; it has no Pixel Data; its pixel data
 * are plain where its transfer syntax says compressed (or the other way round), or hold another number of bytes than
 * Rows x Columns x Bits Allocated ask for; GDCM cannot decode them, or decodes another size or format than the
 * attributes say; a rescaled value is larger than 1e9 in size. */
std::string
ReadDICOMPixels(const std::string &      file,
                const DICOMImageLayout & layout,
                double                   slope,
                double                   intercept,
                float *                  slice);
} // namespace vr::detail

#endif
