// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkBilateralDepthRelaxSolver_h
#define itkBilateralDepthRelaxSolver_h

#include <ostream>

namespace itk
{
/** How BilateralDepthRelaxFilter relaxes the depth map (docs/design.md "Relaxation").
 * \ingroup VesselReformation */
enum class BilateralDepthRelaxSolver
{
  /** The paper's: N Jacobi passes of Eq. 1 with relaxation w. The result depends on N and on the pixel count. */
  Jacobi,
  /** The fixed point of Eq. 1 that the passes approach (BilateralDepthRelaxSteadySolver): independent of N, w and
   * the pixel count. */
  Steady
};

/** Prints "Jacobi" or "Steady". */
std::ostream &
operator<<(std::ostream & os, BilateralDepthRelaxSolver solver);
} // namespace itk

#endif
