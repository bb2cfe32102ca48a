// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrReformationInputs.h"

#include "itkCTAPhantom.h"
#include "vrCenterlineExtraction.h"
#include "vrCenterlineIO.h"
#include "vrCenterlineVolumeFit.h"
#include "vrInputError.h"
#include "vrNodeConversion.h"
#include "vrVolumeIO.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>

#include <algorithm>
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

void
PercentileWindowOf(VolumeNode * volume, double & window, double & level)
{
  window = 0.0;
  level = 0.0;
  vtkImageData * image = volume != nullptr ? volume->GetImageData() : nullptr;
  vtkDataArray * scalars = image != nullptr ? image->GetPointData()->GetScalars() : nullptr;
  if (scalars == nullptr || scalars->GetNumberOfTuples() == 0)
  {
    return;
  }
  constexpr vtkIdType MaximumSamples = vtkIdType{ 1 } << 22;
  const vtkIdType     count = scalars->GetNumberOfTuples();
  const vtkIdType     stride = std::max<vtkIdType>(1, (count + MaximumSamples - 1) / MaximumSamples);
  std::vector<double> samples;
  samples.reserve(static_cast<std::size_t>(count / stride + 1));
  for (vtkIdType k = 0; k < count; k += stride)
  {
    const double value = scalars->GetComponent(k, 0);
    if (std::isfinite(value))
    {
      samples.push_back(value);
    }
  }
  if (samples.empty())
  {
    return;
  }
  // The value at rank q (n - 1), rounded to the nearest rank.
  auto percentile = [&samples](double q)
  {
    const auto rank = static_cast<std::size_t>(std::lround(q * static_cast<double>(samples.size() - 1)));
    std::nth_element(samples.begin(), samples.begin() + static_cast<std::ptrdiff_t>(rank), samples.end());
    return samples[rank];
  };
  const double low = percentile(0.01);
  const double high = percentile(0.99);
  window = std::max(high - low, 1.0);
  level = 0.5 * (low + high);
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
