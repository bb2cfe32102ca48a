// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrOutputWriter.h"

#include "vrImageIO.h"
#include "vrInputError.h"
#include "vrNodeConversion.h"
#include "vrOcclusionTableIO.h"
#include "vrSurfaceIO.h"

#include <filesystem>

namespace vr
{
const char *
OutputFileName(ReformationOutput output)
{
  switch (output)
  {
    case ReformationOutput::CPR:
      return "cpr.nrrd";
    case ReformationOutput::CPRPNG:
      return "cpr.png";
    case ReformationOutput::UnfilteredCPR:
      return "cpr-unfiltered.nrrd";
    case ReformationOutput::Depth:
      return "depth.nrrd";
    case ReformationOutput::RelaxedDepth:
      return "depth-relaxed.nrrd";
    case ReformationOutput::FixedMask:
      return "mask.nrrd";
    case ReformationOutput::OwnerLabels:
      return "labels.nrrd";
    case ReformationOutput::CutSurface:
      return "cut-surface.vtp";
    case ReformationOutput::HiddenLabels:
      return "hidden-labels.nrrd";
    case ReformationOutput::HiddenLengths:
      return "hidden-lengths.csv";
    case ReformationOutput::OcclusionProfile:
      return "occlusion-profile.csv";
  }
  return "";
}

void
OutputWriter::Write(const ReformationOutputs & outputs, double window, double level)
{
  WriteReserved(
    [&outputs](ReformationOutput output)
    {
      switch (output)
      {
        case ReformationOutput::CutSurface:
          return outputs.Surface ? std::string() : std::string("no cut surface was computed for these outputs");
        case ReformationOutput::HiddenLabels:
        case ReformationOutput::HiddenLengths:
          return outputs.HiddenLabels ? std::string()
                                      : std::string("what lies hidden is computed only in the visibility depth mode");
        case ReformationOutput::OcclusionProfile:
          return outputs.OcclusionProfile ? std::string()
                                          : std::string("no occlusion profile was computed for these outputs");
        default:
          return std::string();
      }
    },
    [&](ReformationOutput output, const std::string & path)
    {
      switch (output)
      {
        case ReformationOutput::CPR:
          WriteImage2D(ConvertVolumeNodeToDepthImage(outputs.CPR), path);
          break;
        case ReformationOutput::CPRPNG:
          WriteWindowedPNG(ConvertVolumeNodeToDepthImage(outputs.CPR), window, level, path);
          break;
        case ReformationOutput::UnfilteredCPR:
          WriteImage2D(ConvertVolumeNodeToDepthImage(outputs.UnfilteredCPR), path);
          break;
        case ReformationOutput::Depth:
          WriteImage2D(ConvertVolumeNodeToDepthImage(outputs.Depth), path);
          break;
        case ReformationOutput::RelaxedDepth:
          WriteImage2D(ConvertVolumeNodeToDepthImage(outputs.RelaxedDepth), path);
          break;
        case ReformationOutput::FixedMask:
          WriteImage2D(ConvertVolumeNodeToMaskImage(outputs.FixedMask), path);
          break;
        case ReformationOutput::OwnerLabels:
          WriteImage2D(ConvertVolumeNodeToLabelImage(outputs.OwnerLabels), path);
          break;
        case ReformationOutput::CutSurface:
          // As 3D Slicer writes models: LPS, the space recorded in the file, so Slicer loads it in place. The
          // logic's surface is RAS.
          WriteSurface(outputs.Surface, path, CoordinateSpace::RAS, CoordinateSpace::LPS);
          break;
        case ReformationOutput::HiddenLabels:
          WriteImage2D(ConvertVolumeNodeToLabelImage(outputs.HiddenLabels), path);
          break;
        case ReformationOutput::HiddenLengths:
          WriteHiddenLengthTable(outputs.BranchOcclusions, outputs.View.GetAngleInDegrees(), path);
          break;
        case ReformationOutput::OcclusionProfile:
          WriteOcclusionProfileTable(*outputs.OcclusionProfile, path);
          break;
      }
    });
}

std::vector<std::string>
WriteOutputs(const ReformationOutputs & outputs,
             const OutputSelection &    selection,
             const std::string &        folder,
             double                     window,
             double                     level)
{
  std::vector<ReformationOutput> chosen;
  const auto                     choose = [&chosen](bool selected, ReformationOutput output)
  {
    if (selected)
    {
      chosen.push_back(output);
    }
  };
  choose(selection.CPR, ReformationOutput::CPR);
  choose(selection.CPRPNG, ReformationOutput::CPRPNG);
  choose(selection.UnfilteredCPR, ReformationOutput::UnfilteredCPR);
  choose(selection.DepthMaps, ReformationOutput::Depth);
  choose(selection.DepthMaps, ReformationOutput::RelaxedDepth);
  choose(selection.FixedMask, ReformationOutput::FixedMask);
  choose(selection.OwnerLabels, ReformationOutput::OwnerLabels);
  choose(selection.CutSurface, ReformationOutput::CutSurface);
  choose(selection.HiddenLabels, ReformationOutput::HiddenLabels);
  choose(selection.HiddenLengths, ReformationOutput::HiddenLengths);
  choose(selection.OcclusionProfile, ReformationOutput::OcclusionProfile);
  if (chosen.empty())
  {
    throw InputError("save outputs: no output is checked");
  }
  OutputWriter writer;
  for (const ReformationOutput output : chosen)
  {
    writer.Add(output, (std::filesystem::path(folder) / OutputFileName(output)).string(), OutputFileName(output));
  }
  writer.Write(outputs, window, level);
  writer.CommitAll();
  return writer.Paths();
}
} // namespace vr
