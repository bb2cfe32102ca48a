// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrAtomicOutput_h
#define vrAtomicOutput_h

#include "vrStagedOutputs.h"

#include <string>

namespace vr
{
/** \class AtomicOutput
 * \brief One output file written into a staging folder beside its final path and published on Commit(), so an
 * existing result is never half-overwritten and a killed run leaves nothing the next one does not clean up
 * (docs/design.md "Bad input"). A vr::StagedOutputs of one file; see there for the staging and its recovery.
 *
 * The staged file keeps the final name (so ITK and VTK writers still pick the format from its extension). Without
 * Commit() the destructor removes it. A URI name (vr::IsURIName) is written directly.
 * \ingroup VesselReformation
 */
class AtomicOutput
{
public:
  /** Throws vr::InputError when the folder of \a finalPath does not exist or cannot be written, or the path is a
   * folder or another non-regular file. */
  explicit AtomicOutput(std::string finalPath);
  ~AtomicOutput() = default;
  AtomicOutput(const AtomicOutput &) = delete;
  AtomicOutput &
  operator=(const AtomicOutput &) = delete;

  /** Where the writer should write. */
  const std::string &
  TemporaryPath() const
  {
    return m_Staged.StagedPath(m_Handle);
  }
  const std::string &
  FinalPath() const
  {
    return m_FinalPath;
  }
  /** Publishes the file onto the final path; throws vr::InputError naming the path on failure. */
  void
  Commit();

private:
  std::string   m_FinalPath;
  StagedOutputs m_Staged;
  std::size_t   m_Handle{ 0 };
};
} // namespace vr

#endif
