// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The steady solver's last few pixels: where an outer iteration leaves only a handful of pixels above the tolerance,
// they are relaxed on small windows around them instead of in another outer iteration over the whole image.
// Internal (namespace itk::detail), not installed; see docs/steady-solver.md, "The last few pixels".
#ifndef itkBilateralDepthRelaxSteadyStragglers_h
#define itkBilateralDepthRelaxSteadyStragglers_h

#include "itkBilateralDepthRelaxSteadyField.h"

#include <cstddef>
#include <vector>

namespace itk::detail::BilateralDepthRelaxSteady
{
/** Settling is tried with at most one pixel above the tolerance per this many pixels of the grid (and at least
 * MinimumStragglers): the windows then hold at most a 25th of the grid, so that even many sweeps over them cost less
 * than the outer iteration they save (weights, assembly and at least one V-cycle over the whole grid). */
constexpr std::size_t PixelsPerStraggler = 2048;
constexpr std::size_t MinimumStragglers = 64;

/** The window around a pixel above the tolerance reaches this many pixels in each direction. */
constexpr long StragglerRadius = 4;

/** Sweeps over the windows per round at most; the sweeps of a round stop once no depth moves by more than
 * StragglerStepFraction times the tolerance. */
constexpr unsigned int MaximumStragglerSweeps = 64;
constexpr double       StragglerStepFraction = 0.05;

/** Rounds at most: a round settles the pixels above the tolerance, and may leave a pixel next to a window (whose
 * neighbour moved) above it, which the next round takes. */
constexpr unsigned int MaximumStragglerRounds = 4;

/** What settling a \a width x \a height grid uses, allocated once for the most it may hold and kept from one solve to
 * the next (a solve on a used workspace allocates nothing). */
struct StragglerBuffers
{
  /** The most pixels above the tolerance that the grid settles on their own. */
  static std::size_t
  MostStragglers(long width, long height);
  /** The bytes Reserve(width, height) allocates. */
  static std::size_t
  BytesFor(long width, long height);

  void
  Reserve(long width, long height);

  struct Straggler
  {
    long X;
    long Y;
  };
  /** Rows or columns First to Last, both included. */
  struct Span
  {
    long First;
    long Last;
  };
  std::vector<Straggler> Stragglers;
  /** The runs of rows the windows cover. */
  std::vector<Span> Ranges;
  /** Within one row: the stragglers' windows' column ranges. */
  std::vector<Span> Columns;
  /** The windows' active pixels (index in the padded arrays), each once, in raster order, and their depths before. */
  std::vector<long>   Window;
  std::vector<double> Saved;
};

/** After Field::Assemble(\a hessian) has returned \a residual (max |r| / C): where it is above \a tolerance at no more
 * than StragglerBuffers::MostStragglers pixels, Gauss-Seidel sweeps of the lagged-weights update on the active pixels
 * of the windows around them (each moves to its neighbours' mean weighted by the range weights at the current depths,
 * as an outer iteration moves every pixel), then the rows they touch assembled again (Field::ReassembleRows), in
 * rounds while the residual is above the tolerance. The field is then exactly as if assembled anew at the new depths,
 * and the returned residual is the whole grid's. A round that changed which weights vanish (the floating regions would
 * need classifying again), or found more pixels above the tolerance, leaves the depths and the field as they were. */
double
SettleStragglers(Field & field, StragglerBuffers & buffers, double residual, double tolerance, bool hessian);
} // namespace itk::detail::BilateralDepthRelaxSteady

#endif
