// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkVesselPathSection_h
#define itkVesselPathSection_h

#include "itkPoint.h"
#include "itkVector.h"

#include <limits>
#include <vector>

namespace itk
{

/** \class VesselPathSection
 * \brief One cross-section of a vessel path (docs/vessel-path.md): where it lies along the path and the frame of
 * its plane, in LPS millimetres.
 *
 * (Lateral, Up, Tangent) is a right-handed orthonormal frame: Lateral x Up = Tangent. Lateral is the straightened
 * CPR's horizontal axis at the section (after the roll), Up the cross-section image's second axis; both lie in the
 * plane perpendicular to the path. The frame comes from a rotation-minimising frame along the path, never a
 * Frenet frame, so it does not spin at inflections.
 * \ingroup VesselReformation
 */
struct VesselPathSection
{
  using PointType = Point<double, 3>;
  using VectorType = Vector<double, 3>;

  /** Distance along the path from its start, mm. */
  double ArcLength{ 0.0 };
  /** The centerline point, LPS mm. */
  PointType Center;
  /** Unit tangent, towards increasing arc length. */
  VectorType Tangent;
  /** Unit vector across the vessel: the straightened CPR's x axis and the cross-section's u axis. */
  VectorType Lateral;
  /** Unit vector Tangent x Lateral: the cross-section's v axis. */
  VectorType Up;
  /** The centerline's lumen radius here (mm, interpolated along the path); NaN where the centerlines carry none. */
  double Radius{ std::numeric_limits<double>::quiet_NaN() };
  /** The id of the tree branch this point lies on. */
  int BranchId{ 0 };
};

using VesselPathSectionList = std::vector<VesselPathSection>;

} // namespace itk

#endif
