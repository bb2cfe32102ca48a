// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The steady solver's entry point: a workspace, the units a solve is made of, and their order. The units, each in its
// own file: the grid and its bands of rows (Grid), the row kernels (Rows), the black-box multigrid (Multigrid), the
// floating regions (Regions), the depth map and its energy (Field), the conjugate gradients and line searches
// (Correction), the outer iterations (OuterLoop), the coarser grids of the nested iteration (Nested).
#include "itkBilateralDepthRelaxSteadySolver.h"

#include "itkBilateralDepthRelaxSteadyCorrection.h"
#include "itkBilateralDepthRelaxSteadyField.h"
#include "itkBilateralDepthRelaxSteadyGrid.h"
#include "itkBilateralDepthRelaxSteadyMultigrid.h"
#include "itkBilateralDepthRelaxSteadyNested.h"
#include "itkBilateralDepthRelaxSteadyOuterLoop.h"
#include "itkBilateralDepthRelaxSteadyStragglers.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace itk
{
namespace Steady = detail::BilateralDepthRelaxSteady;

/** Everything a solve allocates: the image's grid, and the coarser grid's map, solution and buffers. The coarser
 * grid's map, arrays and solution are spans of this grid's scratch arrays (Lent), which it does not need until the
 * start is read from that solution: the nested iteration allocates no more than the image's own grid, its coarser
 * grids' rows aside. */
struct BilateralDepthRelaxSteadySolver::Workspace::Buffers
{
  Steady::BandBuffers          Bands;
  Steady::MultigridBuffers     Multigrid;
  Steady::FieldBuffers         Field;
  Steady::StragglerBuffers     Stragglers;
  Steady::Lender               Lent;
  Steady::Array<float>         CoarseDepth;
  Steady::Array<unsigned char> CoarseFixed;
  Steady::Array<float>         CoarseRelaxed;
  std::unique_ptr<Buffers>     Coarse;
};

namespace
{
using Buffers = BilateralDepthRelaxSteadySolver::Workspace::Buffers;
using Report = BilateralDepthRelaxSteadySolver::Report;

/** The share of a nested solve's progress that the coarser grids take (they hold a third of the pixels). */
constexpr double CoarseProgressShare = 0.25;

/** The bytes of one grid's padded arrays: the depths (double), FieldBuffers' floats, the finest level's operator and
 * the coarse levels. A coarser grid of the nested iteration has them in its finer grid's scratch arrays. */
std::size_t
GridArrayBytes(long w, long h)
{
  std::size_t bytes =
    Steady::PaddedSize(w, h) *
    (sizeof(double) + sizeof(float) * (Steady::FieldBuffers::FloatArrays + Steady::Level::FinestArrays));
  long levelWidth = w;
  long levelHeight = h;
  for (std::size_t level = 1; level < Steady::Multigrid::LevelCountFor(w, h); ++level)
  {
    levelWidth = (levelWidth + 1) / 2;
    levelHeight = (levelHeight + 1) / 2;
    bytes += Steady::PaddedSize(levelWidth, levelHeight) * sizeof(float) * Steady::Level::CoarseArrays;
  }
  return bytes;
}

/** The bytes of one grid's other buffers, which every grid allocates itself: the coarsest level's dense factor and
 * the rows. */
std::size_t
GridRowBytes(long w, long h, unsigned int threads)
{
  long levelWidth = w;
  long levelHeight = h;
  for (std::size_t level = 1; level < Steady::Multigrid::LevelCountFor(w, h); ++level)
  {
    levelWidth = (levelWidth + 1) / 2;
    levelHeight = (levelHeight + 1) / 2;
  }
  const std::size_t coarsest = static_cast<std::size_t>(levelWidth * levelHeight);
  std::size_t bytes = coarsest * coarsest * sizeof(double) + coarsest * (sizeof(long) + sizeof(char) + sizeof(double));
  // Rows: per row sums, extremes, maxima, signatures, run starts, counts; per team member a scratch row and three
  // residual rows.
  const std::size_t stride = static_cast<std::size_t>(Steady::PaddedStride(w));
  const std::size_t height = static_cast<std::size_t>(h);
  bytes += height * (5 * sizeof(double) + sizeof(std::uint64_t) + sizeof(long) + sizeof(char));
  bytes += 4 * stride * sizeof(float) * Steady::Bands::TeamSize(threads, h);
  // The floating regions' runs: one per row where no weight within a row vanishes (more where some do).
  bytes += height * (sizeof(Steady::RowRun) + sizeof(std::int32_t) + 4 * sizeof(char) + 2 * sizeof(double));
  // The last few pixels' windows.
  bytes += Steady::StragglerBuffers::BytesFor(w, h);
  return bytes;
}

/** Solves a \a w x \a h map on its own grid: from its input while lagged weights converge fast, else (when it has a
 * coarser grid) from the coarser grid's solution, solved the same way (nested iteration, recursively); \a coarser
 * grids lie between this one and the image's. */
Report
SolveGrid(unsigned int                                              coarser,
          Buffers &                                                 buffers,
          Steady::Lender *                                          lender,
          const float *                                             depth,
          const unsigned char *                                     fixed,
          float *                                                   relaxed,
          long                                                      w,
          long                                                      h,
          double                                                    anisotropy,
          double                                                    tolerance,
          unsigned int                                              threads,
          const BilateralDepthRelaxSteadySolver::ProgressCallback & progress,
          const BilateralDepthRelaxSteadySolver::Settings &         settings)
{
  long       coarseWidth = 0;
  long       coarseHeight = 0;
  const bool canNest = settings.NestedIteration && Steady::HasCoarserStart(w, h, coarser, coarseWidth, coarseHeight);
  // The fraction reported never goes back, across the attempt from the input and the nested solve after it.
  double reported = 0.0;
  auto   report = [&progress, &reported](double fraction)
  {
    reported = std::max(reported, fraction);
    progress(reported);
  };
  BilateralDepthRelaxSteadySolver::ProgressCallback ownProgress;
  if (progress)
  {
    ownProgress = report;
  }
  Steady::Bands      bands(buffers.Bands, threads, h, Steady::PaddedStride(w));
  Steady::Multigrid  multigrid(buffers.Multigrid, bands, w, h, lender);
  Steady::Field      field(buffers.Field, bands, multigrid.Finest(), w, h, anisotropy, lender);
  Steady::Correction correction(field, multigrid, bands);
  buffers.Stragglers.Reserve(w, h);
  field.Load(depth, fixed);
  // From the input first: where lagged weights converge fast (no depth step near the kernel's inflection), that is
  // the whole solve, as before nested iteration.
  auto outcome = Steady::OuterLoop(field, multigrid, correction, buffers.Stragglers)
                   .Run(tolerance, ownProgress, settings.MaximumOuterIterations, {}, canNest);
  unsigned int fromInput = 0;
  unsigned int buildsFromInput = 0;
  Report       coarse;
  coarse.Grids = 0;
  if (outcome.Slowed)
  {
    fromInput = outcome.OuterIterations;
    buildsFromInput = outcome.HierarchyBuilds;
    // The scratch arrays, whose values the outer iterations below compute again, hold the coarser grid's map,
    // arrays and solution until the start is read from that.
    Steady::Lender & lent = buffers.Lent;
    lent.Clear();
    // Taken back as freshly sized arrays (ghost cells zero) once the start is read (OuterLoop::Run), or here when a
    // solve throws before (the workspace is used again).
    auto                                                 zeroTaken = [](Steady::Lender * taken) { taken->ZeroTaken(); };
    std::unique_ptr<Steady::Lender, decltype(zeroTaken)> lending(&lent, zeroTaken);
    multigrid.LendTo(lent);
    field.LendScratchTo(lent);
    const std::size_t coarsePixels = static_cast<std::size_t>(coarseWidth * coarseHeight);
    bool              fresh = false;
    float *           coarseDepth = buffers.CoarseDepth.Reserve(coarsePixels, fresh, &lent);
    unsigned char *   coarseFixed = buffers.CoarseFixed.Reserve(coarsePixels, fresh, &lent);
    float *           coarseRelaxed = buffers.CoarseRelaxed.Reserve(coarsePixels, fresh, &lent);
    if (!buffers.Coarse)
    {
      buffers.Coarse = std::make_unique<Buffers>();
    }
    Steady::CoarsenMap(bands, depth, fixed, w, h, coarseDepth, coarseFixed, coarseWidth, coarseHeight);
    BilateralDepthRelaxSteadySolver::ProgressCallback coarseProgress;
    if (progress)
    {
      coarseProgress = [&report](double fraction) { report(CoarseProgressShare * fraction); };
    }
    coarse = SolveGrid(coarser + 1,
                       *buffers.Coarse,
                       &lent,
                       coarseDepth,
                       coarseFixed,
                       coarseRelaxed,
                       coarseWidth,
                       coarseHeight,
                       Steady::CoarseAnisotropyFactor * anisotropy,
                       Steady::CoarseToleranceFactor * tolerance,
                       threads,
                       coarseProgress,
                       settings);
    if (progress)
    {
      ownProgress = [&report](double fraction)
      { report(CoarseProgressShare + (1.0 - CoarseProgressShare) * fraction); };
    }
    // Back to the input (fixed pixels, floating regions' means), then the coarser solution as the start.
    field.Load(depth, fixed);
    const unsigned int left =
      settings.MaximumOuterIterations > fromInput ? settings.MaximumOuterIterations - fromInput : 0;
    outcome = Steady::OuterLoop(field, multigrid, correction, buffers.Stragglers)
                .Run(tolerance, ownProgress, left, { coarseRelaxed, coarseWidth, coarseHeight, &lent }, false);
  }
  Report result;
  // The energy, one exponential per edge, only for a solve that stopped short (Describe).
  result.Energy = outcome.Converged ? 0.0 : field.Energy();
  field.Store(depth, fixed, relaxed);
  result.OuterIterations = fromInput + outcome.OuterIterations;
  result.CoarseOuterIterations = coarse.OuterIterations + coarse.CoarseOuterIterations;
  result.Grids = coarse.Grids + 1;
  result.Cycles = outcome.Cycles + coarse.Cycles;
  result.HierarchyBuilds = buildsFromInput + outcome.HierarchyBuilds + coarse.HierarchyBuilds;
  result.FloatingPixels = outcome.FloatingPixels;
  result.Residual = outcome.Residual;
  result.Converged = outcome.Converged;
  return result;
}
} // namespace

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
  long        w = static_cast<long>(width);
  long        h = static_cast<long>(height);
  std::size_t bytes = GridArrayBytes(w, h) + GridRowBytes(w, h, threads);
  // The coarser grids of the nested iteration, where a solve takes them: their maps, arrays and solutions lie in the
  // finer grid's scratch arrays; only their rows are their own.
  long coarseWidth = 0;
  long coarseHeight = 0;
  for (unsigned int coarser = 0; Steady::HasCoarserStart(w, h, coarser, coarseWidth, coarseHeight); ++coarser)
  {
    w = coarseWidth;
    h = coarseHeight;
    bytes += GridRowBytes(w, h, threads);
  }
  return bytes;
}

std::string
BilateralDepthRelaxSteadySolver::Describe(const Report & report, double tolerance)
{
  std::ostringstream text;
  text << "the steady relax solver stopped after " << report.OuterIterations
       << " outer iterations at the image's size (after " << report.CoarseOuterIterations << " on " << report.Grids - 1
       << " coarser grids) with the residual at " << report.Residual << " mm, above the tolerance " << tolerance
       << " mm (energy " << report.Energy << " mm^2): the relaxed depths are that last iterate, not the fixed point";
  return text.str();
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
                                       Workspace *              workspace,
                                       const Settings &         settings)
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
  Workspace ownWorkspace;
  return SolveGrid(0,
                   *(workspace ? workspace : &ownWorkspace)->m_Buffers,
                   nullptr,
                   depth,
                   fixed,
                   relaxed,
                   static_cast<long>(width),
                   static_cast<long>(height),
                   anisotropy,
                   tolerance,
                   threads,
                   progress,
                   settings);
}

} // namespace itk
