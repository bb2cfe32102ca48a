// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The steady solver's row kernels for AVX2 with FMA (x86-64-v3): this unit is compiled with -march=x86-64-v3 and
// used only on processors whose CPUID says they run it.
#include "itkBilateralDepthRelaxSteadyRows.hxx"

#if !defined(__AVX2__) || !defined(__FMA__)
#error "itkBilateralDepthRelaxSteadyRowsAVX2.cxx must be compiled for x86-64-v3 (-march=x86-64-v3)"
#endif

namespace itk::detail::BilateralDepthRelaxSteady
{
const RowKernels RowKernelsAVX2 = AllRowKernels();
} // namespace itk::detail::BilateralDepthRelaxSteady
