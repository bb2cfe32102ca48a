// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// What one rotation step costs with the whole view on an OpenCL device, beside the same on the CPU in the same run,
// on the run-off phantom at the paper's sizes (filters kept between iterations, as the module logic keeps them; each
// iteration turns the view by a quarter degree, so every depth map is new):
//   View_CPU/W/H           depth, relax (500 iterations, w = 1, a = 0.5), the relaxed and the unfiltered CPR on the
//                          CPU: what the logic computes for a new angle
//   View_OpenCL/W/H        the same four filters on the device in one session: the volume uploaded once, the depth
//                          map, mask and relaxed depth handed on in the device's memory, each image downloaded once
//   Depth_OpenCL/W/H, Resample_OpenCL/W/H, DepthResample_OpenCL/W/H   the stages alone, beside Depth/W/H,
//                          Resample/W/H and DepthResample/W/H (PipelineBenchmarks.cxx)
// Counters: volume_uploads (in the whole run of the benchmark: 1), hand_offs_per_view (images a filter read from
// another's device buffer), relax_launches.
#include "vrBenchmarkScene.h"

#include "itkBilateralDepthRelaxFilter.h"
#include "itkCPRDepthImageFilter.h"
#include "itkCPRResampleImageFilter.h"
#include "itkOpenCLBilateralDepthRelaxFilter.h"
#include "itkOpenCLCPRDepthImageFilter.h"
#include "itkOpenCLCPRResampleImageFilter.h"
#include "vrOpenCLSession.h"

#include <benchmark/benchmark.h>

namespace
{
using vr::benchmarks::DepthImage;
using vr::benchmarks::PhantomScene;
using vr::benchmarks::VolumeImage;

double
AngleOfIteration(std::size_t iteration)
{
  return vr::benchmarks::DesignAngle + 0.25 * static_cast<double>(iteration % 40);
}

/** The four filters of a view, wired as the logic wires them. */
struct View
{
  itk::CPRDepthImageFilter<DepthImage>::Pointer                             Depth;
  itk::BilateralDepthRelaxFilter<DepthImage>::Pointer                       Relax;
  itk::CPRResampleImageFilter<VolumeImage, DepthImage, DepthImage>::Pointer Unfiltered;
  itk::CPRResampleImageFilter<VolumeImage, DepthImage, DepthImage>::Pointer Relaxed;

  void
  Wire(unsigned int width, unsigned int height, bool relax)
  {
    auto & scene = PhantomScene::Instance();
    Depth->SetCenterlineTree(scene.GetCenterlineTree());
    Depth->SetReferenceVolume(scene.GetVolume());
    Depth->SetViewSpecification(vr::benchmarks::PaperView(width, height));
    Unfiltered->SetVolume(scene.GetVolume());
    Unfiltered->SetDepth(Depth->GetDepthOutput());
    if (relax)
    {
      Relax->SetDepthInput(Depth->GetDepthOutput());
      Relax->SetFixedMask(Depth->GetFixedMaskOutput());
      Relax->SetRelaxation(1.0);
      Relax->SetAnisotropy(0.5);
      Relax->SetNumberOfIterations(500);
      Relaxed->SetVolume(scene.GetVolume());
      Relaxed->SetDepth(Relax->GetOutput());
    }
  }

