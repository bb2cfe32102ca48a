// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCPROcclusionRule_h
#define itkCPROcclusionRule_h

#include <cmath>
#include <limits>

namespace itk::detail
{
// When one vessel hides another along a view ray (docs/design.md "Depth", Visibility mode), in one place for the
// depth filter's hidden labels and lengths and for the occlusion profile, so that both count the same thing.
//
// A stretch of centerline is hidden by a lumen in front of it when the stretch's own lumen lies wholly behind that
// one's: its front (depth - radius) is farther than the other's back (depth + radius), both taken at the closest
// points of their projected centerlines. Where two lumens overlap in depth along the ray (a branch leaving its parent,
// two vessels that touch) they are one lumen on screen and nothing is hidden. A vessel running obliquely in depth
// covers a pixel with the lumen of its own neighbouring stretch, whose closest point lies up to its radius (and the
// pixel) away in the image and so that distance times its depth slope nearer: its front is taken that much nearer
// still, so that a vessel never hides itself where it runs steeply (a loop seen end-on, the aortic arch from the
// side, still hides its far part). A stretch that runs along the view ray (no projected length) is the vessel seen
// end-on and is never hidden.

/** The depth tolerance of a segment whose depth changes by \a depthChange (mm) over \a projectedLength (mm in the
 * image plane): its depth slope times \a reach, the pixel size plus the segment's largest radius (mm); infinite for
 * a segment that points at the viewer. */
inline double
SelfOcclusionTolerance(double depthChange, double projectedLength, double reach)
{
  const double change = std::abs(depthChange);
  if (change == 0.0)
  {
    return 0.0;
  }
  if (!(projectedLength > 1e-9 * reach))
  {
    return std::numeric_limits<double>::infinity();
  }
  return change / projectedLength * reach;
}

/** True when a lumen whose front is \a front lies wholly behind one whose back is \a back (mm along v). */
inline bool
IsBehind(double front, double back)
{
  return front > back;
}
} // namespace itk::detail

#endif
