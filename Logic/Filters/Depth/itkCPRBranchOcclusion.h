// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCPRBranchOcclusion_h
#define itkCPRBranchOcclusion_h

#include <vector>

namespace itk
{
/** A stretch of a branch's centerline, from polyline parameter First to Last: parameter p lies on the segment from
 * point floor(p) to the next, at fraction p - floor(p) of it (0 is the first point, n - 1 the last).
 * \ingroup VesselReformation
 */
struct CPRCenterlineStretch
{
  double First{ 0.0 };
  double Last{ 0.0 };
};

/** \class CPRBranchOcclusion
 * \brief How much of one branch's centerline a view hides behind other lumens (docs/design.md "Depth", Visibility
 * mode): its length and the hidden part of it, in mm along the vessel (3D arc length), counted over the part that
 * projects into the image.
 * \ingroup VesselReformation
 */
struct CPRBranchOcclusion
{
  /** The branch's id in the centerline tree. */
  int BranchId{ 0 };
  /** The centerline's length, mm (the whole branch). */
  double Length{ 0.0 };
  /** The part of it that lies behind another lumen in this view, mm. */
  double HiddenLength{ 0.0 };
  /** Where: the hidden stretches in order along the branch (what a viewer draws dashed). */
  std::vector<CPRCenterlineStretch> HiddenStretches;
};
} // namespace itk

#endif
