// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrAtomicOutput.h"

namespace vr
{
AtomicOutput::AtomicOutput(std::string finalPath)
  : m_FinalPath(std::move(finalPath))
{
  m_Handle = m_Staged.Add(m_FinalPath, "output");
}

void
AtomicOutput::Commit()
{
  m_Staged.CommitAll();
}
} // namespace vr
