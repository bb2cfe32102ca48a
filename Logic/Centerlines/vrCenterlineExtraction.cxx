// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCenterlineExtraction.h"

#include <algorithm>

#include "vrCoordinateFrames.h"
#include "vrImageGrid.h"
#include "vrNodeConversion.h"
#include "vrITKMessages.h"
#include "vrParameterName.h"
#include "vrInputError.h"

#include "itkCenterlineExtractionFilter.h"
#include "itkImageRegionConstIteratorWithIndex.h"
#include "itkNearestNeighborInterpolateImageFunction.h"
#include "itkResampleImageFilter.h"

#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

namespace vr
{
namespace
{
std::string
FileName(const std::string & path)
{
  return std::filesystem::path(path).filename().string();
}

std::string
FormatNumber(double value)
{
  std::ostringstream text;
  text << value;
  return text.str();
}

std::string
ListLabels(const std::vector<double> & labels)
{
  std::string text;
  for (const double label : labels)
  {
    text += (text.empty() ? "" : ", ") + FormatNumber(label);
  }
  return text;
}

/** The distance (mm) from \a point (LPS) to the centre of the nearest vessel voxel of \a mask. */
double
DistanceToNearestVessel(const SegmentationMaskType * mask, const itk::Point<double, 3> & point)
{
  double nearest = std::numeric_limits<double>::infinity();
  for (itk::ImageRegionConstIteratorWithIndex<SegmentationMaskType> it(mask, mask->GetBufferedRegion()); !it.IsAtEnd();
       ++it)
  {
    if (it.Get() != 0)
    {
      itk::Point<double, 3> voxel;
      mask->TransformIndexToPhysicalPoint(it.GetIndex(), voxel);
      nearest = std::min(nearest, voxel.EuclideanDistanceTo(point));
    }
  }
  return nearest;
}

SegmentationMaskType::Pointer
ResampleOnto(const SegmentationMaskType * mask, const SegmentationMaskType * grid)
{
  auto resample = itk::ResampleImageFilter<SegmentationMaskType, SegmentationMaskType>::New();
  resample->SetInput(mask);
  resample->SetReferenceImage(grid);
  resample->UseReferenceImageOn();
  resample->SetInterpolator(itk::NearestNeighborInterpolateImageFunction<SegmentationMaskType, double>::New());
  resample->SetDefaultPixelValue(0);
  resample->Update();
  SegmentationMaskType::Pointer resampled = resample->GetOutput();
  resampled->DisconnectPipeline();
  return resampled;
}
} // namespace

void
CenterlineExtractionParameters::Validate() const
{
  for (const double label : Labels)
  {
    if (!(std::isfinite(label) && label >= 0.0 && label == std::round(label) && label < 16777216.0))
    {
      throw InputError("vessel labels: " + FormatNumber(label) + " is not a label; labels are whole numbers from 0",
                       ParameterName::VesselLabels);
    }
  }
  for (std::size_t k = 0; k < RootPointsRAS.size(); ++k)
  {
    const auto & point = RootPointsRAS[k];
    if (!(std::isfinite(point[0]) && std::isfinite(point[1]) && std::isfinite(point[2])))
    {
      throw InputError("root point " + std::to_string(k + 1) + ": its coordinates must be finite numbers",
                       ParameterName::RootPoint);
    }
  }
  if (!(std::isfinite(RootPointTolerance) && RootPointTolerance > 0.0))
  {
    throw InputError("root point tolerance = " + FormatNumber(RootPointTolerance) + " mm: must be finite and > 0",
                     ParameterName::RootPointTolerance);
  }
  if (!(std::isfinite(MinimumBranchLength) && MinimumBranchLength >= 0.0))
  {
    throw InputError("minimum branch length = " + FormatNumber(MinimumBranchLength) + " mm: must be finite and >= 0",
                     ParameterName::MinimumBranchLength);
  }
}

std::vector<std::string>
SplitSegmentationPaths(const std::string & text)
{
  std::error_code error;
  if (text.find(',') == std::string::npos || std::filesystem::exists(text, error))
  {
    return text.empty() ? std::vector<std::string>{} : std::vector<std::string>{ text };
  }
  std::vector<std::string> paths;
  std::istringstream       stream(text);
  std::string              path;
  while (std::getline(stream, path, ','))
  {
    if (!path.empty())
    {
      paths.push_back(path);
    }
  }
  return paths;
}

std::string
VesselNameOfFile(const std::string & path)
{
  std::string name = FileName(path);
  for (const char * extension : { ".seg.nrrd", ".nii.gz", ".nii", ".nrrd", ".nhdr", ".mha", ".mhd" })
  {
    const std::string ending(extension);
    if (name.size() > ending.size() && name.compare(name.size() - ending.size(), ending.size(), ending) == 0)
    {
      name.erase(name.size() - ending.size());
      break;
    }
  }
  std::replace(name.begin(), name.end(), '_', ' ');
  return name;
}

namespace
{
template<typename TImage>
void
NameBranchesByRegionOf(itk::CenterlineTree & tree, const TImage * regions, const std::map<int, std::string> & names)
{
  if (regions == nullptr || names.empty())
  {
    return;
  }
  const auto & region = regions->GetBufferedRegion();
  for (auto & branch : tree.GetBranches())
  {
    std::map<int, std::size_t> votes;
    for (const auto & point : branch.Points)
    {
      itk::Index<3> index;
      if (!regions->TransformPhysicalPointToIndex(point, index) || !region.IsInside(index))
      {
        continue;
      }
      const int value = static_cast<int>(std::lround(static_cast<double>(regions->GetPixel(index))));
      if (names.count(value) != 0)
      {
        ++votes[value];
      }
    }
    const auto most =
      std::max_element(votes.begin(), votes.end(), [](const auto & a, const auto & b) { return a.second < b.second; });
    if (most != votes.end())
    {
      branch.Name = names.at(most->first);
    }
  }
}
} // namespace

void
NameBranchesByRegion(itk::CenterlineTree &              tree,
                     const itk::Image<float, 3> *       regions,
                     const std::map<int, std::string> & names)
{
  NameBranchesByRegionOf(tree, regions, names);
}

void
NameBranchesByRegion(itk::CenterlineTree &              tree,
                     const SegmentationMaskType *       regions,
                     const std::map<int, std::string> & names)
{
  NameBranchesByRegionOf(tree, regions, names);
}

std::map<int, std::string>
RegionNamesOf(const Segmentation & segmentation)
{
  std::map<int, std::string> names;
  for (std::size_t k = 0; k < segmentation.RegionNames.size() && segmentation.Regions; ++k)
  {
    names[static_cast<int>(k + 1)] = segmentation.RegionNames[k];
  }
  return names;
}

vtkSmartPointer<VolumeNode>
MakeSegmentationNode(const Segmentation & segmentation)
{
  if (!segmentation.Regions)
  {
    return ConvertItkImageToVolumeNode(segmentation.Mask.GetPointer(), segmentation.Name);
  }
  auto node = ConvertItkImageToVolumeNode(segmentation.Regions.GetPointer(), segmentation.Name);
  for (const auto & [value, name] : RegionNamesOf(segmentation))
  {
    node->SetAttribute(RegionNameAttributePrefix + std::to_string(value), name);
  }
  return node;
}

Segmentation
ReadSegmentation(const std::vector<std::string> & paths,
                 const std::vector<double> &      labels,
                 std::vector<std::string> &       warnings)
{
  if (paths.empty())
  {
    throw InputError("segmentation: no file given");
  }
  Segmentation                        segmentation;
  std::vector<SegmentationReadReport> reports(paths.size());
  std::size_t                         vesselVoxels = 0;
  for (std::size_t k = 0; k < paths.size(); ++k)
  {
    SegmentationMaskType::Pointer mask = ReadSegmentationMask(paths[k], labels, &reports[k]);
    segmentation.Name += (k == 0 ? "" : ",") + FileName(paths[k]);
    segmentation.Descriptions.push_back(FileName(paths[k]) + ": " + reports[k].Kind + ", " +
                                        std::to_string(reports[k].ForegroundVoxels) + " vessel voxels");
    vesselVoxels += reports[k].ForegroundVoxels;
    if (reports[k].ForegroundVoxels == 0 && paths.size() > 1)
    {
      warnings.push_back("segmentation " + paths[k] + ": no vessel voxel" +
                         (labels.empty() ? std::string() : " with label " + ListLabels(labels)) + " (values " +
                         reports[k].Values + ")");
    }
    segmentation.RegionNames.push_back(VesselNameOfFile(paths[k]));
    if (k == 0 && paths.size() == 1 && !reports[0].LabelNames.empty() && reports[0].LabelNames.size() <= 255)
    {
      // One label map whose header names its labels (3D Slicer's .seg.nrrd): a region per named label, among the
      // vessel voxels.
      segmentation.RegionNames.clear();
      std::map<int, unsigned char> regionOf;
      for (const auto & [label, labelName] : reports[0].LabelNames)
      {
        segmentation.RegionNames.push_back(labelName);
        regionOf[label] = static_cast<unsigned char>(segmentation.RegionNames.size());
      }
      segmentation.Regions = SegmentationMaskType::New();
      segmentation.Regions->CopyInformation(mask);
      segmentation.Regions->SetRegions(mask->GetBufferedRegion());
      segmentation.Regions->Allocate(true);
      const float *         values = reports[0].LabelValues->GetBufferPointer();
      const unsigned char * vessel = mask->GetBufferPointer();
      unsigned char *       regions = segmentation.Regions->GetBufferPointer();
      for (std::size_t v = 0; v < mask->GetBufferedRegion().GetNumberOfPixels(); ++v)
      {
        const auto found = regionOf.find(static_cast<int>(std::lround(values[v])));
        regions[v] = vessel[v] != 0 && found != regionOf.end() ? found->second : 0;
      }
      segmentation.Mask = mask;
      continue;
    }
    if (k == 0)
    {
      segmentation.Mask = mask;
      // Regions tell vessels apart when several files are combined; a single file's name need not be a vessel's
      // ("segmentation.nii.gz").
      if (paths.size() >= 2 && paths.size() <= 255)
      {
        // Region 1 is the first file's vessel: a copy of its mask (1 = vessel).
        segmentation.Regions = SegmentationMaskType::New();
        segmentation.Regions->CopyInformation(mask);
        segmentation.Regions->SetRegions(mask->GetBufferedRegion());
        segmentation.Regions->Allocate();
        std::copy(mask->GetBufferPointer(),
                  mask->GetBufferPointer() + mask->GetBufferedRegion().GetNumberOfPixels(),
                  segmentation.Regions->GetBufferPointer());
      }
      continue;
    }
    if (!detail::SameGrid(mask, segmentation.Mask))
    {
      warnings.push_back("segmentation " + paths[k] + " is on another grid (" + detail::DescribeGrid(mask) + ") than " +
                         paths[0] + " (" + detail::DescribeGrid(segmentation.Mask) +
                         "); resampled onto the latter's (nearest neighbour)");
      mask = ResampleOnto(mask, segmentation.Mask);
    }
    const std::size_t     count = mask->GetBufferedRegion().GetNumberOfPixels();
    unsigned char *       combined = segmentation.Mask->GetBufferPointer();
    const unsigned char * added = mask->GetBufferPointer();
    unsigned char *       regions = segmentation.Regions ? segmentation.Regions->GetBufferPointer() : nullptr;
    for (std::size_t v = 0; v < count; ++v)
    {
      combined[v] = static_cast<unsigned char>(combined[v] | added[v]);
      if (regions != nullptr && added[v] != 0 && regions[v] == 0)
      {
        regions[v] = static_cast<unsigned char>(k + 1);
      }
    }
  }
  if (vesselVoxels == 0)
  {
    std::string what = paths.size() == 1 ? "segmentation " + paths[0] : "segmentations " + segmentation.Name;
    if (labels.empty())
    {
      what += ": no vessel voxel: every voxel is 0";
    }
    else
    {
      what += ": no voxel with label " + ListLabels(labels) + "; the values present are";
      for (std::size_t k = 0; k < paths.size(); ++k)
      {
        what += (paths.size() == 1 ? " " : (k == 0 ? " " : "; ") + FileName(paths[k]) + ": ") + reports[k].Values;
      }
    }
    throw InputError(what, labels.empty() ? std::string() : ParameterName::VesselLabels);
  }
  return segmentation;
}

void
ConfigureCenterlineExtraction(CenterlineExtractionFilterType *       filter,
                              const SegmentationMaskType *           mask,
                              const std::string &                    name,
                              const CenterlineExtractionParameters & parameters)
{
  parameters.Validate();
  // Root points: RAS in, LPS to the filter; one far from every vessel is said in the user's frame here.
  std::vector<itk::Point<double, 3>> rootPoints;
  for (std::size_t k = 0; k < parameters.RootPointsRAS.size(); ++k)
  {
    rootPoints.push_back(RASToLPS(parameters.RootPointsRAS[k]));
    const double gap = DistanceToNearestVessel(mask, rootPoints.back());
    if (gap > parameters.RootPointTolerance)
    {
      std::ostringstream message;
      const auto &       ras = parameters.RootPointsRAS[k];
      message << "root point " << k + 1 << " (" << ras[0] << ", " << ras[1] << ", " << ras[2] << ") RAS lies " << gap
              << " mm from the nearest vessel voxel of " << name << ", more than " << parameters.RootPointTolerance
              << " mm; is it in LPS (x and y negated)?";
      throw InputError(message.str(), ParameterName::RootPoint);
    }
  }
  filter->SetRootPoints(rootPoints);
  filter->SetRootPointTolerance(parameters.RootPointTolerance);
  filter->SetMinimumBranchLength(parameters.MinimumBranchLength);
}

itk::CenterlineTree
ExtractCenterlineTree(const SegmentationMaskType *                                            mask,
                      const std::string &                                                     name,
                      const CenterlineExtractionParameters &                                  parameters,
                      const std::function<void(double fraction, const std::string & stage)> & progress,
                      std::vector<std::string> &                                              warnings,
                      CenterlineExtractionReport *                                            report)
{
  using FilterType = CenterlineExtractionFilterType;
  auto filter = FilterType::New();
  filter->SetInput(mask);
  ConfigureCenterlineExtraction(filter, mask, name, parameters);
  if (progress)
  {
    FilterType * raw = filter;
    filter->AddObserver(itk::ProgressEvent(),
                        [raw, &progress](const itk::EventObject &) { progress(raw->GetProgress(), "centerlines"); });
  }
  try
  {
    filter->Update();
  }
  catch (const itk::ExceptionObject & exception)
  {
    throw InputError(name + ": " + detail::CondenseITKMessage(exception));
  }
  if (filter->GetNumberOfComponentsWithoutCenterline() > 0)
  {
    warnings.push_back(name + ": " + std::to_string(filter->GetNumberOfComponentsWithoutCenterline()) + " of its " +
                       std::to_string(filter->GetNumberOfComponents()) +
                       " connected components are too small or too round to have a centerline; left out");
  }
  if (report != nullptr)
  {
    report->Components = filter->GetNumberOfComponents();
    report->ComponentsWithoutCenterline = filter->GetNumberOfComponentsWithoutCenterline();
    report->ParentBranchIds = filter->GetParentBranchIds();
  }
  return filter->GetCenterlineTree();
}
} // namespace vr
