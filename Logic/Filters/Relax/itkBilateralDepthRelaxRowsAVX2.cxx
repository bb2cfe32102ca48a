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
  SweepRowsWith<VectorsOf<8>>(grid, current, next, rowBegin, rowEnd, scratch);
}

void
Start(const RelaxGrid & grid, const float * above, const float * row, std::size_t first, RowScratch & scratch)
{
  StartRowsWith<VectorsOf<8>>(grid, above, row, first, scratch);
}

void
Row(const RelaxGrid & grid, const float * row, const float * below, std::size_t y, float * out, RowScratch & scratch)
{
  RelaxOneRowWith<VectorsOf<8>>(grid, row, below, y, out, scratch);
}
} // namespace

const RowKernels KernelsAVX2{ Sweep, Start, Row };
} // namespace detail::BilateralDepthRelaxRows
} // namespace itk
