// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrOutputWriter.h"

#include "vrImageIO.h"
#include "vrInputError.h"
#include "vrNodeConversion.h"
#include "vrStagedOutputs.h"
#include "vrSurfaceIO.h"

#include <filesystem>
#include <functional>

namespace vr
{
std::vector<std::string>
WriteOutputs(const ReformationResult & result,
             const OutputSelection &   selection,
             const std::string &       folder,
             double                    window,
             double                    level)
{
  const ReformationOutputs & outputs = result.Outputs;
  if (selection.CutSurface && !outputs.Surface)
  {
    throw InputError("cut-surface.vtp: the cut surface of this view is still being computed; save again in a moment");
  }
  struct Planned
  {
    std::string                                   Name;
    std::function<void(const std::string & path)> Write;
  };
  std::vector<Planned> planned;
  if (selection.CPR)
  {
    planned.push_back({ "cpr.nrrd", [&](const std::string & path) {
                         WriteImage2D(ConvertVolumeNodeToDepthImage(outputs.CPR), path);
                       } });
  }
  if (selection.CPRPNG)
  {
    planned.push_back({ "cpr.png", [&](const std::string & path) {
                         WriteWindowedPNG(ConvertVolumeNodeToDepthImage(outputs.CPR), window, level, path);
                       } });
  }
  if (selection.UnfilteredCPR)
  {
    planned.push_back({ "cpr-unfiltered.nrrd", [&](const std::string & path) {
                         WriteImage2D(ConvertVolumeNodeToDepthImage(outputs.UnfilteredCPR), path);
                       } });
  }
  if (selection.DepthMaps)
  {
    planned.push_back({ "depth.nrrd", [&](const std::string & path) {
                         WriteImage2D(ConvertVolumeNodeToDepthImage(outputs.Depth), path);
                       } });
    planned.push_back({ "depth-relaxed.nrrd", [&](const std::string & path) {
                         WriteImage2D(ConvertVolumeNodeToDepthImage(outputs.RelaxedDepth), path);
                       } });
  }
  if (selection.FixedMask)
  {
    planned.push_back({ "mask.nrrd", [&](const std::string & path) {
                         WriteImage2D(ConvertVolumeNodeToMaskImage(outputs.FixedMask), path);
                       } });
  }
  if (selection.OwnerLabels)
  {
    planned.push_back({ "labels.nrrd", [&](const std::string & path) {
                         WriteImage2D(ConvertVolumeNodeToLabelImage(outputs.OwnerLabels), path);
                       } });
  }
  if (selection.CutSurface)
  {
    planned.push_back({ "cut-surface.vtp",
                        [&](const std::string & path) { WriteSurface(outputs.Surface, path, CoordinateSpace::RAS); } });
  }
  if (planned.empty())
  {
    throw InputError("save outputs: no output is checked");
  }
  StagedOutputs            staged;
  std::vector<std::size_t> handles;
  std::vector<std::string> paths;
  for (const Planned & output : planned)
  {
    paths.push_back((std::filesystem::path(folder) / output.Name).string());
    handles.push_back(staged.Add(paths.back(), output.Name));
  }
  for (std::size_t k = 0; k < planned.size(); ++k)
  {
    staged.Write(handles[k], planned[k].Write);
  }
  staged.CommitAll();
  return paths;
}
} // namespace vr
