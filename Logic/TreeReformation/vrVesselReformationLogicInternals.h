// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The state of vr::VesselReformationLogic behind its interface, shared by the files that implement it
// (vrVesselReformationLogicUpdate.cxx: the pipeline and the update; vrVesselReformationLogicInputs.cxx: the inputs'
// checks and the centerline extraction). Not installed.
#ifndef vrVesselReformationLogicInternals_h
#define vrVesselReformationLogicInternals_h

#include "vrVesselReformationLogic.h"

#include "vrCenterlineVolumeFit.h"
#include "vrImageGrid.h"
#include "vrMemoryBudget.h"
#include "vrStageMonitor.h"
#include "vrViewBackend.h"
#include "vrVisibilityOutputs.h"
#include "itkBilateralDepthRelaxFilter.h"
#include "itkCPRDepthImageFilter.h"
#include "itkCPRResampleImageFilter.h"
#include "vrCutSurface.h"
#include "vrITKMessages.h"
#include "vrInputError.h"
#include "vrNodeConversion.h"
#include "vrParameterName.h"
#include <vtkPolyData.h>
#include <algorithm>
#include <chrono>
#include <limits>
#include <cmath>
#include <map>
#include <sstream>

namespace vr
{
namespace detail
{
using Clock = std::chrono::steady_clock;

/** Seconds from \a start to now. */
inline double
SecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}
} // namespace detail

struct VesselReformationLogic::Internals
{
  vtkSmartPointer<VolumeNode>     VolumeNodeInput;
  vtkSmartPointer<CenterlineNode> CenterlineNodeInput;
  vtkSmartPointer<VolumeNode>     SegmentationNodeInput;
  CenterlineExtractionParameters  ExtractionParameters;
  ReformationParameters           Parameters;
  bool                            SurfaceEnabled{ true };
  bool                            ProfileEnabled{ false };
  WarningCallback                 Warn;

  // The inputs as ITK sees them, from the cache (converted again only when a node changes; possibly shared with
  // another logic on the same nodes): the ones this logic's pipeline holds now.
  std::shared_ptr<ReformationInputCache>               Inputs = std::make_shared<ReformationInputCache>();
  std::shared_ptr<const ReformationInputCache::Volume> Volume;
  // The volume whose cubic B-spline coefficients the resamplers hold (they keep them between updates), or null.
  const ReformationInputCache::Volume *                      CubicCoefficientsOf{ nullptr };
  std::shared_ptr<const ReformationInputCache::Segmentation> Segmentation;
  std::shared_ptr<const itk::CenterlineTree>                 Tree;
  bool                                                       VolumeChanged{ false };
  // Where Tree came from: a centerline node, or the extraction (its run count when Tree was taken from it).
  bool         TreeFromExtraction{ false };
  unsigned int TreeExtractionRuns{ 0 };

  // The pipeline, one filter of each kind and backend for the logic's lifetime: [extraction ->] depth -> relax ->
  // resample (relaxed CPR), and depth -> resample (unfiltered CPR). Where the relaxation runs on an OpenCL device,
  // the depth map and the resampling run there too (vrViewBackend.h): one set of filters per device asked for.
  CenterlineExtractionFilterType::Pointer         Extraction = CenterlineExtractionFilterType::New();
  DepthFilterType::Pointer                        CPUDepth = DepthFilterType::New();
  RelaxFilterType::Pointer                        CPURelax = RelaxFilterType::New();
  ResampleFilterType::Pointer                     CPUUnfilteredResample = ResampleFilterType::New();
  ResampleFilterType::Pointer                     CPURelaxedResample = ResampleFilterType::New();
  std::map<std::string, RelaxFilterType::Pointer> OpenCLRelax; // by device request
  std::map<std::string, OpenCLViewFilters>        OpenCLViews; // by device request
  // The filters in use.
  DepthFilterType::Pointer       Depth = CPUDepth;
  RelaxFilterType::Pointer       Relax;
  bool                           HasBackendChoice{ false };
  RelaxBackend                   ChosenFor{ RelaxBackend::Auto };
  std::string                    ChosenForDevice;
  itk::BilateralDepthRelaxSolver ChosenForSolver{ itk::BilateralDepthRelaxSolver::Jacobi };
  OpenCLDeviceQuery              OpenCLDevices = QueryOpenCLDevice; // which device Auto would get
  ResampleFilterType::Pointer    UnfilteredResample = CPUUnfilteredResample;
  ResampleFilterType::Pointer    RelaxedResample = CPURelaxedResample;

  detail::StageMonitor Monitor; // counts, times, progress, abort
  bool                 SurfaceValid{ false };
  bool                 HasCPR{ false };
  /** The filters whose outputs the output nodes copy: a node is made anew when another filter (the other
   * backend's) is in use, even where that filter did not need to run. */
  const RelaxFilterType *    RelaxedDepthFrom{ nullptr };
  const DepthFilterType *    DepthFrom{ nullptr };
  const ResampleFilterType * UnfilteredCPRFrom{ nullptr };
  const ResampleFilterType * CPRFrom{ nullptr };
  /** The stage counts when the output nodes were last made: a stage that ran since (also in an update that was
   * cancelled later) gets its node made anew. */
  ReformationStageCounts Refreshed;

  std::string InputWarning;
  std::string SegmentationWarning;
  std::string ExtractionWarning;
  std::string BackendNotice;
  /** The steady solve that stopped short of its tolerance (how far it got), else "". */
  std::string RelaxWarning;
  /** Visibility mode with branches that have no radii: what that costs, else "". */
  std::string                                RadiusWarning;
  std::shared_ptr<const itk::CenterlineTree> RadiusCheckedTree;
  itk::CPRDepthMode                          RadiusCheckedMode{ itk::CPRDepthMode::Scanline };

  detail::OcclusionProfileCache Profile;

  ReformationOutputs     Outputs;
  ReformationStageCounts Counts;

  Internals()
  {
    Monitor.Watch(Extraction, detail::Stage::Extraction, "centerlines");
    WatchView(CPUDepth, CPUUnfilteredResample, CPURelaxedResample);
    Monitor.Watch(CPURelax, detail::Stage::Relax, "relax");
    RelaxedResample->SetDepth(CPURelax->GetOutput());
    UnfilteredResample->SetDepth(Depth->GetDepthOutput());
  }

  void
  Warning(const std::string & message, const std::string & parameter)
  {
    if (Warn && !message.empty())
    {
      Warn(message, parameter);
    }
  }

  void
  WatchView(DepthFilterType * depth, ResampleFilterType * unfiltered, ResampleFilterType * relaxed)
  {
    Monitor.Watch(depth, detail::Stage::Depth, "depth");
    Monitor.Watch(unfiltered, detail::Stage::UnfilteredSampling, "resample");
    Monitor.Watch(relaxed, detail::Stage::RelaxedSampling, "resample");
  }

  void
  ConvertInputs();
  std::string
  SegmentationName() const;
  void
  ChooseViewFilters();
  void
  CheckSegmentationAgainstVolume();
  void
  CheckTreeAgainstVolume();
  void
  ExtractCenterlines();
  void
  ChooseRelaxFilter();
  void
  ConfigurePipeline();
  void
  CheckRadiiForVisibility();
  void
  UpdateOcclusionProfile();
  void
  PlanProgress();
  std::vector<itk::ProcessObject *>
  Filters() const;
  void
  RefreshOutputs(const ReformationStageCounts & now);
};
} // namespace vr

#endif
