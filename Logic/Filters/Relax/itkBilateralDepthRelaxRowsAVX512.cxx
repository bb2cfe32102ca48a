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
namespace
{
void
Sweep(const RelaxGrid & grid,
      const float *     current,
      float *           next,
      std::size_t       rowBegin,
      std::size_t       rowEnd,
      RowScratch &      scratch)
{
  SweepRowsWith<VectorsOf<16>>(grid, current, next, rowBegin, rowEnd, scratch);
}

void
Start(const RelaxGrid & grid, const float * above, const float * row, std::size_t first, RowScratch & scratch)
{
  StartRowsWith<VectorsOf<16>>(grid, above, row, first, scratch);
}

void
Row(const RelaxGrid & grid, const float * row, const float * below, std::size_t y, float * out, RowScratch & scratch)
{
  RelaxOneRowWith<VectorsOf<16>>(grid, row, below, y, out, scratch);
}
} // namespace

const RowKernels KernelsAVX512{ Sweep, Start, Row };
} // namespace detail::BilateralDepthRelaxRows
} // namespace itk
