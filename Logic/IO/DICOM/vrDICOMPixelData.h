// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// One file's pixels, read with GDCM, checked against the file's own attributes (the length of plain pixel data,
// compressed or plain as its transfer syntax says) and its rescaled values checked; into a slice of the stored values
// as GDCM decodes them, or rescaled with the file's own slope and intercept, in double, into a float slice. Internal
// (namespace vr::detail): the DICOM reader process only, where GDCM may abort.
#ifndef vrDICOMPixelData_h
#define vrDICOMPixelData_h

#include "vrDICOMSeriesGroups.h"

#include "itkCommonEnums.h"

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

/** As above, into a slice of \a pixelType: FLOAT for the rescaled values, else the stored values as they are (the
 * rescaled ones checked as above), which needs GDCM to decode the file's pixels as \a pixelType.
 * \param decoded receives the type GDCM decodes the pixels as (UCHAR, CHAR, USHORT, SHORT, UINT or INT) once they
 * are decoded; where it is not \a pixelType and that is not FLOAT, nothing is written to \a slice and the return is
 * empty: the caller reads the series another way. */
std::string
ReadDICOMPixels(const std::string &      file,
                const DICOMImageLayout & layout,
                double                   slope,
                double                   intercept,
                itk::IOComponentEnum     pixelType,
                void *                   slice,
                itk::IOComponentEnum &   decoded);

/** The type GDCM decodes the pixels of files of \a layout as, by Bits Allocated and Pixel Representation (UCHAR,
 * CHAR, USHORT, SHORT, UINT or INT; UNKNOWNCOMPONENTTYPE for another size). */
itk::IOComponentEnum
DICOMStoredPixelType(const DICOMImageLayout & layout);
} // namespace vr::detail

#endif
