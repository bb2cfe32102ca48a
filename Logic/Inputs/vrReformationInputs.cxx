// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrReformationInputs.h"

#include "itkCTAPhantom.h"
#include "vrCenterlineExtraction.h"
#include "vrCenterlineIO.h"
#include "vrCenterlineVolumeFit.h"
#include "vrInputError.h"
#include "vrNodeConversion.h"
#include "vrVolumeIO.h"

#include <cmath>
#include <vector>
#include <sstream>
#include <stdexcept>

namespace vr
{
std::string
ReformationInputs::BranchName(int id) const
{
  for (const auto & branch : Tree.GetBranches())
  {
    if (branch.Id == id && !branch.Name.empty())
    {
      return branch.Name;
    }
  }
  return "branch " + std::to_string(id);
}

std::vector<std::string>
PhantomNames()
{
  return itk::GetCTAPhantomNames();
}

ReformationInputs
MakePhantomInputs(const std::string & name, double spacing)
{
  if (!(std::isfinite(spacing) && spacing > 0.0))
  {
    std::ostringstream message;
    message << "phantom spacing = " << spacing << " mm is invalid: it must be finite and > 0";
    throw InputError(message.str());
  }
  itk::CTAPhantomKind kind;
  try
  {
    kind = itk::ParseCTAPhantomKind(name);
  }
  catch (const std::invalid_argument &)
  {
    std::string known;
    for (const auto & phantom : PhantomNames())
    {
      known += (known.empty() ? "" : ", ") + phantom;
    }
    throw InputError("phantom \"" + name + "\" is unknown; the built-in phantoms are: " + known);
  }
  itk::CTAPhantom phantom = itk::MakeCTAPhantom(kind, spacing);
  try
  {
    phantom.Source->Update();
  }
  catch (const itk::ExceptionObject & error)
  {
    throw InputError("phantom \"" + name + "\": " + error.GetDescription());
  }
  ReformationInputs inputs =
    MakeInputs(ConvertStoredVolumeToVolumeNode(StoredVolume{ phantom.Source->GetOutput(), {} }, phantom.Description),
               ConvertTreeToCenterlineNode(phantom.Tree, phantom.Description + " centerlines"));
  std::ostringstream source;
  source << phantom.Name << " phantom, " << phantom.Description << " (" << spacing << " mm voxels)";
  inputs.VolumeSource = source.str();
  inputs.CenterlineSource = phantom.Name + " phantom (exact centerlines)";
  inputs.IsPhantom = true;
  inputs.PhantomName = phantom.Name;
  inputs.IntensityUnit = "HU";
  return inputs;
}

vtkSmartPointer<VolumeNode>
ReadVolumeNode(const std::string & path, const VolumeReadOptions & options, VolumeReadReport * report)
{
  // In the file's pixel type, the node sharing the voxels the reader put in memory.
  return ConvertStoredVolumeToVolumeNode(ReadStoredVolume(path, options, report), path);
}

void
AddVolumeReport(ReformationInputs & inputs, const VolumeReadReport & report)
{
  inputs.Warnings.insert(inputs.Warnings.begin(), report.Warnings.begin(), report.Warnings.end());
  inputs.Notes.insert(inputs.Notes.end(), report.Notes.begin(), report.Notes.end());
}

vtkSmartPointer<CenterlineNode>
ReadCenterlineNode(const std::string & path)
{
  const itk::CenterlineTree tree = ReadCenterlines(path);
  return ConvertTreeToCenterlineNode(tree, path);
}

vtkSmartPointer<VolumeNode>
ReadSegmentationNode(const std::vector<std::string> & paths,
                     std::vector<std::string> &       warnings,
                     std::vector<std::string> &       descriptions)
{
  const Segmentation segmentation = ReadSegmentation(paths, {}, warnings);
  descriptions = segmentation.Descriptions;
  return MakeSegmentationNode(segmentation);
}

ReformationInputs
MakeSegmentationInputs(vtkSmartPointer<VolumeNode> volume, vtkSmartPointer<VolumeNode> segmentation)
{
  ReformationInputs inputs;
  inputs.Volume = std::move(volume);
  inputs.Segmentation = std::move(segmentation);
  inputs.VolumeSource = inputs.Volume->GetName();
  inputs.CenterlineSource = "centerlines extracted from " + inputs.Segmentation->GetName();
  inputs.IntensityUnit = IntensityUnitOf(inputs.Volume);
  PercentileWindowOf(inputs.Volume, inputs.PercentileWindow, inputs.PercentileLevel);
  return inputs;
}

ReformationInputs
WithExtractedCenterlines(const ReformationInputs & inputs, vtkSmartPointer<CenterlineNode> extracted)
{
  ReformationInputs result = inputs;
  result.Centerlines = std::move(extracted);
  result.Tree = ConvertCenterlineNodeToTree(result.Centerlines);
  return result;
}

ReformationInputs
MakeInputs(vtkSmartPointer<VolumeNode> volume, vtkSmartPointer<CenterlineNode> centerlines)
{
  ReformationInputs inputs;
  inputs.Volume = std::move(volume);
  inputs.Centerlines = std::move(centerlines);
  inputs.Tree = ConvertCenterlineNodeToTree(inputs.Centerlines);
  // Refused here, before anything is replaced, as the logic would refuse it on its first run.
  const std::string warning = CheckCenterlineVolumeFit(MeasureCenterlineVolumeFit(inputs.Tree, inputs.Volume),
                                                       "centerlines \"" + inputs.Centerlines->GetName() + "\"",
                                                       "the volume \"" + inputs.Volume->GetName() + "\"",
                                                       false);
  if (!warning.empty())
  {
    inputs.Warnings.push_back(warning);
  }
  inputs.VolumeSource = inputs.Volume->GetName();
  inputs.CenterlineSource = inputs.Centerlines->GetName();
  inputs.IntensityUnit = IntensityUnitOf(inputs.Volume);
  PercentileWindowOf(inputs.Volume, inputs.PercentileWindow, inputs.PercentileLevel);
  return inputs;
}
} // namespace vr
