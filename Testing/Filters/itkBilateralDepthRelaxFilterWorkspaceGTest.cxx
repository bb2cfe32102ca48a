// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// BilateralDepthRelaxFilter::GetWorkspaceBytes against the bytes an update really keeps, counted by allocation
// (vrAllocationCounter replaces malloc in this executable): Jacobi and Steady, on the depth maps of both phantoms,
// with one and two threads. The run-off phantom's steady solve ends on its own grid, the thoracic phantom's starts
// from the coarser grids: one report for both, as the coarser grids lie in the image's grid's scratch arrays.
#include "vrAllocationCounter.h"
#include "vrTestImages.h"

#include "itkBilateralDepthRelaxFilter.h"
#include "itkCPRDepthImageFilter.h"
#include "itkCTAPhantom.h"

#include <gtest/gtest.h>

#include <iostream>

namespace
{
using vr::test::DepthImage;
using RelaxFilter = itk::BilateralDepthRelaxFilter<DepthImage>;
using DepthFilter = itk::CPRDepthImageFilter<DepthImage>;

/** The depth filter of \a kind's phantom at its design angle, updated, at \a width x \a height. */
DepthFilter::Pointer
PhantomDepth(itk::CTAPhantomKind kind, unsigned int width, unsigned int height)
{
  const auto phantom = itk::MakeCTAPhantom(kind);
  auto       depth = DepthFilter::New();
  depth->SetCenterlineTree(phantom.Tree);
  itk::CPRViewSpecification view;
  view.AngleInDegrees = phantom.DesignAngleInDegrees;
  view.ImageSize = { { width, height } };
  depth->SetViewSpecification(view);
  depth->Update();
  return depth;
}

struct Counted
{
  /** Bytes the update left allocated besides its output image: the workspace the filter keeps. */
  long long Kept;
  /** What the filter reports. */
  std::size_t  Reported;
  unsigned int Grids;
};

Counted
CountUpdate(DepthFilter & depth, itk::BilateralDepthRelaxSolver solver, unsigned int threads)
{
  auto relax = RelaxFilter::New();
  relax->SetInput(depth.GetDepthOutput());
  relax->SetFixedMask(depth.GetFixedMaskOutput());
  relax->SetSolver(solver);
  relax->SetNumberOfIterations(20); // the Jacobi workspace does not depend on the passes beyond the first
  relax->SetNumberOfWorkUnits(threads);
  const auto      size = depth.GetDepthOutput()->GetLargestPossibleRegion().GetSize();
  const long long before = vr::test::AllocatedBytes();
  relax->Update();
  const long long output = static_cast<long long>(size[0] * size[1] * sizeof(float));
  Counted         counted{};
  counted.Kept = vr::test::AllocatedBytes() - before - output;
  counted.Grids = relax->GetSteadyReport().Grids;
  counted.Reported = relax->GetWorkspaceBytes(size);
  return counted;
}
} // namespace

TEST(BilateralDepthRelaxFilterWorkspace, ReportedBytesMatchTheBytesAnUpdateKeeps)
{
  constexpr unsigned int width = 512;
  constexpr unsigned int height = 1024;
  const double           pixels = static_cast<double>(width) * height;
  for (const auto kind : { itk::CTAPhantomKind::Runoff, itk::CTAPhantomKind::Thorax })
  {
    const auto depth = PhantomDepth(kind, width, height);
    for (const auto solver : { itk::BilateralDepthRelaxSolver::Jacobi, itk::BilateralDepthRelaxSolver::Steady })
    {
      for (const unsigned int threads : { 1u, 2u })
      {
        const Counted counted = CountUpdate(*depth, solver, threads);
        std::cout << kind << ", " << solver << ", " << threads << " threads: kept " << counted.Kept / pixels
                  << " bytes per pixel, reported " << counted.Reported / pixels << " (" << counted.Grids << " grids)"
                  << std::endl;
        // Within 1 %: besides the workspace an update keeps only small objects (the first one also some of ITK's
        // and the thread pool's).
        EXPECT_NEAR(static_cast<double>(counted.Kept),
                    static_cast<double>(counted.Reported),
                    0.01 * static_cast<double>(counted.Reported));
        if (solver == itk::BilateralDepthRelaxSolver::Steady)
        {
          // Which path each phantom's map takes (docs/steady-solver.md): both, with one report.
          EXPECT_EQ(counted.Grids > 1, kind == itk::CTAPhantomKind::Thorax);
        }
      }
    }
  }
}
