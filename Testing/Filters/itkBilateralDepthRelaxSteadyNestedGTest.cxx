// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// BilateralDepthRelaxSteadySolver's nested iteration (issue 26): on the thoracic phantom, whose arch seams near the
// range kernel's inflection made the outer iterations multiply with the size, the solve from the coarser grids'
// solution reaches an energy at least as low as the solve from the input depths (the solver before nested iteration,
// still selectable), both measured by the plain reference energy, with the plain residual below 1e-4 mm, in a
// bounded number of outer iterations on the image's own grid; a solve held to fewer outer iterations stops with the
// last iterate and says how far it got; the filter passes that on as its warning; the progress rises across the
// grids.
#include "PlainBilateralDepthRelax.h"
#include "vrTestDepthMaps.h"
#include "vrTestImages.h"

#include "itkBilateralDepthRelaxFilter.h"
#include "itkBilateralDepthRelaxSteadyNested.h"
#include "itkBilateralDepthRelaxSteadySolver.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
using Solver = itk::BilateralDepthRelaxSteadySolver;

/** The jump threshold J = 3 mm of the filter's default, as the anisotropy a = 1/J^2. */
constexpr double Anisotropy = 1.0 / 9.0;

/** The most outer iterations on the image's own grid that a thoracic solve from the coarser grids may take (8 at
 * 256 x 512, 9 at 512 x 1024); from the input it took 34 and 51 (and 19 at 128 x 256, whose grid is solved from its
 * input). */
constexpr unsigned int FineOuterIterationBound = 16;

/** The thoracic phantom's scan-line depth map and fixed mask at its design angle. */
using Map = vr::test::DepthMapBuffers;

Map
ThoraxMap(unsigned int width, unsigned int height)
{
  return vr::test::ThoraxDepthMapBuffers(width, height);
}

std::vector<double>
Solve(const Map & map, const Solver::Settings & settings, Solver::Report & report, unsigned int threads = 2)
{
  std::vector<float> relaxed(map.Depth.size(), -1.0f);
  report = Solver::Solve(map.Depth.data(),
                         map.Fixed.data(),
                         relaxed.data(),
                         map.Width,
                         map.Height,
                         Anisotropy,
                         Solver::DefaultTolerance,
                         threads,
                         {},
                         nullptr,
                         settings);
  for (std::size_t k = 0; k < relaxed.size(); ++k)
  {
    if (map.Fixed[k])
    {
      EXPECT_EQ(relaxed[k], map.Depth[k]) << "fixed pixel " << k;
    }
  }
  return { relaxed.begin(), relaxed.end() };
}

Solver::Settings
FromInput()
{
  Solver::Settings settings = Solver::DefaultSettings();
  settings.NestedIteration = false;
  settings.MaximumOuterIterations = 1000;
  return settings;
}
} // namespace

TEST(BilateralDepthRelaxSteadyNested, ThoraxReachesTheEnergyOfTheSolveFromTheInputInBoundedOuterIterations)
{
  for (const unsigned int width : { 256u, 512u })
  {
    const Map      map = ThoraxMap(width, 2 * width);
    Solver::Report nested, input;
    const auto     fromCoarse = Solve(map, Solver::DefaultSettings(), nested);
    const auto     fromInput = Solve(map, FromInput(), input);
    const double   energy = vr::test::PlainRelaxEnergy(fromCoarse, map.Width, map.Height, Anisotropy);
    const double   inputEnergy = vr::test::PlainRelaxEnergy(fromInput, map.Width, map.Height, Anisotropy);
    const double residual = vr::test::PlainFixedPointResidual(fromCoarse, map.Fixed, map.Width, map.Height, Anisotropy);
    EXPECT_TRUE(nested.Converged);
    EXPECT_GE(nested.Grids, 2u) << width << ": started from a coarser grid";
    EXPECT_LE(nested.OuterIterations, FineOuterIterationBound) << width;
    EXPECT_LE(residual, 1e-4) << width;
    // The energy is not convex: the solves may end in different minima. The nested one must not end in a worse one.
    EXPECT_LE(energy, inputEnergy * (1.0 + 1e-6)) << width;
    std::cout << width << " x " << 2 * width << " thoracic phantom: " << nested.OuterIterations
              << " outer iterations on its grid, " << nested.CoarseOuterIterations << " on " << nested.Grids - 1
              << " coarser grids, energy " << energy << " mm^2, residual " << residual << " mm; from the input "
              << input.OuterIterations << " outer iterations, energy " << inputEnergy << " mm^2" << std::endl;
  }
}

