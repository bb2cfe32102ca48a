// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// vr::VesselReformationLogic (vrVesselReformationLogic.h): its pipeline, what reruns after a change, and the update.
#include "vrVesselReformationLogicInternals.h"

namespace vr
{
using detail::Clock;
using detail::SecondsSince;

void
VesselReformationLogic::Internals::ChooseRelaxFilter()
{
  if (HasBackendChoice && ChosenFor == Parameters.Backend && ChosenForDevice == Parameters.OpenCLDevice &&
      ChosenForSolver == Parameters.Solver)
  {
    return;
  }
  HasBackendChoice = false;
  // The OpenCL filter of a device is made once and kept, with its built kernel.
  auto openCL = [this](const std::string & device, std::string & whyNot) -> RelaxFilterType::Pointer
  {
    auto found = OpenCLRelax.find(device);
    if (found != OpenCLRelax.end())
    {
      return found->second;
    }
    RelaxFilterType::Pointer filter = TryCreateOpenCLRelaxFilter(device, whyNot);
    if (filter)
    {
      Monitor.Watch(filter, detail::Stage::Relax, "relax");
      OpenCLRelax[device] = filter;
    }
    return filter;
  };
  const RelaxFilterChoice choice =
    vr::ChooseRelaxFilter(Parameters.Backend, Parameters.Solver, Parameters.OpenCLDevice, openCL, OpenCLDevices);
  Relax = choice.Filter ? choice.Filter : CPURelax;
  ChooseViewFilters();
  Outputs.RelaxBackendUsed = ToString(choice.Backend);
  Outputs.RelaxBackendReason = choice.Reason;
  BackendNotice = choice.Notice;
  Warning(BackendNotice, ParameterName::Backend);
  HasBackendChoice = true;
  ChosenFor = Parameters.Backend;
  ChosenForDevice = Parameters.OpenCLDevice;
  ChosenForSolver = Parameters.Solver;
}

void
VesselReformationLogic::Internals::ChooseViewFilters()
{
  Depth = CPUDepth;
  UnfilteredResample = CPUUnfilteredResample;
  RelaxedResample = CPURelaxedResample;
  if (Relax == CPURelax)
  {
    return;
  }
  // The relaxation runs on an OpenCL device: so do the depth map and the resampling, on the same device.
  auto found = OpenCLViews.find(Parameters.OpenCLDevice);
  if (found == OpenCLViews.end())
  {
    std::string             whyNot;
    const OpenCLViewFilters view = CreateOpenCLViewFilters(Relax, whyNot);
    if (!view.Depth)
    {
      return;
    }
    WatchView(view.Depth, view.UnfilteredResample, view.RelaxedResample);
    found = OpenCLViews.emplace(Parameters.OpenCLDevice, view).first;
  }
  Depth = found->second.Depth;
  UnfilteredResample = found->second.UnfilteredResample;
  RelaxedResample = found->second.RelaxedResample;
}

void
VesselReformationLogic::Internals::ConfigurePipeline()
{
  ChooseRelaxFilter(); // and with it the depth and resampling filters in use
  Depth->SetCenterlineTree(*Tree);
  if (!Parameters.LeastOccludedAngle)
  {
    Depth->SetViewSpecification(Parameters.ToViewSpecification()); // else UpdateOcclusionProfile() chooses the angle
  }
  Depth->SetReferenceVolume(Volume->Image);
  Depth->SetMode(Parameters.Mode);
  Depth->SetFixLumen(Parameters.FixLumen);

  Relax->SetInput(Depth->GetDepthOutput());
  Relax->SetFixedMask(Depth->GetFixedMaskOutput());
  Parameters.ConfigureRelaxFilter(Relax);

  for (ResampleFilterType * resample : { UnfilteredResample.GetPointer(), RelaxedResample.GetPointer() })
  {
    resample->SetVolume(Volume->Image);
    resample->SetIntensityRescale(Volume->Rescale);
    resample->SetInterpolation(Parameters.Interpolation);
    resample->SetSlabThickness(Parameters.SlabThickness);
    resample->SetSlabMode(Parameters.SlabMode);
    resample->SetDefaultValue(static_cast<float>(Volume->Minimum));
  }
  UnfilteredResample->SetDepth(Depth->GetDepthOutput());
  RelaxedResample->SetDepth(Relax->GetOutput());
}

void
VesselReformationLogic::Internals::CheckRadiiForVisibility()
{
  if (Tree == RadiusCheckedTree && Parameters.Mode == RadiusCheckedMode)
  {
    return;
  }
  RadiusCheckedTree = Tree;
  RadiusCheckedMode = Parameters.Mode;
  RadiusWarning.clear();
  if (Parameters.Mode != itk::CPRDepthMode::Visibility)
  {
    return;
  }
  RadiusWarning = detail::DescribeBranchesWithoutRadii(*Tree);
  Warning(RadiusWarning, ParameterName::DepthMode);
}

void
VesselReformationLogic::Internals::UpdateOcclusionProfile()
{
  Outputs.AngleChosen = false;
  if (!ProfileEnabled && !Parameters.LeastOccludedAngle)
  {
    Outputs.OcclusionProfile = nullptr;
    return;
  }
  itk::CPRViewSpecification specification = Parameters.ToViewSpecification();
  specification.AngleInDegrees = 0.0;
  itk::CPRViewGeometry view;
  try
  {
    view = itk::CPRViewGeometry::Resolve(specification, *Tree, Volume->Image);
  }
  catch (const itk::ExceptionObject &)
  {
    // The depth filter resolves the same view next and names what is wrong with it.
    Depth->SetViewSpecification(Parameters.ToViewSpecification());
    return;
  }
  Outputs.OcclusionProfile = Profile.Get(Tree, view, Outputs.Times.OcclusionProfile);
  if (Parameters.LeastOccludedAngle)
  {
    specification = Parameters.ToViewSpecification();
    specification.AngleInDegrees = static_cast<double>(Outputs.OcclusionProfile->LeastOccludedAngle());
    Depth->SetViewSpecification(specification);
    Outputs.AngleChosen = true;
  }
}

void
VesselReformationLogic::Internals::PlanProgress()
{
  const std::array<bool, 4> runs{ detail::WillRun(Depth->GetDepthOutput()),
                                  detail::WillRun(Relax->GetOutput()),
                                  detail::WillRun(UnfilteredResample->GetOutput()),
                                  detail::WillRun(RelaxedResample->GetOutput()) };
  const bool                surface = SurfaceEnabled && (!SurfaceValid || runs[1] || runs[3]);
  // After the extraction's share, when it ran.
  Monitor.PlanShares(
    runs, static_cast<unsigned int>(Parameters.Iterations), surface, Monitor.GetShareEnd(detail::Stage::Extraction));
}

std::vector<itk::ProcessObject *>
VesselReformationLogic::Internals::Filters() const
{
  std::vector<itk::ProcessObject *> filters = {
    Extraction, CPUDepth, CPURelax, CPUUnfilteredResample, CPURelaxedResample
  };
  for (const auto & entry : OpenCLRelax)
  {
    filters.push_back(entry.second);
  }
  for (const auto & entry : OpenCLViews)
  {
    filters.insert(filters.end(),
                   { entry.second.Depth, entry.second.UnfilteredResample, entry.second.RelaxedResample });
  }
  return filters;
}

void
VesselReformationLogic::Internals::RefreshOutputs(const ReformationStageCounts & now)
{
  const ReformationStageCounts & before = Refreshed;
  if (now.Depth != before.Depth || DepthFrom != Depth.GetPointer())
  {
    DepthFrom = Depth;
    Outputs.View = Depth->GetView();
    Outputs.Depth = ConvertItkImageToVolumeNode(Depth->GetDepthOutput(), "Depth");
    Outputs.FixedMask = ConvertItkImageToVolumeNode(Depth->GetFixedMaskOutput(), "Fixed mask");
    Outputs.OwnerLabels = ConvertItkImageToVolumeNode(Depth->GetOwnerLabelOutput(), "Owner labels");
    Outputs.HiddenLabels = nullptr;
    Outputs.BranchOcclusions.clear();
    if (Depth->GetMode() == itk::CPRDepthMode::Visibility)
    {
      Outputs.HiddenLabels = ConvertItkImageToVolumeNode(Depth->GetHiddenLabelOutput(), "Hidden labels");
      Outputs.BranchOcclusions = detail::NameBranchOcclusions(Depth->GetCenterlineTree(), Depth->GetBranchOcclusions());
    }
  }
  if (now.Relax != before.Relax || RelaxedDepthFrom != Relax.GetPointer())
  {
    Outputs.RelaxedDepth = ConvertItkImageToVolumeNode(Relax->GetOutput(), "Relaxed depth");
    RelaxedDepthFrom = Relax;
  }
  if (now.UnfilteredSamplings != before.UnfilteredSamplings || UnfilteredCPRFrom != UnfilteredResample.GetPointer())
  {
    UnfilteredCPRFrom = UnfilteredResample;
    Outputs.UnfilteredCPR = ConvertItkImageToVolumeNode(UnfilteredResample->GetOutput(), "CPR (unfiltered)");
  }
  if (now.RelaxedSamplings != before.RelaxedSamplings || CPRFrom != RelaxedResample.GetPointer())
  {
    CPRFrom = RelaxedResample;
    Outputs.CPR = ConvertItkImageToVolumeNode(RelaxedResample->GetOutput(), "CPR");
    SurfaceValid = false;
  }
  Refreshed = now;
  HasCPR = true;
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
VesselReformationLogic::SetSegmentationNode(VolumeNode * node)
{
  m_Internals->SegmentationNodeInput = node;
}

VolumeNode *
VesselReformationLogic::GetSegmentationNode() const
{
  return m_Internals->SegmentationNodeInput;
}

void
VesselReformationLogic::SetCenterlineExtractionParameters(const CenterlineExtractionParameters & parameters)
{
  m_Internals->ExtractionParameters = parameters;
}

const CenterlineExtractionParameters &
VesselReformationLogic::GetCenterlineExtractionParameters() const
{
  return m_Internals->ExtractionParameters;
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
VesselReformationLogic::SetOcclusionProfileEnabled(bool enabled)
{
  m_Internals->ProfileEnabled = enabled;
}

bool
VesselReformationLogic::GetOcclusionProfileEnabled() const
{
  return m_Internals->ProfileEnabled;
}

void
VesselReformationLogic::SetProgressCallback(ProgressCallback callback)
{
  m_Internals->Monitor.SetProgressCallback(std::move(callback));
}

void
VesselReformationLogic::SetWarningCallback(WarningCallback callback)
{
  m_Internals->Warn = std::move(callback);
}

void
VesselReformationLogic::SetOpenCLDeviceQuery(OpenCLDeviceQuery query)
{
  m_Internals->OpenCLDevices = query ? std::move(query) : OpenCLDeviceQuery(QueryOpenCLDevice);
  m_Internals->HasBackendChoice = false;
}

void
VesselReformationLogic::SetInputCache(std::shared_ptr<ReformationInputCache> cache)
{
  m_Internals->Inputs = cache ? std::move(cache) : std::make_shared<ReformationInputCache>();
}

std::shared_ptr<ReformationInputCache>
VesselReformationLogic::GetInputCache() const
{
  return m_Internals->Inputs;
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
  if (!d.CenterlineNodeInput && !d.SegmentationNodeInput)
  {
    throw InputError("vessel reformation: no centerline node and no segmentation node is set; set one");
  }
  if (d.CenterlineNodeInput && d.SegmentationNodeInput)
  {
    throw InputError("vessel reformation: both a centerline node and a segmentation node are set; set only one");
  }
  if (d.SegmentationNodeInput)
  {
    d.ExtractionParameters.Validate();
  }
  d.Monitor.BeginUpdate();
  struct RunningFlag
  {
    Internals & Logic;
    ~RunningFlag() { Logic.Monitor.EndUpdate(Logic.Filters()); }
  } running{ d };

  d.Outputs.Times = StageTimes();
  d.ConvertInputs();
  d.ExtractCenterlines();
  d.ConfigurePipeline();
  d.CheckRadiiForVisibility();
  d.UpdateOcclusionProfile();
  try
  {
    // Resolves the view (cheap) so that a view too large for memory is refused before anything is allocated.
    d.Depth->UpdateOutputInformation();
  }
  catch (const itk::ExceptionObject & error)
  {
    if (d.Parameters.PixelSpacing[0] > 0.0 && d.Parameters.ImageSize[0] == 0)
    {
      // The view's size follows from the spacing when only that was given: name it (e.g. a spacing of 1e-300 mm
      // asks for more pixels than an integer holds).
      std::ostringstream stage;
      stage << "view at pixel spacing " << d.Parameters.PixelSpacing[0] << "," << d.Parameters.PixelSpacing[1]
            << " mm: " << error.GetDescription();
      throw InputError(stage.str(), ParameterName::PixelSpacing);
    }
    detail::RethrowFilterError("view", error);
  }
  // The volume is sampled where it lies, in its stored type: only cubic interpolation allocates for it (the
  // coefficients, which the resamplers then keep for the next views of the same volume), and the check counts that.
  const bool cubicHeld =
    d.Parameters.Interpolation == itk::CPRInterpolationMode::Cubic && d.CubicCoefficientsOf == d.Volume.get();
  CheckViewFitsInMemory(d.Depth->GetView(),
                        d.Parameters.ImageSize[0] > 0,
                        *d.Relax,
                        d.SurfaceEnabled,
                        cubicHeld ? 0.0
                                  : EstimateVolumeSamplingBytes(
                                      static_cast<double>(d.Volume->Image->GetBufferedRegion().GetNumberOfPixels()),
                                      d.Parameters.Interpolation),
                        d.Parameters.Mode);
  d.PlanProgress();

  const ReformationStageCounts before = GetStageCounts();
  // One filter at a time, so that an abort between stages is seen; ITK reruns only what is out of date.
  d.Monitor.Run(d.Depth, "depth");
  d.Monitor.Run(d.Relax, "relaxation");
  if (d.Monitor.GetRuns(detail::Stage::Relax) != before.Relax)
  {
    // A steady solve bounded by its outer iterations says how far it got; its output is still shown.
    d.RelaxWarning = d.Relax->GetSolver() == itk::BilateralDepthRelaxSolver::Steady ? d.Relax->GetSteadyWarning() : "";
    d.Warning(d.RelaxWarning, ParameterName::Solver);
  }
  d.Monitor.Run(d.UnfilteredResample, "resample");
  d.Monitor.Run(d.RelaxedResample, "resample");
  d.CubicCoefficientsOf = d.Parameters.Interpolation == itk::CPRInterpolationMode::Cubic ? d.Volume.get() : nullptr;
  d.Counts = GetStageCounts();
  const bool resampled =
    d.Counts.UnfilteredSamplings != before.UnfilteredSamplings || d.Counts.RelaxedSamplings != before.RelaxedSamplings;
  d.Counts.Resample = before.Resample + (resampled ? 1 : 0);
  // The time of each stage that ran in this update (0 for the others).
  const detail::StageMonitor & monitor = d.Monitor;
  d.Outputs.Times.Depth = d.Counts.Depth != before.Depth ? monitor.GetSeconds(detail::Stage::Depth) : 0.0;
  d.Outputs.Times.Relax = d.Counts.Relax != before.Relax ? monitor.GetSeconds(detail::Stage::Relax) : 0.0;
  d.Outputs.Times.Resample =
    (d.Counts.UnfilteredSamplings != before.UnfilteredSamplings ? monitor.GetSeconds(detail::Stage::UnfilteredSampling)
                                                                : 0.0) +
    (d.Counts.RelaxedSamplings != before.RelaxedSamplings ? monitor.GetSeconds(detail::Stage::RelaxedSampling) : 0.0);
  d.RefreshOutputs(d.Counts);
  d.Outputs.DepthBackendUsed = DescribeDepthBackend(d.Depth, d.Outputs.DepthBackendReason);
  d.Outputs.ResampleBackendUsed = DescribeResampleBackend(d.RelaxedResample, d.Outputs.ResampleBackendReason);

  if (d.SurfaceEnabled && !d.SurfaceValid)
  {
    const auto start = Clock::now();
    d.Outputs.Surface = BuildCutSurface(d.Relax->GetOutput(),
                                        d.RelaxedResample->GetOutput(),
                                        d.Outputs.View,
                                        DefaultMaximumBridgedDepthJump(d.Outputs.View));
    d.SurfaceValid = true;
    ++d.Counts.Surface;
    d.Outputs.Times.Surface = SecondsSince(start);
  }
  if (!d.SurfaceEnabled)
  {
    d.Outputs.Surface = nullptr;
    d.SurfaceValid = false;
  }
  d.Monitor.ReportProgress(1.0, "done");
  return d.Outputs;
}

void
VesselReformationLogic::AbortUpdate()
{
  m_Internals->Monitor.RequestAbort();
}

CenterlineExtractionFilterType *
VesselReformationLogic::GetCenterlineExtractionFilter() const
{
  return m_Internals->Extraction;
}

auto
VesselReformationLogic::GetDepthFilter() const -> DepthFilterType *
{
  return m_Internals->Depth;
}

RelaxFilterType *
VesselReformationLogic::GetRelaxFilter() const
{
  return m_Internals->Relax;
}

auto
VesselReformationLogic::GetUnfilteredResampleFilter() const -> ResampleFilterType *
{
  return m_Internals->UnfilteredResample;
}

auto
VesselReformationLogic::GetResampleFilter() const -> ResampleFilterType *
{
  return m_Internals->RelaxedResample;
}

const ReformationOutputs &
VesselReformationLogic::GetOutputs() const
{
  return m_Internals->Outputs;
}

ReformationStageCounts
VesselReformationLogic::GetStageCounts() const
{
  ReformationStageCounts       counts = m_Internals->Counts;
  const detail::StageMonitor & monitor = m_Internals->Monitor;
  counts.Extraction = monitor.GetRuns(detail::Stage::Extraction);
  counts.Depth = monitor.GetRuns(detail::Stage::Depth);
  counts.Relax = monitor.GetRuns(detail::Stage::Relax);
  counts.UnfilteredSamplings = monitor.GetRuns(detail::Stage::UnfilteredSampling);
  counts.RelaxedSamplings = monitor.GetRuns(detail::Stage::RelaxedSampling);
  return counts;
}

std::vector<std::string>
VesselReformationLogic::GetWarnings() const
{
  std::vector<std::string> warnings;
  for (const std::string * warning : { &m_Internals->SegmentationWarning,
                                       &m_Internals->ExtractionWarning,
                                       &m_Internals->InputWarning,
                                       &m_Internals->RelaxWarning,
                                       &m_Internals->RadiusWarning,
                                       &m_Internals->BackendNotice })
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
  const DepthImageType * cpr = m_Internals->HasCPR ? m_Internals->RelaxedResample->GetOutput() : nullptr;
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
                                        std::vector<std::string> &    warnings,
                                        std::string *                 backendUsed,
                                        std::string *                 backendReason)
{
  parameters.Validate();
  if (depth == nullptr)
  {
    throw InputError("relaxation: no depth image given");
  }
  const RelaxFilterChoice choice =
    vr::ChooseRelaxFilter(parameters.Backend, parameters.Solver, parameters.OpenCLDevice);
  RelaxFilterType::Pointer filter = choice.Filter ? choice.Filter : RelaxFilterType::New();
  if (backendReason != nullptr)
  {
    *backendReason = choice.Reason;
  }
  if (!choice.Notice.empty())
  {
    warnings.push_back(choice.Notice);
  }
  if (backendUsed != nullptr)
  {
    *backendUsed = ToString(choice.Backend);
  }
  filter->SetInput(depth);
  filter->SetFixedMask(mask);
  parameters.ConfigureRelaxFilter(filter);
  if (progress)
  {
    RelaxFilterType * raw = filter;
    filter->AddObserver(itk::ProgressEvent(),
                        [raw, &progress](const itk::EventObject &) { progress(raw->GetProgress(), "relax"); });
  }
  try
  {
    filter->Update();
  }
  catch (const itk::ExceptionObject & error)
  {
    detail::RethrowFilterError("relaxation", error);
  }
  DepthImageType::Pointer relaxed = filter->GetOutput();
  relaxed->DisconnectPipeline();
  if (progress)
  {
    progress(1.0, "done");
  }
  return relaxed;
}

double
VesselReformationLogic::FractionOfPointsOutside(const itk::CenterlineTree & tree, const VolumeImageType * volume)
{
  return MeasureCenterlineVolumeFit(tree, volume).OutsideFraction();
}
} // namespace vr