  void
  Update(bool relax)
  {
    Unfiltered->Update();
    if (relax)
    {
      Relaxed->Update();
    }
  }
};

View
CPUView()
{
  return { itk::CPRDepthImageFilter<DepthImage>::New(),
           itk::BilateralDepthRelaxFilter<DepthImage>::New(),
           itk::CPRResampleImageFilter<VolumeImage, DepthImage, DepthImage>::New(),
           itk::CPRResampleImageFilter<VolumeImage, DepthImage, DepthImage>::New() };
}

View
OpenCLView(const std::shared_ptr<vr::OpenCLSession> & session)
{
  auto depth = itk::OpenCLCPRDepthImageFilter::New();
  auto relax = itk::OpenCLBilateralDepthRelaxFilter::New();
  auto unfiltered = itk::OpenCLCPRResampleImageFilter<VolumeImage>::New();
  auto relaxed = itk::OpenCLCPRResampleImageFilter<VolumeImage>::New();
  depth->SetSession(session);
  relax->SetSession(session);
  unfiltered->SetSession(session);
  relaxed->SetSession(session);
  return { depth.GetPointer(), relax.GetPointer(), unfiltered.GetPointer(), relaxed.GetPointer() };
}

/** Rotates \a view by a quarter degree per iteration; \a relax: whether the relaxation and its CPR run. */
void
Rotate(benchmark::State & state, View view, bool relax, const std::shared_ptr<vr::OpenCLSession> & session)
{
  const auto width = static_cast<unsigned int>(state.range(0));
  const auto height = static_cast<unsigned int>(state.range(1));
  view.Wire(width, height, relax);
  try
  {
    view.Update(relax); // not timed: the volume's minimum, and on a device the programs and the volume's upload
  }
  catch (const itk::ExceptionObject & error)
  {
    state.SkipWithError(error.GetDescription());
    return;
  }
  const std::size_t handOffs = session ? session->GetDeviceHandOffs() : 0;
  std::size_t       iteration = 0;
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    view.Depth->SetViewSpecification(vr::benchmarks::PaperView(width, height, AngleOfIteration(++iteration)));
    view.Update(relax);
    benchmark::DoNotOptimize(view.Unfiltered->GetOutput()->GetBufferPointer());
  }
  if (session)
  {
    state.SetLabel(session->GetDeviceInfo().Label());
    state.counters["volume_uploads"] = static_cast<double>(session->GetVolumeUploads());
    state.counters["hand_offs_per_view"] =
      static_cast<double>(session->GetDeviceHandOffs() - handOffs) / static_cast<double>(state.iterations());
    if (relax)
    {
      state.counters["relax_launches"] =
        static_cast<itk::OpenCLBilateralDepthRelaxFilter *>(view.Relax.GetPointer())->GetNumberOfLaunches();
    }
  }
}

std::shared_ptr<vr::OpenCLSession>
OpenSession(benchmark::State & state)
{
  try
  {
    return vr::OpenCLSession::Create("", "benchmark");
  }
  catch (const itk::ExceptionObject & error)
  {
    state.SkipWithError(error.GetDescription());
  }
  catch (const std::exception & error)
  {
    state.SkipWithError(error.what());
  }
  return nullptr;
}

void
ViewCPU(benchmark::State & state)
{
  Rotate(state, CPUView(), true, nullptr);
}

void
ViewOpenCL(benchmark::State & state)
{
  if (const auto session = OpenSession(state))
  {
    Rotate(state, OpenCLView(session), true, session);
  }
}

void
DepthResampleOpenCL(benchmark::State & state)
{
  if (const auto session = OpenSession(state))
  {
    Rotate(state, OpenCLView(session), false, session);
  }
}

void
DepthOpenCL(benchmark::State & state)
{
  const auto session = OpenSession(state);
  if (!session)
  {
    return;
  }
  auto depth = itk::OpenCLCPRDepthImageFilter::New();
  depth->SetSession(session);
  depth->SetCenterlineTree(PhantomScene::Instance().GetCenterlineTree());
  depth->SetReferenceVolume(PhantomScene::Instance().GetVolume());
  depth->SetViewSpecification(vr::benchmarks::PaperView(state.range(0), state.range(1)));
  depth->Update();
  std::size_t iteration = 0;
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    depth->SetViewSpecification(
      vr::benchmarks::PaperView(state.range(0), state.range(1), AngleOfIteration(++iteration)));
    depth->Update();
    benchmark::DoNotOptimize(depth->GetDepthOutput()->GetBufferPointer());
  }
  state.SetLabel(session->GetDeviceInfo().Label());
}

void
ResampleOpenCL(benchmark::State & state)
{
  const auto session = OpenSession(state);
  if (!session)
  {
    return;
  }
  // The depth map comes from the host (uploaded every update), as Resample/W/H takes it.
  const auto & map = PhantomScene::Instance().GetDepthMap(state.range(0), state.range(1));
  auto         resample = itk::OpenCLCPRResampleImageFilter<VolumeImage>::New();
  resample->SetSession(session);
  resample->SetVolume(PhantomScene::Instance().GetVolume());
  resample->SetDepth(map.Depth);
  resample->Update();
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    resample->Modified();
    resample->Update();
    benchmark::DoNotOptimize(resample->GetOutput()->GetBufferPointer());
  }
  state.SetLabel(session->GetDeviceInfo().Label());
  state.counters["volume_uploads"] = static_cast<double>(session->GetVolumeUploads());
}

const bool Registered = []
{
  for (const auto & size : { std::pair<long, long>{ 256, 768 }, std::pair<long, long>{ 512, 1024 } })
  {
    for (const auto & stage : { std::pair<const char *, void (*)(benchmark::State &)>{ "View_CPU", ViewCPU },
                                { "View_OpenCL", ViewOpenCL },
                                { "Depth_OpenCL", DepthOpenCL },
                                { "Resample_OpenCL", ResampleOpenCL },
                                { "DepthResample_OpenCL", DepthResampleOpenCL } })
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
