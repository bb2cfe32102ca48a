// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The geometry attributes of a DICOM series' files, checked before the volume is handed over. ITK takes the volume's
// origin, direction and pixel spacing from the series' first file and its slice spacing from the positions, and GDCM
// parses a decimal string leniently ("-1.6.445" reads as -1.6): one corrupt file could displace the whole volume
// without a word, and the error a user then met ("the centerlines lie outside the volume") named no file. Internal
// (namespace vr::detail): used by the DICOM reader process (vrReadDICOMSeriesMain.cxx).
#ifndef vrDICOMSliceGeometry_h
#define vrDICOMSliceGeometry_h

#include <optional>
#include <string>
#include <vector>

namespace vr::detail
{
/** One file of a series, in the series' order, with its attributes as the text the file holds (none where absent). */
struct DICOMSliceAttributes
{
  std::string                File;
  std::optional<std::string> Position;     ///< Image Position (Patient) (0020,0032): 3 decimal strings
  std::optional<std::string> Orientation;  ///< Image Orientation (Patient) (0020,0037): 6
  std::optional<std::string> PixelSpacing; ///< Pixel Spacing (0028,0030): 2
};

/** The values of a multi-valued Decimal String (DICOM PS3.5, VR DS): exactly \a count values separated by
 * backslashes, each an optional sign, digits with at most one decimal point and an optional exponent, padded by
 * spaces; finite. None when \a text is not that. */
std::optional<std::vector<double>>
ParseDecimalStrings(const std::string & text, std::size_t count);

/** Empty when each of these attributes \a slice has is its count of decimal strings; else what is wrong, naming the
 * file. The reader process checks each file alone before GDCM sorts the folder: GDCM orders a series by position,
 * and where a position does not read it falls back to instance numbers with a comparison that can crash its sort. */
std::string
CheckDICOMSliceAttributes(const DICOMSliceAttributes & slice);

/** Empty when the series' geometry is sound; else what is wrong, naming the file at fault:
 * - every attribute one file has, every file has (ITK takes the origin and directions from the first file alone),
 *   each as exactly its count of decimal strings;
 * - every file's orientation and pixel spacing equal the series' (the median of the files', value by value) within
 *   1e-4 (orientation) and 1e-4 relative (spacing);
 * - with four files or more, no file lies off the series' line of slices: a file both of whose steps to its
 *   neighbours (its one step, at an end) differ from the series' step (the median of the steps, coordinate by
 *   coordinate) by more than a quarter of that step and 0.01 mm. A missing slice leaves a double step between two
 *   files that each keep one regular step, and passes. */
std::string
CheckDICOMSliceGeometry(const std::vector<DICOMSliceAttributes> & slices);
} // namespace vr::detail

#endif
