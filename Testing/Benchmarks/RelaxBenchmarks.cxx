// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Relax_CPU/W/H: BilateralDepthRelaxFilter on the CPU (all cores, the widest instruction set); Relax_Plain/W/H:
// the plain reference (a scalar double loop over Eq. 1, one thread) on the same input, for the ratio;
// Relax_Generic/512/1024: the filter's previous CPU loop (now its generic path), for a second ratio;
// Relax_CPU_<set>/512/1024: the CPU relax forced to a narrower instruction set. The paper's filter
// settings: 500 iterations, w = 1; a = 0.5 mm^-2 (the figures kept comparable with earlier runs; the filter's default
// is now J = 3 mm). Relax_Steady/W/H: the steady solver (the fixed point, J = 3 mm, residual 1e-4 mm) on the same
// map, against the same plain reference; Relax_Steady_Thorax/W/H and Relax_Steady_Aorta/W/H on the thoracic phantom
// and the VMTK aorta MRA, at 256 x 512 to 2048 x 4096 beside Relax_CPU at the same sizes (issue 26: the steady
// solve's cost grows with the pixels); Relax_Steady_AortaIliacs/W/H on the aorta at 97 degrees, where its iliacs
// cross in the image, and Relax_Steady_FullSize/W/H on the thoracic phantom as the module views a full-size study of
// it (0.5 mm voxels) at 1, 0.5 and 0.25 mm a pixel, beside Relax_CPU_FullSize/W/H, the 500 passes on the same maps
// (issue 40: the steady solve on real anatomy).
#include "vrBenchmarkScene.h"

#include "PlainBilateralDepthRelax.h"

#include "itkBilateralDepthRelaxFilter.h"
#include "itkBilateralDepthRelaxKernel.h"
#include "itkPlatformMultiThreader.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <exception>
#include <string>
#include <vector>

namespace
{
using vr::benchmarks::AortaDepthMap;
using vr::benchmarks::DepthImage;
using vr::benchmarks::FullSizeDepthMap;
using vr::benchmarks::PhantomScene;
using vr::benchmarks::ThoraxDepthMap;

constexpr unsigned int Iterations = 500;
constexpr double       Relaxation = 1.0;
constexpr double       Anisotropy = 0.5;

/** Gives \a filter a team of \a threads threads; with 0, leaves it the filter's default, one thread per core
 * (BilateralDepthRelaxFilter::GetNumberOfHostThreads). The team is min(work units, the threader's threads), so a team
 * larger than the cores gets a threader of its own: raising the maximum of ITK's pool threader would grow the
 * process's one pool for good, and the other ITK filters the later benchmarks run (depth, resampling, the generic
 * relax) would share the cores among that many threads. */
void
SetTeam(itk::ProcessObject & filter, unsigned int threads)
{
  if (threads == 0)
  {
    return;
  }
  if (threads > itk::MultiThreaderBase::GetGlobalDefaultNumberOfThreads())
  {
    auto threader = itk::PlatformMultiThreader::New();
    threader->SetMaximumNumberOfThreads(threads);
    filter.SetMultiThreader(threader);
  }
  filter.SetNumberOfWorkUnits(threads);
}

/** One untimed update, so that the timed ones find the filter's workspace allocated, as the viewer's repeated updates
 * do. Each repetition makes a new filter, and the benchmarks that run once per repetition (the steady ones, and the
 * passes at 1024 x 2048 and more) would otherwise time the first touch of tens of MB of fresh pages with every solve
 * (at 512 x 1024 about 50 MB, measured 70 ms of the steady thoracic solve's 310), where the others spread it over
 * their iterations. */
void
WarmUp(itk::ProcessObject & filter)
{
  filter.Update();
  filter.Modified();
}

/** Relax_CPU/W/H (all cores), Relax_CPU/W/H/threads:N (a team of N threads, on any machine), and
 * Relax_CPU_Passes/W/H/threads:N/passes:K (K passes between synchronizations instead of the kernel's choice); with
 * \a fullSize, Relax_CPU_FullSize/W/H on the full-size view's map instead of the run-off phantom's. */
void
RelaxCPU(benchmark::State & state, unsigned int threads, unsigned int passes, bool fullSize = false)
{
  const auto & map = fullSize ? FullSizeDepthMap(state.range(0), state.range(1))
                              : PhantomScene::Instance().GetDepthMap(state.range(0), state.range(1));
  auto         filter = itk::BilateralDepthRelaxFilter<DepthImage>::New();
  filter->SetDepthInput(map.Depth);
  filter->SetFixedMask(map.Fixed);
  filter->SetRelaxation(Relaxation);
  filter->SetAnisotropy(Anisotropy);
  filter->SetNumberOfIterations(Iterations);
  SetTeam(*filter, threads);
  filter->SetPassesBetweenSynchronizations(passes);
  WarmUp(*filter);
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    filter->Modified();
    filter->Update();
    benchmark::DoNotOptimize(filter->GetOutput()->GetBufferPointer());
  }
  // The filter's team: one thread per work unit, at most as many as the threader's threads.
  const unsigned int team = filter->GetNumberOfHostThreads();
  // Which path ran: 1 pass is the plain sweep with a barrier after every pass, more the blocks.
  const unsigned int blocks =
    passes > 0 ? passes : itk::BilateralDepthRelaxKernel::ChoosePassesBetweenSynchronizations(state.range(1), team);
  state.SetLabel(itk::BilateralDepthRelaxKernel::GetInstructionSet() + ", " + std::to_string(team) + " threads, " +
                 std::to_string(blocks) + " passes between synchronizations" +
                 (passes > 0 ? "" : " (kernel's choice)"));
}

