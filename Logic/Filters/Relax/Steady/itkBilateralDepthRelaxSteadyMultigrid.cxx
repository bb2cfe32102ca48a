// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkBilateralDepthRelaxSteadyMultigrid.h"

#include "itkBilateralDepthRelaxSteadyRows.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace itk::detail::BilateralDepthRelaxSteady
{
namespace
{
/** A 9-point level's diagonal coupling \a diagonal of a fine point between two coarse points counts towards the side of
 * the coarse point whose own coupling \a link to the diagonal neighbour is at least DiagonalLink times its diagonal
 * \a coarseC; otherwise it is collapsed like the couplings across. Where a depth step runs between the coarse point and
 * the diagonal neighbour (the corner where two steps meet), counting it towards that side would interpolate from
 * across the step. */
inline void
SortDiagonal(float & toSide, float & across, float diagonal, float link, float coarseC)
{
  if (link >= Multigrid::DiagonalLink * coarseC)
  {
    toSide += diagonal;
  }
  else
  {
    across += diagonal;
  }
}

/** Interpolation weights of coarse row \a J from the operator of the finer level \a f, following the weights: a
 * fine point between two coarse points along x collapses its stencil along y (its couplings above and below are
 * taken as if to itself) and takes each side in proportion to its couplings to that side's column, divided by its
 * collapsed diagonal, so that a point anchored by fixed neighbours interpolates less than all, and a point beside a
 * depth jump takes nothing from across it; likewise along y. A point whose couplings towards the two coarse points
 * are below Multigrid::WeakInterpolation times its couplings across (a line of pixels between two depth steps,
 * coupled along the line only) takes nothing either: collapsing would divide next to nothing by next to nothing and
 * join the two sides of the line on the coarser levels. No weight goes to an inactive coarse point. */
template<bool NinePoint>
void
BuildEdgeInterpolationRow(const Level & f, Level & c, long J)
{
  const long cs = c.Stride;
  for (long I = 0; I < c.Width; ++I)
  {
    const long k = c.At(I, J);
    const long p = f.At(2 * I, 2 * J);
    float      xa = 0.0f;
    float      xb = 0.0f;
    const long px = p + 1;
    if (f.C[px] > 0.0f)
    {
      float toLeft = f.template Weight<-1, 0>(px);
      float toRight = f.template Weight<1, 0>(px);
      float across = f.template Weight<0, 1>(px) + f.template Weight<0, -1>(px);
      if constexpr (NinePoint)
      {
        SortDiagonal(toLeft, across, f.template Weight<-1, 1>(px), f.template Weight<0, 1>(p), f.C[p]);
        SortDiagonal(toLeft, across, f.template Weight<-1, -1>(px), f.template Weight<0, -1>(p), f.C[p]);
        SortDiagonal(toRight, across, f.template Weight<1, 1>(px), f.template Weight<0, 1>(p + 2), f.C[p + 2]);
        SortDiagonal(toRight, across, f.template Weight<1, -1>(px), f.template Weight<0, -1>(p + 2), f.C[p + 2]);
      }
      float denominator = f.C[px] - across;
      denominator = denominator > 0.0f ? denominator : toLeft + toRight;
      if (denominator > 0.0f && !(toLeft + toRight < Multigrid::WeakInterpolation * across))
      {
        xa = toLeft / denominator;
        xb = toRight / denominator;
      }
    }
    float      ya = 0.0f;
    float      yb = 0.0f;
    const long py = p + f.Stride;
    if (f.C[py] > 0.0f)
    {
      float toBelow = f.template Weight<0, -1>(py);
      float toAbove = f.template Weight<0, 1>(py);
      float across = f.template Weight<1, 0>(py) + f.template Weight<-1, 0>(py);
      if constexpr (NinePoint)
      {
        const long q = p + 2 * f.Stride;
        SortDiagonal(toBelow, across, f.template Weight<1, -1>(py), f.template Weight<1, 0>(p), f.C[p]);
        SortDiagonal(toBelow, across, f.template Weight<-1, -1>(py), f.template Weight<-1, 0>(p), f.C[p]);
        SortDiagonal(toAbove, across, f.template Weight<1, 1>(py), f.template Weight<1, 0>(q), f.C[q]);
        SortDiagonal(toAbove, across, f.template Weight<-1, 1>(py), f.template Weight<-1, 0>(q), f.C[q]);
      }
      float denominator = f.C[py] - across;
      denominator = denominator > 0.0f ? denominator : toBelow + toAbove;
      if (denominator > 0.0f && !(toBelow + toAbove < Multigrid::WeakInterpolation * across))
      {
        ya = toBelow / denominator;
        yb = toAbove / denominator;
      }
    }
    c.XA[k] = xa * c.Active[k];
    c.XB[k] = xb * c.Active[k + 1];
    c.YA[k] = ya * c.Active[k];
    c.YB[k] = yb * c.Active[k + cs];
  }
}

/** The weights of the fine point in the middle of four coarse points: through its couplings to them (9-point
 * levels) and to the four edge points just interpolated. Needs the edge weights of rows J and J + 1. */
template<bool NinePoint>
void
BuildCentreInterpolationRow(const Level & f, Level & c, long J)
{
  const long s = c.Stride;
  for (long I = 0; I < c.Width; ++I)
  {
    const long k = c.At(I, J);
    const long p = f.At(2 * I + 1, 2 * J + 1);
    if (!(f.C[p] > 0.0f))
    {
      c.Q0[k] = c.Q1[k] = c.Q2[k] = c.Q3[k] = 0.0f;
      continue;
    }
    const float inverse = 1.0f / f.C[p];
    const float left = f.template Weight<-1, 0>(p);
    const float right = f.template Weight<1, 0>(p);
    const float down = f.template Weight<0, -1>(p);
    const float up = f.template Weight<0, 1>(p);
    float       downLeft = 0.0f;
    float       downRight = 0.0f;
    float       upLeft = 0.0f;
    float       upRight = 0.0f;
    if constexpr (NinePoint)
    {
      downLeft = f.template Weight<-1, -1>(p);
      downRight = f.template Weight<1, -1>(p);
      upLeft = f.template Weight<-1, 1>(p);
      upRight = f.template Weight<1, 1>(p);
    }
    // The left neighbour (2I, 2J+1) interpolates from K (YA) and K + (0, 1) (YB); the one below, (2I+1, 2J), from K
    // (XA) and K + (1, 0) (XB); the right one from K + (1, 0) and K + (1, 1); the one above from K + (0, 1) and
    // K + (1, 1).
    c.Q0[k] = (downLeft + left * c.YA[k] + down * c.XA[k]) * inverse * c.Active[k];
    c.Q1[k] = (downRight + right * c.YA[k + 1] + down * c.XB[k]) * inverse * c.Active[k + 1];
    c.Q2[k] = (upLeft + left * c.YB[k] + up * c.XA[k + s]) * inverse * c.Active[k + s];
    c.Q3[k] = (upRight + right * c.YB[k + 1] + up * c.XB[k + s]) * inverse * c.Active[k + s + 1];
  }
}

/** Gauss-Seidel on every other point of row \a y of level \a l from column \a first. */
template<bool NinePoint>
void
SmoothRow(const Level & l, long y, long first)
{
  const long s = l.Stride;
  const long p = l.At(0, y);
  if constexpr (NinePoint)
  {
    Rows().SmoothRow9(l.X + p,
                      l.X + p + s,
                      l.X + p - s,
                      l.B + p,
                      l.E + p,
                      l.N + p,
                      l.N + p - s,
                      l.NE + p,
                      l.NE + p - s,
                      l.NW + p,
                      l.NW + p - s,
                      l.C + p,
                      first,
                      l.Width);
  }
  else
  {
    Rows().SmoothRow5(
      l.X + p, l.X + p + s, l.X + p - s, l.B + p, l.E + p, l.N + p, l.N + p - s, l.C + p, first, l.Width);
  }
}

/** r = b - A x on row \a y of level \a l, into \a r (the row's Width values). */
template<bool NinePoint>
void
ResidualRowInto(const Level & l, long y, float * r)
{
  const long s = l.Stride;
  const long p = l.At(0, y);
  if constexpr (NinePoint)
  {
    Rows().ResidualRow9(r,
                        l.X + p,
                        l.X + p + s,
                        l.X + p - s,
                        l.B + p,
                        l.C + p,
                        l.E + p,
                        l.N + p,
                        l.N + p - s,
                        l.NE + p,
                        l.NE + p - s,
                        l.NW + p,
                        l.NW + p - s,
                        l.Width);
  }
  else
  {
    Rows().ResidualRow5(r, l.X + p, l.X + p + s, l.X + p - s, l.B + p, l.C + p, l.E + p, l.N + p, l.N + p - s, l.Width);
  }
}

/** The same on the 5-point level \a l right after SmoothRedBlack from x = 0 with colour 0 first. */
void
ResidualAfterSweepFromZeroRowInto(const Level & l, long y, float * r)
{
  const long s = l.Stride;
  const long p = l.At(0, y);
  Rows().ResidualAfterSweepFromZeroRow5(
    r, l.X + p, l.X + p + s, l.X + p - s, l.E + p, l.N + p, l.N + p - s, y & 1, l.Width);
}

/** b . x on row \a y of level \a l. */
double
RowDotBX(const Level & l, long y)
{
  return Rows().RowDot(l.B + l.At(0, y), l.X + l.At(0, y), l.Width);
}

/** Coarse row \a J of b_c = P^T r_f, from the fine residual rows 2J (\a r), 2J + 1 (\a rAbove) and 2J - 1
 * (\a rBelow). */
void
RestrictRowOf(const Level & c, long J, const float * r, const float * rAbove, const float * rBelow)
{
  const long cs = c.Stride;
  const long k = c.At(0, J);
  Rows().RestrictRow(c.B + k,
                     r,
                     rAbove,
                     rBelow,
                     c.XA + k,
                     c.XB + k,
                     c.YA + k,
                     c.YB + k - cs,
                     c.Q0 + k,
                     c.Q1 + k,
                     c.Q2 + k - cs,
                     c.Q3 + k - cs,
                     c.Width);
}

/** x_f += P x_c on coarse rows [J0, J1) (fine rows 2 J0 to 2 J1). */
void
ProlongRows(const Level & c, const Level & f, long J0, long J1)
{
  const long fs = f.Stride;
  const long cs = c.Stride;
  for (long J = J0; J < J1; ++J)
  {
    const long k = c.At(0, J);
    const long p = f.At(0, 2 * J);
    Rows().ProlongRow(f.X + p,
                      f.X + p + fs,
                      c.X + k,
                      c.X + k + cs,
                      c.XA + k,
                      c.XB + k,
                      c.YA + k,
                      c.YB + k,
                      c.Q0 + k,
                      c.Q1 + k,
                      c.Q2 + k,
                      c.Q3 + k,
                      c.Width);
  }
}
} // namespace

std::size_t
Multigrid::LevelCountFor(long width, long height)
{
  std::size_t count = 1;
  for (; width * height > CoarsestPoints; ++count)
  {
    width = (width + 1) / 2;
    height = (height + 1) / 2;
  }
  return count;
}

Multigrid::Multigrid(MultigridBuffers & buffers, Bands & bands, long width, long height, Lender * lender)
  : m_Buffers(buffers)
  , m_Bands(bands)
  , m_Lender(lender)
{
  // Three residual rows per team member for ResidualAndRestrict, zero-padded; the finest level's are the widest.
  buffers.ResidualRows.assign(static_cast<std::size_t>(3 * PaddedStride(width)) * bands.GetSize(), 0.0f);
  // Every level the hierarchy may take, now: Build never moves the levels, so references to them (the finest level's
  // in the solver) stay valid.
  buffers.Levels.resize(std::max(LevelCountFor(width, height), buffers.Levels.size()));
  buffers.Levels[0].Allocate(width, height, false, lender);
}

void
Multigrid::Prolong(std::size_t k)
{
  const Level & c = m_Buffers.Levels[k + 1];
  const Level & f = m_Buffers.Levels[k];
  m_Bands.ForRows(c.Height, f.IsParallel(), [&](long J0, long J1) { ProlongRows(c, f, J0, J1); });
}

void
Multigrid::Build()
{
  std::vector<Level> & levels = m_Buffers.Levels;
  std::size_t          count = 1;
  while (levels[count - 1].Width * levels[count - 1].Height > CoarsestPoints)
  {
    const Level & f = levels[count - 1];
    Level &       c = levels[count];
    c.Allocate((f.Width + 1) / 2, (f.Height + 1) / 2, true, m_Lender);
    const bool parallel = c.IsParallel();
    m_Bands.ForRows(c.Height,
                    parallel,
                    [&](long J0, long J1)
                    {
                      for (long J = J0; J < J1; ++J)
                      {
                        for (long I = 0; I < c.Width; ++I)
                        {
                          c.Active[c.At(I, J)] = f.C[f.At(2 * I, 2 * J)] > 0.0f ? 1.0f : 0.0f;
                        }
                      }
                    });
    m_Bands.ForRows(c.Height,
                    parallel,
                    [&](long J0, long J1)
                    {
                      for (long J = J0; J < J1; ++J)
                      {
                        f.NinePoint ? BuildEdgeInterpolationRow<true>(f, c, J)
                                    : BuildEdgeInterpolationRow<false>(f, c, J);
                      }
                    });
    m_Bands.ForRows(c.Height,
                    parallel,
                    [&](long J0, long J1)
                    {
                      for (long J = J0; J < J1; ++J)
                      {
                        f.NinePoint ? BuildCentreInterpolationRow<true>(f, c, J)
                                    : BuildCentreInterpolationRow<false>(f, c, J);
                      }
                    });
    // Row J's coarse operator reads the interpolation of rows J - 1 to J + 1: all of it must be done first.
    m_Bands.ForRows(c.Height,
                    parallel,
                    [&](long J0, long J1)
                    {
                      for (long J = J0; J < J1; ++J)
                      {
                        f.NinePoint ? Rows().BuildGalerkinRowFrom9(f, c, J) : Rows().BuildGalerkinRowFrom5(f, c, J);
                      }
                    });
    ++count;
  }
  m_LevelCount = count;
  FactorCoarsest();
}

/** Dense Cholesky of the coarsest operator, in double. A pivot that vanishes (a point whose region is all but
 * cut off) drops the point from the coarse correction. */
void
Multigrid::FactorCoarsest()
{
  const Level &       c = m_Buffers.Levels[m_LevelCount - 1];
  std::vector<long> & index = m_Buffers.CoarseIndex;
  index.clear();
  for (long y = 0; y < c.Height; ++y)
  {
    for (long x = 0; x < c.Width; ++x)
    {
      if (c.C[c.At(x, y)] > 0.0f)
      {
        index.push_back(c.At(x, y));
      }
    }
  }
  const std::size_t     m = index.size();
  std::vector<double> & a = m_Buffers.CoarseFactor;
  a.assign(m * m, 0.0);
  const long s = c.Stride;
  // Each coupling is stored at the pair's point in the lower row (or, within a row, the left one).
  auto entry = [&](long p, long q) -> double
  {
    const long d = q - p;
    const long lower = std::min(p, q);
    if (d == 0)
    {
      return c.C[p];
    }
    if (d == 1 || d == -1)
    {
      return -c.E[lower];
    }
    if (d == s || d == -s)
    {
      return -c.N[lower];
    }
    if (c.NinePoint && (d == s + 1 || d == -s - 1))
    {
      return -c.NE[lower];
    }
    if (c.NinePoint && (d == s - 1 || d == -s + 1))
    {
      return -c.NW[lower];
    }
    return 0.0;
  };
  for (std::size_t i = 0; i < m; ++i)
  {
    for (std::size_t j = 0; j < m; ++j)
    {
      a[i * m + j] = entry(index[i], index[j]);
    }
  }
  std::vector<char> & dropped = m_Buffers.CoarseDropped;
  dropped.assign(m, 0);
  for (std::size_t k = 0; k < m; ++k)
  {
    double pivot = a[k * m + k];
    for (std::size_t j = 0; j < k; ++j)
    {
      pivot -= a[k * m + j] * a[k * m + j];
    }
    if (!(pivot > 1e-9 * c.C[index[k]]))
    {
      dropped[k] = 1;
      for (std::size_t i = k; i < m; ++i)
      {
        a[i * m + k] = 0.0;
      }
      a[k * m + k] = 1.0;
      continue;
    }
    pivot = std::sqrt(pivot);
    a[k * m + k] = pivot;
    for (std::size_t i = k + 1; i < m; ++i)
    {
      double value = a[i * m + k];
      for (std::size_t j = 0; j < k; ++j)
      {
        value -= a[i * m + j] * a[k * m + j];
      }
      a[i * m + k] = value / pivot;
    }
  }
}

void
Multigrid::SolveCoarsest()
{
  Level &                     c = m_Buffers.Levels[m_LevelCount - 1];
  const std::vector<long> &   index = m_Buffers.CoarseIndex;
  const std::vector<double> & a = m_Buffers.CoarseFactor;
  const std::vector<char> &   dropped = m_Buffers.CoarseDropped;
  std::vector<double> &       v = m_Buffers.CoarseVector;
  const std::size_t           m = index.size();
  v.assign(m, 0.0);
  for (std::size_t i = 0; i < m; ++i)
  {
    double value = c.B[index[i]];
    for (std::size_t j = 0; j < i; ++j)
    {
      value -= a[i * m + j] * v[j];
    }
    v[i] = dropped[i] ? 0.0 : value / a[i * m + i];
  }
  for (std::size_t i = m; i-- > 0;)
  {
    double value = v[i];
    for (std::size_t j = i + 1; j < m; ++j)
    {
      value -= a[j * m + i] * v[j];
    }
    v[i] = dropped[i] ? 0.0 : value / a[i * m + i];
  }
  for (long y = 0; y < c.Height; ++y)
  {
    std::fill(c.X + c.At(0, y), c.X + c.At(0, y) + c.Width, 0.0f);
  }
  for (std::size_t i = 0; i < m; ++i)
  {
    c.X[index[i]] = static_cast<float>(v[i]);
  }
}

/** One Gauss-Seidel sweep of level \a l: red-black on the 5-point finest level (exact Gauss-Seidel), four
 * colours on 9-point levels (no two points of a colour are neighbours), so any split of the rows among threads
 * gives the same bits. A forward pre-sweep and a backward post-sweep keep the V-cycle symmetric, as the conjugate
 * gradients need. */
void
Multigrid::Smooth(const Level & l, bool forward)
{
  if (l.NinePoint)
  {
    SmoothFourColour(l, forward);
  }
  else
  {
    SmoothRedBlack(l, forward ? 0 : 1, false);
  }
}

/** A four-colour Gauss-Seidel sweep of the 9-point level \a l in one pass over memory. Colour c holds the points
 * with x % 2 + 2 (y % 2) == c; an even row holds colours 0 and 1, an odd row 2 and 3, and a point's neighbours of
 * its own row are of the row's other colour. Forward (colours 0, 1, 2, 3): colours 0 and 1 on each even row y,
 * then colours 2 and 3 on the odd row y - 1, whose neighbours in rows y - 2 and y are then done. Backward (3, 2, 1,
 * 0): from the top, colours 3 and 2 on each odd row y, then 1 and 0 on the even row y + 1. Every point so sees the
 * same values as in four passes, one per colour, at half the passes over memory. The rows of the second pair at
 * the edges of each band wait for the neighbouring band, in a second step. */
void
Multigrid::SmoothFourColour(const Level & l, bool forward)
{
  const long firstParity = forward ? 0 : 1;
  // Forward, colours x % 2 == 0 then 1 on each row; backward, 1 then 0.
  auto pair = [&](long y)
  {
    SmoothRow<true>(l, y, forward ? 0 : 1);
    SmoothRow<true>(l, y, forward ? 1 : 0);
  };
  m_Bands.ForRows(l.Height,
                  l.IsParallel(),
                  [&](long y0, long y1)
                  {
                    if (forward)
                    {
                      for (long y = y0; y < y1; ++y)
                      {
                        if (y % 2 == firstParity)
                        {
                          pair(y);
                          if (y - 1 > y0)
                          {
                            pair(y - 1);
                          }
                        }
                      }
                    }
                    else
                    {
                      for (long y = y1 - 1; y >= y0; --y)
                      {
                        if (y % 2 == firstParity)
                        {
                          pair(y);
                          if (y + 1 < y1 - 1)
                          {
                            pair(y + 1);
                          }
                        }
                      }
                    }
                  });
  m_Bands.ForRows(l.Height,
                  l.IsParallel(),
                  [&](long y0, long y1)
                  {
                    if (y0 % 2 != firstParity)
                    {
                      pair(y0);
                    }
                    if (y1 - 1 > y0 && (y1 - 1) % 2 != firstParity)
                    {
                      pair(y1 - 1);
                    }
                  });
}

/** A red-black Gauss-Seidel sweep of the 5-point level \a l in one pass over memory: colour \a first on row y,
 * then the other colour on row y - 1, whose neighbours of the first colour (rows y - 2 to y) are then done. The
 * second colour's rows at the edges of each band wait for the neighbouring band, in a second step. With
 * \a fromZero, the sweep starts from x = 0 (and need not clear x first). Colour c holds the points with
 * (x + y) % 2 == c. */
void
Multigrid::SmoothRedBlack(const Level & l, int first, bool fromZero, double * rowDots)
{
  const int second = 1 - first;
  // A row is final once its second colour is done: its b . x then, while both are in cache.
  auto finished = [&](long y)
  {
    if (rowDots)
    {
      rowDots[y] = RowDotBX(l, y);
    }
  };
  auto colourRow = [&](int colour, long y, bool zero)
  {
    const long p = l.At(0, y);
    if (zero)
    {
      Rows().SmoothRowFromZero(l.X + p, l.B + p, l.C + p, (y + colour) & 1, l.Width);
    }
    else
    {
      SmoothRow<false>(l, y, (y + colour) & 1);
    }
  };
  const bool parallel = l.IsParallel();
  m_Bands.ForRows(l.Height,
                  parallel,
                  [&](long y0, long y1)
                  {
                    for (long y = y0; y < y1; ++y)
                    {
                      colourRow(first, y, fromZero);
                      if (y - 1 > y0)
                      {
                        colourRow(second, y - 1, false);
                        finished(y - 1);
                      }
                    }
                  });
  m_Bands.ForRows(l.Height,
                  parallel,
                  [&](long y0, long y1)
                  {
                    colourRow(second, y0, false);
                    finished(y0);
                    if (y1 - 1 > y0)
                    {
                      colourRow(second, y1 - 1, false);
                      finished(y1 - 1);
                    }
                  });
}

/** b_c = P^T (b_f - A_f x_f); with \a afterSweepFromZero (a 5-point level whose x is one red-black sweep from 0,
 * colour 0 first) from x and the couplings alone (ResidualAfterSweepFromZeroRow5). Coarse row J needs the fine residual
 * of rows 2J - 1 to 2J + 1; each member of the team computes them into three rows of its own as it goes up its band
 * (its first coarse row computes row 2J - 1 too, which the band below computes as well), so the residual never goes
 * through memory and no band waits for another. */
void
Multigrid::ResidualAndRestrict(const Level & f, const Level & c, bool afterSweepFromZero)
{
  const long stride = f.Stride;
  float *    scratch = m_Buffers.ResidualRows.data();
  m_Bands.ForRowsOfMembers(c.Height,
                           f.IsParallel(),
                           [&](unsigned int member, long J0, long J1)
                           {
                             // Three zero-padded rows: RestrictRow reads one column beyond each end.
                             float * below = scratch + 3 * stride * member + 1;
                             float * middle = below + stride;
                             float * above = middle + stride;
                             auto    residual = [&](long y, float * r)
                             {
                               if (y < 0 || y >= f.Height)
                               {
                                 std::fill(r, r + f.Width, 0.0f);
                               }
                               else if (afterSweepFromZero)
                               {
                                 ResidualAfterSweepFromZeroRowInto(f, y, r);
                               }
                               else
                               {
                                 f.NinePoint ? ResidualRowInto<true>(f, y, r) : ResidualRowInto<false>(f, y, r);
                               }
                             };
                             residual(2 * J0 - 1, below);
                             for (long J = J0; J < J1; ++J)
                             {
                               residual(2 * J, middle);
                               residual(2 * J + 1, above);
                               RestrictRowOf(c, J, middle, above, below);
                               std::swap(below, above);
                             }
                           });
}

/** One V(1,1)-cycle from level \a k down: x_k = M^-1 b_k, x_k starting at 0; with \a rowDots (the 5-point finest
 * level), each row's b . x in it. */
void
Multigrid::CycleFrom(std::size_t k, double * rowDots)
{
  std::vector<Level> & levels = m_Buffers.Levels;
  const Level &        f = levels[k];
  if (k + 1 == m_LevelCount)
  {
    SolveCoarsest();
    return;
  }
  const Level & c = levels[k + 1];
  const bool    parallel = f.IsParallel();
  if (f.NinePoint)
  {
    m_Bands.ForRows(f.Height,
                    parallel,
                    [&](long y0, long y1)
                    {
                      for (long y = y0; y < y1; ++y)
                      {
                        std::fill(f.X + f.At(0, y), f.X + f.At(0, y) + f.Width, 0.0f);
                      }
                    });
    Smooth(f, true);
  }
  else
  {
    SmoothRedBlack(f, 0, true);
  }
  ResidualAndRestrict(f, c, !f.NinePoint);
  CycleFrom(k + 1);
  m_Bands.ForRows(c.Height, parallel, [&](long J0, long J1) { ProlongRows(c, f, J0, J1); });
  if (k == 0 && rowDots)
  {
    SmoothRedBlack(f, 1, false, rowDots);
  }
  else
  {
    Smooth(f, false);
  }
}

double
Multigrid::CycleAndDot()
{
  double * rows = m_Bands.RowSums();
  CycleFrom(0, rows);
  if (m_LevelCount == 1)
  {
    // The direct solve of a grid too small for a hierarchy has no smoothing to form the row sums in.
    const Level & f = m_Buffers.Levels[0];
    for (long y = 0; y < f.Height; ++y)
    {
      rows[y] = RowDotBX(f, y);
    }
  }
  return m_Bands.SumOfRowSums();
}
} // namespace itk::detail::BilateralDepthRelaxSteady
