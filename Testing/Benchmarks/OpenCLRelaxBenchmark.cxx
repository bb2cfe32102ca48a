// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The OpenCL relax at the paper's sizes (Table 1: 256x768 and 512x1024, 500 iterations), upload and download
// included, on the run-off phantom's mpCPR depth map at 30 degrees. Names follow Relax_CPU/W/H and Relax_Plain/W/H.
//   Relax_OpenCL/W/H                    the device's choice of passes per launch (several on a GPU, one on a CPU
//   device) Relax_OpenCL_Passes/512/1024/passes:K  K passes per launch (1: the one-pass kernel, 500 launches), to see
//   what
//                                       the multi-pass kernel's tiles save on a GPU and to set its default there
// Counters: launches (kernel launches per update), first_run_ms (device choice, program build, first run: not in
// the time), process_cpu_ms (the process's CPU time per update, driver threads included).
#include "vrBenchmarkScene.h"

#include "itkOpenCLBilateralDepthRelaxFilter.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <ctime>

namespace
{
void
RelaxOpenCL(benchmark::State & state, unsigned int passesPerLaunch)
{
  const auto   width = static_cast<unsigned int>(state.range(0));
  const auto   height = static_cast<unsigned int>(state.range(1));
  const auto & depth = vr::benchmarks::PhantomScene::Instance().GetDepthMap(width, height);

  auto relax = itk::OpenCLBilateralDepthRelaxFilter::New();
  relax->SetDepthInput(depth.Depth);
  relax->SetFixedMask(depth.Fixed);
  relax->SetRelaxation(1.0);
  relax->SetAnisotropy(0.5);
  relax->SetNumberOfIterations(500);
  relax->SetPassesPerLaunch(passesPerLaunch);

  // Not timed: choosing the device, building the program and the first run (which may compile the kernel for its
  // work-group size); reported as a counter.
  const auto start = std::chrono::steady_clock::now();
  try
  {
    relax->Update();
  }
  catch (const itk::ExceptionObject & error)
  {
    state.SkipWithError(error.GetDescription());
    return;
  }
  const std::chrono::duration<double, std::milli> firstRun = std::chrono::steady_clock::now() - start;

  // The CPU time of the whole process (the OpenCL driver's threads included): on a machine shared with other work,
  // it tells what the run cost where real time also counts the waits for a core.
  const std::clock_t processStart = std::clock();
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    relax->Modified();
    relax->Update();
    benchmark::DoNotOptimize(relax->GetOutput()->GetBufferPointer());
  }
  const double processMilliseconds = 1000.0 * static_cast<double>(std::clock() - processStart) / CLOCKS_PER_SEC;
  state.SetLabel(relax->GetDeviceLabel() + ", " + std::to_string(relax->GetEffectivePassesPerLaunch()) +
                 " passes a launch");
  state.counters["launches"] = relax->GetNumberOfLaunches();
  state.counters["first_run_ms"] = firstRun.count();
  state.counters["process_cpu_ms"] = processMilliseconds / static_cast<double>(state.iterations());
  state.counters["pixel_updates_per_s"] =
    benchmark::Counter(static_cast<double>(width) * height * 500 * state.iterations(), benchmark::Counter::kIsRate);
}

const bool Registered = []
{
  benchmark::RegisterBenchmark("Relax_OpenCL", RelaxOpenCL, 0u)
    ->Args({ 256, 768 })
    ->Args({ 512, 1024 })
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
  for (const unsigned int passes : { 1u, 2u, 4u, 6u, 8u, 12u, 16u })
  {
    benchmark::RegisterBenchmark("Relax_OpenCL_Passes", RelaxOpenCL, passes)
      ->Args({ 512, 1024, passes })
      ->ArgNames({ "", "", "passes" })
      ->Unit(benchmark::kMillisecond)
      ->UseRealTime()
      ->Repetitions(5)
      ->ReportAggregatesOnly();
  }
  return true;
}();
} // namespace
