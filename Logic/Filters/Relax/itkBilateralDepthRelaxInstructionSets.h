// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Which instruction set the relax kernels run: the Jacobi row sweep (itkBilateralDepthRelaxRows.hxx) and the steady
// solver's row kernels (itkBilateralDepthRelaxSteadyRows.hxx) are each compiled once per instruction set, one
// translation unit each with its own -march, and both choose among them by this one CPUID check (CMake option
// VR_RELAX_RUNTIME_DISPATCH, on by default on x86-64 with GCC or Clang). Without it, the baseline units alone are
// built, as wide as the compiler flags allow (e.g. -march=native). Internal (namespace itk::detail), not installed.
#ifndef itkBilateralDepthRelaxInstructionSets_h
#define itkBilateralDepthRelaxInstructionSets_h

#include <vector>

namespace itk::detail
{
/** The instruction sets a relax kernel is compiled for. */
enum class InstructionSet
{
  AVX512,  ///< x86-64-v4
  AVX2,    ///< x86-64-v3: AVX2 with FMA
  Baseline ///< the compiler flags' target: x86-64 (SSE2) by default
};

/** The instruction sets this build holds kernels for and this processor runs, widest first: Baseline always. */
const std::vector<InstructionSet> &
RunnableInstructionSets();
} // namespace itk::detail

#endif
