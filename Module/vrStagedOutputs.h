#ifndef vrStagedOutputs_h
#define vrStagedOutputs_h

#include "vrAtomicOutput.h"

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
 */
class StagedOutputs
{
public:
  /** \param path the final path.
   * \param flag how the command line named it ("--outputDepth", "<outputCPR>"), for messages.
   * \return the temporary path to write to (same folder, same extension). Throws vr::InputError naming the flag
   * when the folder does not exist or another output already has this path. */
  const std::string &
  Add(const std::string & path, const std::string & flag);

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
