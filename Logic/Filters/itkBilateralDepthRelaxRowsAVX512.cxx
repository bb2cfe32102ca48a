// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The row sweep for AVX-512 (x86-64-v4): this file alone is compiled with -march=x86-64-v4, and runs only on
// processors whose CPUID says they support it.
#include "itkBilateralDepthRelaxRows.hxx"

#if !defined(__AVX512F__)
#error "itkBilateralDepthRelaxRowsAVX512.cxx must be compiled for x86-64-v4 (-march=x86-64-v4)"
#endif

namespace itk
{
namespace detail::BilateralDepthRelaxRows
{
void
SweepAVX512(const RelaxGrid & grid,
            const float *     current,
            float *           next,
            std::size_t       rowBegin,
            std::size_t       rowEnd,
            RowScratch &      scratch)
{
  SweepRowsWith<VectorsOf<16>>(grid, current, next, rowBegin, rowEnd, scratch);
}
} // namespace detail::BilateralDepthRelaxRows
} // namespace itk
