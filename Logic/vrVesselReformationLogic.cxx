// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrVesselReformationLogic.h"

#include "itkBilateralDepthRelaxFilter.h"
#include "itkCPRDepthImageFilter.h"
#include "itkCPRResampleImageFilter.h"
#include "itkMinimumMaximumImageCalculator.h"
#include "vrCutSurface.h"
#include "vrInputError.h"
#include "vrNodeConversion.h"

#include <vtkPolyData.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <unistd.h>

namespace vr
{
namespace
{
using DepthFilterType = itk::CPRDepthImageFilter<DepthImageType>;
using ResampleFilterType = itk::CPRResampleImageFilter<VolumeImageType, DepthImageType, DepthImageType>;
using Clock = std::chrono::steady_clock;

double
SecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string
Gibibytes(double bytes)
{
  std::ostringstream text;
  text << std::setprecision(3) << bytes / (1024.0 * 1024.0 * 1024.0) << " GiB";
  return text.str();
}

/** The parameters that decide the depth map (and so everything after it). */
bool
SameDepthParameters(const ReformationParameters & a, const ReformationParameters & b)
{
  return a.AutomaticUp == b.AutomaticUp && (a.AutomaticUp || a.Up == b.Up) && a.AngleInDegrees == b.AngleInDegrees &&
         a.HasCenter == b.HasCenter && (!a.HasCenter || a.Center == b.Center) && a.ImageSize == b.ImageSize &&
         a.PixelSpacing == b.PixelSpacing && a.Mode == b.Mode && a.FixLumen == b.FixLumen;
}

bool
SameBackend(const ReformationParameters & a, const ReformationParameters & b)
{
  return a.Backend == b.Backend && a.OpenCLDevice == b.OpenCLDevice;
}

bool
SameRelaxParameters(const ReformationParameters & a, const ReformationParameters & b)
{
  return a.Relaxation == b.Relaxation && a.Anisotropy == b.Anisotropy && a.Iterations == b.Iterations &&
         SameBackend(a, b);
}

bool
SameResampleParameters(const ReformationParameters & a, const ReformationParameters & b)
{
  return a.Interpolation == b.Interpolation && a.SlabThickness == b.SlabThickness && a.SlabMode == b.SlabMode;
}

/** Turns a filter's itk::ExceptionObject into the one error type the logic reports. */
[[noreturn]] void
RethrowAsInputError(const std::string & stage, const itk::ExceptionObject & error)
{
  throw InputError(stage + ": " + error.GetDescription());
}

/** Sets w, a, N on \a filter and runs it on \a depth with \a mask, reporting progress in [from, to]. */
DepthImageType::Pointer
RunRelaxFilter(RelaxFilterType *                                filter,
               const DepthImageType *                           depth,
               const MaskImageType *                            mask,
               const ReformationParameters &                    parameters,
               const VesselReformationLogic::ProgressCallback & progress,
               double                                           from,
               double                                           to)
{
  filter->SetInput(depth);
  filter->SetFixedMask(mask);
  filter->SetRelaxation(parameters.Relaxation);
  filter->SetAnisotropy(parameters.Anisotropy);
  filter->SetNumberOfIterations(static_cast<unsigned int>(parameters.Iterations));
  filter->Modified(); // rerun even when a previous run of the same settings failed
  unsigned long observer = 0;
  if (progress)
  {
    observer = filter->AddObserver(itk::ProgressEvent(),
                                   [filter, &progress, from, to](const itk::EventObject &)
                                   { progress(from + (to - from) * filter->GetProgress(), "relax"); });
  }
  try
  {
    filter->Update();
  }
  catch (const itk::ExceptionObject & error)
  {
    if (progress)
    {
      filter->RemoveObserver(observer);
    }
    RethrowAsInputError("relaxation", error);
  }
  if (progress)
  {
    filter->RemoveObserver(observer);
  }
  DepthImageType::Pointer relaxed = filter->GetOutput();
  relaxed->DisconnectPipeline();
  return relaxed;
}
} // namespace

struct VesselReformationLogic::Internals
{
  vtkSmartPointer<VolumeNode>     VolumeNodeInput;
  vtkSmartPointer<CenterlineNode> CenterlineNodeInput;
  ReformationParameters           Parameters;
  bool                            SurfaceEnabled{ true };
  ProgressCallback                Progress;
  WarningCallback                 Warn;