// Which grids start from a coarser one (docs/steady-solver.md): an image whose coarser grid has 128 x 128 pixels or
// more (from about 181 x 362 at H = 2 W; odd sizes rounded up), a coarser grid of a nested solve down to 64 x 128,
// never more than three coarser grids below the image's.
TEST(BilateralDepthRelaxSteadyNested, ImagesWithCoarserGridsFrom128x128AndCoarserGridsTo64x128NestAtMostThreeGridsDeep)
{
  namespace Steady = itk::detail::BilateralDepthRelaxSteady;
  long w = 0;
  long h = 0;
  ASSERT_TRUE(Steady::HasCoarserStart(256, 512, 0, w, h));
  EXPECT_EQ(w, 128);
  EXPECT_EQ(h, 256);
  ASSERT_TRUE(Steady::HasCoarserStart(253, 395, 0, w, h)) << "the full-size thoracic view at 1 mm a pixel";
  EXPECT_EQ(w, 127);
  EXPECT_EQ(h, 198);
  ASSERT_TRUE(Steady::HasCoarserStart(181, 363, 0, w, h));
  EXPECT_EQ(w, 91);
  EXPECT_EQ(h, 182);
  EXPECT_FALSE(Steady::HasCoarserStart(180, 362, 0, w, h)) << "90 x 181 coarser pixels";
  EXPECT_FALSE(Steady::HasCoarserStart(128, 256, 0, w, h)) << "an image of 128 x 256 is solved from its input";
  ASSERT_TRUE(Steady::HasCoarserStart(128, 256, 1, w, h)) << "a coarser grid of 128 x 256";
  EXPECT_EQ(w, 64);
  EXPECT_EQ(h, 128);
  EXPECT_FALSE(Steady::HasCoarserStart(126, 254, 1, w, h)) << "63 x 127 coarser pixels";
  EXPECT_FALSE(Steady::HasCoarserStart(64, 128, 2, w, h));
  unsigned int grids = 0;
  while (Steady::HasCoarserStart(4096, 8192, grids, w, h))
  {
    ++grids;
  }
  EXPECT_EQ(grids, 3u) << "coarser grids below a 4096 x 8192 image";
  EXPECT_EQ(Steady::MaximumCoarserGrids, 3u);
}

// Issue 40: a map that lagged weights bring down tenfold before they slow down goes on from there with Newton steps
// (the run-off phantom at 200 x 400: the same bits as the solve from its input), where one whose lagged weights slow
// down at once starts again from the coarser grid (the thoracic phantom at 200 x 400: fewer outer iterations on its
// grid, and no higher an energy).
TEST(BilateralDepthRelaxSteadyNested, OnlyMapsWhoseLaggedWeightsSlowDownEarlyStartAgainFromTheCoarserGrid)
{
  const Map        runoff = vr::test::RunoffDepthMapBuffers(200, 400);
  Solver::Report   nested, input;
  const auto       runoffNested = Solve(runoff, Solver::DefaultSettings(), nested);
  Solver::Settings fromInput = FromInput();
  fromInput.MaximumOuterIterations = Solver::DefaultMaximumOuterIterations;
  const auto runoffInput = Solve(runoff, fromInput, input);
  EXPECT_EQ(nested.Grids, 1u);
  EXPECT_EQ(runoffNested, runoffInput);

  const Map  thorax = ThoraxMap(200, 400);
  const auto thoraxNested = Solve(thorax, Solver::DefaultSettings(), nested);
  const auto thoraxInput = Solve(thorax, FromInput(), input);
  EXPECT_EQ(nested.Grids, 2u);
  EXPECT_LT(nested.OuterIterations, input.OuterIterations);
  EXPECT_LE(vr::test::PlainRelaxEnergy(thoraxNested, thorax.Width, thorax.Height, Anisotropy),
            vr::test::PlainRelaxEnergy(thoraxInput, thorax.Width, thorax.Height, Anisotropy) * (1.0 + 1e-6));
  EXPECT_LE(vr::test::PlainFixedPointResidual(thoraxNested, thorax.Fixed, thorax.Width, thorax.Height, Anisotropy),
            1e-4);
}

