// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrStagedOutputs_h
#define vrStagedOutputs_h

#include <functional>
#include <string>
#include <vector>

namespace vr
{
/** \class StagedOutputs
 * \brief All-or-nothing output files of a run, published together and recoverably (docs/design.md "Bad input").
 *
 * Each output is reserved before any work (its folder is checked then, so a bad path fails in a second, not after
 * the computation) and written into a staging folder, ".vr-staging-<pid>-XXXXXX", created beside the outputs in their
 * own folder (so on their file system, where a rename is atomic). CommitAll() then publishes them together:
 *
 * 1. every staged file is flushed to disk, and every staging folder gets a journal listing its files, its run's
 *    first ("primary") staging folder and all the others (outputs may lie in several folders);
 * 2. the commit point: a "committed" marker appears, atomically, in the primary staging folder;
 * 3. the files are renamed onto their final names, folder by folder (the primary last), and the staging folders
 *    are removed.
 *
 * On any error before the commit point, the staging folders are removed: no output appears and an existing file of
 * the same name is left byte for byte as it was. A run killed at any moment (SIGKILL included) leaves its staging
 * folder behind, locked by nobody: the next run that reserves an output in that folder finds it (a staging folder
 * whose lock no live process holds) and rolls it forward when its primary is committed, finishing the renames,
 * or else deletes it. So the published outputs are always one run's complete set, and no stray file outlives the
 * next run. A run holds an exclusive flock() on its staging folders' lock files while it lives; the kernel drops it
 * when the process dies, however it dies. A staging folder without its lock file (a run killed while creating or
 * removing it) is deleted once the process id in its name is no longer alive.
 *
 * A name with a URI scheme (vr::IsURIName, e.g. 3D Slicer's in-memory "slicer:0x...#node") is no file: the writer
 * gets the name itself, it is neither staged nor renamed, and CommitAll() leaves it alone. So is a path inside
 * another StagedOutputs' staging folder (a writer such as vr::WriteImage2D, which stages what it writes, called by
 * Write()): the enclosing staging already makes it atomic.
 * \ingroup VesselReformation
 */
class StagedOutputs
{
public:
  StagedOutputs();
  /** Removes the staging folders of outputs not yet committed (nothing is published). */
  ~StagedOutputs();
  StagedOutputs(const StagedOutputs &) = delete;
  StagedOutputs &
  operator=(const StagedOutputs &) = delete;

  /** Reserves an output. The first output in a folder recovers that folder's stale staging of dead runs (see the
   * class description) and creates this run's staging folder there.
   * \param path the final path.
   * \param flag how the command line named it ("--outputDepth", "<outputCPR>"), for messages.
   * \return a handle for Write() and StagedPath(). Throws vr::InputError naming the flag when the folder does not
   * exist or cannot be written, the path is a folder or another non-regular file, or another output already has
   * this path. */
  std::size_t
  Add(const std::string & path, const std::string & flag);

  /** \return where the writer of output \a handle writes: a file in the staging folder with the final name (so
   * ITK and VTK writers still pick the format from its extension), or the name itself for a URI name. */
  const std::string &
  StagedPath(std::size_t handle) const;

  /** Writes an output into the staging folder.
   * \param handle what Add() returned.
   * \param writer writes the file at the path it is given (StagedPath()).
   * Rethrows the writer's vr::InputError naming the flag and the final path instead of the staged one. */
  void
  Write(std::size_t handle, const std::function<void(const std::string & stagedPath)> & writer);

  /** Publishes every staged output (see the class description). Throws vr::InputError naming the path on failure;
   * a failure after the commit point leaves the committed staging for the next run to finish. */
  void
  CommitAll();

  /** Recovers the stale staging folders of dead runs in \a folder: committed ones are rolled forward, others
   * deleted; staging folders of live runs are left alone. Add() calls it; public for tools and tests.
   * \return the number of stale staging folders handled. */
  static std::size_t
  RecoverStaleStaging(const std::string & folder);

private:
  struct Folder
  {
    std::string              OutputFolder;
    std::string              Staging;
    int                      LockDescriptor{ -1 };
    std::vector<std::string> FileNames;
  };
  struct Entry
  {
    std::string Flag;
    std::string FinalPath;
    std::string StagedPath;
    /** Index into m_Folders; -1 for a URI name, written directly. */
    long Folder{ -1 };
  };

  std::size_t
  FolderFor(const std::string & outputFolder, const std::string & what);
  void
  Discard();

  std::vector<Folder> m_Folders;
  std::vector<Entry>  m_Entries;
  bool                m_Committed{ false };
};
} // namespace vr

#endif
