// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrURINames_h
#define vrURINames_h

#include <string>

namespace vr
{
/** Whether \a name is a URI-style name for an ITK ImageIO of the host process rather than a local file: a scheme
 * of two or more characters (a letter, then letters, digits, '+', '-' or '.'), then ':', and no local file or
 * folder of that name exists.
 *
 * 3D Slicer runs a shared-library command-line module in its own process and passes images as in-memory names
 * such as "slicer:0x55d0c1a2b3c0#vtkMRMLScalarVolumeNode1" (the MRML scene's address, '#', the node's id), which
 * an ImageIO that Slicer registers with ITK's factory reads and writes. Such names go to ITK's reader or writer
 * untouched: the readers skip their file checks, and outputs are written straight to the name instead of being
 * staged and renamed (vr::StagedOutputs). A one-letter scheme is not taken as one, so that "C:/data/ct.nrrd"
 * stays a path. */
bool
IsURIName(const std::string & name);
} // namespace vr

#endif
