// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrViewerOptions_h
#define vrViewerOptions_h

#include "vrCPRView.h"
#include "vrReformationParameters.h"

#include <optional>
#include <string>
#include <vector>

namespace vr
{
/** What the VesselReformationViewer's command line asks for.
 * \ingroup VesselReformation
 */
struct ViewerOptions
{
  /** Files to open; both empty: the phantom. */
  std::string VolumePath;
  std::string CenterlinePath;
  /** Which series of a DICOM folder that holds several (vr::VolumeReadOptions::DICOMSeries); empty: ask. */
  std::string DICOMSeries;
  /** Vessel segmentation files (combined) whose centerlines the logic extracts, instead of CenterlinePath. */
  std::vector<std::string> SegmentationPaths;
  /** The built-in phantom and its voxel spacing (mm) when no files are given. */
  std::string Phantom{ "runoff" };
  double      PhantomSpacing{ 1.5 };
  /** The view and filter parameters (the panel starts with them). */
  ReformationParameters Parameters;
  /** A window/level preset name, or empty (then Window/Level, or the input's default). */
  std::string   Preset;
  bool          HasWindowLevel{ false };
  CPROverlays   Overlays;
  CPRComparison Comparison{ CPRComparison::Filtered };
  /** Scripted mode: render once, write this PNG, exit. */
  std::string ScreenshotPath;
  /** The window's size in pixels. */
  int WindowWidth{ 1600 };
  int WindowHeight{ 1000 };
};

/** Parses the viewer's command line.
 * \param argc, argv the arguments.
 * \param options receives the options.
 * \param message receives the help text (\return 0 with an exit request) or the error naming the flag.
 * \return std::nullopt to go on, or the exit status: 0 after --help, 1 on bad input. */
std::optional<int>
ParseViewerOptions(int argc, char ** argv, ViewerOptions & options, std::string & message);
} // namespace vr

#endif
