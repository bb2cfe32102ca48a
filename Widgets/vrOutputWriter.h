// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrOutputWriter_h
#define vrOutputWriter_h

#include "vrModulePanel.h"
#include "vrReformationController.h"

#include <string>
#include <vector>

namespace vr
{
/** Writes the outputs of a displayed reformation into \a folder through the logic's writers, all or nothing
 * (vr::StagedOutputs): cpr.nrrd, cpr.png (through \a window and \a level), cpr-unfiltered.nrrd, depth.nrrd,
 * depth-relaxed.nrrd, mask.nrrd, labels.nrrd and cut-surface.vtp (RAS), as \a selection asks.
 * \param result the result on screen; its full cut surface is needed for cut-surface.vtp.
 * \param selection which outputs.
 * \param folder an existing folder.
 * \param window the PNG's window width (> 0, intensity unit).
 * \param level the PNG's level.
 * \return the paths written. Throws vr::InputError naming the file or what is missing; then nothing is written. */
std::vector<std::string>
WriteOutputs(const ReformationResult & result,
             const OutputSelection &   selection,
             const std::string &       folder,
             double                    window,
             double                    level);
} // namespace vr

#endif
