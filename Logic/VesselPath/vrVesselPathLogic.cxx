// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrVesselPathLogic.h"

#include "itkCPRVolumeSampler.h"
#include "itkCrossSectionStackImageFilter.h"
#include "itkImageDuplicator.h"
#include "itkRotationMinimizingFrame.h"
#include "itkStraightenedCPRImageFilter.h"
#include "vrInputError.h"
#include "vrLumenMeasurement.h"
#include "vrStageMonitor.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <limits>
#include <sstream>

namespace vr
{
namespace
{
// The volume in its stored pixel type, whichever it is (docs/design.md "Volumes in their stored type").
using CPRFilterType = itk::StraightenedCPRImageFilter<itk::ImageBase<3>, DepthImageType>;
using StackFilterType = itk::CrossSectionStackImageFilter<itk::ImageBase<3>, VolumeImageType>;

/** What identifies an image's content for the recompute rules: the object, its buffer and its modified time. */
struct ImageStamp
{
  const itk::Object *   Object{ nullptr };
  const void *          Buffer{ nullptr };
  itk::ModifiedTimeType Time{ 0 };

  static ImageStamp
  Of(const itk::ImageBase<3> * image)
  {
    return image ? ImageStamp{ image, BufferOf(image), image->GetMTime() } : ImageStamp{};
  }
  static const void *
  BufferOf(const itk::ImageBase<3> * image)
  {
    return itk::VisitStoredVolume(image,
                                          [](const auto * typed) -> const void * { return typed->GetBufferPointer(); });
  }
  bool
  operator==(const ImageStamp & other) const
  {
    return Object == other.Object && Buffer == other.Buffer && Time == other.Time;
  }
  bool
  operator!=(const ImageStamp & other) const
  {
    return !(*this == other);
  }
};

/** A copy of \a image, buffer and geometry, of its own. */
template<typename TImage>
typename TImage::Pointer
CopyOf(const TImage * image)
{
  auto duplicator = itk::ImageDuplicator<TImage>::New();
  duplicator->SetInputImage(image);
  duplicator->Update();
  return duplicator->GetOutput();
}

std::string
Describe(const itk::ExceptionObject & error)
{
  return error.GetDescription();
}

/** The tree view of \a parameters on \a tree (for the frame's start and the stretch direction). */
itk::CPRViewGeometry
TreeView(const VesselPathParameters & parameters, const itk::CenterlineTree & tree, const itk::ImageBase<3> * volume)
{
  itk::CPRViewSpecification specification;
  specification.AutomaticUp = parameters.AutomaticUp;
  specification.Up = parameters.Up;
  specification.AngleInDegrees = parameters.ViewAngleInDegrees;
  return itk::CPRViewGeometry::Resolve(specification, tree, volume);
}
} // namespace

struct VesselPathLogic::Internals
{
  // The nodes as a host gives them, and their conversion (through the cache) as of the latest Update().
  vtkSmartPointer<VolumeNode>                CurrentVolumeNode;
  vtkSmartPointer<CenterlineNode>            CurrentCenterlineNode;
  vtkSmartPointer<VolumeNode>                CurrentSegmentationNode;
  std::shared_ptr<ReformationInputCache>     Cache = std::make_shared<ReformationInputCache>();
  std::shared_ptr<const itk::CenterlineTree> ConvertedTree;
  ProgressCallback                           Progress;
  WarningCallback                            Warn;
  std::atomic<bool>                          Running{ false };
  std::atomic<bool>                          AbortRequested{ false };

  itk::ImageBase<3>::ConstPointer  Volume;
  itk::CPRIntensityRescale         Rescale;
  itk::CenterlineTree              Tree;
  LabelMapVolumeType::ConstPointer Mask;
  std::string                      MaskName;
  VesselPathParameters             Parameters;
  bool                             CrossSectionsEnabled{ false };
  bool                             PointImageEnabled{ false };

