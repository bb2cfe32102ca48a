// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrPixelReadout_h
#define vrPixelReadout_h

#include "vrReformationController.h"

#include <QString>

#include <array>

namespace vr
{
/** What the CPR view reads out at one pixel, every value taken from the logic's output nodes.
 * \ingroup VesselReformation
 */
struct PixelReadout
{
  /** False outside the image (the other fields are then meaningless). */
  bool Inside{ false };
  /** True when the pixel belongs to the unfiltered image (left half of the split, left of side by side). */
  bool Unfiltered{ false };
  /** Column i and row j (row 0 at the top). */
  int Column{ 0 };
  int Row{ 0 };
  /** The sampled point X = B(i, j) + d v in RAS mm: the output node's IJK->RAS matrix at (i, j, d), its third axis
   * being 1 mm along v. */
  std::array<double, 3> RAS{ { 0.0, 0.0, 0.0 } };
  /** The CPR intensity there, and its unit ("HU" for CT, empty for data without one; ReformationInputs). */
  double      Intensity{ 0.0 };
  std::string IntensityUnit;
  /** The depth d along the view direction, mm (relaxed for the filtered image, unfiltered otherwise). */
  double Depth{ 0.0 };
  /** The owner label (branch id, 0 = none) and its name. */
  int         Branch{ 0 };
  std::string BranchName;
  /** Visibility mode: the branch whose lumen lies behind the visible one here (0 = none), and its name. */
  int         HiddenBranch{ 0 };
  std::string HiddenBranchName;

  /** \return one line for the status bar: "(i, j)  RAS (x, y, z) mm  v HU  depth d mm  branch" ("value v" for
   * intensities without a unit), and where a vessel lies hidden behind it, "branch, in front of hidden branch". */
  QString
  ToText() const;
};

/** Reads the outputs of \a result at pixel (\a column, \a row).
 * \param result a displayed result.
 * \param unfiltered read the unfiltered CPR and depth instead of the relaxed ones.
 * \return the readout; Inside is false outside the image. */
PixelReadout
ReadPixel(const ReformationResult & result, bool unfiltered, int column, int row);
} // namespace vr

#endif