/** The same relax with a narrower instruction set than the processor's widest: how a build runs elsewhere. */
void
RelaxCPUWithInstructionSet(benchmark::State & state, const std::string & instructionSet)
{
  itk::BilateralDepthRelaxKernel::SetInstructionSet(instructionSet);
  RelaxCPU(state, 0, 0);
  itk::BilateralDepthRelaxKernel::SetInstructionSet("");
}

/** The filter's previous CPU loop, kept as its generic path for pixel types other than float: Eq. 1 in double,
 * one exponential per neighbour, rows through ITK's threader (all cores). Run on a double copy of the map. */
void
RelaxGeneric(benchmark::State & state)
{
  using DoubleImage = itk::Image<double, 2>;
  const auto & map = PhantomScene::Instance().GetDepthMap(state.range(0), state.range(1));
  auto         depth = DoubleImage::New();
  depth->CopyInformation(map.Depth);
  depth->SetRegions(map.Depth->GetLargestPossibleRegion());
  depth->Allocate();
  std::copy_n(
    map.Depth->GetBufferPointer(), map.Depth->GetBufferedRegion().GetNumberOfPixels(), depth->GetBufferPointer());
  auto filter = itk::BilateralDepthRelaxFilter<DoubleImage>::New();
  filter->SetDepthInput(depth);
  filter->SetFixedMask(map.Fixed);
  filter->SetRelaxation(Relaxation);
  filter->SetAnisotropy(Anisotropy);
  filter->SetNumberOfIterations(Iterations);
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    filter->Modified();
    filter->Update();
    benchmark::DoNotOptimize(filter->GetOutput()->GetBufferPointer());
  }
  state.SetLabel("generic loop, double image, " + std::to_string(filter->GetNumberOfWorkUnits()) + " work units");
}

/** Where a steady benchmark's map comes from. */
enum class SteadyCase
{
  Runoff,
  Thorax,
  Aorta,
  AortaIliacs,
  FullSize
};

/** The steady solver with the filter's defaults (J = 3 mm, tolerance 1e-4 mm), all cores, on the run-off phantom's
 * map (Relax_Steady), the thoracic phantom's (Relax_Steady_Thorax, whose arch seams the solver works longest on) or
 * the VMTK aorta MRA's (Relax_Steady_Aorta). */
