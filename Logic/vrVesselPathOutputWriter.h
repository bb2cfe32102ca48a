// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrVesselPathOutputWriter_h
#define vrVesselPathOutputWriter_h

#include "vrStagedOutputs.h"
#include "vrVesselPathLogic.h"

#include <string>
#include <vector>

namespace vr
{
/** The files a single-vessel reading can write. */
enum class VesselPathOutput
{
  /** The straightened or stretched CPR (float). */
  CPR,
  /** The cross-section stack (u, v, s). */
  CrossSections,
  /** The LPS point of every CPR pixel (3 components). */
  Points,
  /** 1 where the CPR's rows fold over each other. */
  FoldMask,
  /** One row per cross-section, CSV or TSV by the extension (vr::WriteLumenTable). */
  LumenTable
};

/** \class VesselPathOutputWriter
 * \brief Writes the outputs of a single-vessel reading all or nothing (vr::StagedOutputs): each is reserved before
 * the work, written into staging, and published together by CommitAll().
 * \ingroup VesselReformation
 */
class VesselPathOutputWriter
{
public:
  /** Reserves \a output at \a path; \a flag names it in messages. Throws vr::InputError naming the flag when the
   * folder is not writable, the path is taken twice, or a lumen table's extension is neither .csv nor .tsv. */
  void
  Add(VesselPathOutput output, const std::string & path, const std::string & flag);
  bool
  Has(VesselPathOutput output) const;
  /** Writes every reserved output of \a results into staging. Throws vr::InputError naming the flag when an output
   * asked for was not computed (a lumen table without a lumen) or a write fails. */
  void
  Write(const VesselPathResults & results);
  /** Publishes what Write() staged. */
  void
  CommitAll();

private:
  struct Reserved
  {
    VesselPathOutput Output;
    std::size_t      Handle;
    std::string      Flag;
  };
  StagedOutputs         m_Staged;
  std::vector<Reserved> m_Reserved;
};
} // namespace vr

#endif
