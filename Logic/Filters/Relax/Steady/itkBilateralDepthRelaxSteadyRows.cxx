// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkBilateralDepthRelaxSteadyRows.h"

namespace itk::detail::BilateralDepthRelaxSteady
{
const RowKernels &
RowsFor(InstructionSet set)
{
  switch (set)
  {
#if defined(VR_RELAX_RUNTIME_DISPATCH)
    case InstructionSet::AVX512:
      return RowKernelsAVX512;
    case InstructionSet::AVX2:
      return RowKernelsAVX2;
#endif
    default:
      return RowKernelsBaseline;
  }
}

const RowKernels &
Rows()
{
  static const RowKernels & widest = RowsFor(RunnableInstructionSets().front());
  return widest;
}
} // namespace itk::detail::BilateralDepthRelaxSteady
