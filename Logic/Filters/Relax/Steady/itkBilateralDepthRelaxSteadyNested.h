// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The steady solver's nested iteration: the same depth map on a grid of half the pixels per axis, whose solution,
// interpolated back, is the finer grid's start. Internal (namespace itk::detail), not installed; see
// itkBilateralDepthRelaxSteadySolver.h for the method.
#ifndef itkBilateralDepthRelaxSteadyNested_h
#define itkBilateralDepthRelaxSteadyNested_h

#include "itkBilateralDepthRelaxSteadyGrid.h"

namespace itk::detail::BilateralDepthRelaxSteady
{
/** An image's map starts from a coarser grid's solution only when that grid has at least this many pixels
 * (128 x 128; an image from about 181 x 362 at H = 2 W): smaller maps are solved from their input, as before nested
 * iteration, which is cheap there and keeps their results. (Until issue 40 the limit was 128 x 256, and the module's
 * 253 x 395 view of a full-size thoracic study took 26 outer iterations from its input: docs/steady-solver.md.) */
constexpr long NestedMinimumPixels = 1 << 14;

/** A coarser grid of a nested solve starts from a coarser grid of its own down to this many pixels (64 x 128): its
 * solution is only a start, and one from a coarser start costs less and is a lower minimum
 * (docs/steady-solver.md). */
constexpr long CoarseNestedMinimumPixels = 1 << 13;

/** At most this many coarser grids below the image's: the coarsest one then solves with at most 2 sqrt 2 times the
 * requested J. A longer continuation smoothed seams away on the coarsest grid, which the finer grids then kept in
 * higher minima. */
constexpr unsigned int MaximumCoarserGrids = 3;

/** The coarser grid solves with a times this (J times sqrt 2): on a grid of twice the spacing a smooth depth change
 * puts twice the difference on each edge, which the same a would take for seams to keep (a / 4 would undo that, and
 * halve every real jump instead); the coarser problem is also the more convex one, a continuation in J. */
constexpr double CoarseAnisotropyFactor = 0.5;

/** The coarser grid solves to this times the tolerance: its solution is only a start. */
constexpr double CoarseToleranceFactor = 10.0;

/** Whether a \a width x \a height map starts from a coarser grid's solution, and that grid's size; \a coarser is the
 * number of grids between the map and the image's own (0: the image's own grid). */
inline bool
HasCoarserStart(long width, long height, unsigned int coarser, long & coarseWidth, long & coarseHeight)
{
  coarseWidth = (width + 1) / 2;
  coarseHeight = (height + 1) / 2;
  const long minimum = coarser == 0 ? NestedMinimumPixels : CoarseNestedMinimumPixels;
  return coarser < MaximumCoarserGrids && width > 1 && height > 1 && coarseWidth * coarseHeight >= minimum;
}

/** The same view at half the pixels per axis: coarse pixel (I, J) covers fine pixels 2I, 2I + 1 x 2J, 2J + 1 (those
 * inside the image). It is fixed where any of them is, with the depth of the first fixed one in raster order; else it
 * takes the depth of the first one: input depths, never a mean across a depth jump. Rows of \a width x \a height in, \a
 * coarseWidth x \a coarseHeight out (row-major, no padding). */
void
CoarsenMap(Bands &               bands,
           const float *         depth,
           const unsigned char * fixed,
           long                  width,
           long                  height,
           float *               coarseDepth,
           unsigned char *       coarseFixed,
           long                  coarseWidth,
           long                  coarseHeight);

/** The coarse solution (row-major \a coarseWidth x \a coarseHeight) interpolated onto the active pixels (\a active
 * non-zero) of the fine padded \a depth (layout of Level with \a stride): bilinear between the centres of the four
 * nearest coarse pixels, each neighbour's weight multiplied by the range weight R of its difference to the pixel's
 * own coarse pixel (\a scale as in RangeWeight; 0: plain bilinear), so that a depth jump stays a jump. */
void
ProlongStart(Bands &       bands,
             const float * coarse,
             long          coarseWidth,
             long          coarseHeight,
             float         scale,
             const float * active,
             double *      depth,
             long          width,
             long          height,
             long          stride);
} // namespace itk::detail::BilateralDepthRelaxSteady

#endif
