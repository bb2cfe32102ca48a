// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The steady solver's row kernels for AVX-512 (x86-64-v4): this unit is compiled with -march=x86-64-v4 and used
// only on processors whose CPUID says they run it.
#include "itkBilateralDepthRelaxSteadyRows.hxx"

#if !defined(__AVX512F__) || !defined(__AVX512BW__)
#error "itkBilateralDepthRelaxSteadyRowsAVX512.cxx must be compiled for x86-64-v4 (-march=x86-64-v4)"
#endif

namespace itk::detail::BilateralDepthRelaxSteady
{
const RowKernels RowKernelsAVX512 = AllRowKernels();
} // namespace itk::detail::BilateralDepthRelaxSteady
