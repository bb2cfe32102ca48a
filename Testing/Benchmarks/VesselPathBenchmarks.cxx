// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The single-vessel path view (issue 21, docs/vessel-path.md) on the run-off phantom's longest path (about 1 m,
// aorta to foot), its filters kept between iterations as a viewer keeps them:
//   VesselPath_Build              the default path from the tree (what choosing a vessel costs before any frame)
//   VesselPath_Frame/N            the rotation-minimising frame at N sections (what a path change adds)
//   VesselPath_Straightened/W/H   a straightened CPR of W x H pixels of 0.25 mm for a new roll (target 20 ms at
//                                 512 x 1024)
//   VesselPath_Stretched/W/H      the stretched CPR at the same size (a stretched CPR ignores the roll, so each
//                                 iteration recomputes the same image)
//   VesselPath_CrossSections/U/V/N  the cross-section stack of N planes of U x V pixels for a new roll (target 100 ms
//                                 at 128 x 128 x 400)
// The plain reference is the tree CPR's Resample/512/1024 in PipelineBenchmarks.cxx: the same number of linear
// samples of the same volume, by the sampling code these filters share.
#include "vrBenchmarkScene.h"

#include "itkCrossSectionStackImageFilter.h"
#include "itkRotationMinimizingFrame.h"
#include "itkStraightenedCPRImageFilter.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <string>

namespace
{
using vr::benchmarks::PhantomScene;
using vr::benchmarks::VolumeImage;
using CPRFilter = itk::StraightenedCPRImageFilter<VolumeImage>;
using StackFilter = itk::CrossSectionStackImageFilter<VolumeImage>;

const itk::VesselPath &
LongestPath()
{
  static const itk::VesselPath path = itk::VesselPath::FromTree(PhantomScene::Instance().GetCenterlineTree());
  return path;
}

void
Build(benchmark::State & state)
{
  const auto & tree = PhantomScene::Instance().GetCenterlineTree();
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    benchmark::DoNotOptimize(itk::VesselPath::FromTree(tree).GetLength());
  }
}

void
Frame(benchmark::State & state)
{
  const auto & path = LongestPath();
  const double step = path.GetLength() / static_cast<double>(state.range(0) - 1);
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    benchmark::DoNotOptimize(itk::RotationMinimizingFrame::Compute(path, step, itk::CPRViewGeometry()).size());
  }
}

/** W x H pixels of 0.25 mm: a quarter of a metre of the path (aorta to thigh), 128 mm wide, every sample inside the
 * volume as in a real reading. */
void
CPR(benchmark::State & state, itk::VesselPathCPRMode mode)
{
  const double spacing = 0.25;
  auto         filter = CPRFilter::New();
  filter->SetVolume(PhantomScene::Instance().GetVolume());
  filter->SetMode(mode);
  filter->SetPixelSpacing(spacing);
  filter->SetWidth(static_cast<double>(state.range(0)) * spacing);
  // Stretched rows follow the projected path, shorter than the path: cut the path so either has H rows.
  double length = static_cast<double>(state.range(1) - 1) * spacing;
  filter->SetPath(LongestPath().Cut(0.0, length + 0.1));
  if (mode == itk::VesselPathCPRMode::Stretched)
  {
    filter->UpdateOutputInformation();
    length *= length / (static_cast<double>(filter->GetSections().size() - 1) * spacing);
    filter->SetPath(LongestPath().Cut(0.0, std::min(LongestPath().GetLength(), length + 0.1)));
  }
  // The phantom's path bends tighter than 64 mm: every update would warn of folds (a figure, not a failure here).
  const bool warnings = itk::Object::GetGlobalWarningDisplay();
  itk::Object::GlobalWarningDisplayOff();
  filter->Update(); // not timed: the volume's minimum, once per volume
  double roll = 0.0;
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    filter->SetRollAngle(roll += 1.0);
    filter->Update();
    benchmark::DoNotOptimize(filter->GetOutput()->GetBufferPointer());
  }
  itk::Object::SetGlobalWarningDisplay(warnings);
  state.counters["folded_pixels"] = static_cast<double>(filter->GetNumberOfFoldedPixels());
  const auto size = filter->GetOutput()->GetLargestPossibleRegion().GetSize();
  state.SetLabel(std::to_string(size[0]) + " x " + std::to_string(size[1]) + " pixels");
}

void
Straightened(benchmark::State & state)
{
  CPR(state, itk::VesselPathCPRMode::Straightened);
}

void
Stretched(benchmark::State & state)
{
  CPR(state, itk::VesselPathCPRMode::Stretched);
}

void
CrossSections(benchmark::State & state)
{
  auto filter = StackFilter::New();
  filter->SetVolume(PhantomScene::Instance().GetVolume());
  filter->SetPath(LongestPath());
  filter->SetSectionSize(
    { { static_cast<itk::SizeValueType>(state.range(0)), static_cast<itk::SizeValueType>(state.range(1)) } });
  filter->SetSectionSpacing(itk::Vector<double, 2>(0.3));
  filter->SetSectionStep(LongestPath().GetLength() / static_cast<double>(state.range(2) - 1) * (1.0 - 1e-9));
  filter->Update(); // not timed: the volume's minimum
  double roll = 0.0;
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    filter->SetRollAngle(roll += 1.0);
    filter->Update();
    benchmark::DoNotOptimize(filter->GetOutput()->GetBufferPointer());
  }
}

const bool Registered = []
{
  const auto configure = [](benchmark::internal::Benchmark * b)
  { b->Unit(benchmark::kMillisecond)->UseRealTime()->Repetitions(10)->ReportAggregatesOnly(); };
  configure(benchmark::RegisterBenchmark("VesselPath_Build", Build));
  configure(benchmark::RegisterBenchmark("VesselPath_Frame", Frame)->Arg(1024));
  configure(benchmark::RegisterBenchmark("VesselPath_Straightened", Straightened)->Args({ 512, 1024 }));
  configure(benchmark::RegisterBenchmark("VesselPath_Stretched", Stretched)->Args({ 512, 1024 }));
  configure(benchmark::RegisterBenchmark("VesselPath_CrossSections", CrossSections)->Args({ 128, 128, 400 }));
  return true;
}();
} // namespace
