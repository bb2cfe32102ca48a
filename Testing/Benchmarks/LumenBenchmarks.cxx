// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// LumenTable/400/2: the lumen table of 400 sections of a stenosed tube (radius 4 mm narrowing to 2 mm; a 0.6 x 0.8 x
// 1.1 mm mask, rotated, the tube oblique to it) on 2 threads (LumenTable/400/1: on one, for the thread count's
// share): measured from the mask, graded (interpolated reference) and written as CSV. Issue 21: <= 100 ms on 2
// cores.
#include "vrTestLumenTubes.h"

#include "vrVesselStenosis.h"
#include "vrLumenTableIO.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <filesystem>

namespace
{
void
LumenTable(benchmark::State & state)
{
  vr::test::LumenTube tube;
  tube.Radius = vr::test::StenosisRadius;
  tube.SectionStep = 0.2;
  tube.PathLength = 0.2 * static_cast<double>(state.range(0) - 1);
  const auto scene = vr::test::MakeLumenTube(tube);
  const auto path = (std::filesystem::temp_directory_path() / "vr-lumen-benchmark.csv").string();
  itk::VesselLumenMeasurementOptions options;
  options.NumberOfWorkUnits = static_cast<unsigned int>(state.range(1));
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    auto       profile = itk::MeasureVesselLumen(scene.Mask, scene.Sections, options);
    const auto summary = vr::AnalyseVesselStenosis(profile);
    vr::WriteLumenTable(profile, path);
    benchmark::DoNotOptimize(summary.DiameterStenosisPercent);
  }
  std::remove(path.c_str());
  state.counters["sections"] = static_cast<double>(scene.Sections.size());
}
BENCHMARK(LumenTable)->Args({ 400, 2 })->Args({ 400, 1 })->Unit(benchmark::kMillisecond)->UseRealTime();
} // namespace
