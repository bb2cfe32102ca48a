// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkBilateralDepthRelaxRows_h
#define itkBilateralDepthRelaxRows_h

#include <cstddef>

namespace itk
{
/** The row kernels of BilateralDepthRelaxKernel (one Jacobi iteration over a band of rows, or row by row), compiled
 * once per instruction set in its own translation unit (itkBilateralDepthRelaxRows*.cxx, from
 * itkBilateralDepthRelaxRows.hxx). Internal to the kernel. */
namespace detail::BilateralDepthRelaxRows
{
/** Rows are padded to a multiple of the widest vector, so every instruction set sees the same grid. */
constexpr std::size_t RowAlignment = 16;

/** The grid the team works on: rows padded to whole vectors, plus what stays constant over the iterations.
 *
 * Each depth is held as a pair of floats, high + low (about 48 bits, like a double): a single float depth of
 * 70 mm cannot take a step below 4e-6 mm, and over hundreds of iterations such lost steps add up to more than
 * 1e-4 mm. A padded row of the depth buffers is Stride high parts followed by Stride low parts. Differences,
 * weights and steps are small and computed in plain float.
 * \ingroup VesselReformation
 */
struct RelaxGrid
{
  std::size_t Width;
  std::size_t Height;
  /** Values per padded row: a multiple of RowAlignment, >= Width. */
  std::size_t Stride;
  /** a = 0: every weight is 1. Otherwise depths are held multiplied by sqrt(a log2(e)) (see DepthScale()), so
   * that R = 2^-(x^2) for a difference x of held values. */
  bool Isotropic;
  /** Per padded pixel ((1 - w) / w) |Omega|; infinite for fixed pixels and padding, which so never move. */
  const float * SelfWeight;
};

/** One thread's buffers: the vertical edges above and below the row being relaxed (Weight R and Flux
 * R (D_below - D_above) of each column), and a row that takes the discarded output of the band's first edge row.
 * \ingroup VesselReformation
 */
struct RowScratch
{
  float * UpWeight;
  float * UpFlux;
  float * DownWeight;
  float * DownFlux;
  float * DiscardedRow;
};

/** Rows [rowBegin, rowEnd) of one Jacobi iteration from \a current into \a next (whole padded images). */
using SweepFunction = void (*)(const RelaxGrid &, const float *, float *, std::size_t, std::size_t, RowScratch &);

/** Starts a run of single rows (RowFunction) at row \a first of one Jacobi iteration: clears the edges above it at
 * the image's top, or computes them by relaxing row first - 1 (\a above, the iteration's input) into
 * scratch.DiscardedRow, exactly as a sweep starting there does. \a row is the input's row \a first. */
using StartFunction =
  void (*)(const RelaxGrid &, const float * above, const float * row, std::size_t first, RowScratch &);

/** Relaxes row \a y of one Jacobi iteration from its input (\a row and \a below, null for the image's last row;
 * each a padded high row followed by its low row) into \a out, using the edges above from \a scratch and leaving
 * there the edges below for row y + 1. The same operations as a sweep, so the same bits. */
using RowFunction =
  void (*)(const RelaxGrid &, const float * row, const float * below, std::size_t y, float * out, RowScratch &);

/** The row kernels of one instruction set. */
struct RowKernels
{
  SweepFunction Sweep;
  StartFunction Start;
  RowFunction   Row;
};

/** 16 float lanes; only in builds with runtime dispatch, and only for processors with AVX-512 (x86-64-v4). */
extern const RowKernels KernelsAVX512;
/** 8 float lanes; only in builds with runtime dispatch, and only for processors with AVX2 and FMA (x86-64-v3). */
extern const RowKernels KernelsAVX2;
/** The build's own target: 4 lanes for baseline x86-64, or as wide as the compiler flags allow. */
extern const RowKernels KernelsBaseline;
/** The instruction set KernelsBaseline was compiled for, e.g. "x86-64". */
extern const char * const BaselineInstructionSet;
} // namespace detail::BilateralDepthRelaxRows
} // namespace itk

#endif
