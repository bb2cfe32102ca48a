// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The stages around the relax, on the phantom at the paper's sizes, each with its filters kept between
// iterations as the module logic keeps them while the user rotates the view:
//   Depth/W/H          CPRDepthImageFilter for a new angle (the paper's "mpCPR" column)
//   Resample/W/H       CPRResampleImageFilter (linear, outside = the volume's minimum) of a given depth map
//   DepthResample/W/H  both, for a new angle: what rotating costs without relaxing
//   Pipeline_CPU/W/H   depth + relax (500 iterations, CPU) + resample for a new angle (the paper's "total")
//   Pipeline_OpenCL/W/H  the same with the OpenCL relax (the paper's "total with GPU"), when built with OpenCL
//   Depth_Visibility/W/H  the depth map in Visibility mode (issue 38), the same angles as Depth: its ratio to Depth
//   Depth_Overlap/W/H, Depth_Visibility_Overlap/W/H  both modes at 120-130 degrees, where the legs overlap
//   OcclusionProfile/512/1024  the hidden length at 180 angles, computed from the segments
//   (itk::ComputeCPROcclusionProfile) OcclusionProfile_DepthMaps/512/1024  its plain reference: 180 depth maps in
//   Visibility mode, their hidden lengths
// Each iteration turns the view by a quarter degree, so every depth map is new.
#include "vrBenchmarkScene.h"

#include "itkBilateralDepthRelaxFilter.h"
#include "itkCPRDepthImageFilter.h"
#include "itkCPROcclusionProfile.h"
#include "itkCPRResampleImageFilter.h"
#ifdef VESSELREFORMATION_HAS_OPENCL
#include "itkOpenCLBilateralDepthRelaxFilter.h"
#endif

#include <benchmark/benchmark.h>

#include <vector>

namespace
{
using vr::benchmarks::DepthImage;
using vr::benchmarks::PhantomScene;
using vr::benchmarks::VolumeImage;
using DepthFilter = itk::CPRDepthImageFilter<DepthImage>;
using RelaxFilter = itk::BilateralDepthRelaxFilter<DepthImage>;
using ResampleFilter = itk::CPRResampleImageFilter<VolumeImage, DepthImage>;

/** Angles 30, 30.25, ... 39.75, 30, ...: always a new view, always near the design angle. */
double
AngleOfIteration(std::size_t iteration)
{
  return vr::benchmarks::DesignAngle + 0.25 * static_cast<double>(iteration % 40);
}

/** Angles 120, 120.25, ... 129.75, 120, ...: the legs of the run-off phantom overlap (the scanline ladder). */
double
OverlapAngleOfIteration(std::size_t iteration)
{
  return 120.0 + 0.25 * static_cast<double>(iteration % 40);
}

DepthFilter::Pointer
MakeDepthFilter(unsigned int width, unsigned int height)
{
  auto & scene = PhantomScene::Instance();
  auto   filter = DepthFilter::New();
  filter->SetCenterlineTree(scene.GetCenterlineTree());
  filter->SetReferenceVolume(scene.GetVolume());
  filter->SetViewSpecification(vr::benchmarks::PaperView(width, height));
  return filter;
}

ResampleFilter::Pointer
MakeResampleFilter(const DepthImage * depth)
{
  auto filter = ResampleFilter::New();
  filter->SetVolume(PhantomScene::Instance().GetVolume());
  filter->SetDepth(depth);
  return filter;
}

void
Depth(benchmark::State & state)
{
  auto        depth = MakeDepthFilter(state.range(0), state.range(1));
  std::size_t iteration = 0;
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    depth->SetViewSpecification(
      vr::benchmarks::PaperView(state.range(0), state.range(1), AngleOfIteration(++iteration)));
    depth->Update();
    benchmark::DoNotOptimize(depth->GetDepthOutput()->GetBufferPointer());
  }
}

void
DepthInMode(benchmark::State & state, itk::CPRDepthMode mode, double (*angleOfIteration)(std::size_t))
{
  auto depth = MakeDepthFilter(state.range(0), state.range(1));
  depth->SetMode(mode);
  depth->Update(); // not timed: the workspace's first allocation
  std::size_t iteration = 0;
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    depth->SetViewSpecification(
      vr::benchmarks::PaperView(state.range(0), state.range(1), angleOfIteration(++iteration)));
    depth->Update();
    benchmark::DoNotOptimize(depth->GetDepthOutput()->GetBufferPointer());
  }
}

void
DepthVisibility(benchmark::State & state)
{
  DepthInMode(state, itk::CPRDepthMode::Visibility, AngleOfIteration);
}

void
DepthOverlap(benchmark::State & state)
{
  DepthInMode(state, itk::CPRDepthMode::Scanline, OverlapAngleOfIteration);
}

void
DepthVisibilityOverlap(benchmark::State & state)
{
  DepthInMode(state, itk::CPRDepthMode::Visibility, OverlapAngleOfIteration);
}

itk::CPRViewGeometry
ResolvedPaperView(unsigned int width, unsigned int height)
{
  auto depth = MakeDepthFilter(width, height);
  depth->UpdateOutputInformation();
  return depth->GetView();
}

