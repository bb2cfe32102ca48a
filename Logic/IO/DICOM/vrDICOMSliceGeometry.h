// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Where the slices of a DICOM series lie, from their Image Position (Patient) and Image Orientation (Patient) alone
// (never from Slice Thickness, which says how thick a slice was reconstructed, not where it is), and how the volume's
// regular grid of slices is filled from the files: each grid slice one file, or, across a gap of whole slices, two
// files interpolated. The rules and their tolerances: docs/dicom-series.md "Geometry from positions". Internal
// (namespace vr::detail), used by the DICOM reader process (vrReadDICOMSeriesMain.cxx); no GDCM, no ITK.
#ifndef vrDICOMSliceGeometry_h
#define vrDICOMSliceGeometry_h

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace vr::detail
{
/** The values of a multi-valued Decimal String (DICOM PS3.5, VR DS): exactly \a count values separated by
 * backslashes, each an optional sign, digits with at most one decimal point and an optional exponent, padded by
 * spaces; finite. None when \a text is not that. */
std::optional<std::vector<double>>
ParseDecimalStrings(const std::string & text, std::size_t count);

/** A file of a series and its Image Position (Patient), LPS mm. */
struct DICOMSlicePosition
{
  std::string           File;
  std::array<double, 3> Position{};
};

/** The volume's slices as the files give them: a regular grid along the slice normal. */
struct DICOMSliceGrid
{
  /** The first grid slice's first pixel, LPS mm. */
  std::array<double, 3> Origin{};
  /** The slice normal, row direction × column direction (unit length): the volume's third axis. */
  std::array<double, 3> Normal{};
  /** The distance between grid slices along the normal, mm, measured from the positions. */
  double SliceSpacing{ 0.0 };
  /** One grid slice: the file at index First of the input (Weight 0), or (1 - Weight) First + Weight Second for a
   * slice missing from the series, interpolated linearly between the files on either side of it. */
  struct Slice
  {
    std::size_t First{ 0 };
    std::size_t Second{ 0 };
    double      Weight{ 0.0 };
  };
  std::vector<Slice> Slices;
  /** The input indices left out as duplicates of another file (same position, same pixels). */
  std::vector<std::size_t> Duplicates;
  /** What the user must be told: a gap interpolated (the two files around it and the positions made up), a
   * duplicate left out. Each one line. */
  std::vector<std::string> Warnings;
};

/** Plans the grid of a series whose files all have the orientation \a orientation (the six direction cosines,
 * checked unit and orthogonal before) and pixels of at least \a smallestPixelSpacing mm.
 * \param files the files, in the order the caller numbers them (their names' order).
 * \param samePixels whether two files (input indices) hold the same pixels after rescaling: asked only for files at
 *        the same position.
 * \param gantryTilt the series' Gantry/Detector Tilt (0018,1120) as written, for the message, if any.
 * \param grid receives the plan.
 * \return empty when the series can be read; else why not, naming the file or files at fault:
 * - two files at one position (within 0.01 mm along the normal) with different pixels;
 * - a file whose position lies off the series' line of slices (in the slice plane, more than 0.01 mm or 5 % of the
 *   smallest pixel spacing from the series' median), or a series whose positions step aside steadily (a gantry tilt:
 *   the angle is given; reading it onto a grid at right angles to its slices would shear the anatomy);
 * - a step between neighbours that is no whole number of the series' slice spacing, or a file farther from its grid
 *   position along the normal than 0.01 mm or 5 % of the slice spacing.
 * A step of n whole slice spacings (n >= 2) is a gap of n - 1 slices: read, interpolated, with a warning. */
std::string
PlanDICOMSliceGrid(const std::vector<DICOMSlicePosition> &               files,
                   const std::array<double, 6> &                         orientation,
                   double                                                smallestPixelSpacing,
                   const std::function<bool(std::size_t, std::size_t)> & samePixels,
                   const std::optional<std::string> &                    gantryTilt,
                   DICOMSliceGrid &                                      grid);
} // namespace vr::detail

#endif