  // What each stage last ran on.
  bool                       PathValid{ false };
  itk::CenterlineTree        PathTree;
  VesselPathParameters       PathParameters;
  bool                       FrameValid{ false };
  ImageStamp                 FrameVolume;
  double                     FrameSectionSpacing{ 0.0 };
  itk::VesselPathSectionList FrameSections;
  itk::CPRViewGeometry       View;
  bool                       ResamplingValid{ false };
  ImageStamp                 ResampledVolume;
  itk::CPRIntensityRescale   ResampledRescale;
  VesselPathParameters       ResampledParameters;
  bool                       ResampledStack{ false };
  bool                       ResampledPoints{ false };
  bool                       MeasurementValid{ false };
  ImageStamp                 MeasuredMask;
  std::vector<double>        MeasuredReferences;
  vr::VesselReferenceMethod  MeasuredMethod{ vr::VesselReferenceMethod::Interpolated };
  StenosisScale              MeasuredScale{ StenosisScale::Automatic };
  /** Whether the range cut the path at its start or its end: such an end is no vessel end. */
  bool CutAtStart{ false };
  bool CutAtEnd{ false };

  CPRFilterType::Pointer   CPRFilter = CPRFilterType::New();
  StackFilterType::Pointer StackFilter = StackFilterType::New();
  VesselPathOutputs        Results;
  VesselPathStageCounts    Counts;

  double
  ResolvedPixelSpacing() const
  {
    if (Parameters.PixelSpacing > 0.0)
    {
      return Parameters.PixelSpacing;
    }
    const auto & spacing = Volume->GetSpacing();
    return std::min({ spacing[0], spacing[1], spacing[2] });
  }
  double
  ResolvedSectionSpacing() const
  {
    return Parameters.SectionSpacing > 0.0 ? Parameters.SectionSpacing : ResolvedPixelSpacing();
  }

  /** The nodes to ITK: the volume in its stored type, the tree, the segmentation's vessel mask. */
  void
  ConvertNodes();
  void
  ReportProgress(double fraction, const char * stage) const
  {
    if (Progress)
    {
      Progress(fraction, stage);
    }
  }
  /** Throws vr::Cancelled when AbortUpdate() was called, naming the stage about to run. */
  void
  StopIfAborted(const char * stage) const
  {
    if (AbortRequested)
    {
      throw Cancelled(std::string(stage) + ": cancelled");
    }
  }
  /** Progress of \a filter mapped to [from, to] of the whole update as \a stage; the abort flag raised from within
   * the filter's own progress report (on its thread, as vr::detail::StageMonitor does for the tree). */
  void
  Watch(itk::ProcessObject * filter, double from, double to, const char * stage)
  {
    detail::ObserveFilterStarts(filter);
    filter->AddObserver(itk::ProgressEvent(),
                        [this, filter, from, to, stage](const itk::EventObject &)
                        {
                          if (AbortRequested && !filter->GetAbortGenerateData())
                          {
                            filter->AbortGenerateDataOn();
                          }
                          ReportProgress(from + (to - from) * filter->GetProgress(), stage);
                        });
  }

