// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The steady solver on real anatomy: VMTK's aorta MRA where its two iliac arteries cross in the image (the benchmark
// case Relax_Steady_AortaIliacs), whose depth map has lines of pixels between two depth steps, coupled along the line
// only (docs/steady-solver.md, "Lines of pixels coupled along themselves only"). Before the multigrid's interpolation
// left those lines alone, the conjugate gradients stopped at their cap from the eighth outer iteration on: 158
// V-cycles at 256 x 512 and 400 at 512 x 1024; now 18 and 12
// (docs/measurements/2026-11-29-steady-weak-regions.md).
#include "PlainBilateralDepthRelax.h"
#include "vrBenchmarkScene.h"
#include "vrTestImages.h"

#include "itkBilateralDepthRelaxSteadySolver.h"

#include <gtest/gtest.h>

#include <iostream>
#include <vector>

namespace
{
using Solver = itk::BilateralDepthRelaxSteadySolver;
constexpr double Anisotropy = 1.0 / 9.0; // J = 3 mm, the filter's default

struct Solved
{
  Solver::Report     Report;
  std::vector<float> Relaxed;
};

Solved
SolveAorta(const vr::benchmarks::DepthMap & map, unsigned int width, unsigned int height, unsigned int threads)
{
  Solved solved;
  solved.Relaxed.resize(static_cast<std::size_t>(width) * height);
  solved.Report = Solver::Solve(map.Depth->GetBufferPointer(),
                                map.Fixed->GetBufferPointer(),
                                solved.Relaxed.data(),
                                width,
                                height,
                                Anisotropy,
                                Solver::DefaultTolerance,
                                threads);
  return solved;
}
} // namespace

// Converged in a few tens of V-cycles at both sizes, the fixed pixels bit for bit, the fixed point judged by the plain
// reference code within the filter's 1e-3 mm; the same bits at 1 and 3 threads.
TEST(BilateralDepthRelaxSteadyRealAnatomy, AortaWhereItsIliacsCrossConvergesInFewCycles)
{
  for (const unsigned int width : { 256u, 512u })
  {
    const unsigned int               height = 2 * width;
    const vr::benchmarks::DepthMap & map =
      vr::benchmarks::AortaDepthMap(width, height, vr::benchmarks::AortaIliacsOverlapAngle);
    const std::size_t                pixels = static_cast<std::size_t>(width) * height;
    const float *                    depth = map.Depth->GetBufferPointer();
    const unsigned char *            fixed = map.Fixed->GetBufferPointer();
    const std::vector<unsigned char> fixedPixels(fixed, fixed + pixels);
    const Solved                     solved = SolveAorta(map, width, height, 1);
    std::cout << width << " x " << height << ": " << solved.Report.OuterIterations << " outer iterations, "
              << solved.Report.Cycles << " V-cycles, residual " << solved.Report.Residual << " mm" << std::endl;
    EXPECT_TRUE(solved.Report.Converged);
    EXPECT_LE(solved.Report.Residual, Solver::DefaultTolerance);
    EXPECT_LE(solved.Report.Cycles, 40u) << "the conjugate gradients no longer stop at their cap";
    const std::vector<double> relaxed(solved.Relaxed.begin(), solved.Relaxed.end());
    EXPECT_LT(vr::test::PlainFixedPointResidual(relaxed, fixedPixels, width, height, Anisotropy), 1e-3);
    std::size_t changedFixed = 0;
    for (std::size_t p = 0; p < pixels; ++p)
    {
      changedFixed += fixed[p] && solved.Relaxed[p] != depth[p];
    }
    EXPECT_EQ(changedFixed, 0u);
    if (width == 256)
    {
      EXPECT_EQ(SolveAorta(map, width, height, 3).Relaxed, solved.Relaxed) << "3 threads";
    }
  }
}