TEST(BilateralDepthRelaxSteadyNested, ABoundedSolveStopsWithTheLastIterateAndSaysHowFarItGot)
{
  const Map        map = ThoraxMap(128, 256);
  Solver::Settings settings = FromInput();
  settings.MaximumOuterIterations = 3;
  Solver::Report report;
  const auto     relaxed = Solve(map, settings, report);
  EXPECT_FALSE(report.Converged);
  EXPECT_EQ(report.OuterIterations, 3u);
  EXPECT_GT(report.Residual, Solver::DefaultTolerance);
  const double energy = vr::test::PlainRelaxEnergy(relaxed, map.Width, map.Height, Anisotropy);
  EXPECT_NEAR(report.Energy, energy, 1e-8 * energy) << "the report's energy (of depths in double, the output in float)";
  const double inputEnergy = vr::test::PlainRelaxEnergy(
    std::vector<double>(map.Depth.begin(), map.Depth.end()), map.Width, map.Height, Anisotropy);
  EXPECT_LT(energy, inputEnergy) << "three descent steps lower the energy";
  const std::string message = Solver::Describe(report, Solver::DefaultTolerance);
  EXPECT_NE(message.find("stopped after 3 outer iterations"), std::string::npos) << message;
  EXPECT_NE(message.find("residual"), std::string::npos) << message;
  EXPECT_NE(message.find("energy"), std::string::npos) << message;

  // No outer iteration at all: the input itself, said so.
  settings.MaximumOuterIterations = 0;
  const auto untouched = Solve(map, settings, report);
  EXPECT_FALSE(report.Converged);
  EXPECT_EQ(report.OuterIterations, 0u);
  EXPECT_EQ(untouched, std::vector<double>(map.Depth.begin(), map.Depth.end()));
}

TEST(BilateralDepthRelaxSteadyNested, TheFilterWarnsWhenItsBoundStopsTheSolve)
{
  const Map  map = ThoraxMap(64, 128);
  auto       filter = itk::BilateralDepthRelaxFilter<itk::Image<float, 2>>::New();
  const auto depth = vr::test::MakeDepthImage(map.Width, map.Height, map.Depth);
  const auto fixed = vr::test::MakeMaskImage(map.Width, map.Height, map.Fixed);
  filter->SetDepthInput(depth);
  filter->SetFixedMask(fixed);
  filter->SetSolver(itk::BilateralDepthRelaxSolver::Steady);
  EXPECT_EQ(filter->GetSteadyMaximumOuterIterations(), Solver::DefaultMaximumOuterIterations);
  filter->Update();
  EXPECT_TRUE(filter->GetSteadyReport().Converged);
  EXPECT_EQ(filter->GetSteadyWarning(), "");
  filter->SetSteadyMaximumOuterIterations(2);
  filter->Update();
  EXPECT_FALSE(filter->GetSteadyReport().Converged);
  const std::string warning = filter->GetSteadyWarning();
  EXPECT_NE(warning.find("stopped after 2 outer iterations"), std::string::npos) << warning;
  EXPECT_NE(warning.find("tolerance 0.0001 mm"), std::string::npos) << warning;
}

