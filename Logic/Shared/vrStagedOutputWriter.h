// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrStagedOutputWriter_h
#define vrStagedOutputWriter_h

#include "vrInputError.h"
#include "vrStagedOutputs.h"

#include <algorithm>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace vr
{
/** \class StagedOutputWriter
 * \brief The shape every writer of a run's outputs shares, all or nothing through vr::StagedOutputs (docs/design.md
 * section 5): vr::OutputWriter (a tree reformation) and vr::VesselPathOutputWriter (a single vessel) derive from it
 * and keep only what is their own: which outputs there are (\a TOutput, an enumeration), what each needs, and how
 * it is written.
 *
 * Each output is reserved at its path before the work, so that a bad path fails at once (the folder is checked
 * then); WriteReserved() checks that every reserved output was computed before anything is staged, then writes each
 * into the staging folder; CommitAll() publishes them together. Until CommitAll() nothing appears, existing files of
 * the same names are left as they were, and a writer destroyed uncommitted (an error, a cancel) removes its staging.
 * \ingroup VesselReformation
 */
template<typename TOutput>
class StagedOutputWriter
{
public:
  virtual ~StagedOutputWriter() = default;

  /** Reserves \a output at \a path (vr::StagedOutputs::Add: the folder is checked now).
   * \param flag how the caller names it in messages ("--outputDepth", "cpr.png").
   * Throws vr::InputError naming the flag when the output is already reserved, CheckPath() refuses the path, or the
   * folder cannot take it. */
  void
  Add(TOutput output, const std::string & path, const std::string & flag)
  {
    const auto earlier = Find(output);
    if (earlier != m_Reserved.end())
    {
      throw InputError(flag + ": " + path + ": this output is already reserved as " + earlier->Path);
    }
    try
    {
      CheckPath(output, path);
    }
    catch (const InputError & error)
    {
      throw InputError(flag + ": " + error.what());
    }
    const std::size_t handle = m_Staged.Add(path, flag);
    m_Reserved.push_back({ output, handle, path, flag });
  }

  /** \return whether \a output is reserved. */
  bool
  Has(TOutput output) const
  {
    return Find(output) != m_Reserved.end();
  }

  /** \return the final paths of the reserved outputs, in the order they were reserved. */
  std::vector<std::string>
  Paths() const
  {
    std::vector<std::string> paths;
    for (const Reserved & reserved : m_Reserved)
    {
      paths.push_back(reserved.Path);
    }
    return paths;
  }

  /** Publishes every written output together (vr::StagedOutputs::CommitAll). */
  void
  CommitAll()
  {
    m_Staged.CommitAll();
  }

protected:
  StagedOutputWriter() = default;
  StagedOutputWriter(const StagedOutputWriter &) = delete;
  StagedOutputWriter &
  operator=(const StagedOutputWriter &) = delete;

  /** Refuses a path that cannot hold \a output (a lumen table's extension), before the work: throws vr::InputError,
   * which Add() prefixes with the flag. Any path is accepted unless a writer says otherwise. */
  virtual void
  CheckPath(TOutput /*output*/, const std::string & /*path*/) const
  {
  }

  /** Writes every reserved output into the staging folder.
   * \param missing what an output lacks to be written ("no cut surface was computed for these outputs"), or empty
   * when it can be written. It is asked of every reserved output before anything is staged, so that a missing output
   * costs no writing; the first answer is thrown as vr::InputError naming the flag and the path.
   * \param write writes \a output at the staged path it is given. Its vr::InputError is rethrown naming the flag and
   * the final path (vr::StagedOutputs::Write). */
  void
  WriteReserved(const std::function<std::string(TOutput output)> &                          missing,
                const std::function<void(TOutput output, const std::string & stagedPath)> & write)
  {
    for (const Reserved & reserved : m_Reserved)
    {
      const std::string lacking = missing(reserved.Output);
      if (!lacking.empty())
      {
        throw InputError(reserved.Flag + " (" + reserved.Path + "): " + lacking);
      }
    }
    for (const Reserved & reserved : m_Reserved)
    {
      m_Staged.Write(reserved.Handle, [&](const std::string & stagedPath) { write(reserved.Output, stagedPath); });
    }
  }

private:
  struct Reserved
  {
    TOutput     Output;
    std::size_t Handle;
    std::string Path;
    std::string Flag;
  };

  typename std::vector<Reserved>::const_iterator
  Find(TOutput output) const
  {
    return std::find_if(
      m_Reserved.begin(), m_Reserved.end(), [output](const Reserved & reserved) { return reserved.Output == output; });
  }

  StagedOutputs         m_Staged;
  std::vector<Reserved> m_Reserved;
};
} // namespace vr

#endif
