// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The row sweep for whatever the build's compiler flags target: baseline x86-64 (SSE2, 4 lanes) by default, or
// as wide as e.g. -march=native allows when runtime dispatch is off.
#include "itkBilateralDepthRelaxRows.hxx"

namespace itk
{
namespace detail::BilateralDepthRelaxRows
{
namespace
{
#if defined(__AVX512F__)
using BaselineVectors = VectorsOf<16>;
#elif defined(__AVX2__)
using BaselineVectors = VectorsOf<8>;
#else
using BaselineVectors = VectorsOf<4>;
#endif
} // namespace

#if defined(__AVX512F__)
const char * const BaselineInstructionSet = "AVX-512 (compiler flags)";
#elif defined(__AVX2__)
const char * const BaselineInstructionSet = "AVX2 (compiler flags)";
#elif defined(__x86_64__)
const char * const BaselineInstructionSet = "x86-64";
#else
const char * const BaselineInstructionSet = "128-bit vectors";
#endif

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
  SweepRowsWith<BaselineVectors>(grid, current, next, rowBegin, rowEnd, scratch);
}

void
Start(const RelaxGrid & grid, const float * above, const float * row, std::size_t first, RowScratch & scratch)
{
  StartRowsWith<BaselineVectors>(grid, above, row, first, scratch);
}

void
Row(const RelaxGrid & grid, const float * row, const float * below, std::size_t y, float * out, RowScratch & scratch)
{
  RelaxOneRowWith<BaselineVectors>(grid, row, below, y, out, scratch);
}
} // namespace

const RowKernels KernelsBaseline{ Sweep, Start, Row };
} // namespace detail::BilateralDepthRelaxRows
} // namespace itk
