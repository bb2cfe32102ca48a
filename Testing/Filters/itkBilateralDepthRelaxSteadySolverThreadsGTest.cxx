// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// BilateralDepthRelaxSteadySolver: the same bits for any number of threads at 512 x 1024, a size whose first coarse
// levels are large enough to be worked in parallel (the four-colour sweep, the Galerkin build, restriction and
// prolongation on bands of rows), on both phantoms' maps: the run-off phantom's (lagged weights only) and the thoracic
// phantom's (Newton steps, negative curvature, hierarchy rebuilds; 54 outer iterations, so against 3 and 7 threads
// only, the uneven splits).
#include "vrTestImages.h"

#include "itkBilateralDepthRelaxSteadyGrid.h"
#include "itkBilateralDepthRelaxSteadySolver.h"
#include "itkCPRDepthImageFilter.h"
#include "itkCTAPhantom.h"

#include <gtest/gtest.h>

#include <initializer_list>
#include <vector>

namespace
{
using Solver = itk::BilateralDepthRelaxSteadySolver;

constexpr unsigned int Width = 512;
constexpr unsigned int Height = 1024;

struct Map
{
  std::vector<float>         Depth;
  std::vector<unsigned char> Fixed;
};

std::vector<float>
Solve(const Map & map, unsigned int threads, Solver::Report & report)
{
  std::vector<float> relaxed(map.Depth.size(), -1.0f);
  report = Solver::Solve(
    map.Depth.data(), map.Fixed.data(), relaxed.data(), Width, Height, 1.0 / 9.0, Solver::DefaultTolerance, threads);
  return relaxed;
}

void
ExpectSameBitsForAnyThreadCount(const Map & map, std::initializer_list<unsigned int> counts)
{
  Solver::Report reference;
  const auto     one = Solve(map, 1, reference);
  for (const unsigned int threads : counts)
  {
    Solver::Report report;
    EXPECT_EQ(Solve(map, threads, report), one) << threads << " threads";
    EXPECT_EQ(report.OuterIterations, reference.OuterIterations) << threads << " threads";
    EXPECT_EQ(report.Cycles, reference.Cycles) << threads << " threads";
  }
}
} // namespace

// The first coarse level (256 x 512 points) is worked in parallel; so is the finest.
TEST(BilateralDepthRelaxSteadySolverThreads, TheCoarseLevelsOfThisSizeRunInParallel)
{
  EXPECT_GE(long{ Width / 2 } * (Height / 2), itk::detail::BilateralDepthRelaxSteady::ParallelPoints);
}

TEST(BilateralDepthRelaxSteadySolverThreads, RunoffPhantomGivesTheSameBitsForAnyThreadCount)
{
  const auto map = vr::test::MakePhantomDepthMap(Width, Height);
  ExpectSameBitsForAnyThreadCount(
    { vr::test::PixelsOf(map.Depth.GetPointer()), vr::test::PixelsOf(map.Fixed.GetPointer()) }, { 2, 3, 4, 7 });
}

TEST(BilateralDepthRelaxSteadySolverThreads, ThoraxPhantomGivesTheSameBitsForAnyThreadCount)
{
  const auto phantom = itk::MakeCTAPhantom(itk::CTAPhantomKind::Thorax);
  auto       filter = itk::CPRDepthImageFilter<itk::Image<float, 2>>::New();
  filter->SetCenterlineTree(phantom.Tree);
  itk::CPRViewSpecification view;
  view.AngleInDegrees = phantom.DesignAngleInDegrees;
  view.ImageSize = { { Width, Height } };
  filter->SetViewSpecification(view);
  filter->Update();
  ExpectSameBitsForAnyThreadCount(
    { vr::test::PixelsOf(filter->GetDepthOutput()), vr::test::PixelsOf(filter->GetFixedMaskOutput()) }, { 3, 7 });
}