  // What the current results were made from.
  VolumeNode *          ConvertedVolumeNode{ nullptr };
  vtkMTimeType          ConvertedVolumeTime{ 0 };
  CenterlineNode *      ConvertedCenterlineNode{ nullptr };
  vtkMTimeType          ConvertedCenterlineTime{ 0 };
  ReformationParameters LastParameters;
  bool                  HasRun{ false };

  // Stage results and their validity.
  VolumeImageType::Pointer Volume;
  float                    VolumeMinimum{ 0.0f };
  itk::CenterlineTree      Tree;
  itk::CPRViewGeometry     View;
  DepthImageType::Pointer  Depth;
  MaskImageType::Pointer   Mask;
  LabelImageType::Pointer  Labels;
  DepthImageType::Pointer  Relaxed;
  DepthImageType::Pointer  UnfilteredCPR;
  DepthImageType::Pointer  CPR;
  RelaxFilterType::Pointer RelaxFilter;
  RelaxBackend             RelaxFilterBackend{ RelaxBackend::Auto };
  std::string              RelaxFilterDevice;
  bool                     DepthValid{ false };
  bool                     RelaxValid{ false };
  bool                     UnfilteredValid{ false };
  bool                     RelaxedCPRValid{ false };
  bool                     SurfaceValid{ false };

  std::string InputWarning;
  std::string BackendNotice;

  ReformationOutputs Outputs;
  StageCounts        Counts;

  void
  Warning(const std::string & message)
  {
    if (Warn && !message.empty())
    {
      Warn(message);
    }
  }

  void
  InvalidateFromDepth()
  {
    DepthValid = false;
    InvalidateFromRelax();
    UnfilteredValid = false;
  }
  void
  InvalidateFromRelax()
  {
    RelaxValid = false;
    RelaxedCPRValid = false;
    SurfaceValid = false;
  }
  void
  InvalidateResample()
  {
    UnfilteredValid = false;
    RelaxedCPRValid = false;
    SurfaceValid = false;
  }