// Across the attempt from the input, the coarser grids and the image's grid, the progress never goes back and ends
// at 1; a callback that throws on a coarser grid stops the whole solve.
TEST(BilateralDepthRelaxSteadyNested, ProgressRisesAcrossTheGridsAndAThrowingCallbackStopsTheSolve)
{
  const Map           map = ThoraxMap(256, 512);
  std::vector<double> reported;
  std::vector<float>  relaxed(map.Depth.size());
  const auto          report = Solver::Solve(map.Depth.data(),
                                    map.Fixed.data(),
                                    relaxed.data(),
                                    map.Width,
                                    map.Height,
                                    Anisotropy,
                                    Solver::DefaultTolerance,
                                    2,
                                    [&](double fraction) { reported.push_back(fraction); });
  ASSERT_GE(report.Grids, 2u);
  ASSERT_GE(reported.size(), 3u);
  EXPECT_TRUE(std::is_sorted(reported.begin(), reported.end()));
  EXPECT_EQ(reported.front(), 0.0);
  EXPECT_EQ(reported.back(), 1.0);

  // The attempt from the input calls it a few times (report.OuterIterations counts them too); the coarser grid's
  // solve is the next to call it.
  unsigned int calls = 0;
  EXPECT_THROW(Solver::Solve(map.Depth.data(),
                             map.Fixed.data(),
                             relaxed.data(),
                             map.Width,
                             map.Height,
                             Anisotropy,
                             Solver::DefaultTolerance,
                             2,
                             [&](double)
                             {
                               if (++calls == 4)
                               {
                                 throw std::runtime_error("stop");
                               }
                             }),
               std::runtime_error);
  EXPECT_EQ(calls, 4u);
}

// The coarser grids borrow the finer grid's scratch arrays and give them back zeroed: a workspace whose solve threw
// while a coarser grid was being solved (its arrays lent, dirty) then gives the same bits as a fresh one, and so
// does a third solve after a completed nested one.
TEST(BilateralDepthRelaxSteadyNested, AWorkspaceLentToACoarserGridThatThrewChangesNoBit)
{
  const Map          map = ThoraxMap(256, 512);
  std::vector<float> fresh(map.Depth.size());
  const auto         report = Solver::Solve(
    map.Depth.data(), map.Fixed.data(), fresh.data(), map.Width, map.Height, Anisotropy, Solver::DefaultTolerance, 2);
  ASSERT_GE(report.Grids, 2u);

  Solver::Workspace  workspace;
  std::vector<float> relaxed(map.Depth.size());
  unsigned int       calls = 0;
  EXPECT_THROW(Solver::Solve(
                 map.Depth.data(),
                 map.Fixed.data(),
                 relaxed.data(),
                 map.Width,
                 map.Height,
                 Anisotropy,
                 Solver::DefaultTolerance,
                 2,
                 [&](double)
                 {
                   if (++calls == 4) // the coarser grid's first call (see the test above)
                   {
                     throw std::runtime_error("stop");
                   }
                 },
                 &workspace),
               std::runtime_error);
  for (int solve = 0; solve < 2; ++solve)
  {
    std::fill(relaxed.begin(), relaxed.end(), 0.0f);
    const auto again = Solver::Solve(map.Depth.data(),
                                     map.Fixed.data(),
                                     relaxed.data(),
                                     map.Width,
                                     map.Height,
                                     Anisotropy,
                                     Solver::DefaultTolerance,
                                     2,
                                     Solver::ProgressCallback(),
                                     &workspace);
    EXPECT_EQ(again.Grids, report.Grids);
    EXPECT_EQ(again.OuterIterations, report.OuterIterations);
    EXPECT_EQ(std::memcmp(relaxed.data(), fresh.data(), fresh.size() * sizeof(float)), 0) << "solve " << solve;
  }
}
