// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrStagedOutputs_h
#define vrStagedOutputs_h

#include "vrAtomicOutput.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace vr
{
/** \class StagedOutputs
 * \brief All-or-nothing output files of a command-line module.
 *
 * Each output is reserved before any work (its folder is checked then, so a bad path fails in a second, not after
 * the computation), written under a temporary name beside its final path, and renamed into place only when every
 * output has been written. On any error before CommitAll() the temporary files are removed: no output appears
 * and an existing file of the same name is left as it was.
 * \ingroup VesselReformation
 */
class StagedOutputs
{
public:
  /** Reserves an output.
   * \param path the final path.
   * \param flag how the command line named it ("--outputDepth", "<outputCPR>"), for messages.
   * \return a handle for Write(). Throws vr::InputError naming the flag when the folder does not exist, the path is a
   * folder, or another output already has this path. */
  std::size_t
  Add(const std::string & path, const std::string & flag);

  /** Writes an output under its temporary name.
   * \param handle what Add() returned.
   * \param writer writes the file at the path it is given (the temporary one, which keeps the final extension).
   * Rethrows the writer's vr::InputError naming the flag and the final path instead of the temporary one. */
  void
  Write(std::size_t handle, const std::function<void(const std::string & temporaryPath)> & writer);

  /** Renames every staged file onto its final path. Throws vr::InputError naming the path on failure. */
  void
  CommitAll();

private:
  struct Entry
  {
    std::string                   Flag;
    std::unique_ptr<AtomicOutput> Output;
  };
  std::vector<Entry> m_Entries;
};
} // namespace vr

#endif
