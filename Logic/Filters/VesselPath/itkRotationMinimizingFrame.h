// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkRotationMinimizingFrame_h
#define itkRotationMinimizingFrame_h

#include "itkCPRViewGeometry.h"
#include "itkVesselPath.h"
#include "itkVesselPathSection.h"

namespace itk
{

/** \class RotationMinimizingFrame
 * \brief The sections of a vessel path every step mm with a rotation-minimising frame (docs/vessel-path.md "Frame").
 *
 * The frame is carried along the path by double reflection (Wang, Juettler, Zheng, Liu, "Computation of rotation
 * minimizing frames", ACM TOG 27(1), 2008): it turns with the tangent and never about it, so it does not spin at an
 * inflection as a Frenet frame does. Its first Lateral is chosen so that the straightened CPR at roll 0 looks the
 * way the tree view looks at the path's start: Lateral is the view's screen-right u made normal to the tangent, and
 * Up = Tangent x Lateral then points towards the viewer (anterior for the default view). Where the tangent lies
 * within about 10 degrees of u (cosine above NearlyParallelCosine), Up is taken from the direction towards the viewer
 * (-v) instead and Lateral = Up x Tangent. The roll angle (degrees, right-hand rule about the tangent) then turns
 * Lateral towards Up: Lateral' = cos(roll) Lateral + sin(roll) Up.
 *
 * Sections lie at arc lengths 0, step, 2 step, ... (VesselPath::SampleArcLengths).
 * \ingroup VesselReformation
 */
class RotationMinimizingFrame
{
public:
  using PointType = VesselPathSection::PointType;
  using VectorType = VesselPathSection::VectorType;

  /** Above this |u . tangent| the first Lateral comes from the view direction instead of u. */
  static constexpr double NearlyParallelCosine = 0.985;

  /** The sections of \a path every \a step mm, the frame's start chosen from \a view, turned by \a rollInDegrees.
   * Throws naming the step, the roll or the path's length when the step is not finite and > 0, the roll is not
   * finite, or the path is shorter than one step. */
  static VesselPathSectionList
  Compute(const VesselPath & path, double step, const CPRViewGeometry & view, double rollInDegrees = 0.0);

  /** The first Lateral for a unit \a tangent in \a view (the class comment's rule). */
  static VectorType
  InitialLateral(const VectorType & tangent, const CPRViewGeometry & view);

  /** Turns every section's Lateral and Up about its tangent by \a rollInDegrees. */
  static void
  Roll(VesselPathSectionList & sections, double rollInDegrees);

  /** The curvature vector dTangent/ds (1/mm) at each section, by central differences of the sections' tangents
   * (one-sided at the ends); its norm is 1 / the radius of curvature. */
  static std::vector<VectorType>
  CurvatureVectors(const VesselPathSectionList & sections);
};

} // namespace itk

#endif
