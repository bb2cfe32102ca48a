// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The stages around the relax, on the phantom at the paper's sizes, each with its filters kept between
// iterations as the module logic keeps them while the user rotates the view:
//   Depth/W/H          CPRDepthImageFilter for a new angle (the paper's "mpCPR" column)
//   Resample/W/H       CPRResampleImageFilter (linear, outside = the volume's minimum) of a given depth map
//   DepthResample/W/H  both, for a new angle: what rotating costs without relaxing
//   Pipeline_CPU/W/H   depth + relax (500 iterations, CPU) + resample for a new angle (the paper's "total")
//   Pipeline_OpenCL/W/H  the same with the OpenCL relax (the paper's "total with GPU"), when built with OpenCL
// Each iteration turns the view by a quarter degree, so every depth map is new.
#include "vrBenchmarkScene.h"

#include "itkBilateralDepthRelaxFilter.h"
#include "itkCPRDepthImageFilter.h"
#include "itkCPRResampleImageFilter.h"
#ifdef VESSELREFORMATION_HAS_OPENCL
#include "itkOpenCLBilateralDepthRelaxFilter.h"
#endif

#include <benchmark/benchmark.h>

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
  }
  return true;
}();
} // namespace
