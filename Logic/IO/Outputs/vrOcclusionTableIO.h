// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrOcclusionTableIO_h
#define vrOcclusionTableIO_h

#include "itkCPRBranchOcclusion.h"
#include "itkCPROcclusionProfile.h"

#include <string>
#include <vector>

namespace vr
{
/** One branch's part of a view's hidden lengths (CPRDepthImageFilter's Visibility mode), with its name.
 * \ingroup VesselReformation
 */
struct BranchOcclusionRow
{
  int         BranchId{ 0 };
  std::string Name;
  /** Centerline length and its hidden part in this view, mm. */
  double Length{ 0.0 };
  double HiddenLength{ 0.0 };
  /** Where along the branch's polyline (what the viewer draws dashed); not written to the table. */
  std::vector<itk::CPRCenterlineStretch> HiddenStretches;
};

/** The hidden-length table's columns, in order: branch id (0 for the whole tree's row), name, length, hidden length,
 * hidden percentage of the branch, and the view's angle. */
constexpr const char * HiddenLengthColumns[] = { "branch_id",        "name",           "length_mm",
                                                 "hidden_length_mm", "hidden_percent", "angle_degrees" };

/** Writes \a rows as CSV (HiddenLengthColumns), one row per branch and a last one for the whole tree ("whole tree",
 * id 0), with \a angle (degrees) on every row. Names are quoted as CSV quotes them. Atomic (vr::AtomicOutput). Throws
 * vr::InputError naming \a path when it cannot be written. */
void
WriteHiddenLengthTable(const std::vector<BranchOcclusionRow> & rows, double angle, const std::string & path);

/** Writes \a profile as CSV: angle_degrees,hidden_length_mm,hidden_percent, one row per degree. Atomic. Throws
 * vr::InputError naming \a path when it cannot be written or the profile is empty. */
void
WriteOcclusionProfileTable(const itk::CPROcclusionProfile & profile, const std::string & path);
} // namespace vr

#endif
