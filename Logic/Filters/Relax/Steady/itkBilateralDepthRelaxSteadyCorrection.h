// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// One outer iteration's correction of the steady solver: preconditioned conjugate gradients on the lagged-weights
// operator or the energy's Hessian, and the line searches along a correction or a direction of negative curvature.
// Internal (namespace itk::detail), not installed; see itkBilateralDepthRelaxSteadySolver.h for the method.
#ifndef itkBilateralDepthRelaxSteadyCorrection_h
#define itkBilateralDepthRelaxSteadyCorrection_h

#include "itkBilateralDepthRelaxSteadyField.h"
#include "itkBilateralDepthRelaxSteadyMultigrid.h"

namespace itk::detail::BilateralDepthRelaxSteady
{
/** Corrections of a Field's depths, preconditioned by a Multigrid built from its lagged-weights operator. */
class Correction
{
public:
  /** Conjugate-gradient iterations per solve at most. */
  static constexpr unsigned int MaximumInnerIterations = 40;

  /** The longest step along a lagged-weights correction, in multiples of it. */
  static constexpr float MaximumStep = 64.0f;

  Correction(Field & field, Multigrid & multigrid, Bands & bands)
    : m_Field(field)
    , m_Multigrid(multigrid)
    , m_Bands(bands)
  {
  }

  /** Conjugate gradients on the finest level, preconditioned by V-cycles of the lagged-weights operator, until
   * max |r| / C falls below \a target: on the energy's Hessian when \a newton, else on the lagged-weights operator
   * (the field's Residual is the right-hand side, and is overwritten). Leaves the correction in the field's Delta.
   * Returns false when a Newton solve meets a direction of non-positive curvature (left in the field's Direction,
   * MetNegativeCurvature() true); the correction is then unusable. */
  bool
  Solve(double target, bool newton);

  /** The step along the direction of negative curvature the conjugate gradients met (copied into the correction),
   * in either sense, that lowers the energy most: first steps move a depth by at most J / 32, and each further one
   * doubles it, up to 2 J. Returns the energy change, times 2a (0 with a step of 0 when no step lowers it). */
  double
  SearchNegativeCurvature(float & step);

  /** The step along the lagged-weights correction, 1 or a power of two up to MaximumStep, that lowers the energy
   * most (the step 1 lowers it: each lagged-weights problem majorises the energy). Returns the energy change, times
   * 2a. */
  double
  SearchLaggedStep(float & step);

  /** Whether the last Solve met a direction of non-positive curvature. */
  bool
  MetNegativeCurvature() const
  {
    return m_NegativeCurvature;
  }
  /** V-cycles over all solves, and in the last one. */
  unsigned int
  GetCycles() const
  {
    return m_Cycles;
  }
  unsigned int
  GetLastCycles() const
  {
    return m_LastCycles;
  }

private:
  /** z = M^-1 r: one V-cycle on the finest level, whose right-hand side is r and whose correction is z; returns
   * r . z. */
  double
  Precondition()
  {
    ++m_Cycles;
    return m_Multigrid.CycleAndDot();
  }

  Field &      m_Field;
  Multigrid &  m_Multigrid;
  Bands &      m_Bands;
  unsigned int m_Cycles{ 0 };
  unsigned int m_LastCycles{ 0 };
  bool         m_NegativeCurvature{ false };
};
} // namespace itk::detail::BilateralDepthRelaxSteady

#endif
