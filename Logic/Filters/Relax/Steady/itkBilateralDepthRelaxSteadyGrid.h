// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The steady solver's grids and how its work is shared: padded row-major arrays kept from one solve to the next, one
// grid of the multigrid hierarchy (Level), and the bands of rows a thread team works on (Bands). Internal (namespace
// itk::detail), not installed; see itkBilateralDepthRelaxSteadySolver.h for the method.
#ifndef itkBilateralDepthRelaxSteadyGrid_h
#define itkBilateralDepthRelaxSteadyGrid_h

#include "itkBilateralDepthRelaxArrays.h"
#include "itkThreadTeam.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace itk::detail::BilateralDepthRelaxSteady
{
/** Levels with fewer points than this are worked by the calling thread alone: below it, handing out the work costs
 * more than it saves. */
constexpr long ParallelPoints = 1 << 14;

/** Partial sums per row: a fixed number of lanes, added in a fixed order, whatever the vector width or thread. */
constexpr long Lanes = 16;

/** Floats per padded row: a multiple of 16, with room for a ghost column on the left and two on the right. */
inline long
PaddedStride(long width)
{
  return (width + 3 + 15) / 16 * 16;
}

/** Values of a padded grid of \a width x \a height points: a ghost row below, two above. */
inline std::size_t
PaddedSize(long width, long height)
{
  return static_cast<std::size_t>(PaddedStride(width) * (height + 3));
}

/** The solver's arrays: kept from one solve to the next, zero-filled when (re)sized, some lent by a finer grid
 * (itkBilateralDepthRelaxArrays.h). */
template<typename T>
using Array = ReusableArray<T>;
using detail::Lender;

/** One grid of the multigrid hierarchy. Points (x, y), 0 <= x < Width, 0 <= y < Height, live at At(x, y) in
 * padded arrays whose ghost border stays zero: coefficients, corrections and residuals all vanish outside the grid
 * (every loop writes the grid's points only).
 *
 * The operator is a symmetric 9-point stencil (5-point on the finest level): (A v)_p = C_p v_p - sum_q w_pq v_q,
 * with w_pq stored once per pair: E (p, p + (1, 0)), N (p, p + (0, 1)), NE (p, p + (1, 1)), NW (p, p + (-1, 1)).
 * Inactive points (fixed pixels, floating regions, and coarse points above inactive ones) have C = 0 and no
 * couplings; their correction stays 0.
 *
 * A coarse level also holds the interpolation from it to the next finer level, at its own points K = (I, J): the
 * fine point (2I+1, 2J) takes XA times K's value and XB times K + (1, 0)'s; (2I, 2J+1) takes YA from K and YB from
 * K + (0, 1); (2I+1, 2J+1) takes Q0, Q1, Q2, Q3 from K, K + (1, 0), K + (0, 1), K + (1, 1); (2I, 2J) takes K's. */
struct Level
{
  /** Arrays of a finest level (C, E, N; its X and B are the solver's) and of a coarse one (all of them). */
  static constexpr std::size_t FinestArrays = 3;
  static constexpr std::size_t CoarseArrays = 16;

  long Width{ 0 };
  long Height{ 0 };
  long Stride{ 0 };
  bool NinePoint{ false };

  float * C{}, *E{}, *N{}, *NE{}, *NW{};
  float * X{}, *B{};
  float * XA{}, *XB{}, *YA{}, *YB{}, *Q0{}, *Q1{}, *Q2{}, *Q3{};
  float * Active{}; // coarse levels: 1 where the point is active (its fine C point is), else 0

  std::vector<Array<float>> Storage;

  long
  At(long x, long y) const
  {
    return (y + 1) * Stride + x + 1;
  }
  std::size_t
  Size() const
  {
    return static_cast<std::size_t>(Stride * (Height + 3));
  }
  bool
  IsParallel() const
  {
    return Width * Height >= ParallelPoints;
  }

  /** Sizes the arrays (the finest level has no X, B, interpolation and activity arrays of its own), in \a lender's
   * memory when given. */
  void
  Allocate(long width, long height, bool coarse, Lender * lender = nullptr);

  /** Lends a coarse level's arrays to \a lender (Build computes them again). */
  void
  LendTo(Lender & lender);

  /** w(p, p + (DX, DY)). */
  template<int DX, int DY>
  float
  Weight(long p) const
  {
    if constexpr (DY == 0)
    {
      return DX > 0 ? E[p] : E[p - 1];
    }
    else if constexpr (DX == 0)
    {
      return DY > 0 ? N[p] : N[p - Stride];
    }
    else if constexpr (DX == DY)
    {
      return DX > 0 ? NE[p] : NE[p - Stride - 1];
    }
    else
    {
      return DY > 0 ? NW[p] : NW[p - Stride + 1];
    }
  }
};

/** Row buffers of the bands: one sum per row, one scratch row per team member. */
struct BandBuffers
{
  std::vector<double> RowSums;
  std::vector<float>  ScratchRows;
};

/** A thread team working on bands of the rows of a grid of \a height rows and padded \a stride. Every row is
 * computed by the same code whatever thread takes it, and sums are formed per row and added in row order, so
 * results do not depend on the number of threads. */
class Bands
{
public:
  Bands(BandBuffers & buffers, unsigned int threads, long height, long stride);

  /** The members of the team: \a threads, but no more than one per 8 rows. */
  static unsigned int
  TeamSize(unsigned int threads, long height);

  unsigned int
  GetSize() const
  {
    return m_Team.GetSize();
  }

  /** Runs \a job(begin, end) on bands of rows [0, rows), in parallel when \a parallel. */
  template<typename TJob>
  void
  ForRows(long rows, bool parallel, const TJob & job)
  {
    m_Team.ForBands(
      static_cast<std::size_t>(rows),
      [&](std::size_t begin, std::size_t end) { job(static_cast<long>(begin), static_cast<long>(end)); },
      parallel);
  }

  /** Runs \a job(member, begin, end) on the same bands of rows [0, rows) as ForRows, with the team member that
   * works each band (0 for all of them when not \a parallel). */
  template<typename TJob>
  void
  ForRowsOfMembers(long rows, bool parallel, const TJob & job)
  {
    m_Team.ForMemberBands(
      static_cast<std::size_t>(rows),
      [&](unsigned int member, std::size_t begin, std::size_t end)
      { job(member, static_cast<long>(begin), static_cast<long>(end)); },
      parallel);
  }

  /** sum over the grid's rows of \a rowSum(y, scratch), each row's sum formed independently and the rows added in
   * order; \a scratch is a row of Stride floats of the thread's own, for values the row's sum needs only while it is
   * formed. */
  template<typename TRowSum>
  double
  SumRows(const TRowSum & rowSum)
  {
    std::vector<double> & rows = m_Buffers.RowSums;
    ForRowsOfMembers(m_Height,
                     true,
                     [&](unsigned int member, long y0, long y1)
                     {
                       float * scratch = ScratchRow(member);
                       for (long y = y0; y < y1; ++y)
                       {
                         rows[static_cast<std::size_t>(y)] = rowSum(y, scratch);
                       }
                     });
    return SumOfRowSums();
  }

  /** One sum per row, for jobs that form them as they go; SumOfRowSums adds them in row order. */
  double *
  RowSums()
  {
    return m_Buffers.RowSums.data();
  }
  double
  SumOfRowSums() const
  {
    double sum = 0.0;
    for (const double value : m_Buffers.RowSums)
    {
      sum += value;
    }
    return sum;
  }

  /** Team member \a member's scratch row. */
  float *
  ScratchRow(unsigned int member)
  {
    return m_Buffers.ScratchRows.data() + static_cast<std::size_t>(m_Stride) * member;
  }

private:
  BandBuffers & m_Buffers;
  ThreadTeam    m_Team;
  long          m_Height;
  long          m_Stride;
};
} // namespace itk::detail::BilateralDepthRelaxSteady

#endif
