// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The steady solver's entry point: a workspace, the units a solve is made of, and their order. The units, each in its
// own file: the grid and its bands of rows (Grid), the row kernels (Rows), the black-box multigrid (Multigrid), the
// floating regions (Regions), the depth map and its energy (Field), the conjugate gradients and line searches
// (Correction), the outer iterations (OuterLoop).
#include "itkBilateralDepthRelaxSteadySolver.h"

#include "itkBilateralDepthRelaxSteadyCorrection.h"
#include "itkBilateralDepthRelaxSteadyField.h"
#include "itkBilateralDepthRelaxSteadyGrid.h"
#include "itkBilateralDepthRelaxSteadyMultigrid.h"
#include "itkBilateralDepthRelaxSteadyOuterLoop.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace itk
{
namespace Steady = detail::BilateralDepthRelaxSteady;

static_assert(BilateralDepthRelaxSteadySolver::MaximumOuterIterations == Steady::OuterLoop::MaximumOuterIterations);

/** Everything a solve allocates. */
struct BilateralDepthRelaxSteadySolver::Workspace::Buffers
{
  Steady::BandBuffers      Bands;
  Steady::MultigridBuffers Multigrid;
  Steady::FieldBuffers     Field;
};

BilateralDepthRelaxSteadySolver::Workspace::Workspace()
  : m_Buffers(std::make_unique<Buffers>())
{
}

BilateralDepthRelaxSteadySolver::Workspace::~Workspace() = default;

std::size_t
BilateralDepthRelaxSteadySolver::GetWorkspaceBytes(std::size_t width, std::size_t height, unsigned int threads)
{
  if (width == 0 || height == 0)
  {
    return 0;
  }
  const long w = static_cast<long>(width);
  const long h = static_cast<long>(height);
  // The finest grid: the depths (double), FieldBuffers' floats, the finest level's operator.
  std::size_t bytes =
    Steady::PaddedSize(w, h) *
    (sizeof(double) + sizeof(float) * (Steady::FieldBuffers::FloatArrays + Steady::Level::FinestArrays));
  // The coarse levels, down to the coarsest, and the coarsest's dense factor.
  long levelWidth = w;
  long levelHeight = h;
  for (std::size_t level = 1; level < Steady::Multigrid::LevelCountFor(w, h); ++level)
  {
    levelWidth = (levelWidth + 1) / 2;
    levelHeight = (levelHeight + 1) / 2;
    bytes += Steady::PaddedSize(levelWidth, levelHeight) * sizeof(float) * Steady::Level::CoarseArrays;
  }
  const std::size_t coarsest = static_cast<std::size_t>(levelWidth * levelHeight);
  bytes += coarsest * coarsest * sizeof(double) + coarsest * (sizeof(long) + sizeof(char) + sizeof(double));
  // Rows: per row sums, extremes, maxima, signatures, run starts, counts; per team member a scratch row and three
  // residual rows.
  const std::size_t stride = static_cast<std::size_t>(Steady::PaddedStride(w));
  bytes += height * (5 * sizeof(double) + sizeof(std::uint64_t) + sizeof(long) + sizeof(char));
  bytes += 4 * stride * sizeof(float) * Steady::Bands::TeamSize(threads, h);
  // The floating regions' runs: one per row where no weight within a row vanishes (more where some do).
  bytes += height * (sizeof(Steady::RowRun) + sizeof(std::int32_t) + 4 * sizeof(char) + 2 * sizeof(double));
  return bytes;
}

BilateralDepthRelaxSteadySolver::Report
BilateralDepthRelaxSteadySolver::Solve(const float *            depth,
                                       const unsigned char *    fixed,
                                       float *                  relaxed,
                                       std::size_t              width,
                                       std::size_t              height,
                                       double                   anisotropy,
                                       double                   tolerance,
                                       unsigned int             threads,
                                       const ProgressCallback & progress,
                                       Workspace *              workspace)
{
  if (!(tolerance > 0.0) || !std::isfinite(tolerance))
  {
    throw std::invalid_argument("BilateralDepthRelaxSteadySolver: tolerance " + std::to_string(tolerance) +
                                " mm must be finite and > 0");
  }
  if (width == 0 || height == 0)
  {
    return Report();
  }
  Workspace            ownWorkspace;
  Workspace::Buffers & buffers = *(workspace ? workspace : &ownWorkspace)->m_Buffers;
  const long           w = static_cast<long>(width);
  const long           h = static_cast<long>(height);
  Steady::Bands        bands(buffers.Bands, threads, h, Steady::PaddedStride(w));
  Steady::Multigrid    multigrid(buffers.Multigrid, bands, w, h);
  Steady::Field        field(buffers.Field, bands, multigrid.Finest(), w, h, anisotropy);
  Steady::Correction   correction(field, multigrid, bands);
  field.Load(depth, fixed);
  const auto outcome = Steady::OuterLoop(field, multigrid, correction).Run(tolerance, progress);
  field.Store(depth, fixed, relaxed);
  Report report;
  report.OuterIterations = outcome.OuterIterations;
  report.Cycles = outcome.Cycles;
  report.HierarchyBuilds = outcome.HierarchyBuilds;
  report.FloatingPixels = outcome.FloatingPixels;
  report.Residual = outcome.Residual;
  return report;
}

} // namespace itk
