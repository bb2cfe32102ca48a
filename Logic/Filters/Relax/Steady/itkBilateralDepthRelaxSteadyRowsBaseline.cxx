// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The steady solver's row kernels for baseline x86-64, or for what the compiler flags target in a build without
// runtime dispatch.
#include "itkBilateralDepthRelaxSteadyRows.hxx"

namespace itk::detail::BilateralDepthRelaxSteady
{
const RowKernels RowKernelsBaseline = AllRowKernels();
} // namespace itk::detail::BilateralDepthRelaxSteady