void
RelaxSteady(benchmark::State & state, SteadyCase steadyCase)
{
  const auto   width = static_cast<unsigned int>(state.range(0));
  const auto   height = static_cast<unsigned int>(state.range(1));
  const auto * map = &PhantomScene::Instance().GetDepthMap(width, height);
  try
  {
    if (steadyCase == SteadyCase::Thorax)
    {
      map = &ThoraxDepthMap(width, height);
    }
    else if (steadyCase == SteadyCase::Aorta)
    {
      map = &AortaDepthMap(width, height);
    }
    else if (steadyCase == SteadyCase::AortaIliacs)
    {
      map = &AortaDepthMap(width, height, vr::benchmarks::AortaIliacsOverlapAngle);
    }
    else if (steadyCase == SteadyCase::FullSize)
    {
      map = &FullSizeDepthMap(width, height);
    }
  }
  catch (const std::exception & error)
  {
    state.SkipWithError(error.what());
    return;
  }
  auto filter = itk::BilateralDepthRelaxFilter<DepthImage>::New();
  filter->SetDepthInput(map->Depth);
  filter->SetFixedMask(map->Fixed);
  filter->SetSolver(itk::BilateralDepthRelaxSolver::Steady);
  WarmUp(*filter);
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    filter->Modified();
    filter->Update();
    benchmark::DoNotOptimize(filter->GetOutput()->GetBufferPointer());
  }
  const auto & report = filter->GetSteadyReport();
  state.SetLabel("steady, J = 3 mm, " + std::to_string(filter->GetNumberOfHostThreads()) + " threads, " +
                 std::to_string(report.OuterIterations) + " outer iterations (" +
                 std::to_string(report.CoarseOuterIterations) + " on " + std::to_string(report.Grids - 1) +
                 " coarser grids), " + std::to_string(report.Cycles) + " V-cycles" +
                 (report.Converged ? "" : ", stopped short"));
}

void
RelaxPlain(benchmark::State & state)
{
  const auto &             map = PhantomScene::Instance().GetDepthMap(state.range(0), state.range(1));
  const auto               size = map.Depth->GetLargestPossibleRegion().GetSize();
  const std::vector<float> depth(map.Depth->GetBufferPointer(), map.Depth->GetBufferPointer() + size[0] * size[1]);
  const std::vector<unsigned char> fixed(map.Fixed->GetBufferPointer(),
                                         map.Fixed->GetBufferPointer() + size[0] * size[1]);
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    auto relaxed =
      vr::test::PlainBilateralDepthRelax(depth, fixed, size[0], size[1], Relaxation, Anisotropy, Iterations);
    benchmark::DoNotOptimize(relaxed.data());
  }
  state.SetLabel("scalar double loop, 1 thread");
}

/** What every relax benchmark shares: a W x H image, milliseconds of real time, the median of \a repetitions; with
 * \a oneRun, one iteration per repetition, for those that take seconds per run. \a threads and \a passes, where not
 * 0, name RelaxCPU's team size and passes between synchronizations in the benchmark's name. */
void
Register(benchmark::internal::Benchmark * b,
         long                             width,
         long                             height,
         int                              repetitions,
         bool                             oneRun,
         long                             threads = 0,
         long                             passes = 0)
{
  std::vector<long>        args{ width, height };
  std::vector<std::string> names{ "", "" };
  if (threads > 0)
  {
    args.push_back(threads);
    names.emplace_back("threads");
  }
  if (passes > 0)
  {
    args.push_back(passes);
    names.emplace_back("passes");
  }
  b->Args(args)->ArgNames(names);
  b->Unit(benchmark::kMillisecond)->UseRealTime()->Repetitions(repetitions)->ReportAggregatesOnly();
  if (oneRun)
  {
    b->Iterations(1);
  }
}

