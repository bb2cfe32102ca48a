// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrReformationInputs.h"

#include "itkRunoffPhantomImageSource.h"
#include "vrCenterlineIO.h"
#include "vrInputError.h"
#include "vrNodeConversion.h"
#include "vrVolumeIO.h"

#include <cmath>
#include <sstream>

namespace vr
{
std::string
ReformationInputs::BranchName(int id) const
{
  const auto found = BranchNames.find(id);
  return found != BranchNames.end() ? found->second : "branch " + std::to_string(id);
}

std::vector<std::string>
PhantomNames()
{
  return { "runoff" };
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
  if (name != "runoff")
  {
    std::string known;
    for (const auto & phantom : PhantomNames())
    {
      known += (known.empty() ? "" : ", ") + phantom;
    }
    throw InputError("phantom \"" + name + "\" is unknown; the built-in phantoms are: " + known);
  }
  auto phantom = itk::RunoffPhantomImageSource::New();
  phantom->SetSpacing(spacing);
  try
  {
    phantom->Update();
  }
  catch (const itk::ExceptionObject & error)
  {
    throw InputError("phantom \"" + name + "\": " + error.GetDescription());
  }
  const itk::CenterlineTree tree = phantom->GetCenterlineTree();
  ReformationInputs         inputs = MakeInputs(ConvertItkImageToVolumeNode(phantom->GetOutput(), "Run-off phantom"),
                                        ConvertTreeToCenterlineNode(tree, "Run-off phantom centerlines"));
  for (const auto & branch : inputs.Tree.GetBranches())
  {
    inputs.BranchNames[branch.Id] = itk::RunoffPhantomImageSource::GetBranchName(branch.Id);
  }
  std::ostringstream source;
  source << "run-off phantom (" << spacing << " mm voxels)";
  inputs.VolumeSource = source.str();
  inputs.CenterlineSource = "run-off phantom (exact centerlines)";
  inputs.IsPhantom = true;
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

ReformationInputs
MakeInputs(vtkSmartPointer<VolumeNode> volume, vtkSmartPointer<CenterlineNode> centerlines)
{
  ReformationInputs inputs;
  inputs.Volume = std::move(volume);
  inputs.Centerlines = std::move(centerlines);
  inputs.Tree = ConvertCenterlineNodeToTree(inputs.Centerlines);
  inputs.VolumeSource = inputs.Volume->GetName();
  inputs.CenterlineSource = inputs.Centerlines->GetName();
  return inputs;
}
} // namespace vr
