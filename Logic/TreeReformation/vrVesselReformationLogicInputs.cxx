// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// vr::VesselReformationLogic's inputs: converted from their nodes, checked against each other, centerlines extracted
// from a segmentation when no centerlines are given.
#include "vrVesselReformationLogicInternals.h"

namespace vr
{
using detail::Clock;
using detail::SecondsSince;

void
VesselReformationLogic::Internals::ConvertInputs()
{
  const auto start = Clock::now();
  // The cache converts what changed; a value other than the one the pipeline holds is a change.
  const auto volume = Inputs->GetVolume(VolumeNodeInput);
  const bool volumeChanged = volume != Volume;
  Volume = volume;
  bool centerlinesChanged = false;
  bool segmentationChanged = false;
  if (CenterlineNodeInput)
  {
    const auto tree = Inputs->GetCenterlines(CenterlineNodeInput);
    centerlinesChanged = tree != Tree || TreeFromExtraction;
    Tree = tree;
    TreeFromExtraction = false;
  }
  else
  {
    const auto segmentation = Inputs->GetSegmentation(SegmentationNodeInput, ExtractionParameters.Labels);
    segmentationChanged = segmentation != Segmentation;
    Segmentation = segmentation;
    Extraction->SetInput(Segmentation->Mask);
  }
  VolumeChanged = volumeChanged;
  if (!volumeChanged && !centerlinesChanged && !segmentationChanged)
  {
    return;
  }
  ++Counts.Conversion;
  if (SegmentationNodeInput)
  {
    CheckSegmentationAgainstVolume();
  }
  else
  {
    CheckTreeAgainstVolume();
  }
  Outputs.Times.Conversion = SecondsSince(start);
}

std::string
VesselReformationLogic::Internals::SegmentationName() const
{
  return ReformationInputCache::DescribeSegmentationNode(SegmentationNodeInput);
}

void
VesselReformationLogic::Internals::CheckTreeAgainstVolume()
{
  InputWarning.clear();
  std::string centerlines = "centerlines";
  if (TreeFromExtraction)
  {
    centerlines = "the centerlines of " + SegmentationName();
  }
  else if (!CenterlineNodeInput->GetName().empty())
  {
    centerlines += " \"" + CenterlineNodeInput->GetName() + "\"";
  }
  const std::string volume = VolumeNodeInput->GetName().empty() ? std::string("the volume")
                                                                : "the volume \"" + VolumeNodeInput->GetName() + "\"";
  // No point inside throws: an empty reformation would look like a result.
  InputWarning =
    CheckCenterlineVolumeFit(MeasureCenterlineVolumeFit(*Tree, Volume->Image), centerlines, volume, TreeFromExtraction);
  if (!InputWarning.empty())
  {
    Warning(InputWarning, TreeFromExtraction ? std::string() : std::string(ParameterName::CenterlineSpace));
  }
}

void
VesselReformationLogic::Internals::CheckSegmentationAgainstVolume()
{
  SegmentationWarning.clear();
  if (detail::SameGrid(Segmentation->Mask, Volume->Image))
  {
    return;
  }
  const std::string     volumeName = VolumeNodeInput->GetName().empty()
                                       ? std::string("the volume")
                                       : "the volume \"" + VolumeNodeInput->GetName() + "\"";
  itk::Point<double, 3> segmentationLow;
  itk::Point<double, 3> segmentationHigh;
  itk::Point<double, 3> volumeLow;
  itk::Point<double, 3> volumeHigh;
  detail::PhysicalBounds(Segmentation->Mask, segmentationLow, segmentationHigh);
  detail::PhysicalBounds(Volume->Image, volumeLow, volumeHigh);
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    if (segmentationHigh[axis] < volumeLow[axis] || segmentationLow[axis] > volumeHigh[axis])
    {
      throw InputError(SegmentationName() + " (" + detail::DescribeGrid(Segmentation->Mask) + ") does not overlap " +
                       volumeName + " (" + detail::DescribeGrid(Volume->Image) +
                       "); is it the segmentation of this scan?");
    }
  }
  SegmentationWarning = SegmentationName() + " lies on another grid (" + detail::DescribeGrid(Segmentation->Mask) +
                        ") than " + volumeName + " (" + detail::DescribeGrid(Volume->Image) +
                        "); its centerlines are extracted on its own grid, in physical space, and reformed in the "
                        "volume. The reformation continues.";
  Warning(SegmentationWarning, "");
}

void
VesselReformationLogic::Internals::ExtractCenterlines()
{
  Monitor.SetShare(detail::Stage::Extraction, 0.0, 0.0);
  if (!SegmentationNodeInput)
  {
    Outputs.ExtractedCenterlines = nullptr;
    ExtractionWarning.clear();
    return;
  }
  ConfigureCenterlineExtraction(Extraction, Segmentation->Mask, SegmentationName(), ExtractionParameters);
  // The extraction takes a fixed share of the progress bar when it runs; the other stages share the rest.
  Monitor.SetShare(detail::Stage::Extraction, 0.0, detail::WillRun(Extraction->GetOutput()) ? 0.3 : 0.0);
  const unsigned int runsBefore = Monitor.GetRuns(detail::Stage::Extraction);
  try
  {
    Extraction->Update();
  }
  catch (const itk::ExceptionObject & error)
  {
    if (dynamic_cast<const itk::ProcessAborted *>(&error) != nullptr)
    {
      throw Cancelled("centerlines: cancelled");
    }
    throw InputError(SegmentationName() + ": " + detail::CondenseITKMessage(error));
  }
  if (Monitor.IsAbortRequested())
  {
    throw Cancelled("centerlines: cancelled");
  }
  const unsigned int runs = Monitor.GetRuns(detail::Stage::Extraction);
  Outputs.Times.Extraction = runs != runsBefore ? Monitor.GetSeconds(detail::Stage::Extraction) : 0.0;
  if (TreeFromExtraction && TreeExtractionRuns == runs)
  {
    if (VolumeChanged)
    {
      CheckTreeAgainstVolume();
    }
    return;
  }
  auto extracted = std::make_shared<itk::CenterlineTree>(Extraction->GetCenterlineTree());
  NameBranchesByRegion(*extracted, Segmentation->Values.GetPointer(), Segmentation->RegionNames);
  Tree = std::move(extracted);
  TreeFromExtraction = true; // a centerline node set later is taken again
  TreeExtractionRuns = runs;
  const std::string & name = SegmentationNodeInput->GetName();
  Outputs.ExtractedCenterlines =
    ConvertTreeToCenterlineNode(*Tree, (name.empty() ? "segmentation" : name) + " centerlines");
  ExtractionWarning.clear();
  if (Extraction->GetNumberOfComponentsWithoutCenterline() > 0)
  {
    ExtractionWarning = SegmentationName() + ": " +
                        std::to_string(Extraction->GetNumberOfComponentsWithoutCenterline()) + " of its " +
                        std::to_string(Extraction->GetNumberOfComponents()) +
                        " connected components are too small or too round to have a centerline; left out";
    Warning(ExtractionWarning, "");
  }
  CheckTreeAgainstVolume();
}
} // namespace vr
