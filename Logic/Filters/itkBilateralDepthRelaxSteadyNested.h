// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The steady solver's nested iteration: the same depth map on a grid of half the pixels per axis, whose solution,
// interpolated back, is the finer grid's start. Internal (namespace itk::detail), not installed; see
// itkBilateralDepthRelaxSteadySolver.h for the method.
#ifndef itkBilateralDepthRelaxSteadyNested_h
#define itkBilateralDepthRelaxSteadyNested_h

#include "itkBilateralDepthRelaxSteadyGrid.h"

namespace itk::detail::BilateralDepthRelaxSteady
{
/** A map starts from a coarser grid's solution when that grid has at least this many pixels (128 x 256): smaller
 * maps are solved from their input, as before nested iteration, which is cheap there and keeps their results. */
constexpr long NestedMinimumPixels = 1 << 15;

/** The coarser grid solves with a times this (J times sqrt 2): on a grid of twice the spacing a smooth depth change
 * puts twice the difference on each edge, which the same a would take for seams to keep (a / 4 would undo that, and
 * halve every real jump instead); the coarser problem is also the more convex one, a continuation in J. */
constexpr double CoarseAnisotropyFactor = 0.5;

/** The coarser grid solves to this times the tolerance: its solution is only a start. */
constexpr double CoarseToleranceFactor = 10.0;

/** Whether a \a width x \a height map starts from a coarser grid's solution, and that grid's size. */
inline bool
HasCoarserStart(long width, long height, long & coarseWidth, long & coarseHeight)
{
  coarseWidth = (width + 1) / 2;
  coarseHeight = (height + 1) / 2;
  return width > 1 && height > 1 && coarseWidth * coarseHeight >= NestedMinimumPixels;
}

/** The same view at half the pixels per axis: coarse pixel (I, J) covers fine pixels 2I, 2I + 1 x 2J, 2J + 1 (those
 * inside the image). It is fixed where any of them is, with their mean depth; else it takes the mean of their
 * depths. Rows of \a width x \a height in, \a coarseWidth x \a coarseHeight out (row-major, no padding). */
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