  void
  ConvertInputs();
  void
  CheckMemory(const itk::CPRViewGeometry & view) const;
  void
  RunDepth(double from, double to);
  void
  RunRelax(double from, double to);
  void
  RunResample(double from, double to);
  void
  RunSurface();
};

void
VesselReformationLogic::Internals::ConvertInputs()
{
  const auto         start = Clock::now();
  const vtkMTimeType volumeTime = VolumeNodeInput->GetMTime();
  const vtkMTimeType centerlineTime = CenterlineNodeInput->GetMTime();
  const bool volumeChanged = VolumeNodeInput.GetPointer() != ConvertedVolumeNode || volumeTime != ConvertedVolumeTime;
  const bool centerlinesChanged =
    CenterlineNodeInput.GetPointer() != ConvertedCenterlineNode || centerlineTime != ConvertedCenterlineTime;
  if (!volumeChanged && !centerlinesChanged)
  {
    return;
  }
  InvalidateFromDepth();
  if (volumeChanged)
  {
    ConvertedVolumeNode = nullptr;
    Volume = ConvertVolumeNodeToItkImage(VolumeNodeInput);
    auto calculator = itk::MinimumMaximumImageCalculator<VolumeImageType>::New();
    calculator->SetImage(Volume);
    calculator->ComputeMinimum();
    VolumeMinimum = calculator->GetMinimum();
    ConvertedVolumeNode = VolumeNodeInput;
    ConvertedVolumeTime = volumeTime;
  }
  if (centerlinesChanged)
  {
    ConvertedCenterlineNode = nullptr;
    Tree = ConvertCenterlineNodeToTree(CenterlineNodeInput);
    ConvertedCenterlineNode = CenterlineNodeInput;
    ConvertedCenterlineTime = centerlineTime;
  }
  ++Counts.Conversion;

  InputWarning.clear();
  const double outside = FractionOfPointsOutside(Tree, Volume);
  if (outside > 0.5)
  {
    std::ostringstream message;
    message << "centerlines";
    if (!CenterlineNodeInput->GetName().empty())
    {
      message << " \"" << CenterlineNodeInput->GetName() << "\"";
    }
    message << ": " << std::lround(100.0 * outside) << "% of the " << Tree.GetNumberOfPoints()
            << " points lie outside the volume";
    if (!VolumeNodeInput->GetName().empty())
    {
      message << " \"" << VolumeNodeInput->GetName() << "\"";
    }
    message << "; they may be in the other coordinate system (RAS vs LPS): check --centerlineSpace (RAS or LPS). "
               "The reformation continues.";
    InputWarning = message.str();
    Warning(InputWarning);
  }
  Outputs.Times.Conversion = SecondsSince(start);
}

void
VesselReformationLogic::Internals::CheckMemory(const itk::CPRViewGeometry & view) const
{
  const auto &       size = view.GetSize();
  std::ostringstream origin;
  if (Parameters.ImageSize[0] > 0)
  {
    origin << "size (--size) = " << size[0] << "," << size[1];
  }
  else
  {
    origin << "the view of " << size[0] << " x " << size[1] << " pixels (spacing " << view.GetSpacing()[0] << ","
           << view.GetSpacing()[1] << " mm, --spacing)";
  }
  if (size[0] > static_cast<itk::SizeValueType>(INT_MAX) || size[1] > static_cast<itk::SizeValueType>(INT_MAX))
  {
    throw InputError(origin.str() + ": at most " + std::to_string(INT_MAX) + " pixels per side are supported");
  }
  const double needed = EstimateMemoryInBytes(size);
  const double available = AvailableMemoryInBytes();
  if (needed > available)
  {
    throw InputError(origin.str() + ": the images would need about " + Gibibytes(needed) + ", more than the " +
                     Gibibytes(available) + " of memory available; choose a smaller --size or a larger --spacing");
  }
}

void
VesselReformationLogic::Internals::RunDepth(double from, double to)
{
  const auto                      start = Clock::now();
  const itk::CPRViewSpecification specification = Parameters.ToViewSpecification();
  try
  {
    CheckMemory(itk::CPRViewGeometry::Resolve(specification, Tree, Volume));
  }
  catch (const itk::ExceptionObject & error)
  {
    // The view's size follows from the spacing when only that was given: name it (e.g. a spacing of 1e-300 mm).
    std::ostringstream stage;
    stage << "view";
    if (Parameters.PixelSpacing[0] > 0.0 && Parameters.ImageSize[0] == 0)
    {
      stage << " at spacing (--spacing) " << Parameters.PixelSpacing[0] << "," << Parameters.PixelSpacing[1] << " mm";
    }
    RethrowAsInputError(stage.str(), error);
  }
  auto filter = DepthFilterType::New();
  filter->SetCenterlineTree(Tree);
  filter->SetViewSpecification(specification);
  filter->SetReferenceVolume(Volume);
  filter->SetMode(Parameters.Mode);
  filter->SetFixLumen(Parameters.FixLumen);
  if (Progress)
  {
    DepthFilterType * raw = filter;
    filter->AddObserver(itk::ProgressEvent(),
                        [raw, this, from, to](const itk::EventObject &)
                        { Progress(from + (to - from) * raw->GetProgress(), "depth"); });
  }
  try
  {
    filter->Update();
  }
  catch (const itk::ExceptionObject & error)
  {
    RethrowAsInputError("depth", error);
  }
  View = filter->GetView();
  Depth = filter->GetDepthOutput();
  Mask = filter->GetFixedMaskOutput();
  Labels = filter->GetOwnerLabelOutput();
  Depth->DisconnectPipeline();
  Mask->DisconnectPipeline();
  Labels->DisconnectPipeline();
  Outputs.View = View;
  Outputs.Depth = ConvertItkImageToVolumeNode(Depth.GetPointer(), "Depth");
  Outputs.FixedMask = ConvertItkImageToVolumeNode(Mask.GetPointer(), "Fixed mask");
  Outputs.OwnerLabels = ConvertItkImageToVolumeNode(Labels.GetPointer(), "Owner labels");
  DepthValid = true;
  ++Counts.Depth;
  Outputs.Times.Depth = SecondsSince(start);
}

void
VesselReformationLogic::Internals::RunRelax(double from, double to)
{
  const auto start = Clock::now();
  if (!RelaxFilter || RelaxFilterBackend != Parameters.Backend || RelaxFilterDevice != Parameters.OpenCLDevice)
  {
    RelaxFilter = nullptr;
    std::string  notice;
    RelaxBackend chosen = RelaxBackend::CPU;
    RelaxFilter = CreateRelaxFilter(Parameters.Backend, Parameters.OpenCLDevice, notice, &chosen);
    RelaxFilterBackend = Parameters.Backend;
    RelaxFilterDevice = Parameters.OpenCLDevice;
    Outputs.RelaxBackendUsed = ToString(chosen);
    BackendNotice = notice;
    Warning(BackendNotice);
  }
  Relaxed = RunRelaxFilter(RelaxFilter, Depth, Mask, Parameters, Progress, from, to);
  Outputs.RelaxedDepth = ConvertItkImageToVolumeNode(Relaxed.GetPointer(), "Relaxed depth");
  RelaxValid = true;
  ++Counts.Relax;
  Outputs.Times.Relax = SecondsSince(start);
}

void
VesselReformationLogic::Internals::RunResample(double from, double to)
{
  const auto start = Clock::now();
  const int  images = (UnfilteredValid ? 0 : 1) + (RelaxedCPRValid ? 0 : 1);
  int        done = 0;
  const auto sample = [&](const DepthImageType * depth)
  {
    auto filter = ResampleFilterType::New();
    filter->SetVolume(Volume);
    filter->SetDepth(depth);
    filter->SetView(View);
    filter->SetInterpolation(Parameters.Interpolation);
    filter->SetSlabThickness(Parameters.SlabThickness);
    filter->SetSlabMode(Parameters.SlabMode);
    filter->SetDefaultValue(VolumeMinimum);
    const double imageFrom = from + (to - from) * done / images;
    const double imageTo = from + (to - from) * (done + 1) / images;
    if (Progress)
    {
      ResampleFilterType * raw = filter;
      filter->AddObserver(itk::ProgressEvent(),
                          [raw, this, imageFrom, imageTo](const itk::EventObject &)
                          { Progress(imageFrom + (imageTo - imageFrom) * raw->GetProgress(), "resample"); });
    }
    try
    {
      filter->Update();
    }
    catch (const itk::ExceptionObject & error)
    {
      RethrowAsInputError("resample", error);
    }
    DepthImageType::Pointer image = filter->GetOutput();
    image->DisconnectPipeline();
    ++done;
    return image;
  };
  if (!UnfilteredValid)
  {
    UnfilteredCPR = sample(Depth);
    Outputs.UnfilteredCPR = ConvertItkImageToVolumeNode(UnfilteredCPR.GetPointer(), "CPR (unfiltered)");
    UnfilteredValid = true;
    ++Counts.UnfilteredSamplings;
  }
  if (!RelaxedCPRValid)
  {
    CPR = sample(Relaxed);
    Outputs.CPR = ConvertItkImageToVolumeNode(CPR.GetPointer(), "CPR");
    RelaxedCPRValid = true;
    ++Counts.RelaxedSamplings;
  }
  ++Counts.Resample;
  Outputs.Times.Resample = SecondsSince(start);
}

void
VesselReformationLogic::Internals::RunSurface()
{
  const auto start = Clock::now();
  Outputs.Surface = BuildCutSurface(Relaxed, CPR, View, DefaultMaximumBridgedDepthJump(View));
  SurfaceValid = true;
  ++Counts.Surface;
  Outputs.Times.Surface = SecondsSince(start);
}

VesselReformationLogic::VesselReformationLogic()
  : m_Internals(std::make_unique<Internals>())
{
}

VesselReformationLogic::~VesselReformationLogic() = default;

void
VesselReformationLogic::SetVolumeNode(VolumeNode * node)
{
  m_Internals->VolumeNodeInput = node;
}

VolumeNode *
VesselReformationLogic::GetVolumeNode() const
{
  return m_Internals->VolumeNodeInput;
}

void
VesselReformationLogic::SetCenterlineNode(CenterlineNode * node)
{
  m_Internals->CenterlineNodeInput = node;
}

CenterlineNode *
VesselReformationLogic::GetCenterlineNode() const
{
  return m_Internals->CenterlineNodeInput;
}

void
VesselReformationLogic::SetParameters(const ReformationParameters & parameters)
{
  m_Internals->Parameters = parameters;
}

const ReformationParameters &
VesselReformationLogic::GetParameters() const
{
  return m_Internals->Parameters;
}

void
VesselReformationLogic::SetSurfaceEnabled(bool enabled)
{
  m_Internals->SurfaceEnabled = enabled;
}

bool
VesselReformationLogic::GetSurfaceEnabled() const
{
  return m_Internals->SurfaceEnabled;
}

void
VesselReformationLogic::SetProgressCallback(ProgressCallback callback)
{
  m_Internals->Progress = std::move(callback);
}

void
VesselReformationLogic::SetWarningCallback(WarningCallback callback)
{
  m_Internals->Warn = std::move(callback);
}

const ReformationOutputs &
VesselReformationLogic::Update()
{
  Internals & d = *m_Internals;
  d.Parameters.Validate();
  if (!d.VolumeNodeInput)
  {
    throw InputError("vessel reformation: no volume node is set");
  }
  if (!d.CenterlineNodeInput)
  {
    throw InputError("vessel reformation: no centerline node is set");
  }
  d.Outputs.Times = StageTimes();
  d.ConvertInputs();

  if (d.HasRun)
  {
    if (!SameDepthParameters(d.Parameters, d.LastParameters))
    {
      d.InvalidateFromDepth();
    }
    if (!SameRelaxParameters(d.Parameters, d.LastParameters))
    {
      d.InvalidateFromRelax();
    }
    if (!SameResampleParameters(d.Parameters, d.LastParameters))
    {
      d.InvalidateResample();
    }
  }
  d.LastParameters = d.Parameters;
  d.HasRun = true;

  // Progress weights of the stages this update runs: relaxation dominates unless N is small.
  const double relaxWeight = 0.05 + 0.6 * std::min(1.0, static_cast<double>(d.Parameters.Iterations) / 100.0);
  const bool   runSurface = d.SurfaceEnabled && !d.SurfaceValid;
  const double weights[4] = { d.DepthValid ? 0.0 : 0.1,
                              d.RelaxValid ? 0.0 : relaxWeight,
                              (d.UnfilteredValid ? 0.0 : 0.1) + (d.RelaxedCPRValid ? 0.0 : 0.1),
                              runSurface ? 0.1 : 0.0 };
  const double total = weights[0] + weights[1] + weights[2] + weights[3];
  double       bounds[5] = { 0.0 };
  for (int k = 0; k < 4; ++k)
  {
    bounds[k + 1] = bounds[k] + (total > 0.0 ? weights[k] / total : 0.0);
  }

  if (!d.DepthValid)
  {
    d.RunDepth(bounds[0], bounds[1]);
  }
  if (!d.RelaxValid)
  {
    d.RunRelax(bounds[1], bounds[2]);
  }
  if (!d.UnfilteredValid || !d.RelaxedCPRValid)
  {
    d.RunResample(bounds[2], bounds[3]);
  }
  if (runSurface)
  {
    d.RunSurface();
  }
  if (!d.SurfaceEnabled)
  {
    d.Outputs.Surface = nullptr;
    d.SurfaceValid = false;
  }
  if (d.Progress)
  {
    d.Progress(1.0, "done");
  }
  return d.Outputs;
}

const ReformationOutputs &
VesselReformationLogic::GetOutputs() const
{
  return m_Internals->Outputs;
}

StageCounts
VesselReformationLogic::GetStageExecutionCounts() const
{
  return m_Internals->Counts;
}

std::vector<std::string>
VesselReformationLogic::GetWarnings() const
{
  std::vector<std::string> warnings;
  for (const std::string * warning : { &m_Internals->InputWarning, &m_Internals->BackendNotice })
  {
    if (!warning->empty())
    {
      warnings.push_back(*warning);
    }
  }
  return warnings;
}

void
VesselReformationLogic::GetDisplayWindowLevel(double & window, double & level) const
{
  const ReformationParameters & parameters = m_Internals->Parameters;
  if (parameters.Window > 0.0)
  {
    window = parameters.Window;
    level = parameters.Level;
    return;
  }
  const DepthImageType * cpr = m_Internals->CPR;
  if (cpr == nullptr)
  {
    window = 1.0;
    level = parameters.Level;
    return;
  }
  const auto  count = cpr->GetBufferedRegion().GetNumberOfPixels();
  const auto  range = std::minmax_element(cpr->GetBufferPointer(), cpr->GetBufferPointer() + count);
  const float low = *range.first;
  const float high = *range.second;
  window = high > low ? static_cast<double>(high) - low : 1.0;
  level = 0.5 * (static_cast<double>(high) + low);
}

DepthImageType::Pointer
VesselReformationLogic::RelaxDepthImage(const DepthImageType *        depth,
                                        const MaskImageType *         mask,
                                        const ReformationParameters & parameters,
                                        const ProgressCallback &      progress,
                                        std::vector<std::string> &    warnings)
{
  parameters.Validate();
  if (depth == nullptr)
  {
    throw InputError("relaxation: no depth image given");
  }
  std::string notice;
  auto        filter = CreateRelaxFilter(parameters.Backend, parameters.OpenCLDevice, notice);
  if (!notice.empty())
  {
    warnings.push_back(notice);
  }
  auto relaxed = RunRelaxFilter(filter, depth, mask, parameters, progress, 0.0, 1.0);
  if (progress)
  {
    progress(1.0, "done");
  }
  return relaxed;
}

double
VesselReformationLogic::EstimateMemoryInBytes(const itk::Size<2> & size)
{
  // Per pixel: centerline raster 20 B, depth assignment 9, depth filter outputs 9, relaxation output and its
  // Jacobi buffer 8, two CPR images 8, six output nodes 21, surface points, scalars and two triangles 84.
  return BytesPerViewPixel * static_cast<double>(size[0]) * static_cast<double>(size[1]);
}

double
VesselReformationLogic::AvailableMemoryInBytes()
{
  std::ifstream meminfo("/proc/meminfo");
  std::string   key;
  double        kibibytes = 0.0;
  std::string   unit;
  while (meminfo >> key >> kibibytes >> unit)
  {
    if (key == "MemAvailable:")
    {
      return kibibytes * 1024.0;
    }
  }
  const long pages = ::sysconf(_SC_AVPHYS_PAGES);
  const long pageSize = ::sysconf(_SC_PAGESIZE);
  return pages > 0 && pageSize > 0 ? static_cast<double>(pages) * pageSize : 1e18;
}

double
VesselReformationLogic::FractionOfPointsOutside(const itk::CenterlineTree & tree, const VolumeImageType * volume)
{
  const auto & region = volume->GetLargestPossibleRegion();
  std::size_t  outside = 0;
  std::size_t  total = 0;
  for (const auto & branch : tree.GetBranches())
  {
    for (const auto & point : branch.Points)
    {
      itk::ContinuousIndex<double, 3> index;
      volume->TransformPhysicalPointToContinuousIndex(point, index);
      bool inside = true;
      for (unsigned int axis = 0; axis < 3; ++axis)
      {
        const double low = region.GetIndex(axis) - 0.5;
        const double high = region.GetIndex(axis) + static_cast<double>(region.GetSize(axis)) - 0.5;
        inside = inside && index[axis] >= low && index[axis] <= high;
      }
      outside += inside ? 0 : 1;
      ++total;
    }
  }
  return total == 0 ? 0.0 : static_cast<double>(outside) / total;
}
} // namespace vr
