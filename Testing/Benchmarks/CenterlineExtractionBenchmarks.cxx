// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// CenterlineExtraction/N: itk::CenterlineExtractionFilter on an N^3 mask of a branching tree (1 mm voxels, five
// generations of tubes: 63 sections); CenterlineExtraction_Plain/N: the plain reference (the same TEASAR on the
// whole grid, see PlainCenterlineExtraction.h) on the same mask, for the ratio. docs/design.md "Numbers": 256^3 in <= 2
// s.
#include "PlainCenterlineExtraction.h"
#include "vrTestSegmentations.h"

#include "itkCenterlineExtractionFilter.h"

#include <benchmark/benchmark.h>

#include <map>

namespace
{
using vr::test::LabelMap;

/** The mask of MakeBranchingTree(size, 5), made once per size. */
const LabelMap *
BranchingTreeMask(unsigned int size)
{
  static std::map<unsigned int, LabelMap::Pointer> masks;
  auto &                                           mask = masks[size];
  if (!mask)
  {
    itk::Size<3> extent;
    extent.Fill(size);
    itk::Vector<double, 3> spacing;
    spacing.Fill(1.0);
    itk::Point<double, 3> origin;
    origin.Fill(0.0);
    itk::Matrix<double, 3, 3> direction;
    direction.SetIdentity();
    mask = vr::test::MakeLabelMap(extent, spacing, origin, direction);
    vr::test::DrawTubes(mask, vr::test::MakeBranchingTree(size, 5));
  }
  return mask;
}

std::size_t
ForegroundVoxels(const LabelMap * mask)
{
  const auto count = mask->GetBufferedRegion().GetNumberOfPixels();
  return static_cast<std::size_t>(
    std::count_if(mask->GetBufferPointer(), mask->GetBufferPointer() + count, [](unsigned char v) { return v != 0; }));
}

void
CenterlineExtraction(benchmark::State & state)
{
  const LabelMap * mask = BranchingTreeMask(static_cast<unsigned int>(state.range(0)));
  auto             filter = itk::CenterlineExtractionFilter<LabelMap>::New();
  filter->SetInput(mask);
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    filter->Modified();
    filter->Update();
    benchmark::DoNotOptimize(filter->GetCenterlineTree().GetNumberOfPoints());
  }
  state.counters["branches"] = static_cast<double>(filter->GetCenterlineTree().GetNumberOfBranches());
  state.counters["foreground"] = static_cast<double>(ForegroundVoxels(mask));
  state.SetLabel(std::to_string(filter->GetNumberOfWorkUnits()) + " work units");
}

void
CenterlineExtractionPlain(benchmark::State & state)
{
  const LabelMap *    mask = BranchingTreeMask(static_cast<unsigned int>(state.range(0)));
  itk::CenterlineTree tree;
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    tree = vr::test::PlainCenterlineExtraction(mask);
    benchmark::DoNotOptimize(tree.GetNumberOfPoints());
  }
  state.counters["branches"] = static_cast<double>(tree.GetNumberOfBranches());
}
} // namespace

BENCHMARK(CenterlineExtraction)->Arg(128)->Arg(256)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(CenterlineExtractionPlain)
  ->Name("CenterlineExtraction_Plain")
  ->Arg(128)
  ->Arg(256)
  ->Unit(benchmark::kMillisecond)
  ->UseRealTime();