void
OcclusionProfile(benchmark::State & state)
{
  const itk::CPRViewGeometry view = ResolvedPaperView(state.range(0), state.range(1));
  const auto &               tree = PhantomScene::Instance().GetCenterlineTree();
  auto                       threader = itk::MultiThreaderBase::New();
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    const itk::CPROcclusionProfile profile = itk::ComputeCPROcclusionProfile(tree, view, threader);
    benchmark::DoNotOptimize(profile.HiddenLength.data());
  }
}

void
OcclusionProfileDepthMaps(benchmark::State & state)
{
  auto depth = MakeDepthFilter(state.range(0), state.range(1));
  depth->SetMode(itk::CPRDepthMode::Visibility);
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    std::vector<double> hidden;
    for (unsigned int angle = 0; angle < itk::CPROcclusionProfile::NumberOfAngles; ++angle)
    {
      depth->SetViewSpecification(vr::benchmarks::PaperView(state.range(0), state.range(1), angle));
      depth->Update();
      double sum = 0.0;
      for (const auto & entry : depth->GetBranchOcclusions())
      {
        sum += entry.HiddenLength;
      }
      hidden.push_back(sum);
    }
    benchmark::DoNotOptimize(hidden.data());
  }
}

void
Resample(benchmark::State & state)
{
  auto depth = MakeDepthFilter(state.range(0), state.range(1));
  depth->Update();
  auto resample = MakeResampleFilter(depth->GetDepthOutput());
  // The first update finds the volume's minimum (once per volume, ~0.1 s); rotating the view never repeats it.
  resample->Update();
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    resample->Modified();
    resample->Update();
    benchmark::DoNotOptimize(resample->GetOutput()->GetBufferPointer());
  }
}

void
DepthResample(benchmark::State & state)
{
  auto depth = MakeDepthFilter(state.range(0), state.range(1));
  auto resample = MakeResampleFilter(depth->GetDepthOutput());
  resample->Update();
  std::size_t iteration = 0;
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    depth->SetViewSpecification(
      vr::benchmarks::PaperView(state.range(0), state.range(1), AngleOfIteration(++iteration)));
    resample->Update();
    benchmark::DoNotOptimize(resample->GetOutput()->GetBufferPointer());
  }
}

void
Pipeline(benchmark::State & state, RelaxFilter * relax)
{
  auto depth = MakeDepthFilter(state.range(0), state.range(1));
  relax->SetDepthInput(depth->GetDepthOutput());
  relax->SetFixedMask(depth->GetFixedMaskOutput());
  relax->SetRelaxation(1.0);
  relax->SetAnisotropy(0.5);
  relax->SetNumberOfIterations(500);
  auto resample = MakeResampleFilter(relax->GetOutput());
  try
  {
    resample->Update(); // not timed: the volume's minimum, and for OpenCL the device and program build
  }
  catch (const itk::ExceptionObject & error)
  {
    state.SkipWithError(error.GetDescription());
    return;
  }
  std::size_t iteration = 0;
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    depth->SetViewSpecification(
      vr::benchmarks::PaperView(state.range(0), state.range(1), AngleOfIteration(++iteration)));
    resample->Update();
    benchmark::DoNotOptimize(resample->GetOutput()->GetBufferPointer());
  }
}

void
PipelineCPU(benchmark::State & state)
{
  Pipeline(state, RelaxFilter::New());
}

#ifdef VESSELREFORMATION_HAS_OPENCL
void
PipelineOpenCL(benchmark::State & state)
{
  auto relax = itk::OpenCLBilateralDepthRelaxFilter::New();
  Pipeline(state, relax);
  state.SetLabel(relax->GetDeviceLabel());
}
#endif

const bool Registered = []
{
  for (const auto & size : { std::pair<long, long>{ 256, 768 }, std::pair<long, long>{ 512, 1024 } })
  {
    for (const auto & stage : {
           std::pair<const char *, void (*)(benchmark::State &)>{ "Depth", Depth },
           { "Resample", Resample },
           { "DepthResample", DepthResample },
           { "Pipeline_CPU", PipelineCPU },
#ifdef VESSELREFORMATION_HAS_OPENCL
           { "Pipeline_OpenCL", PipelineOpenCL },
#endif
         })
    {
      benchmark::RegisterBenchmark(stage.first, stage.second)
        ->Args({ size.first, size.second })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Repetitions(10)
        ->ReportAggregatesOnly();
    }
    for (const auto & stage : {
           std::pair<const char *, void (*)(benchmark::State &)>{ "Depth_Visibility", DepthVisibility },
           { "Depth_Overlap", DepthOverlap },
           { "Depth_Visibility_Overlap", DepthVisibilityOverlap },
         })
    {
      benchmark::RegisterBenchmark(stage.first, stage.second)
        ->Args({ size.first, size.second })
        ->Unit(benchmark::kMillisecond)
        ->UseRealTime()
        ->Repetitions(10)
        ->ReportAggregatesOnly();
    }
  }
  benchmark::RegisterBenchmark("OcclusionProfile", OcclusionProfile)
    ->Args({ 512, 1024 })
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Repetitions(10)
    ->ReportAggregatesOnly();
  benchmark::RegisterBenchmark("OcclusionProfile_DepthMaps", OcclusionProfileDepthMaps)
    ->Args({ 512, 1024 })
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1)
    ->Repetitions(3)
    ->ReportAggregatesOnly();
  return true;
}();
} // namespace
