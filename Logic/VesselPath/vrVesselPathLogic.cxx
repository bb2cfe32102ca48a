// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrVesselPathLogic.h"

#include "itkCPRVolumeSampler.h"
#include "itkCrossSectionStackImageFilter.h"
#include "itkRotationMinimizingFrame.h"
#include "itkStraightenedCPRImageFilter.h"
#include "vrInputError.h"
#include "vrLumenMeasurement.h"

#include <algorithm>
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
  itk::ImageBase<3>::ConstPointer  Volume;
  itk::CPRIntensityRescale         Rescale;
  itk::CenterlineTree              Tree;
  bool                             HasTree{ false };
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
  VesselPathResults        Results;
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
DescribePath(const VesselPathResults & results)
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
}

VesselPathLogic::~VesselPathLogic() = default;

void
VesselPathLogic::SetVolume(const itk::ImageBase<3> * volume, const itk::CPRIntensityRescale & rescale)
{
  m->Volume = volume;
  m->Rescale = rescale;
}

void
VesselPathLogic::SetCenterlineTree(const itk::CenterlineTree & tree)
{
  m->Tree = tree;
  m->HasTree = true;
}

void
VesselPathLogic::SetSegmentationMask(const LabelMapVolumeType * mask, const std::string & name)
{
  m->Mask = mask;
  m->MaskName = name.empty() ? std::string("the segmentation") : name;
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

const VesselPathResults &
VesselPathLogic::GetResults() const
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
  catch (const itk::ExceptionObject & error)
  {
    throw InputError(Describe(error));
  }
  Results.CPR = CPRFilter->GetOutput();
  Results.FoldMask = CPRFilter->GetFoldMask();
  Results.Points = PointImageEnabled ? VesselPathResults::PointImageType::Pointer(CPRFilter->GetPointImage()) : nullptr;
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
    catch (const itk::ExceptionObject & error)
    {
      throw InputError(Describe(error));
    }
    Results.CrossSections = StackFilter->GetOutput();
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

const VesselPathResults &
VesselPathLogic::Update()
{
  if (!m->Volume)
  {
    throw InputError("no volume: the single-vessel reading samples a volume");
  }
  if (!m->HasTree || m->Tree.IsEmpty())
  {
    throw InputError("no centerlines: the single-vessel reading follows a path of the centerline tree");
  }
  const VesselPathParameters & p = m->Parameters;
  const VesselPathParameters & last = m->PathParameters;
  // Stages rerun from the first whose inputs changed; each later stage reruns with it.
  bool rerun = !m->PathValid || m->PathTree != m->Tree || last.BranchId != p.BranchId || last.HasRange != p.HasRange ||
               last.RangeStart != p.RangeStart || last.RangeEnd != p.RangeEnd;
  if (rerun)
  {
    m->FrameValid = m->ResamplingValid = m->MeasurementValid = false;
    m->RunPath();
  }
  const bool viewChanged = last.AutomaticUp != p.AutomaticUp || (!p.AutomaticUp && last.Up != p.Up) ||
                           last.ViewAngleInDegrees != p.ViewAngleInDegrees;
  const bool frameStale = !m->FrameValid || m->FrameSectionSpacing != m->ResolvedSectionSpacing() || viewChanged ||
                          (p.AutomaticUp && m->FrameVolume != ImageStamp::Of(m->Volume.GetPointer()));
  m->PathParameters = p;
  if (frameStale)
  {
    m->ResamplingValid = m->MeasurementValid = false;
    m->RunFrame();
  }
  const VesselPathParameters & sampled = m->ResampledParameters;
  if (!m->ResamplingValid || m->ResampledVolume != ImageStamp::Of(m->Volume.GetPointer()) ||
      m->ResampledRescale != m->Rescale || sampled.Reformation != p.Reformation ||
      sampled.RollInDegrees != p.RollInDegrees || sampled.Width != p.Width || sampled.PixelSpacing != p.PixelSpacing ||
      sampled.Interpolation != p.Interpolation || sampled.SlabThickness != p.SlabThickness ||
      sampled.SlabMode != p.SlabMode || m->ResampledStack != m->CrossSectionsEnabled ||
      m->ResampledPoints != m->PointImageEnabled)
  {
    m->RunResampling();
  }
  if (!m->MeasurementValid || m->MeasuredMask != ImageStamp::Of(m->Mask.GetPointer()) ||
      m->MeasuredReferences != p.ReferencePoints || m->MeasuredMethod != p.ReferenceMethod ||
      m->MeasuredScale != p.GradingScale)
  {
    m->RunMeasurement();
  }

  // Warnings describe the results as they stand.
  auto & warnings = m->Results.Warnings;
  warnings.clear();
  if (m->Results.FoldedPixels > 0)
  {
    warnings.push_back(m->CPRFilter->GetFoldWarning());
  }
  const auto & lumen = m->Results.Lumen;
  if (m->Mask && lumen.SectionsOutsideSegmentation > 0)
  {
    warnings.push_back(std::to_string(lumen.SectionsOutsideSegmentation) + " of " +
                       std::to_string(m->FrameSections.size()) + " cross-section centres lie outside " + m->MaskName +
                       ": no lumen measured there");
  }
  if (m->Mask && lumen.ClippedSections > 0)
  {
    warnings.push_back(std::to_string(lumen.ClippedSections) +
                       " cross-sections' lumen reaches the edge of the measured square: their areas are lower bounds");
  }
  if (!m->Mask && !m->Results.HasLumen)
  {
    warnings.push_back("the lumen is not measured: the centerlines carry no radii and no segmentation was given");
  }
  return m->Results;
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
  const auto & sections = m->Results.Sections;
  if (sections.empty())
  {
    throw InputError("no path: run Update() first");
  }
  // The frame between two sections: their Laterals blended, made normal to the tangent there.
  const double           step = m->Results.SectionSpacing;
  const double           position = std::clamp(s / step, 0.0, static_cast<double>(sections.size() - 1));
  const auto             k = std::min(static_cast<std::size_t>(position), sections.size() - 1);
  const auto             next = std::min(k + 1, sections.size() - 1);
  const double           t = position - static_cast<double>(k);
  itk::VesselPathSection section = sections[k];
  section.ArcLength = std::clamp(s, 0.0, m->Results.Path.GetLength());
  section.Center = m->Results.Path.PointAt(section.ArcLength);
  section.Tangent = m->Results.Path.TangentAt(section.ArcLength);
  section.Radius = m->Results.Path.RadiusAt(section.ArcLength);
  section.BranchId = m->Results.Path.BranchIdAt(section.ArcLength);
  auto lateral = sections[k].Lateral * (1.0 - t) + sections[next].Lateral * t;
  lateral -= section.Tangent * (lateral * section.Tangent);
  lateral.Normalize();
  section.Lateral = lateral;
  section.Up = itk::CrossProduct(section.Tangent, lateral);
  return section;
}
} // namespace vr