const bool Registered = []
{
  for (const auto & size : { std::pair<long, long>{ 256, 768 }, std::pair<long, long>{ 512, 1024 } })
  {
    // Seconds per run: a few runs give a stable median.
    Register(benchmark::RegisterBenchmark("Relax_Plain", RelaxPlain), size.first, size.second, 3, true);
  }
  // The paper's sizes, and the steady solver's from 256 x 512 to 2048 x 4096 (each x 4 of pixels), the largest once
  // (its runs take seconds).
  for (const auto & size : { std::pair<long, long>{ 256, 512 },
                             std::pair<long, long>{ 256, 768 },
                             std::pair<long, long>{ 512, 1024 },
                             std::pair<long, long>{ 1024, 2048 },
                             std::pair<long, long>{ 2048, 4096 } })
  {
    const bool largest = size.first == 2048;
    const bool large = size.first >= 1024;
    Register(benchmark::RegisterBenchmark("Relax_CPU", RelaxCPU, 0u, 0u, false),
             size.first,
             size.second,
             large ? 3 : 10,
             large);
    if (size.second == 2 * size.first)
    {
      Register(benchmark::RegisterBenchmark("Relax_Steady", RelaxSteady, SteadyCase::Runoff),
               size.first,
               size.second,
               largest ? 1 : (large ? 3 : 10),
               large);
      Register(benchmark::RegisterBenchmark("Relax_Steady_Thorax", RelaxSteady, SteadyCase::Thorax),
               size.first,
               size.second,
               largest ? 1 : (large ? 3 : 10),
               large);
      Register(benchmark::RegisterBenchmark("Relax_Steady_Aorta", RelaxSteady, SteadyCase::Aorta),
               size.first,
               size.second,
               largest ? 1 : (large ? 3 : 10),
               large);
      Register(benchmark::RegisterBenchmark("Relax_Steady_AortaIliacs", RelaxSteady, SteadyCase::AortaIliacs),
               size.first,
               size.second,
               largest ? 1 : (large ? 3 : 10),
               large);
    }
  }
  // The full-size study's views, each x 4 the pixels of the one before, with the 500 passes on the same maps.
  for (const auto & view : vr::benchmarks::FullSizeViews())
  {
    const bool large = static_cast<double>(view.Width) * view.Height > 1.5e6;
    Register(benchmark::RegisterBenchmark("Relax_Steady_FullSize", RelaxSteady, SteadyCase::FullSize),
             view.Width,
             view.Height,
             large ? 3 : 10,
             large);
    Register(benchmark::RegisterBenchmark("Relax_CPU_FullSize", RelaxCPU, 0u, 0u, true),
             view.Width,
             view.Height,
             large ? 3 : 10,
             large);
  }
  // Team sizes for scaling: the same run compares them (docs/design.md, temporal blocking).
  for (const unsigned int threads : { 1u, 2u, 4u, 8u, 16u })
  {
    Register(benchmark::RegisterBenchmark("Relax_CPU", RelaxCPU, threads, 0u, false), 512, 1024, 10, false, threads);
  }
  // Fixed passes between synchronizations, to check the kernel's choice on a new machine.
  for (const unsigned int threads : { 1u, 2u, 16u })
  {
    for (const unsigned int passes : { 1u, 4u, 8u, 16u, 32u })
    {
      Register(benchmark::RegisterBenchmark("Relax_CPU_Passes", RelaxCPU, threads, passes, false),
               512,
               1024,
               5,
               false,
               threads,
               passes);
    }
  }
  Register(benchmark::RegisterBenchmark("Relax_Generic", RelaxGeneric), 512, 1024, 3, true);
  const auto supported = itk::BilateralDepthRelaxKernel::GetSupportedInstructionSets();
  for (std::size_t k = 1; k < supported.size(); ++k)
  {
    // "AVX2+FMA" -> "Relax_CPU_AVX2+FMA": no slash, so the name keeps its W/H fields.
    Register(
      benchmark::RegisterBenchmark(("Relax_CPU_" + supported[k]).c_str(), RelaxCPUWithInstructionSet, supported[k]),
      512,
      1024,
      5,
      true);
  }
  return true;
}();
} // namespace
