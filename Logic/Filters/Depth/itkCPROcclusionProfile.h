// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCPROcclusionProfile_h
#define itkCPROcclusionProfile_h

#include "itkCPRViewGeometry.h"
#include "itkCenterlineTree.h"
#include "itkMultiThreaderBase.h"

#include <vector>

namespace itk
{
/** \class CPROcclusionProfile
 * \brief How much of a centerline tree each view about one up axis hides behind other lumens: the hidden centerline
 * length at every angle 0, 1, ..., 179 degrees (docs/design.md "Depth", Visibility mode).
 * \ingroup VesselReformation
 */
struct CPROcclusionProfile
{
  /** The number of angles, one per degree from 0. */
  static constexpr unsigned int NumberOfAngles = 180;

  /** Hidden centerline length in mm (3D arc length) at angle 0, 1, ... degrees; empty before a computation. */
  std::vector<double> HiddenLength;
  /** The whole tree's centerline length, mm. */
  double TreeLength{ 0.0 };

  /** \return HiddenLength[angle] / TreeLength (0 for an empty tree). */
  double
  HiddenFraction(unsigned int angle) const;
  /** \return the angle in degrees with the least hidden length; of equal ones, the nearest to 0. */
  unsigned int
  LeastOccludedAngle() const;
  /** \return the angle in degrees with the most hidden length; of equal ones, the nearest to 0. */
  unsigned int
  MostOccludedAngle() const;
};

/** Computes the occlusion profile of \a tree for views about \a view's up axis, through its centre, at its pixel
 * spacing (its angle and size do not matter). A stretch of centerline is hidden when its lumen lies wholly behind
 * another's along the view ray (the rule of CPRDepthImageFilter's Visibility mode and its hidden lengths); lumens are
 * the centerlines' radii, at least half a pixel (what a centerline drawn in pixels covers; a branch without radii has
 * only that). Exact per pair of segments that can overlap: on each segment, the parameter intervals inside another
 * segment's footprint and behind its lumen are solved in closed form (lines and circles), and their union measured;
 * no image is drawn, so 180 angles cost about as much as a few depth maps. Angles run in parallel on \a threader (a
 * new one when null). Throws when the tree is invalid. */
CPROcclusionProfile
ComputeCPROcclusionProfile(const CenterlineTree &  tree,
                           const CPRViewGeometry & view,
                           MultiThreaderBase *     threader = nullptr);
} // namespace itk

#endif
