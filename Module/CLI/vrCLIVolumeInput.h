// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrCLIVolumeInput_h
#define vrCLIVolumeInput_h

#include "vrCLIArguments.h"
#include "vrCLIProgress.h"
#include "vrStoredVolume.h"

#include <string>
#include <vector>

namespace vr
{
/** Reads a module's input volume as every module that reads one spells it in its XML: the file or DICOM folder of
 * \a parameter, and the DICOM series that the "series" parameter chooses in a folder of several (its number in the
 * list or its Series Instance UID; docs/dicom-series.md). What the reader warns about is printed on stderr as
 * "warning: ..." and what it skipped as "note: ...", through \a progress, and the warnings are appended to \a warnings
 * (the module returns them as inputWarnings). The volume is in its file's pixel type (vr::ReadStoredVolume).
 * Throws vr::InputError as vr::ReadStoredVolume does; the error that a folder
 * holds several series names the "series" parameter (the runner prefixes its flag). */
StoredVolume
ReadModuleVolume(const CLIArguments &       arguments,
                 const std::string &        parameter,
                 CLIProgress &              progress,
                 std::vector<std::string> & warnings);

/** \a warnings as one returned value: each in full, separated by " | "; "none" when there are none (the value's
 * default: CTK hosts pass it back as a trailing argument, which must not be empty). */
std::string
JoinedWarnings(const std::vector<std::string> & warnings);
} // namespace vr

#endif
