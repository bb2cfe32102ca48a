// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrOutputWriter_h
#define vrOutputWriter_h

#include "vrStagedOutputWriter.h"
#include "vrVesselReformationLogic.h"

#include <string>
#include <vector>

namespace vr
{
/** The files a reformation can write, one each. */
enum class ReformationOutput
{
  CPR,             ///< the relaxed CPR image (NRRD or any ITK 2D format)
  CPRPNG,          ///< the relaxed CPR through window and level, 8-bit greyscale PNG
  UnfilteredCPR,   ///< the CPR on the unrelaxed depth map
  Depth,           ///< the depth map before relaxation (mm)
  RelaxedDepth,    ///< the relaxed depth map (mm)
  FixedMask,       ///< the pixels the relaxation keeps fixed
  OwnerLabels,     ///< the branch that owns each pixel
  CutSurface,      ///< the cut surface (.vtp or .vtk), LPS with the space recorded, as 3D Slicer writes models
  HiddenLabels,    ///< Visibility mode: the branch hidden behind the visible one, per pixel
  HiddenLengths,   ///< Visibility mode: each branch's length and hidden length, and the view's angle (CSV)
  OcclusionProfile ///< the hidden length at every angle 0-179 degrees (CSV)
};

/** \return the name an output has in a folder of outputs ("cpr.nrrd", "cut-surface.vtp", ...). */
const char *
OutputFileName(ReformationOutput output);

/** Which outputs to write into a folder (WriteOutputs).
 * \ingroup VesselReformation
 */
struct OutputSelection
{
  bool CPR{ true };
  bool CPRPNG{ true };
  bool UnfilteredCPR{ true };
  /** Both depth maps: before and after relaxation. */
  bool DepthMaps{ true };
  bool FixedMask{ true };
  bool OwnerLabels{ true };
  bool CutSurface{ true };
  /** Visibility mode's hidden labels and hidden lengths; off by default (the other modes have none). */
  bool HiddenLabels{ false };
  bool HiddenLengths{ false };
  /** The occlusion profile, when the outputs have one. */
  bool OcclusionProfile{ false };
};

/** \class OutputWriter
 * \brief The one writer of a reformation's outputs (the command-line module, the viewer and the demo use it), all or
 * nothing on the shape every output writer shares (vr::StagedOutputWriter: reserve before the work, write into
 * staging, publish together; docs/design.md "Bad input").
 *
 * What is its own: the outputs (vr::ReformationOutput), what each needs when it is reserved (the cut surface, the
 * hidden labels and lengths of Visibility mode, the occlusion profile), and how each is written. The cut surface is
 * written in LPS with "SPACE" recorded in the file, as 3D Slicer writes models (vr::WriteSurface), from the logic's RAS
 * surface. \ingroup VesselReformation
 */
class OutputWriter : public StagedOutputWriter<ReformationOutput>
{
public:
  /** Writes every reserved output of \a outputs into the staging folder. The PNG goes through \a window (> 0) and
   * \a level. Throws vr::InputError naming the flag and the path, or saying which output \a outputs lacks (the cut
   * surface when it was not computed, hidden labels or lengths outside Visibility mode, a profile that was not
   * computed); nothing is published then. */
  void
  Write(const ReformationOutputs & outputs, double window, double level);
};

/** Writes the outputs \a selection asks for into \a folder under their OutputFileName()s, all or nothing.
 * \param outputs the logic's outputs; their cut surface is needed when \a selection asks for it.
 * \param selection which outputs.
 * \param folder an existing folder.
 * \param window the PNG's window width (> 0, intensity unit).
 * \param level the PNG's level.
 * \return the paths written. Throws vr::InputError naming the file or what is missing; then nothing is written. */
std::vector<std::string>
WriteOutputs(const ReformationOutputs & outputs,
             const OutputSelection &    selection,
             const std::string &        folder,
             double                     window,
             double                     level);
} // namespace vr

#endif
