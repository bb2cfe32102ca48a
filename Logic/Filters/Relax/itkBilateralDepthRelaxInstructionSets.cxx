// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkBilateralDepthRelaxInstructionSets.h"

namespace itk::detail
{
namespace
{
#if defined(VR_RELAX_RUNTIME_DISPATCH)
/** Whether the processor runs code built with -march=x86-64-v3 (\a level 3) or -v4 (\a level 4). GCC 12 knows
 * the levels by name; otherwise the features the kernels can use are asked one by one. */
bool
SupportsLevel(int level)
{
  __builtin_cpu_init();
#if defined(__GNUC__) && !defined(__clang__) && __GNUC__ >= 12
  return level == 4 ? __builtin_cpu_supports("x86-64-v4") : __builtin_cpu_supports("x86-64-v3");
#else
  const bool level3 = __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma") &&
                      __builtin_cpu_supports("bmi") && __builtin_cpu_supports("bmi2");
  return level == 3 ? level3
                    : level3 && __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("avx512bw") &&
                        __builtin_cpu_supports("avx512cd") && __builtin_cpu_supports("avx512dq") &&
                        __builtin_cpu_supports("avx512vl");
#endif
}
#endif

std::vector<InstructionSet>
FindRunnableInstructionSets()
{
  std::vector<InstructionSet> sets;
#if defined(VR_RELAX_RUNTIME_DISPATCH)
  if (SupportsLevel(4))
  {
    sets.push_back(InstructionSet::AVX512);
  }
  if (SupportsLevel(3))
  {
    sets.push_back(InstructionSet::AVX2);
  }
#endif
  sets.push_back(InstructionSet::Baseline);
  return sets;
}
} // namespace

const std::vector<InstructionSet> &
RunnableInstructionSets()
{
  static const std::vector<InstructionSet> sets = FindRunnableInstructionSets();
  return sets;
}
} // namespace itk::detail
