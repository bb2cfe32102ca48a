// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The row sweep for AVX2 with FMA (x86-64-v3): this file alone is compiled with -march=x86-64-v3, and runs only
// on processors whose CPUID says they support it.
#include "itkBilateralDepthRelaxRows.hxx"

#if !defined(__AVX2__) || !defined(__FMA__)
#error "itkBilateralDepthRelaxRowsAVX2.cxx must be compiled for x86-64-v3 (-march=x86-64-v3)"
#endif

namespace itk
{
namespace detail::BilateralDepthRelaxRows
{
void
SweepAVX2(const RelaxGrid & grid,
          const float *     current,
          float *           next,
          std::size_t       rowBegin,
          std::size_t       rowEnd,
          RowScratch &      scratch)
{
  SweepRowsWith<VectorsOf<8>>(grid, current, next, rowBegin, rowEnd, scratch);
}
} // namespace detail::BilateralDepthRelaxRows
} // namespace itk