  /** Runs the stages whose inputs changed (the recompute rules) and states the warnings. */
  void
  UpdateStages();
  void
  RunPath();
  void
  RunFrame();
  void
  RunResampling();
  void
  RunMeasurement();
};

std::string
DescribePath(const VesselPathOutputs & results)
{
  std::ostringstream text;
  text.setf(std::ios::fixed);
  text.precision(1);
  text << results.Path.GetLength() << " mm: " << results.PathName;
  return text.str();
}

VesselPathLogic::VesselPathLogic()
  : m(std::make_unique<Internals>())
{
  m->Watch(m->CPRFilter, 0.2, 0.5, "resampling");
  m->Watch(m->StackFilter, 0.5, 0.85, "cross-sections");
}

VesselPathLogic::~VesselPathLogic() = default;

void
VesselPathLogic::SetVolumeNode(VolumeNode * node)
{
  m->CurrentVolumeNode = node;
}

VolumeNode *
VesselPathLogic::GetVolumeNode() const
{
  return m->CurrentVolumeNode;
}

void
VesselPathLogic::SetCenterlineNode(CenterlineNode * node)
{
  m->CurrentCenterlineNode = node;
}

CenterlineNode *
VesselPathLogic::GetCenterlineNode() const
{
  return m->CurrentCenterlineNode;
}

void
VesselPathLogic::SetSegmentationNode(VolumeNode * node)
{
  m->CurrentSegmentationNode = node;
}

VolumeNode *
VesselPathLogic::GetSegmentationNode() const
{
  return m->CurrentSegmentationNode;
}

void
VesselPathLogic::SetInputCache(std::shared_ptr<ReformationInputCache> cache)
{
  m->Cache = cache ? std::move(cache) : std::make_shared<ReformationInputCache>();
}

std::shared_ptr<ReformationInputCache>
VesselPathLogic::GetInputCache() const
{
  return m->Cache;
}

void
VesselPathLogic::SetProgressCallback(ProgressCallback callback)
{
  m->Progress = std::move(callback);
}

void
VesselPathLogic::SetWarningCallback(WarningCallback callback)
{
  m->Warn = std::move(callback);
}

void
VesselPathLogic::AbortUpdate()
{
  if (m->Running)
  {
    m->AbortRequested = true;
  }
}

std::vector<std::string>
VesselPathLogic::GetWarnings() const
{
  return m->Results.Warnings;
}

void
VesselPathLogic::Internals::ConvertNodes()
{
  if (!CurrentVolumeNode)
  {
    throw InputError("no volume: the single-vessel reading samples a volume");
  }
  if (!CurrentCenterlineNode)
  {
    throw InputError("no centerlines: the single-vessel reading follows a path of the centerline tree");
  }
  // The cache hands back the same objects while a node is unchanged: the recompute rules compare them.
  const auto volume = Cache->GetVolume(CurrentVolumeNode);
  Volume = volume->Image;
  Rescale = volume->Rescale;
  const auto tree = Cache->GetCenterlines(CurrentCenterlineNode);
  if (tree != ConvertedTree)
  {
    Tree = *tree;
    ConvertedTree = tree;
  }
  if (Tree.IsEmpty())
  {
    throw InputError("no centerlines: the single-vessel reading follows a path of the centerline tree");
  }
  if (CurrentSegmentationNode)
  {
    Mask = Cache->GetSegmentation(CurrentSegmentationNode, {})->Mask;
    MaskName = ReformationInputCache::DescribeSegmentationNode(CurrentSegmentationNode);
  }
  else
  {
    Mask = nullptr;
    MaskName = "the segmentation";
  }
}

void
VesselPathLogic::SetParameters(const VesselPathParameters & parameters)
{
  parameters.Validate();
  m->Parameters = parameters;
}

const VesselPathParameters &
VesselPathLogic::GetParameters() const
{
  return m->Parameters;
}

void
VesselPathLogic::SetCrossSectionsEnabled(bool enabled)
{
  m->CrossSectionsEnabled = enabled;
}

void
VesselPathLogic::SetPointImageEnabled(bool enabled)
{
  m->PointImageEnabled = enabled;
}

const VesselPathOutputs &
VesselPathLogic::GetOutputs() const
{
  return m->Results;
}

const VesselPathStageCounts &
VesselPathLogic::GetStageCounts() const
{
  return m->Counts;
}

void
VesselPathLogic::Internals::RunPath()
{
  const VesselPathParameters & p = Parameters;
  itk::VesselPath              path;
  try
  {
    path = itk::VesselPath::FromTree(Tree, p.BranchId);
  }
  catch (const itk::ExceptionObject & error)
  {
    throw InputError(Describe(error), p.BranchId > 0 ? ParameterName::Branch : "");
  }
  CutAtStart = CutAtEnd = false;
  if (p.HasRange)
  {
    CutAtStart = p.RangeStart > 0.0;
    CutAtEnd = p.RangeEnd < path.GetLength();
    if (p.RangeEnd > path.GetLength())
    {
      std::ostringstream message;
      message << "path range = " << p.RangeStart << "," << p.RangeEnd << " mm: the path is " << path.GetLength()
              << " mm long";
      throw InputError(message.str(), ParameterName::PathRange);
    }
    try
    {
      path = path.Cut(p.RangeStart, p.RangeEnd);
    }
    catch (const itk::ExceptionObject & error)
    {
      throw InputError(Describe(error), ParameterName::PathRange);
    }
  }
  Results.Path = path;
  std::vector<std::string> names;
  for (const int id : path.GetBranchChain())
  {
    std::string name = "branch " + std::to_string(id);
    for (const auto & branch : Tree.GetBranches())
    {
      if (branch.Id == id && !branch.Name.empty())
      {
        name = branch.Name;
      }
    }
    names.push_back(name);
  }
  Results.PathName = JoinPathNames(names);
  Results.Layout = FindPathLayout(Tree, path, CutAtStart, CutAtEnd);
  PathTree = Tree;
  PathParameters = p;
  PathValid = true;
  ++Counts.Path;
}

void
VesselPathLogic::Internals::RunFrame()
{
  const double step = ResolvedSectionSpacing();
  if (Results.Path.GetLength() < step)
  {
    std::ostringstream message;
    message << "section spacing = " << step << " mm: the path is only " << Results.Path.GetLength()
            << " mm long, shorter than one section";
    throw InputError(message.str(), ParameterName::SectionSpacing);
  }
  View = TreeView(Parameters, Tree, Volume);
  try
  {
    FrameSections = itk::RotationMinimizingFrame::Compute(Results.Path, step, View, 0.0);
  }
  catch (const itk::ExceptionObject & error)
  {
    throw InputError(Describe(error), ParameterName::SectionSpacing);
  }
  FrameVolume = ImageStamp::Of(Volume.GetPointer());
  FrameSectionSpacing = step;
  FrameValid = true;
  ++Counts.Frame;
}

void
VesselPathLogic::Internals::RunResampling()
{
  const VesselPathParameters & p = Parameters;
  const double                 spacing = ResolvedPixelSpacing();
  if (Results.Path.GetLength() < spacing)
  {
    std::ostringstream message;
    message << "pixel spacing = " << spacing << " mm: the path is only " << Results.Path.GetLength()
            << " mm long, shorter than one row";
    throw InputError(message.str(), ParameterName::PixelSpacing);
  }
  CPRFilter->SetVolume(Volume);
  CPRFilter->SetIntensityRescale(Rescale);
  CPRFilter->SetPath(Results.Path);
  CPRFilter->SetView(View);
  CPRFilter->SetMode(p.Reformation == PathReformation::Stretched ? itk::VesselPathCPRMode::Stretched
                                                                 : itk::VesselPathCPRMode::Straightened);
  CPRFilter->SetRollAngle(p.RollInDegrees);
  CPRFilter->SetWidth(p.Width);
  CPRFilter->SetPixelSpacing(spacing);
  CPRFilter->SetInterpolation(p.Interpolation);
  CPRFilter->SetSlabThickness(p.SlabThickness);
  CPRFilter->SetSlabMode(p.SlabMode);
  CPRFilter->SetComputePointImage(PointImageEnabled);
  try
  {
    // The largest region: a narrower width than the last run's must not keep the last requested region.
    CPRFilter->UpdateLargestPossibleRegion();
  }
  catch (const itk::ProcessAborted &)
  {
    throw Cancelled("resampling: cancelled");
  }
  catch (const itk::ExceptionObject & error)
  {
    throw InputError(Describe(error));
  }
  // Taken out of the pipeline: the next run makes new images, and the ones handed out stay as they are (the filter's
  // further outputs, which ITK cannot disconnect from it, copied: each is the CPR's size).
  Results.CPR = CPRFilter->GetOutput();
  Results.CPR->DisconnectPipeline();
  Results.FoldMask = CPRFilter->GetFoldMask();
  Results.FoldMask = CopyOf(Results.FoldMask.GetPointer());
  Results.Points = PointImageEnabled ? VesselPathOutputs::PointImageType::Pointer(CPRFilter->GetPointImage()) : nullptr;
  if (Results.Points)
  {
    Results.Points = CopyOf(Results.Points.GetPointer());
  }
  Results.FoldedPixels = CPRFilter->GetNumberOfFoldedPixels();
  Results.FoldFreeHalfWidth = CPRFilter->GetFoldFreeHalfWidth();
  Results.PixelSpacing = spacing;

  // The sections turned by the roll: the cross-sections' u axis is the CPR's x axis.
  Results.Sections = FrameSections;
  itk::RotationMinimizingFrame::Roll(Results.Sections, p.RollInDegrees);
  Results.SectionSpacing = FrameSectionSpacing;
  if (CrossSectionsEnabled)
  {
    // Square sections as wide as the CPR, at its pixel spacing: plane k is the section of the CPR's row k.
    const auto                       side = static_cast<itk::SizeValueType>(std::lround(p.Width / spacing)) | 1u;
    StackFilterType::SectionSizeType size;
    size.Fill(side);
    StackFilterType::SectionSpacingType sectionPixel;
    sectionPixel.Fill(spacing);
    StackFilter->SetVolume(Volume);
    StackFilter->SetIntensityRescale(Rescale);
    StackFilter->SetPath(Results.Path);
    StackFilter->SetView(View);
    StackFilter->SetRollAngle(p.RollInDegrees);
    StackFilter->SetSectionStep(FrameSectionSpacing);
    StackFilter->SetSectionSize(size);
    StackFilter->SetSectionSpacing(sectionPixel);
    StackFilter->SetInterpolation(p.Interpolation);
    StackFilter->SetSlabThickness(p.SlabThickness);
    StackFilter->SetSlabMode(p.SlabMode);
    try
    {
      StackFilter->UpdateLargestPossibleRegion();
    }
    catch (const itk::ProcessAborted &)
    {
      throw Cancelled("cross-sections: cancelled");
    }
    catch (const itk::ExceptionObject & error)
    {
      throw InputError(Describe(error));
    }
    Results.CrossSections = StackFilter->GetOutput();
    Results.CrossSections->DisconnectPipeline();
  }
  else
  {
    Results.CrossSections = nullptr;
  }
  ResampledVolume = ImageStamp::Of(Volume.GetPointer());
  ResampledRescale = Rescale;
  ResampledParameters = p;
  ResampledStack = CrossSectionsEnabled;
  ResampledPoints = PointImageEnabled;
  ResamplingValid = true;
  ++Counts.Resampling;
}

void
VesselPathLogic::Internals::RunMeasurement()
{
  // Invalid until it succeeds: a refused segmentation must not leave the cleared lumen standing as measured.
  MeasurementValid = false;
  Results.HasLumen = false;
  Results.Lumen = itk::VesselLumenProfile();
  Results.Stenosis = vr::VesselStenosisSummary();
  if (Mask || Results.Path.HasRadii())
  {
    LumenMeasurementParameters measurement;
    measurement.ReferenceArcLengths = Parameters.ReferencePoints;
    measurement.ReferenceMethod = Parameters.ReferenceMethod;
    measurement.Layout = Results.Layout;
    measurement.Scale = Parameters.GradingScale;
    LumenMeasurement lumen = MeasureLumen(FrameSections, Mask, MaskName, measurement);
    Results.Lumen = std::move(lumen.Profile);
    Results.Stenosis = lumen.Summary;
    Results.HasLumen = true;
  }
  else if (!Parameters.ReferencePoints.empty())
  {
    throw InputError("reference points given, but the lumen is not measured: the centerlines carry no radii and no "
                     "segmentation was given",
                     ParameterName::ReferencePoints);
  }
  MeasuredMask = ImageStamp::Of(Mask.GetPointer());
  MeasuredReferences = Parameters.ReferencePoints;
  MeasuredMethod = Parameters.ReferenceMethod;
  MeasuredScale = Parameters.GradingScale;
  MeasurementValid = true;
  ++Counts.Measurement;
}

const VesselPathOutputs &
VesselPathLogic::Update()
{
  m->AbortRequested = false;
  m->Running = true;
  struct Finish
  {
    Internals * Logic;
    ~Finish()
    {
      // The next Update() runs normally, whatever stopped this one.
      Logic->CPRFilter->AbortGenerateDataOff();
      Logic->StackFilter->AbortGenerateDataOff();
      Logic->Running = false;
      Logic->AbortRequested = false;
    }
  } finish{ m.get() };
  m->ReportProgress(0.0, "conversion");
  m->ConvertNodes();
  m->UpdateStages();
  if (m->Warn)
  {
    for (const auto & warning : m->Results.Warnings)
    {
      m->Warn(warning, "");
    }
  }
  m->ReportProgress(1.0, "measurement");
  return m->Results;
}

void
VesselPathLogic::Internals::UpdateStages()
{
  const VesselPathParameters & p = Parameters;
  const VesselPathParameters & last = PathParameters;
  // Stages rerun from the first whose inputs changed; each later stage reruns with it.
  bool rerun = !PathValid || PathTree != Tree || last.BranchId != p.BranchId || last.HasRange != p.HasRange ||
               last.RangeStart != p.RangeStart || last.RangeEnd != p.RangeEnd;
  if (rerun)
  {
    FrameValid = ResamplingValid = MeasurementValid = false;
    StopIfAborted("path");
    ReportProgress(0.05, "path");
    RunPath();
  }
  const bool viewChanged = last.AutomaticUp != p.AutomaticUp || (!p.AutomaticUp && last.Up != p.Up) ||
                           last.ViewAngleInDegrees != p.ViewAngleInDegrees;
  const bool frameStale = !FrameValid || FrameSectionSpacing != ResolvedSectionSpacing() || viewChanged ||
                          (p.AutomaticUp && FrameVolume != ImageStamp::Of(Volume.GetPointer()));
  PathParameters = p;
  if (frameStale)
  {
    ResamplingValid = MeasurementValid = false;
    StopIfAborted("frame");
    ReportProgress(0.1, "frame");
    RunFrame();
  }
  const VesselPathParameters & sampled = ResampledParameters;
  if (!ResamplingValid || ResampledVolume != ImageStamp::Of(Volume.GetPointer()) || ResampledRescale != Rescale ||
      sampled.Reformation != p.Reformation || sampled.RollInDegrees != p.RollInDegrees || sampled.Width != p.Width ||
      sampled.PixelSpacing != p.PixelSpacing || sampled.Interpolation != p.Interpolation ||
      sampled.SlabThickness != p.SlabThickness || sampled.SlabMode != p.SlabMode ||
      ResampledStack != CrossSectionsEnabled || ResampledPoints != PointImageEnabled)
  {
    StopIfAborted("resampling");
    RunResampling();
  }
  if (!MeasurementValid || MeasuredMask != ImageStamp::Of(Mask.GetPointer()) ||
      MeasuredReferences != p.ReferencePoints || MeasuredMethod != p.ReferenceMethod || MeasuredScale != p.GradingScale)
  {
    StopIfAborted("measurement");
    ReportProgress(0.85, "measurement");
    RunMeasurement();
  }

  // Warnings describe the results as they stand.
  auto & warnings = Results.Warnings;
  warnings.clear();
  if (Results.FoldedPixels > 0)
  {
    warnings.push_back(CPRFilter->GetFoldWarning());
  }
  const auto & lumen = Results.Lumen;
  if (Mask && lumen.SectionsOutsideSegmentation > 0)
  {
    warnings.push_back(std::to_string(lumen.SectionsOutsideSegmentation) + " of " +
                       std::to_string(FrameSections.size()) + " cross-section centres lie outside " + MaskName +
                       ": no lumen measured there");
  }
  if (Mask && lumen.ClippedSections > 0)
  {
    warnings.push_back(std::to_string(lumen.ClippedSections) +
                       " cross-sections' lumen reaches the edge of the measured square: their areas are lower bounds");
  }
  if (!Mask && !Results.HasLumen)
  {
    warnings.push_back("the lumen is not measured: the centerlines carry no radii and no segmentation was given");
  }
}

itk::Point<double, 3>
VesselPathLogic::ComputePoint(double column, double row) const
{
  return m->CPRFilter->ComputePoint(column, row);
}

double
VesselPathLogic::RowOfArcLength(double s) const
{
  return m->CPRFilter->RowOfArcLength(s);
}

itk::VesselPathSection
VesselPathLogic::SectionAt(double s) const
{
  return vr::SectionAt(m->Results, s);
}

itk::VesselPathSection
SectionAt(const VesselPathOutputs & outputs, double s)
{
  const auto & sections = outputs.Sections;
  if (sections.empty())
  {
    throw InputError("no path: run Update() first");
  }
  // The frame between two sections: their Laterals blended, made normal to the tangent there.
  const double           step = outputs.SectionSpacing;
  const double           position = std::clamp(s / step, 0.0, static_cast<double>(sections.size() - 1));
  const auto             k = std::min(static_cast<std::size_t>(position), sections.size() - 1);
  const auto             next = std::min(k + 1, sections.size() - 1);
  const double           t = position - static_cast<double>(k);
  itk::VesselPathSection section = sections[k];
  section.ArcLength = std::clamp(s, 0.0, outputs.Path.GetLength());
  section.Center = outputs.Path.PointAt(section.ArcLength);
  section.Tangent = outputs.Path.TangentAt(section.ArcLength);
  section.Radius = outputs.Path.RadiusAt(section.ArcLength);
  section.BranchId = outputs.Path.BranchIdAt(section.ArcLength);
  auto lateral = sections[k].Lateral * (1.0 - t) + sections[next].Lateral * t;
  lateral -= section.Tangent * (lateral * section.Tangent);
  lateral.Normalize();
  section.Lateral = lateral;
  section.Up = itk::CrossProduct(section.Tangent, lateral);
  return section;
}
} // namespace vr
