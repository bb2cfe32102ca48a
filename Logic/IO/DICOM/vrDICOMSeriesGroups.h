// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The image files of a DICOM folder sorted into sets that can each be one volume, the set a caller chose, and the
// checks that every file of that set agrees with the others (docs/dicom-series.md "One series" and "Every file
// agrees"). Internal (namespace vr::detail), used by the DICOM reader process; no GDCM, no ITK.
#ifndef vrDICOMSeriesGroups_h
#define vrDICOMSeriesGroups_h

#include "vrDICOMFileAttributes.h"
#include "vrDICOMSeriesChoice.h"

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace vr::detail
{
/** Files that can be one volume: one Series Instance UID, and within it one size (Rows, Columns), one pixel format
 * (Samples per Pixel, Photometric Interpretation, Bits Allocated, Bits Stored, High Bit, Pixel Representation, the
 * transfer syntax's family), one orientation (within 1e-4) and one Frame of Reference UID. */
struct DICOMImageSet
{
  /** Indices into the folder's files, in their names' order. */
  std::vector<std::size_t> Files;
  /** How it differs from the largest set of its Series Instance UID ("Rows 256, not 512"); empty for that one. */
  std::string Difference;
};

/** Sorts \a files into sets, ordered by Series Number (as a number; none last), Series Instance UID, then size
 * (largest first). */
std::vector<DICOMImageSet>
GroupDICOMImages(const std::vector<DICOMFileAttributes> & files);

/** \return each set as the reader lists it (vr::DICOMSeriesSummary), numbered from 1. */
std::vector<DICOMSeriesSummary>
SummarizeDICOMImageSets(const std::vector<DICOMFileAttributes> & files, const std::vector<DICOMImageSet> & sets);

/** Finds the set \a choice names: its number in the list (from 1) or its Series Instance UID.
 * \return empty and \a chosen set, or why none is chosen. */
std::string
ChooseDICOMImageSet(const std::vector<DICOMFileAttributes> & files,
                    const std::vector<DICOMImageSet> &       sets,
                    const std::string &                      choice,
                    std::size_t &                            chosen);

/** What the chosen set's files agree on, and each file's position and rescale, as numbers. */
struct DICOMImageLayout
{
  unsigned int Rows{ 0 };
  unsigned int Columns{ 0 };
  unsigned int BitsAllocated{ 0 };
  unsigned int BitsStored{ 0 };
  unsigned int PixelRepresentation{ 0 };
  std::string  TransferSyntaxFamily;
  /** Image Orientation (Patient): the row direction, then the column direction. */
  std::array<double, 6> Orientation{};
  /** Pixel Spacing as DICOM orders it: between rows (along the column direction), then between columns. */
  std::array<double, 2> PixelSpacing{};
  /** Where the pixel spacing came from when the files have no Pixel Spacing: Imager Pixel Spacing (radiographs) or
   * Nominal Scanned Pixel Spacing (secondary captures), as GDCM and ITK take it; empty otherwise. */
  std::string PixelSpacingSource;
  /** Per file of the set, in its order: Image Position (Patient), Rescale Slope and Rescale Intercept. */
  std::vector<std::array<double, 3>> Positions;
  std::vector<double>                Slopes;
  std::vector<double>                Intercepts;
};

/** Checks that the files of \a set can be read as one volume and fills \a layout:
 * - the pixel format is one the reader decodes: one sample (MONOCHROME1 or 2), 8, 16 or 32 bits allocated, High Bit
 *   one below Bits Stored, one frame a file, a transfer syntax GDCM decodes;
 * - Image Position (Patient), Image Orientation (Patient) and Pixel Spacing in every file (where no file has Pixel
 *   Spacing: Imager Pixel Spacing, else Nominal Scanned Pixel Spacing), each its count of decimal strings; the
 *   orientation two orthogonal unit vectors (within 1e-4); every file's pixel spacing the series' (the median, within
 *   1e-4 relative);
 * - each file's Rescale Slope and Intercept finite, the slope not 0, and no stored value rescaled beyond 1e9 in size.
 * \return empty, or why not, naming the file and the attribute (with its value and the series' where they differ). */
std::string
CheckDICOMImageSet(const std::vector<DICOMFileAttributes> & files,
                   const DICOMImageSet &                    set,
                   DICOMImageLayout &                       layout);
} // namespace vr::detail

#endif
