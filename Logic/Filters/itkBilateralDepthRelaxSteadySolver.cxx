// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkBilateralDepthRelaxSteadySolver.h"

#include "itkThreadTeam.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

// The row loops below are compiled for baseline x86-64, AVX2 (x86-64-v3) and AVX-512 (x86-64-v4), and the dynamic
// loader picks one per process from the CPU (GNU ifunc): every row of a solve runs the same code, so results stay
// independent of the thread count. Builds without runtime dispatch follow the compiler flags.
#if defined(VR_STEADY_SOLVER_RUNTIME_DISPATCH)
#define VR_ROW_LOOP __attribute__((target_clones("default", "arch=x86-64-v3", "arch=x86-64-v4")))
#else
#define VR_ROW_LOOP
#endif

namespace itk
{
namespace
{
/** Grids of this many points or fewer are solved directly. */
constexpr long CoarsestPoints = 64;

/** Levels with fewer points than this are worked by the calling thread alone: below it, handing out the work costs
 * more than it saves. */
constexpr long ParallelPoints = 1 << 14;

/** Each outer iteration's conjugate gradients stop once the residual has fallen this much. */
constexpr double InnerReduction = 0.1;

/** Conjugate-gradient iterations per outer iteration at most; more than RebuildAfterCycles V-cycles in one outer
 * iteration rebuild the hierarchy from the current weights before the next. */
constexpr unsigned int MaximumInnerIterations = 40;
constexpr unsigned int RebuildAfterCycles = 4;

/** Outer iterations take Newton steps from the first one whose residual has not fallen below this fraction of the
 * previous one. */
constexpr double NewtonAfterReduction = 0.5;

/** The longest step along a lagged-weights correction, in multiples of it. */
constexpr float MaximumStep = 64.0f;

/** Partial sums per row: a fixed number of lanes, added in a fixed order, whatever the vector width or thread. */
constexpr long Lanes = 16;

/** Floats per padded row: a multiple of 16, with room for a ghost column on the left and two on the right. */
long
PaddedStride(long width)
{
  return (width + 3 + 15) / 16 * 16;
}

/** Values kept from one solve to the next; zero-filled when (re)sized, so ghost cells start at zero. */
template<typename T>
class Array
{
public:
  T *
  Reserve(std::size_t count, bool & fresh)
  {
    if (m_Values.size() != count)
    {
      m_Values.assign(count, T{});
      fresh = true;
    }
    return m_Values.data();
  }

private:
  std::vector<T> m_Values;
};

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

