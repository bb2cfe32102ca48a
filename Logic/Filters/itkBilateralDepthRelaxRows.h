// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkBilateralDepthRelaxRows_h
#define itkBilateralDepthRelaxRows_h

#include <cstddef>

namespace itk
{
/** The row sweep of BilateralDepthRelaxKernel, one Jacobi iteration over a band of rows, compiled once per
 * instruction set in its own translation unit (itkBilateralDepthRelaxRows*.cxx, from
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

/** 16 float lanes; only in builds with runtime dispatch, and only for processors with AVX-512 (x86-64-v4). */
void
SweepAVX512(const RelaxGrid & grid,
            const float *     current,
            float *           next,
            std::size_t       rowBegin,
            std::size_t       rowEnd,
            RowScratch &      scratch);
/** 8 float lanes; only in builds with runtime dispatch, and only for processors with AVX2 and FMA (x86-64-v3). */
void
SweepAVX2(const RelaxGrid & grid,
          const float *     current,
          float *           next,
          std::size_t       rowBegin,
          std::size_t       rowEnd,
          RowScratch &      scratch);
/** The build's own target: 4 lanes for baseline x86-64, or as wide as the compiler flags allow. */
void
SweepBaseline(const RelaxGrid & grid,
              const float *     current,
              float *           next,
              std::size_t       rowBegin,
              std::size_t       rowEnd,
              RowScratch &      scratch);
/** The instruction set SweepBaseline was compiled for, e.g. "x86-64". */
extern const char * const BaselineInstructionSet;
} // namespace detail::BilateralDepthRelaxRows
} // namespace itk

#endif
