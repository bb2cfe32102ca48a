// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrVesselPathOutputWriter_h
#define vrVesselPathOutputWriter_h

#include "vrStagedOutputWriter.h"
#include "vrVesselPathLogic.h"

#include <string>

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
 * \brief Writes the outputs of a single-vessel reading all or nothing, on the shape every output writer shares
 * (vr::StagedOutputWriter: each is reserved before the work, written into staging, and published together by
 * CommitAll()). What is its own: the outputs (vr::VesselPathOutput), a lumen table's extension checked when it is
 * reserved, what each output needs, and how it is written.
 * \ingroup VesselReformation
 */
class VesselPathOutputWriter : public StagedOutputWriter<VesselPathOutput>
{
public:
  /** Writes every reserved output of \a results into staging. Throws vr::InputError naming the flag and the path
   * when an output asked for was not computed (a lumen table without a lumen), before anything is written, or naming
   * the flag when a write fails. */
  void
  Write(const VesselPathOutputs & results);

protected:
  /** A lumen table is CSV or TSV by its extension (vr::LumenTableSeparator): any other is refused by Add(). */
  void
  CheckPath(VesselPathOutput output, const std::string & path) const override;
};
} // namespace vr

#endif