  /** Sizes the arrays (the finest level has no X, B, interpolation and activity arrays of its own). */
  void
  Allocate(long width, long height, bool coarse)
  {
    Width = width;
    Height = height;
    Stride = PaddedStride(width);
    NinePoint = coarse;
    Storage.resize(16);
    std::size_t next = 0;
    bool        fresh = false;
    auto        take = [&]() { return Storage[next++].Reserve(Size(), fresh); };
    C = take();
    E = take();
    N = take();
    if (coarse)
    {
      NE = take();
      NW = take();
      X = take();
      B = take();
      XA = take();
      XB = take();
      YA = take();
      YB = take();
      Q0 = take();
      Q1 = take();
      Q2 = take();
      Q3 = take();
      Active = take();
    }
  }

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

using NineOffsets = std::make_integer_sequence<int, 9>;

/** P(p, K) for the fine point p = 2K + (OX, OY), read from the coarse level \a c at K's index \a k. */
template<int OX, int OY>
[[gnu::always_inline]] inline float
Interpolation(const Level & c, long k)
{
  const long s = c.Stride;
  if constexpr (OX == 0 && OY == 0)
  {
    return c.Active[k];
  }
  else if constexpr (OY == 0)
  {
    return OX > 0 ? c.XA[k] : c.XB[k - 1];
  }
  else if constexpr (OX == 0)
  {
    return OY > 0 ? c.YA[k] : c.YB[k - s];
  }
  else if constexpr (OX > 0 && OY > 0)
  {
    return c.Q0[k];
  }
  else if constexpr (OX < 0 && OY > 0)
  {
    return c.Q1[k - 1];
  }
  else if constexpr (OX > 0 && OY < 0)
  {
    return c.Q2[k - s];
  }
  else
  {
    return c.Q3[k - s - 1];
  }
}

/** A(p, p + (DX, DY)) on level \a f. */
template<bool NinePoint, int DX, int DY>
[[gnu::always_inline]] inline float
OperatorEntry(const Level & f, long p)
{
  if constexpr (DX == 0 && DY == 0)
  {
    return f.C[p];
  }
  else if constexpr (!NinePoint && DX != 0 && DY != 0)
  {
    return 0.0f;
  }
  else
  {
    return -f.template Weight<DX, DY>(p);
  }
}

/** Fine point p's term of GalerkinEntry for its stencil offset D (0 to 8, (dx, dy) = (D % 3 - 1, D / 3 - 1)):
 * A(p, q) P(q, K + L) for q = p + (dx, dy) in K + L's support, else 0. p = 2K + (OX, OY); \a kl is K + L's index. */
template<bool NinePoint, int LX, int LY, int OX, int OY, int D>
[[gnu::always_inline]] inline double
GalerkinTerm(const Level & f, const Level & c, long kl, long p)
{
  constexpr int dx = D % 3 - 1;
  constexpr int dy = D / 3 - 1;
  constexpr int qx = OX + dx - 2 * LX;
  constexpr int qy = OY + dy - 2 * LY;
  if constexpr ((NinePoint || dx == 0 || dy == 0) && qx >= -1 && qx <= 1 && qy >= -1 && qy <= 1)
  {
    return static_cast<double>(OperatorEntry<NinePoint, dx, dy>(f, p)) * Interpolation<qx, qy>(c, kl);
  }
  else
  {
    return 0.0;
  }
}

/** Fine point p = 2K + (O % 3 - 1, O / 3 - 1)'s share of GalerkinEntry: P(p, K) times the sum of its terms. */
template<bool NinePoint, int LX, int LY, int O, int... D>
[[gnu::always_inline]] inline double
GalerkinShare(const Level & f, const Level & c, long k, long kl, long p0, std::integer_sequence<int, D...>)
{
  constexpr int ox = O % 3 - 1;
  constexpr int oy = O / 3 - 1;
  const long    p = p0 + ox + oy * f.Stride;
  const double  row = (0.0 + ... + GalerkinTerm<NinePoint, LX, LY, ox, oy, D>(f, c, kl, p));
  return static_cast<double>(Interpolation<ox, oy>(c, k)) * row;
}

template<bool NinePoint, int LX, int LY, int... O>
[[gnu::always_inline]] inline double
GalerkinSum(const Level & f, const Level & c, long k, long p0, std::integer_sequence<int, O...>)
{
  const long kl = k + LX + LY * c.Stride;
  return (0.0 + ... + GalerkinShare<NinePoint, LX, LY, O>(f, c, k, kl, p0, NineOffsets{}));
}

/** The Galerkin coarse operator's entry A_c(K, K + (LX, LY)) = sum over fine p, q of P(p, K) A(p, q) P(q, K + L),
 * p in K's 3 x 3 support, q a stencil neighbour of p in K + L's support. Written as folds over compile-time offsets,
 * not loops, so that a row of coarse points becomes vector operations. */
template<bool NinePoint, int LX, int LY>
[[gnu::always_inline]] inline double
GalerkinEntry(const Level & f, const Level & c, long k, long p0)
{
  return GalerkinSum<NinePoint, LX, LY>(f, c, k, p0, NineOffsets{});
}

/** Interpolation weights of coarse row \a J from the operator of the finer level \a f, following the weights: a
 * fine point between two coarse points along x collapses its stencil along y (its couplings above and below are
 * taken as if to itself) and takes each side in proportion to its couplings to that side's column, divided by its
 * collapsed diagonal, so that a point anchored by fixed neighbours interpolates less than all, and a point beside a
 * depth jump takes nothing from across it; likewise along y. No weight goes to an inactive coarse point. */
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
      if constexpr (NinePoint)
      {
        toLeft += f.template Weight<-1, 1>(px) + f.template Weight<-1, -1>(px);
        toRight += f.template Weight<1, 1>(px) + f.template Weight<1, -1>(px);
      }
      float denominator = f.C[px] - f.template Weight<0, 1>(px) - f.template Weight<0, -1>(px);
      denominator = denominator > 0.0f ? denominator : toLeft + toRight;
      if (denominator > 0.0f)
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
      if constexpr (NinePoint)
      {
        toBelow += f.template Weight<1, -1>(py) + f.template Weight<-1, -1>(py);
        toAbove += f.template Weight<1, 1>(py) + f.template Weight<-1, 1>(py);
      }
      float denominator = f.C[py] - f.template Weight<1, 0>(py) - f.template Weight<-1, 0>(py);
      denominator = denominator > 0.0f ? denominator : toBelow + toAbove;
      if (denominator > 0.0f)
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

/** Coarse row \a J's operator. Each coarse point's entries read the interpolation and the finer operator only and
 * write that point's own entries, so no point of the row depends on another (ivdep tells the vectoriser so). An
 * inactive point has no interpolation to or from it, so its entries come out 0 without a test. */
template<bool NinePoint>
[[gnu::always_inline]] inline void
BuildGalerkinRowOf(const Level & f, Level & c, long J)
{
  const long k0 = c.At(0, J);
  const long p00 = f.At(0, 2 * J);
  const long width = c.Width;
#pragma GCC ivdep
  for (long I = 0; I < width; ++I)
  {
    const long   k = k0 + I;
    const long   p0 = p00 + 2 * I;
    const double diagonal = GalerkinEntry<NinePoint, 0, 0>(f, c, k, p0);
    c.C[k] = diagonal > 0.0 ? static_cast<float>(diagonal) : 0.0f;
    // 0 - entry, not -entry: an inactive point's couplings are +0.
    c.E[k] = static_cast<float>(0.0 - GalerkinEntry<NinePoint, 1, 0>(f, c, k, p0));
    c.N[k] = static_cast<float>(0.0 - GalerkinEntry<NinePoint, 0, 1>(f, c, k, p0));
    c.NE[k] = static_cast<float>(0.0 - GalerkinEntry<NinePoint, 1, 1>(f, c, k, p0));
    c.NW[k] = static_cast<float>(0.0 - GalerkinEntry<NinePoint, -1, 1>(f, c, k, p0));
  }
}

/** BuildGalerkinRowOf from the finest (5-point) and from a 9-point level, each compiled for every instruction set. */
VR_ROW_LOOP void
BuildGalerkinRowFrom5(const Level & f, Level & c, long J)
{
  BuildGalerkinRowOf<false>(f, c, J);
}
VR_ROW_LOOP void
BuildGalerkinRowFrom9(const Level & f, Level & c, long J)
{
  BuildGalerkinRowOf<true>(f, c, J);
}

// The row loops below take raw pointers and plain numbers only, so that the compiler sees unit strides, no aliasing
// and loop-invariant bounds, and turns each into vector operations.

/** value / C_p at an active point (C_p > 0; one below FLT_MIN taken as FLT_MIN, so that nothing overflows), 0 at an
 * inactive one (C_p = 0). Divided where needed rather than multiplied by stored inverses: the solver is bound by
 * memory traffic, and an array of inverses per level cost more to stream than the divisions. */
inline float
DividedByDiagonal(float value, float diagonal)
{
  const float quotient = value / std::max(diagonal, std::numeric_limits<float>::min());
  return diagonal > 0.0f ? quotient : 0.0f;
}

/** Gauss-Seidel on every other point of a 5-point row from column \a first: x_p = (b_p + sum w_pq x_q) / C_p.
 * The points updated are never each other's neighbours, so the row is one vector operation. */
VR_ROW_LOOP void
SmoothRow5(float * __restrict x,
           const float * __restrict above,
           const float * __restrict below,
           const float * __restrict b,
           const float * __restrict e,
           const float * __restrict n,
           const float * __restrict nBelow,
           const float * __restrict c,
           long first,
           long width)
{
  for (long i = first; i < width; i += 2)
  {
    const float sum = b[i] + e[i] * x[i + 1] + e[i - 1] * x[i - 1] + n[i] * above[i] + nBelow[i] * below[i];
    x[i] = DividedByDiagonal(sum, c[i]);
  }
}

/** The first colour of a Gauss-Seidel sweep that starts from x = 0: the neighbours are all 0, so x_p = b_p / C_p. */
VR_ROW_LOOP void
SmoothRowFromZero(float * __restrict x, const float * __restrict b, const float * __restrict c, long first, long width)
{
  for (long i = first; i < width; i += 2)
  {
    x[i] = DividedByDiagonal(b[i], c[i]);
  }
}

/** The same on a 9-point row; \a neBelow and \a nwBelow point at the row below's NE and NW (see Level). */
VR_ROW_LOOP void
SmoothRow9(float * __restrict x,
           const float * __restrict above,
           const float * __restrict below,
           const float * __restrict b,
           const float * __restrict e,
           const float * __restrict n,
           const float * __restrict nBelow,
           const float * __restrict ne,
           const float * __restrict neBelow,
           const float * __restrict nw,
           const float * __restrict nwBelow,
           const float * __restrict c,
           long first,
           long width)
{
  for (long i = first; i < width; i += 2)
  {
    const float sum = b[i] + e[i] * x[i + 1] + e[i - 1] * x[i - 1] + n[i] * above[i] + nBelow[i] * below[i] +
                      ne[i] * above[i + 1] + neBelow[i - 1] * below[i - 1] + nw[i] * above[i - 1] +
                      nwBelow[i + 1] * below[i + 1];
    x[i] = DividedByDiagonal(sum, c[i]);
  }
}

/** r = b - A x on a 5-point row. */
VR_ROW_LOOP void
ResidualRow5(float * __restrict r,
             const float * __restrict x,
             const float * __restrict above,
             const float * __restrict below,
             const float * __restrict b,
             const float * __restrict c,
             const float * __restrict e,
             const float * __restrict n,
             const float * __restrict nBelow,
             long width)
{
  for (long i = 0; i < width; ++i)
  {
    r[i] = b[i] - c[i] * x[i] + e[i] * x[i + 1] + e[i - 1] * x[i - 1] + n[i] * above[i] + nBelow[i] * below[i];
  }
}

/** r = b - A x on a 9-point row. */
VR_ROW_LOOP void
ResidualRow9(float * __restrict r,
             const float * __restrict x,
             const float * __restrict above,
             const float * __restrict below,
             const float * __restrict b,
             const float * __restrict c,
             const float * __restrict e,
             const float * __restrict n,
             const float * __restrict nBelow,
             const float * __restrict ne,
             const float * __restrict neBelow,
             const float * __restrict nw,
             const float * __restrict nwBelow,
             long width)
{
  for (long i = 0; i < width; ++i)
  {
    r[i] = b[i] - c[i] * x[i] + e[i] * x[i + 1] + e[i - 1] * x[i - 1] + n[i] * above[i] + nBelow[i] * below[i] +
           ne[i] * above[i + 1] + neBelow[i - 1] * below[i - 1] + nw[i] * above[i - 1] + nwBelow[i + 1] * below[i + 1];
  }
}

/** q = A v on a 5-point row. */
VR_ROW_LOOP void
ApplyRow5(float * __restrict q,
          const float * __restrict v,
          const float * __restrict above,
          const float * __restrict below,
          const float * __restrict c,
          const float * __restrict e,
          const float * __restrict n,
          const float * __restrict nBelow,
          long width)
{
  for (long i = 0; i < width; ++i)
  {
    q[i] = c[i] * v[i] - e[i] * v[i + 1] - e[i - 1] * v[i - 1] - n[i] * above[i] - nBelow[i] * below[i];
  }
}

/** One coarse row of b_c = P^T r_f: \a r is the fine row 2J, \a rAbove row 2J + 1, \a rBelow row 2J - 1; the
 * weights of the coarse row (and, for those stored a row lower, of the row below). */
VR_ROW_LOOP void
RestrictRow(float * __restrict b,
            const float * __restrict r,
            const float * __restrict rAbove,
            const float * __restrict rBelow,
            const float * __restrict xa,
            const float * __restrict xb,
            const float * __restrict ya,
            const float * __restrict ybBelow,
            const float * __restrict q0,
            const float * __restrict q1,
            const float * __restrict q2Below,
            const float * __restrict q3Below,
            long width)
{
  for (long I = 0; I < width; ++I)
  {
    const long i = 2 * I;
    b[I] = r[i] + xa[I] * r[i + 1] + xb[I - 1] * r[i - 1] + ya[I] * rAbove[i] + ybBelow[I] * rBelow[i] +
           q0[I] * rAbove[i + 1] + q1[I - 1] * rAbove[i - 1] + q2Below[I] * rBelow[i + 1] +
           q3Below[I - 1] * rBelow[i - 1];
  }
}

/** One coarse row of x_f += P x_c: fine rows 2J (\a fine) and 2J + 1 (\a fineAbove) from coarse rows J (\a x) and
 * J + 1 (\a xAbove). */
VR_ROW_LOOP void
ProlongRow(float * __restrict fine,
           float * __restrict fineAbove,
           const float * __restrict x,
           const float * __restrict xAbove,
           const float * __restrict xa,
           const float * __restrict xb,
           const float * __restrict ya,
           const float * __restrict yb,
           const float * __restrict q0,
           const float * __restrict q1,
           const float * __restrict q2,
           const float * __restrict q3,
           long width)
{
  for (long I = 0; I < width; ++I)
  {
    const long i = 2 * I;
    fine[i] += x[I];
    fine[i + 1] += xa[I] * x[I] + xb[I] * x[I + 1];
    fineAbove[i] += ya[I] * x[I] + yb[I] * xAbove[I];
    fineAbove[i + 1] += q0[I] * x[I] + q1[I] * x[I + 1] + q2[I] * xAbove[I] + q3[I] * xAbove[I + 1];
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
    SmoothRow9(l.X + p,
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
    SmoothRow5(l.X + p, l.X + p + s, l.X + p - s, l.B + p, l.E + p, l.N + p, l.N + p - s, l.C + p, first, l.Width);
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
    ResidualRow9(r,
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
    ResidualRow5(r, l.X + p, l.X + p + s, l.X + p - s, l.B + p, l.C + p, l.E + p, l.N + p, l.N + p - s, l.Width);
  }
}

/** Coarse row \a J of b_c = P^T r_f, from the fine residual rows 2J (\a r), 2J + 1 (\a rAbove) and 2J - 1
 * (\a rBelow). */
void
RestrictRowOf(const Level & c, long J, const float * r, const float * rAbove, const float * rBelow)
{
  const long cs = c.Stride;
  const long k = c.At(0, J);
  RestrictRow(c.B + k,
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
    ProlongRow(f.X + p,
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

/** R = exp(-a x^2), 0 when a x^2 exceeds -ln(FLT_MIN) (BilateralDepthRelaxFilter::WeightUnderflowExponent), as
 * 2^u with u = -(scale x)^2, scale = sqrt(a log2(e)): 2^u = 2^n 2^f, n the nearest integer, f in [-1/2, 1/2], 2^f
 * by a degree-5 minimax polynomial (relative error below 3e-7), 2^n built in the exponent bits. Written without
 * branches or library calls so that whole rows become vector operations. */
inline float
RangeWeight(float difference, float scale)
{
  const float     t = scale * difference;
  const float     u = -(t * t);
  const float     clamped = std::max(u, -126.0f);
  constexpr float RoundingShifter = 12582912.0f; // 1.5 * 2^23: adding it rounds to an integer
  const float     shifted = clamped + RoundingShifter;
  const float     f = clamped - (shifted - RoundingShifter);
  const float     power = __builtin_bit_cast(float, (__builtin_bit_cast(std::uint32_t, shifted) << 23) + 0x3F800000u);
  float           p = f * 1.327647198e-3f + 9.675541334e-3f;
  p = p * f + 5.550713274e-2f;
  p = p * f + 2.402211972e-1f;
  p = p * f + 6.931469671e-1f;
  p = p * f + 1.000000072f;
  const float weight = p * power;
  return u >= -126.0f ? weight : 0.0f;
}

/** The range weights of a row's edges to the right (the last column has none) and, when \a below is not null, to
 * the row below; returns a signature of the vanishing ones (their count and the sum of their columns). */
VR_ROW_LOOP std::uint64_t
            WeightRow(float * __restrict right,
                      float * __restrict down,
                      const double * __restrict d,
                      const double * __restrict below,
                      float scale,
                      bool  isotropic,
                      long  width)
{
  std::uint64_t signature = 0;
  if (isotropic)
  {
    for (long x = 0; x + 1 < width; ++x)
    {
      right[x] = 1.0f;
    }
    for (long x = 0; x < width; ++x)
    {
      down[x] = below ? 1.0f : 0.0f;
    }
  }
  else
  {
    for (long x = 0; x + 1 < width; ++x)
    {
      right[x] = RangeWeight(static_cast<float>(d[x + 1] - d[x]), scale);
    }
    if (below)
    {
      for (long x = 0; x < width; ++x)
      {
        down[x] = RangeWeight(static_cast<float>(below[x] - d[x]), scale);
      }
    }
    else
    {
      for (long x = 0; x < width; ++x)
      {
        down[x] = 0.0f;
      }
    }
  }
  right[width - 1] = 0.0f;
  // The count of vanishing edges and the sum of their columns, in 32-bit lanes the compiler can vectorise.
  std::uint32_t count = 0;
  std::uint32_t columns = 0;
  for (long x = 0; x + 1 < width; ++x)
  {
    const std::uint32_t vanishes = right[x] == 0.0f ? 1u : 0u;
    count += vanishes;
    columns += vanishes * static_cast<std::uint32_t>(2 * x + 1);
  }
  if (below)
  {
    for (long x = 0; x < width; ++x)
    {
      const std::uint32_t vanishes = down[x] == 0.0f ? 1u : 0u;
      count += vanishes;
      columns += vanishes * static_cast<std::uint32_t>(2 * x + 2);
    }
  }
  signature = (static_cast<std::uint64_t>(count) << 32) + columns;
  return signature;
}

/** One row of the finest level's operator and residual (see SteadySolve::Assemble), and with \a Hessian the energy's
 * Hessian too. */
template<bool Hessian>
[[gnu::always_inline]] inline void
AssembleRow(float * __restrict c,
            float * __restrict e,
            float * __restrict n,
            float * __restrict hc,
            float * __restrict he,
            float * __restrict hn,
            float * __restrict residual,
            const double * __restrict d,
            const double * __restrict dAbove,
            const double * __restrict dBelow,
            const float * __restrict active,
            const float * __restrict activeAbove,
            const float * __restrict right,
            const float * __restrict down,
            const float * __restrict up,
            float twiceAnisotropy,
            long  width)
{
  for (long x = 0; x < width; ++x)
  {
    const float toRight = static_cast<float>(d[x + 1] - d[x]);
    const float toLeft = static_cast<float>(d[x - 1] - d[x]);
    const float toAbove = static_cast<float>(dAbove[x] - d[x]);
    const float toBelow = static_cast<float>(dBelow[x] - d[x]);
    const float diagonal = ((right[x] + right[x - 1]) + (down[x] + up[x])) * active[x];
    const float flux = right[x] * toRight + right[x - 1] * toLeft + down[x] * toAbove + up[x] * toBelow;
    const float live = diagonal > 0.0f ? 1.0f : 0.0f;
    c[x] = diagonal;
    e[x] = right[x] * active[x] * active[x + 1];
    n[x] = down[x] * active[x] * activeAbove[x];
    residual[x] = flux * live;
    if constexpr (Hessian)
    {
      // The energy's curvature along each edge: d^2/dx^2 (1 - R(x)) / (2a) = R(x) (1 - 2 a x^2).
      const float curvatureRight = right[x] * (1.0f - twiceAnisotropy * toRight * toRight);
      const float curvatureLeft = right[x - 1] * (1.0f - twiceAnisotropy * toLeft * toLeft);
      const float curvatureAbove = down[x] * (1.0f - twiceAnisotropy * toAbove * toAbove);
      const float curvatureBelow = up[x] * (1.0f - twiceAnisotropy * toBelow * toBelow);
      hc[x] = ((curvatureRight + curvatureLeft) + (curvatureAbove + curvatureBelow)) * active[x];
      he[x] = curvatureRight * active[x] * active[x + 1];
      hn[x] = curvatureAbove * active[x] * activeAbove[x];
    }
  }
}

/** AssembleRow without and with the Hessian, each compiled for every instruction set. */
VR_ROW_LOOP void
AssembleOperatorRow(float * __restrict c,
                    float * __restrict e,
                    float * __restrict n,
                    float * __restrict hc,
                    float * __restrict he,
                    float * __restrict hn,
                    float * __restrict residual,
                    const double * __restrict d,
                    const double * __restrict dAbove,
                    const double * __restrict dBelow,
                    const float * __restrict active,
                    const float * __restrict activeAbove,
                    const float * __restrict right,
                    const float * __restrict down,
                    const float * __restrict up,
                    float twiceAnisotropy,
                    long  width)
{
  AssembleRow<false>(
    c, e, n, hc, he, hn, residual, d, dAbove, dBelow, active, activeAbove, right, down, up, twiceAnisotropy, width);
}
VR_ROW_LOOP void
AssembleOperatorAndHessianRow(float * __restrict c,
                              float * __restrict e,
                              float * __restrict n,
                              float * __restrict hc,
                              float * __restrict he,
                              float * __restrict hn,
                              float * __restrict residual,
                              const double * __restrict d,
                              const double * __restrict dAbove,
                              const double * __restrict dBelow,
                              const float * __restrict active,
                              const float * __restrict activeAbove,
                              const float * __restrict right,
                              const float * __restrict down,
                              const float * __restrict up,
                              float twiceAnisotropy,
                              long  width)
{
  AssembleRow<true>(
    c, e, n, hc, he, hn, residual, d, dAbove, dBelow, active, activeAbove, right, down, up, twiceAnisotropy, width);
}

/** delta += alpha v, r -= alpha q on a row. */
VR_ROW_LOOP void
UpdateRow(float * __restrict delta,
          float * __restrict r,
          const float * __restrict v,
          const float * __restrict q,
          float alpha,
          long  width)
{
  for (long x = 0; x < width; ++x)
  {
    delta[x] += alpha * v[x];
    r[x] -= alpha * q[x];
  }
}

/** v = z + beta v on a row. */
VR_ROW_LOOP void
DirectionRow(float * __restrict v, const float * __restrict z, float beta, long width)
{
  for (long x = 0; x < width; ++x)
  {
    v[x] = z[x] + beta * v[x];
  }
}

/** expm1(u) for |u| <= 1/2, by its Taylor polynomial to degree 8 (relative error below 3e-8). */
inline float
SmallExpMinusOne(float u)
{
  float p = u * (1.0f / 40320.0f) + 1.0f / 5040.0f;
  p = p * u + 1.0f / 720.0f;
  p = p * u + 1.0f / 120.0f;
  p = p * u + 1.0f / 24.0f;
  p = p * u + 1.0f / 6.0f;
  p = p * u + 0.5f;
  p = p * u + 1.0f;
  return p * u;
}

/** (1 - R(from + step)) - (1 - R(from)) = R(from) - R(from + step): an edge's share of the energy change, times 2a.
 * Where the exponent's change u = -a step (2 from + step) is small, as R(from) (-expm1(u)), which keeps its digits
 * when the step is much smaller than the difference; elsewhere as the plain difference of the two weights. */
inline float
EdgeEnergyChange(float from, float step, float anisotropy, float scale)
{
  const float to = from + step;
  const float u = -anisotropy * step * (from + to);
  const float near = -RangeWeight(from, scale) * SmallExpMinusOne(std::clamp(u, -0.5f, 0.5f));
  const float far = RangeWeight(from, scale) - RangeWeight(to, scale);
  return std::abs(u) <= 0.5f ? near : far;
}

/** The change of the energy sum (1 - R(D_p - D_q)) over a row's edges to the right and to the row below (\a below
 * null for the last row) when the depths move by \a step times \a delta, times 2a, summed in Lanes partial sums. */
VR_ROW_LOOP double
EnergyChangeRow(const double * __restrict d,
                const double * __restrict below,
                const float * __restrict delta,
                const float * __restrict deltaBelow,
                float step,
                float anisotropy,
                float scale,
                float * __restrict scratch,
                long width)
{
  for (long x = 0; x + 1 < width; ++x)
  {
    scratch[x] =
      EdgeEnergyChange(static_cast<float>(d[x + 1] - d[x]), step * (delta[x + 1] - delta[x]), anisotropy, scale);
  }
  scratch[width - 1] = 0.0f;
  if (below)
  {
    for (long x = 0; x < width; ++x)
    {
      scratch[x] +=
        EdgeEnergyChange(static_cast<float>(below[x] - d[x]), step * (deltaBelow[x] - delta[x]), anisotropy, scale);
    }
  }
  double lanes[Lanes] = {};
  long   i = 0;
  for (; i + Lanes <= width; i += Lanes)
  {
    for (long j = 0; j < Lanes; ++j)
    {
      lanes[j] += scratch[i + j];
    }
  }
  for (long j = 0; i < width; ++i, ++j)
  {
    lanes[j] += scratch[i];
  }
  double sum = 0.0;
  for (long j = 0; j < Lanes; ++j)
  {
    sum += lanes[j];
  }
  return sum;
}

/** depth += delta on a row, kept within [low, high]: the fixed point lies within the range of the input (each free
 * pixel a weighted mean of its neighbours), so a correction that leaves it, as one can in a mode the weights all
 * but decouple, is cut back to it. */
VR_ROW_LOOP void
AddRow(double * __restrict depth, const float * __restrict delta, float step, double low, double high, long width)
{
  for (long x = 0; x < width; ++x)
  {
    const double moved = depth[x] + static_cast<double>(step * delta[x]);
    depth[x] = std::min(std::max(moved, low), high);
  }
}

/** Union-find over row runs, for the regions of pixels connected through non-zero weights. */
class Regions
{
public:
  std::int32_t
  Find(std::int32_t a)
  {
    while (m_Parent[a] != a)
    {
      m_Parent[a] = m_Parent[m_Parent[a]];
      a = m_Parent[a];
    }
    return a;
  }
  void
  Unite(std::int32_t a, std::int32_t b)
  {
    a = Find(a);
    b = Find(b);
    if (a != b)
    {
      m_Parent[std::max(a, b)] = std::min(a, b);
    }
  }
  /** \a count regions, each its own. */
  void
  Reset(std::size_t count)
  {
    m_Parent.resize(count);
    for (std::size_t k = 0; k < count; ++k)
    {
      m_Parent[k] = static_cast<std::int32_t>(k);
    }
  }

private:
  std::vector<std::int32_t> m_Parent;
};

/** A run of pixels of one row, [Begin, End), joined by non-zero weights, and its region. */
struct RowRun
{
  long         Begin;
  long         End;
  std::int32_t Region;
};

/** Everything a solve allocates. */
struct SolverBuffers
{
  std::vector<Level>         Levels;
  Array<double>              Depth;
  Array<float>               WeightRight, WeightDown, Fixed, Active;
  Array<float>               Residual, Z, Delta, Direction;
  Array<float>               HessianC, HessianE, HessianN, Saved;
  std::vector<float>         ResidualRows, ScratchRows;
  std::vector<double>        RowSums;
  std::vector<std::uint64_t> RowSignatures;
  std::vector<double>        RowMaxima;
  std::vector<RowRun>        Runs;
  std::vector<long>          RowRunStart;
  std::vector<char>          RunJoined, RunFixed, RowChanged;
  Regions                    RunRegions;
  std::vector<char>          RegionAnchored;
  std::vector<double>        RegionSum, RegionPixels;
  std::vector<double>        CoarseFactor;
  std::vector<long>          CoarseIndex;
  std::vector<char>          CoarseDropped;
  std::vector<double>        CoarseVector;
};

/** sum of a[i] b[i] over a row, in Lanes partial sums added in a fixed order: the same bits on any machine. */
VR_ROW_LOOP double
RowDot(const float * __restrict a, const float * __restrict b, long count)
{
  double lanes[Lanes] = {};
  long   i = 0;
  for (; i + Lanes <= count; i += Lanes)
  {
    for (long j = 0; j < Lanes; ++j)
    {
      lanes[j] += static_cast<double>(a[i + j]) * b[i + j];
    }
  }
  for (long j = 0; i < count; ++i, ++j)
  {
    lanes[j] += static_cast<double>(a[i]) * b[i];
  }
  double sum = 0.0;
  for (long j = 0; j < Lanes; ++j)
  {
    sum += lanes[j];
  }
  return sum;
}

/** max |r[i]| s[i] over a row, in Lanes partial maxima. */
VR_ROW_LOOP float
RowMaximum(const float * __restrict r, const float * __restrict s, long count)
{
  float lanes[Lanes] = {};
  long  i = 0;
  for (; i + Lanes <= count; i += Lanes)
  {
    for (long j = 0; j < Lanes; ++j)
    {
      const float value = std::abs(r[i + j]) * s[i + j];
      lanes[j] = lanes[j] > value ? lanes[j] : value;
    }
  }
  for (long j = 0; i < count; ++i, ++j)
  {
    const float value = std::abs(r[i]) * s[i];
    lanes[j] = lanes[j] > value ? lanes[j] : value;
  }
  float largest = 0.0f;
  for (long j = 0; j < Lanes; ++j)
  {
    largest = largest > lanes[j] ? largest : lanes[j];
  }
  return largest;
}

/** max |r[i]| / c[i] over a row's active points (see DividedByDiagonal), in Lanes partial maxima. */
VR_ROW_LOOP float
RowMaximumOverDiagonal(const float * __restrict r, const float * __restrict c, long count)
{
  float lanes[Lanes] = {};
  long  i = 0;
  for (; i + Lanes <= count; i += Lanes)
  {
    for (long j = 0; j < Lanes; ++j)
    {
      const float value = DividedByDiagonal(std::abs(r[i + j]), c[i + j]);
      lanes[j] = lanes[j] > value ? lanes[j] : value;
    }
  }
  for (long j = 0; i < count; ++i, ++j)
  {
    const float value = DividedByDiagonal(std::abs(r[i]), c[i]);
    lanes[j] = lanes[j] > value ? lanes[j] : value;
  }
  float largest = 0.0f;
  for (long j = 0; j < Lanes; ++j)
  {
    largest = largest > lanes[j] ? largest : lanes[j];
  }
  return largest;
}
} // namespace

struct BilateralDepthRelaxSteadySolver::Workspace::Buffers : SolverBuffers
{
};

BilateralDepthRelaxSteadySolver::Workspace::Workspace()
  : m_Buffers(std::make_unique<Buffers>())
{
}

BilateralDepthRelaxSteadySolver::Workspace::~Workspace() = default;

namespace
{
/** The whole solve, on the buffers of a workspace. */
class SteadySolve
{
public:
  SteadySolve(SolverBuffers & buffers, long width, long height, double anisotropy, unsigned int threads)
    : m_Buffers(buffers)
    , m_Team(std::max(1u, std::min<unsigned int>(threads, static_cast<unsigned int>(std::max(1L, height / 8)))))
    , m_Width(width)
    , m_Height(height)
    , m_Stride(PaddedStride(width))
    , m_Scale(static_cast<float>(anisotropy > 0.0 ? std::sqrt(anisotropy / std::log(2.0)) : 0.0))
    , m_Isotropic(anisotropy == 0.0)
    , m_TwiceAnisotropy(static_cast<float>(2.0 * anisotropy))
  {
    const std::size_t size = static_cast<std::size_t>(m_Stride * (height + 3));
    bool              fresh = false;
    m_Depth = buffers.Depth.Reserve(size, fresh);
    m_WeightRight = buffers.WeightRight.Reserve(size, fresh);
    m_WeightDown = buffers.WeightDown.Reserve(size, fresh);
    m_Fixed = buffers.Fixed.Reserve(size, fresh);
    m_Active = buffers.Active.Reserve(size, fresh);
    m_Residual = buffers.Residual.Reserve(size, fresh);
    m_Z = buffers.Z.Reserve(size, fresh);
    m_Delta = buffers.Delta.Reserve(size, fresh);
    m_Direction = buffers.Direction.Reserve(size, fresh);
    m_HessianC = buffers.HessianC.Reserve(size, fresh);
    m_HessianE = buffers.HessianE.Reserve(size, fresh);
    m_HessianN = buffers.HessianN.Reserve(size, fresh);
    m_Saved = buffers.Saved.Reserve(size, fresh);
    buffers.RowSums.assign(static_cast<std::size_t>(height), 0.0);
    // Three residual rows per team member for ResidualAndRestrict, zero-padded; the finest level's are the widest.
    buffers.ResidualRows.assign(static_cast<std::size_t>(3 * m_Stride) * m_Team.GetSize(), 0.0f);
    buffers.ScratchRows.assign(static_cast<std::size_t>(m_Stride) * m_Team.GetSize(), 0.0f);
    buffers.RowSignatures.assign(static_cast<std::size_t>(height), 0);
    buffers.RowMaxima.assign(static_cast<std::size_t>(height), 0.0);
    buffers.Levels.resize(std::max<std::size_t>(1, buffers.Levels.size()));
    Level & finest = buffers.Levels[0];
    finest.Allocate(width, height, false);
    // The finest level's right-hand side and correction are the conjugate gradients' residual and preconditioned
    // residual.
    finest.B = m_Residual;
    finest.X = m_Z;
  }

  long
  At(long x, long y) const
  {
    return (y + 1) * m_Stride + x + 1;
  }

  /** Runs \a job on bands of rows [0, rows), in parallel when \a parallel. */
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

  void
  Load(const float * depth, const unsigned char * fixed)
  {
    // The input's range, per row in the same pass (into two per-row arrays free until the solve starts).
    std::vector<double> & lowest = m_Buffers.RowSums;
    std::vector<double> & highest = m_Buffers.RowMaxima;
    ForRows(m_Height,
            true,
            [&](long y0, long y1)
            {
              for (long y = y0; y < y1; ++y)
              {
                const float * in = depth + y * m_Width;
                const long    row = At(0, y);
                for (long x = 0; x < m_Width; ++x)
                {
                  m_Depth[row + x] = in[x];
                  m_Fixed[row + x] = fixed && fixed[y * m_Width + x] ? 1.0f : 0.0f;
                }
                const auto range = std::minmax_element(in, in + m_Width);
                lowest[static_cast<std::size_t>(y)] = *range.first;
                highest[static_cast<std::size_t>(y)] = *range.second;
              }
            });
    m_Lowest = *std::min_element(lowest.begin(), lowest.end());
    m_Highest = *std::max_element(highest.begin(), highest.end());
  }

  void
  Store(const float * depth, const unsigned char * fixed, float * relaxed)
  {
    ForRows(m_Height,
            true,
            [&](long y0, long y1)
            {
              for (long y = y0; y < y1; ++y)
              {
                const long row = At(0, y);
                for (long x = 0; x < m_Width; ++x)
                {
                  const long k = y * m_Width + x;
                  relaxed[k] = fixed && fixed[k] ? depth[k] : static_cast<float>(m_Depth[row + x]);
                }
              }
            });
  }

  /** The weight of every edge at the current depths (0 across the image border), and a signature of the pattern
   * of vanishing weights, to notice when regions may have changed. */
  std::uint64_t
  ComputeWeights()
  {
    std::vector<std::uint64_t> & signatures = m_Buffers.RowSignatures;
    ForRows(m_Height,
            true,
            [&](long y0, long y1)
            {
              for (long y = y0; y < y1; ++y)
              {
                const long row = At(0, y);
                signatures[static_cast<std::size_t>(y)] =
                  WeightRow(m_WeightRight + row,
                            m_WeightDown + row,
                            m_Depth + row,
                            y + 1 < m_Height ? m_Depth + row + m_Stride : nullptr,
                            m_Scale,
                            m_Isotropic,
                            m_Width);
              }
            });
    std::uint64_t signature = 0;
    for (const std::uint64_t value : signatures)
    {
      signature = signature * 0x9E3779B97F4A7C15ull + value;
    }
    return signature;
  }

  /** Marks the free pixels of regions without a fixed pixel (regions connected through non-zero weights), gives
   * each such region its mean depth, and marks every other free pixel active. Works on runs of pixels joined
   * within their row, united with the runs they touch through a non-zero weight in the next row. The passes over
   * pixels run on bands of rows; only the union-find over runs and the means of floating regions are serial.
   * Returns the floating pixel count; \a changed tells whether any pixel's activity changed. */
  std::size_t
  ClassifyRegions(bool & changed)
  {
    Regions &             regions = m_Buffers.RunRegions;
    std::vector<RowRun> & runs = m_Buffers.Runs;
    std::vector<long> &   rowStart = m_Buffers.RowRunStart;
    const std::size_t     rowCount = static_cast<std::size_t>(m_Height);
    // The runs of each row (a run ends at a vanishing weight to its right or at the row's end), then their places.
    rowStart.assign(rowCount + 1, 0);
    ForRows(m_Height,
            true,
            [&](long y0, long y1)
            {
              for (long y = y0; y < y1; ++y)
              {
                const float * right = m_WeightRight + At(0, y);
                long          count = 1;
                for (long x = 0; x + 1 < m_Width; ++x)
                {
                  count += right[x] == 0.0f ? 1 : 0;
                }
                rowStart[static_cast<std::size_t>(y) + 1] = count;
              }
            });
    for (std::size_t y = 0; y < rowCount; ++y)
    {
      rowStart[y + 1] += rowStart[y];
    }
    const std::size_t   count = static_cast<std::size_t>(rowStart[rowCount]);
    std::vector<char> & fixedRun = m_Buffers.RunFixed;
    runs.resize(count);
    fixedRun.assign(count, 0);
    ForRows(m_Height,
            true,
            [&](long y0, long y1)
            {
              for (long y = y0; y < y1; ++y)
              {
                const float * right = m_WeightRight + At(0, y);
                const float * fixed = m_Fixed + At(0, y);
                long          k = rowStart[static_cast<std::size_t>(y)];
                long          begin = 0;
                for (long x = 0; x < m_Width; ++x)
                {
                  if (x + 1 == m_Width || right[x] == 0.0f)
                  {
                    runs[static_cast<std::size_t>(k)] = { begin, x + 1, static_cast<std::int32_t>(k) };
                    fixedRun[static_cast<std::size_t>(k)] =
                      std::any_of(fixed + begin, fixed + x + 1, [](float value) { return value != 0.0f; });
                    ++k;
                    begin = x + 1;
                  }
                }
              }
            });
    // Walks the overlapping runs of rows y and y + 1 in order. Row pair y's walk takes fewer than
    // rowStart[y + 2] - rowStart[y] steps, so its steps can be numbered from rowStart[y] + rowStart[y + 1].
    auto walk = [&](long y, const auto & step)
    {
      const std::size_t row = static_cast<std::size_t>(y);
      std::size_t       a = static_cast<std::size_t>(rowStart[row]);
      std::size_t       b = static_cast<std::size_t>(rowStart[row + 1]);
      const std::size_t aEnd = b;
      const std::size_t bEnd = static_cast<std::size_t>(rowStart[row + 2]);
      std::size_t       number = static_cast<std::size_t>(rowStart[row] + rowStart[row + 1]);
      while (a < aEnd && b < bEnd)
      {
        step(a, b, number++);
        runs[a].End < runs[b].End ? ++a : ++b;
      }
    };
    // Whether each such pair is joined by a non-zero weight, in parallel; then the unions, in order.
    std::vector<char> & joined = m_Buffers.RunJoined;
    joined.assign(2 * count, 0);
    ForRows(m_Height - 1,
            true,
            [&](long y0, long y1)
            {
              for (long y = y0; y < y1; ++y)
              {
                const float * down = m_WeightDown + At(0, y);
                walk(y,
                     [&](std::size_t a, std::size_t b, std::size_t number)
                     {
                       const long begin = std::max(runs[a].Begin, runs[b].Begin);
                       const long end = std::min(runs[a].End, runs[b].End);
                       joined[number] =
                         std::any_of(down + begin, down + end, [](float weight) { return weight > 0.0f; });
                     });
              }
            });
    regions.Reset(count);
    for (long y = 0; y + 1 < m_Height; ++y)
    {
      walk(y,
           [&](std::size_t a, std::size_t b, std::size_t number)
           {
             if (joined[number])
             {
               regions.Unite(runs[a].Region, runs[b].Region);
             }
           });
    }
    std::vector<char> & anchored = m_Buffers.RegionAnchored;
    anchored.assign(count, 0);
    for (std::size_t k = 0; k < count; ++k)
    {
      runs[k].Region = regions.Find(runs[k].Region);
      anchored[static_cast<std::size_t>(runs[k].Region)] |= fixedRun[k];
    }
    // The mean depth of each floating region, over its free pixels (a floating region has no fixed ones).
    std::vector<double> & sum = m_Buffers.RegionSum;
    std::vector<double> & pixels = m_Buffers.RegionPixels;
    sum.assign(count, 0.0);
    pixels.assign(count, 0.0);
    for (long y = 0; y < m_Height; ++y)
    {
      const double * depth = m_Depth + At(0, y);
      for (long k = rowStart[static_cast<std::size_t>(y)]; k < rowStart[static_cast<std::size_t>(y + 1)]; ++k)
      {
        const RowRun & run = runs[static_cast<std::size_t>(k)];
        if (!anchored[static_cast<std::size_t>(run.Region)])
        {
          for (long x = run.Begin; x < run.End; ++x)
          {
            sum[static_cast<std::size_t>(run.Region)] += depth[x];
          }
          pixels[static_cast<std::size_t>(run.Region)] += static_cast<double>(run.End - run.Begin);
        }
      }
    }
    // Activity and the floating regions' means, per row; the counts per row go to RowMaxima (free until the next
    // assembly) and are added in order.
    std::vector<double> & rowCounts = m_Buffers.RowMaxima;
    std::vector<char> &   rowChanged = m_Buffers.RowChanged;
    rowChanged.assign(rowCount, 0);
    ForRows(m_Height,
            true,
            [&](long y0, long y1)
            {
              for (long y = y0; y < y1; ++y)
              {
                const long    row = At(0, y);
                const float * fixed = m_Fixed + row;
                float *       active = m_Active + row;
                double *      depth = m_Depth + row;
                long          floating = 0;
                long          changes = 0;
                for (long k = rowStart[static_cast<std::size_t>(y)]; k < rowStart[static_cast<std::size_t>(y + 1)]; ++k)
                {
                  const RowRun &    run = runs[static_cast<std::size_t>(k)];
                  const std::size_t region = static_cast<std::size_t>(run.Region);
                  if (anchored[region])
                  {
                    for (long x = run.Begin; x < run.End; ++x)
                    {
                      const float now = 1.0f - fixed[x];
                      changes += now != active[x];
                      active[x] = now;
                    }
                  }
                  else
                  {
                    const double mean = sum[region] / pixels[region];
                    for (long x = run.Begin; x < run.End; ++x)
                    {
                      changes += active[x] != 0.0f;
                      active[x] = 0.0f;
                      depth[x] = mean;
                    }
                    floating += run.End - run.Begin;
                  }
                }
                rowCounts[static_cast<std::size_t>(y)] = static_cast<double>(floating);
                rowChanged[static_cast<std::size_t>(y)] = changes > 0 ? 1 : 0;
              }
            });
    std::size_t floating = 0;
    changed = false;
    for (std::size_t y = 0; y < rowCount; ++y)
    {
      floating += static_cast<std::size_t>(rowCounts[y]);
      changed = changed || rowChanged[y] != 0;
    }
    return floating;
  }

  /** The finest level's operator from the weights (C = the pixel's weight sum, couplings between active pixels)
   * and the residual sum R (D_q - D_p) as the conjugate gradients' right-hand side, and with \a hessian the energy's
   * Hessian for Newton steps (a third of the work, left out while lagged weights suffice). Returns max |residual| / C
   * over active pixels: the fixed-point residual |D_p - sum R D_q / sum R| in mm. */
  double
  Assemble(bool hessian)
  {
    Level &               l = m_Buffers.Levels[0];
    std::vector<double> & maxima = m_Buffers.RowMaxima;
    const long            s = m_Stride;
    ForRows(m_Height,
            true,
            [&](long y0, long y1)
            {
              for (long y = y0; y < y1; ++y)
              {
                const long row = At(0, y);
                (hessian ? AssembleOperatorAndHessianRow : AssembleOperatorRow)(l.C + row,
                                                                                l.E + row,
                                                                                l.N + row,
                                                                                m_HessianC + row,
                                                                                m_HessianE + row,
                                                                                m_HessianN + row,
                                                                                m_Residual + row,
                                                                                m_Depth + row,
                                                                                m_Depth + row + s,
                                                                                m_Depth + row - s,
                                                                                m_Active + row,
                                                                                m_Active + row + s,
                                                                                m_WeightRight + row,
                                                                                m_WeightDown + row,
                                                                                m_WeightDown + row - s,
                                                                                m_TwiceAnisotropy,
                                                                                m_Width);
                maxima[static_cast<std::size_t>(y)] = RowMaximumOverDiagonal(m_Residual + row, l.C + row, m_Width);
              }
            });
    return *std::max_element(maxima.begin(), maxima.end());
  }

  void
  BuildHierarchy()
  {
    std::vector<Level> & levels = m_Buffers.Levels;
    std::size_t          count = 1;
    while (levels[count - 1].Width * levels[count - 1].Height > CoarsestPoints)
    {
      if (levels.size() <= count)
      {
        levels.emplace_back();
      }
      const Level & f = levels[count - 1];
      Level &       c = levels[count];
      c.Allocate((f.Width + 1) / 2, (f.Height + 1) / 2, true);
      const bool parallel = c.IsParallel();
      ForRows(c.Height,
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
      ForRows(c.Height,
              parallel,
              [&](long J0, long J1)
              {
                for (long J = J0; J < J1; ++J)
                {
                  f.NinePoint ? BuildEdgeInterpolationRow<true>(f, c, J) : BuildEdgeInterpolationRow<false>(f, c, J);
                }
              });
      ForRows(c.Height,
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
      ForRows(c.Height,
              parallel,
              [&](long J0, long J1)
              {
                for (long J = J0; J < J1; ++J)
                {
                  f.NinePoint ? BuildGalerkinRowFrom9(f, c, J) : BuildGalerkinRowFrom5(f, c, J);
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
  FactorCoarsest()
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
  SolveCoarsest()
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
  Smooth(const Level & l, bool forward)
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
  SmoothFourColour(const Level & l, bool forward)
  {
    const long firstParity = forward ? 0 : 1;
    // Forward, colours x % 2 == 0 then 1 on each row; backward, 1 then 0.
    auto pair = [&](long y)
    {
      SmoothRow<true>(l, y, forward ? 0 : 1);
      SmoothRow<true>(l, y, forward ? 1 : 0);
    };
    ForRows(l.Height,
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
    ForRows(l.Height,
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
  SmoothRedBlack(const Level & l, int first, bool fromZero)
  {
    const int second = 1 - first;
    auto      colourRow = [&](int colour, long y, bool zero)
    {
      const long p = l.At(0, y);
      if (zero)
      {
        SmoothRowFromZero(l.X + p, l.B + p, l.C + p, (y + colour) & 1, l.Width);
      }
      else
      {
        SmoothRow<false>(l, y, (y + colour) & 1);
      }
    };
    const bool parallel = l.IsParallel();
    ForRows(l.Height,
            parallel,
            [&](long y0, long y1)
            {
              for (long y = y0; y < y1; ++y)
              {
                colourRow(first, y, fromZero);
                if (y - 1 > y0)
                {
                  colourRow(second, y - 1, false);
                }
              }
            });
    ForRows(l.Height,
            parallel,
            [&](long y0, long y1)
            {
              colourRow(second, y0, false);
              if (y1 - 1 > y0)
              {
                colourRow(second, y1 - 1, false);
              }
            });
  }

  /** b_c = P^T (b_f - A_f x_f). Coarse row J needs the fine residual of rows 2J - 1 to 2J + 1; each member of the
   * team computes them into three rows of its own as it goes up its band (its first coarse row computes row 2J - 1
   * too, which the band below computes as well), so the residual never goes through memory and no band waits for
   * another. */
  void
  ResidualAndRestrict(const Level & f, const Level & c)
  {
    const long stride = f.Stride;
    float *    scratch = m_Buffers.ResidualRows.data();
    ForRowsOfMembers(c.Height,
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

  /** One V(1,1)-cycle from level \a k down: x_k = M^-1 b_k, x_k starting at 0. */
  void
  Cycle(std::size_t k)
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
      ForRows(f.Height,
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
    ResidualAndRestrict(f, c);
    Cycle(k + 1);
    ForRows(c.Height, parallel, [&](long J0, long J1) { ProlongRows(c, f, J0, J1); });
    Smooth(f, false);
  }

  /** z = M^-1 r: one V-cycle on the finest level, whose right-hand side is r and whose correction is z. */
  void
  Precondition()
  {
    Cycle(0);
    ++m_Cycles;
  }

  /** sum over rows of \a rowSum(y, scratch), each row's sum formed independently and the rows added in order;
   * \a scratch is a row of Width floats of the thread's own, for values the row's sum needs only while it is formed. */
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
    double sum = 0.0;
    for (const double value : rows)
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

  /** Conjugate gradients on the finest level, preconditioned by V-cycles of the lagged-weights operator, until
   * max |r| / C falls below \a target: on the energy's Hessian when \a newton, else on the lagged-weights operator.
   * Leaves the correction in m_Delta and the V-cycles spent in m_LastCycles. Returns false when a Newton solve meets
   * a direction of non-positive curvature (left in m_Direction, m_NegativeCurvature set); the correction is then
   * unusable. */
  bool
  SolveCorrection(double target, bool newton)
  {
    const float * opC = newton ? m_HessianC : m_Buffers.Levels[0].C;
    const float * opE = newton ? m_HessianE : m_Buffers.Levels[0].E;
    const float * opN = newton ? m_HessianN : m_Buffers.Levels[0].N;
    m_NegativeCurvature = false;
    const Level &         l = m_Buffers.Levels[0];
    const long            s = m_Stride;
    const long            width = m_Width;
    const unsigned int    cyclesBefore = m_Cycles;
    std::vector<double> & maxima = m_Buffers.RowMaxima;
    Precondition();
    double rz = SumRows(
      [&](long y, float *)
      {
        const long row = At(0, y);
        std::copy(m_Z + row, m_Z + row + width, m_Direction + row);
        std::fill(m_Delta + row, m_Delta + row + width, 0.0f);
        return RowDot(m_Residual + row, m_Z + row, width);
      });
    for (unsigned int iteration = 0; iteration < MaximumInnerIterations; ++iteration)
    {
      // A v row by row into the thread's scratch row, here for its dot product and again in the update below:
      // computing it twice costs less than writing it out and reading it back.
      auto applyRow = [&](long y, float * product)
      {
        const long row = At(0, y);
        ApplyRow5(product,
                  m_Direction + row,
                  m_Direction + row + s,
                  m_Direction + row - s,
                  opC + row,
                  opE + row,
                  opN + row,
                  opN + row - s,
                  width);
      };
      const double curvature = SumRows(
        [&](long y, float * product)
        {
          applyRow(y, product);
          return RowDot(m_Direction + At(0, y), product, width);
        });
      m_NegativeCurvature = newton && !(curvature > 0.0) && rz > 0.0;
      if (m_NegativeCurvature)
      {
        return false;
      }
      if (!(curvature > 0.0) || !(rz > 0.0))
      {
        break;
      }
      const float alpha = static_cast<float>(rz / curvature);
      ForRowsOfMembers(m_Height,
                       true,
                       [&](unsigned int member, long y0, long y1)
                       {
                         float * product = ScratchRow(member);
                         for (long y = y0; y < y1; ++y)
                         {
                           const long row = At(0, y);
                           applyRow(y, product);
                           UpdateRow(m_Delta + row, m_Residual + row, m_Direction + row, product, alpha, width);
                           maxima[static_cast<std::size_t>(y)] =
                             RowMaximumOverDiagonal(m_Residual + row, l.C + row, width);
                         }
                       });
      if (*std::max_element(maxima.begin(), maxima.end()) <= target)
      {
        break;
      }
      Precondition();
      const double rzNext = SumRows(
        [&](long y, float *)
        {
          const long row = At(0, y);
          return RowDot(m_Residual + row, m_Z + row, width);
        });
      const float beta = static_cast<float>(rzNext / rz);
      rz = rzNext;
      ForRows(m_Height,
              true,
              [&](long y0, long y1)
              {
                for (long y = y0; y < y1; ++y)
                {
                  DirectionRow(m_Direction + At(0, y), m_Z + At(0, y), beta, width);
                }
              });
    }
    m_LastCycles = m_Cycles - cyclesBefore;
    return true;
  }

  /** The energy change, times 2a, when the depths move by \a step times the correction. */
  double
  EnergyChange(float step)
  {
    const float anisotropy = 0.5f * m_TwiceAnisotropy;
    return SumRows(
      [&](long y, float * scratch)
      {
        const long row = At(0, y);
        const bool last = y + 1 == m_Height;
        return EnergyChangeRow(m_Depth + row,
                               last ? nullptr : m_Depth + row + m_Stride,
                               m_Delta + row,
                               m_Delta + row + m_Stride,
                               step,
                               anisotropy,
                               m_Scale,
                               scratch,
                               m_Width);
      });
  }

  /** The step along the direction of negative curvature the conjugate gradients met (copied into the correction),
   * in either sense, that lowers the energy most: first steps move a depth by at most J / 32, and each further one
   * doubles it, up to 2 J. Returns the energy change, times 2a (0 with a step of 0 when no step lowers it). */
  double
  SearchNegativeCurvature(float & step)
  {
    std::vector<double> & maxima = m_Buffers.RowMaxima;
    ForRows(m_Height,
            true,
            [&](long y0, long y1)
            {
              for (long y = y0; y < y1; ++y)
              {
                const long row = At(0, y);
                std::copy(m_Direction + row, m_Direction + row + m_Width, m_Delta + row);
                maxima[static_cast<std::size_t>(y)] = RowMaximum(m_Delta + row, m_Active + row, m_Width);
              }
            });
    step = 0.0f;
    const double largest = *std::max_element(maxima.begin(), maxima.end());
    if (!(largest > 0.0))
    {
      return 0.0;
    }
    const float  unit = static_cast<float>(1.0 / (32.0 * largest * std::sqrt(0.5 * m_TwiceAnisotropy)));
    const double forward = EnergyChange(unit);
    const double backward = EnergyChange(-unit);
    double       change = std::min(forward, backward);
    if (!(change < 0.0))
    {
      return 0.0;
    }
    step = forward <= backward ? unit : -unit;
    while (std::abs(step) < 64.0f * unit)
    {
      const double further = EnergyChange(2.0f * step);
      if (!(further < change))
      {
        break;
      }
      change = further;
      step *= 2.0f;
    }
    return change;
  }

  /** The step along the lagged-weights correction, 1 or a power of two up to MaximumStep, that lowers the energy
   * most (the step 1 lowers it: each lagged-weights problem majorises the energy). Returns the energy change, times
   * 2a. */
  double
  SearchLaggedStep(float & step)
  {
    step = 1.0f;
    double change = EnergyChange(step);
    while (step < MaximumStep)
    {
      const double further = EnergyChange(2.0f * step);
      if (!(further < change))
      {
        break;
      }
      change = further;
      step *= 2.0f;
    }
    return change;
  }

  /** to = from on every row. */
  void
  CopyRows(const float * from, float * to)
  {
    ForRows(m_Height, true, [&](long y0, long y1) { std::copy(from + At(0, y0), from + At(0, y1), to + At(0, y0)); });
  }

  /** depth += step times the correction. */
  void
  ApplyCorrection(float step)
  {
    ForRows(m_Height,
            true,
            [&](long y0, long y1)
            {
              for (long y = y0; y < y1; ++y)
              {
                AddRow(m_Depth + At(0, y), m_Delta + At(0, y), step, m_Lowest, m_Highest, m_Width);
              }
            });
  }

  BilateralDepthRelaxSteadySolver::Report
  Run(double tolerance, const BilateralDepthRelaxSteadySolver::ProgressCallback & progress)
  {
    BilateralDepthRelaxSteadySolver::Report report;
    std::uint64_t                           signature = ComputeWeights();
    bool                                    changed = false;
    report.FloatingPixels = ClassifyRegions(changed);
    if (report.FloatingPixels > 0)
    {
      signature = ComputeWeights();
    }
    bool   rebuild = true;
    double first = 0.0;
    double done = 0.0;
    double previous = std::numeric_limits<double>::infinity();
    bool   newton = false;
    for (unsigned int outer = 0;; ++outer)
    {
      if (outer > 0)
      {
        const std::uint64_t next = ComputeWeights();
        if (next != signature)
        {
          signature = next;
          report.FloatingPixels = ClassifyRegions(changed);
          if (changed)
          {
            // Floating regions took their mean, or former ones joined anchored regions: new weights, new hierarchy.
            signature = ComputeWeights();
            rebuild = true;
          }
        }
      }
      // The Hessian while Newton steps go on; an outer iteration that turns to them below assembles it then.
      const double residual = Assemble(newton);
      report.Residual = residual;
      report.OuterIterations = outer;
      if (outer == 0)
      {
        first = residual;
      }
      if (progress)
      {
        // The residual need not fall at every outer iteration; the progress never goes back.
        const double fraction =
          residual <= tolerance ? 1.0 : std::clamp(std::log(first / residual) / std::log(first / tolerance), 0.0, 1.0);
        done = std::max(done, fraction);
        progress(done);
      }
      if (residual <= tolerance)
      {
        break;
      }
      if (outer == BilateralDepthRelaxSteadySolver::MaximumOuterIterations)
      {
        throw std::runtime_error("BilateralDepthRelaxSteadySolver: the residual is still " + std::to_string(residual) +
                                 " mm after " + std::to_string(outer) + " outer iterations");
      }
      if (rebuild)
      {
        BuildHierarchy();
        ++report.HierarchyBuilds;
        rebuild = false;
      }
      const double target = std::max(InnerReduction * residual, 0.5 * tolerance);
      // Newton steps once lagged weights have slowed down, for as long as they are taken.
      const bool hessianAssembled = newton;
      newton = !m_Isotropic && (newton || residual > NewtonAfterReduction * previous);
      previous = residual;
      if (newton && !hessianAssembled)
      {
        Assemble(true);
      }
      if (!newton)
      {
        SolveCorrection(target, false);
        ApplyCorrection(1.0f);
      }
      else if (SolveCorrection(target, true) && EnergyChange(1.0f) <= 0.0)
      {
        ApplyCorrection(1.0f);
      }
      else
      {
        newton = false;
        float        curvatureStep = 0.0f;
        const double curvatureChange = m_NegativeCurvature ? SearchNegativeCurvature(curvatureStep) : 0.0;
        if (curvatureStep != 0.0f)
        {
          CopyRows(m_Delta, m_Saved);
        }
        Assemble(false);
        SolveCorrection(target, false);
        float        laggedStep = 1.0f;
        const double laggedChange = SearchLaggedStep(laggedStep);
        if (curvatureStep != 0.0f && curvatureChange < laggedChange)
        {
          CopyRows(m_Saved, m_Delta);
          ApplyCorrection(curvatureStep);
        }
        else
        {
          ApplyCorrection(laggedStep);
        }
      }
      rebuild = m_LastCycles > RebuildAfterCycles;
    }
    report.Cycles = m_Cycles;
    return report;
  }

private:
  SolverBuffers &    m_Buffers;
  detail::ThreadTeam m_Team;
  long               m_Width;
  long               m_Height;
  long               m_Stride;
  float              m_Scale;
  bool               m_Isotropic;
  float              m_TwiceAnisotropy;
  std::size_t        m_LevelCount{ 1 };
  unsigned int       m_Cycles{ 0 };
  unsigned int       m_LastCycles{ 0 };
  bool               m_NegativeCurvature{ false };

  double * m_Depth;
  float *  m_WeightRight;
  float *  m_WeightDown;
  float *  m_Fixed;
  float *  m_Active;
  float *  m_Residual;
  double   m_Lowest{ 0.0 };
  double   m_Highest{ 0.0 };
  float *  m_Z;
  float *  m_Delta;
  float *  m_Direction;
  float *  m_HessianC;
  float *  m_HessianE;
  float *  m_HessianN;
  float *  m_Saved;
};
} // namespace

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
  Report report;
  if (width == 0 || height == 0)
  {
    return report;
  }
  Workspace       ownWorkspace;
  SolverBuffers & buffers = *(workspace ? workspace : &ownWorkspace)->m_Buffers;
  SteadySolve     solve(buffers, static_cast<long>(width), static_cast<long>(height), anisotropy, threads);
  solve.Load(depth, fixed);
  report = solve.Run(tolerance, progress);
  solve.Store(depth, fixed, relaxed);
  return report;
}

} // namespace itk
