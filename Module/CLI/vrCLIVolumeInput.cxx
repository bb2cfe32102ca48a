// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCLIVolumeInput.h"

#include "vrVolumeIO.h"

#include <iostream>

namespace vr
{
StoredVolume
ReadModuleVolume(const CLIArguments &       arguments,
                 const std::string &        parameter,
                 CLIProgress &              progress,
                 std::vector<std::string> & warnings)
{
  VolumeReadOptions options;
  options.DICOMSeries = arguments.String("series");
  VolumeReadReport   report;
  const StoredVolume volume = ReadStoredVolume(arguments.String(parameter), options, &report);
  for (const std::string & note : report.Notes)
  {
    progress.Print(std::cerr, "note: " + note);
  }
  for (const std::string & warning : report.Warnings)
  {
    progress.Print(std::cerr, "warning: " + warning);
  }
  warnings.insert(warnings.end(), report.Warnings.begin(), report.Warnings.end());
  return volume;
}

std::string
JoinedWarnings(const std::vector<std::string> & warnings)
{
  std::string text;
  for (const std::string & warning : warnings)
  {
    text += (text.empty() ? "" : " | ") + warning;
  }
  return text.empty() ? std::string("none") : text;
}
} // namespace vr
