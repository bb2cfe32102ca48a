// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrReformationInputs.h"

#include "itkCTAPhantom.h"
#include "vrCenterlineExtraction.h"
#include "vrCenterlineIO.h"
#include "vrInputError.h"
#include "vrNodeConversion.h"
#include "vrVolumeIO.h"

#include <vtkImageData.h>
#include <vtkPointData.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace vr
{
std::string
ReformationInputs::BranchName(int id) const
{
  const auto found = BranchNames.find(id);
  return found != BranchNames.end() ? found->second : "branch " + std::to_string(id);
}

std::string
IntensityUnitOf(VolumeNode * volume)
{
  // Air in CT is about -1000 HU; no other modality stores intensities this far below 0.
  constexpr double AirBound = -500.0;
  vtkImageData *   image = volume != nullptr ? volume->GetImageData() : nullptr;
  if (image == nullptr || image->GetPointData()->GetScalars() == nullptr)
  {
    return std::string();
  }
  double range[2];
  image->GetScalarRange(range);
  return range[0] <= AirBound ? "HU" : std::string();
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
    MakeInputs(ConvertItkImageToVolumeNode(phantom.Source->GetOutput(), phantom.Description),
               ConvertTreeToCenterlineNode(phantom.Tree, phantom.Description + " centerlines"));
  for (const auto & branch : inputs.Tree.GetBranches())
  {
    inputs.BranchNames[branch.Id] = phantom.BranchName(branch.Id);
  }
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
ReadVolumeNode(const std::string & path)
{
  const VolumeImageType::Pointer image = ReadVolume(path);
  return ConvertItkImageToVolumeNode(image, path);
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
  return ConvertItkImageToVolumeNode(segmentation.Mask.GetPointer(), segmentation.Name);
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
  inputs.VolumeSource = inputs.Volume->GetName();
  inputs.CenterlineSource = inputs.Centerlines->GetName();
  inputs.IntensityUnit = IntensityUnitOf(inputs.Volume);
  return inputs;
}
} // namespace vr
