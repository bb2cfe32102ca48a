// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkBilateralDepthRelaxFilter.h"

namespace itk
{
std::ostream &
operator<<(std::ostream & os, BilateralDepthRelaxSolver solver)
{
  return os << (solver == BilateralDepthRelaxSolver::Steady ? "Steady" : "Jacobi");
}

template class BilateralDepthRelaxFilter<Image<float, 2>>;
} // namespace itk
