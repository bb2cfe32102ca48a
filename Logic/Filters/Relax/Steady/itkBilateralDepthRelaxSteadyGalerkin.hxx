// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The steady solver's Galerkin coarse operator A_c = P^T A P, a coarse row at a time: included by the row kernels'
// units (itkBilateralDepthRelaxSteadyRows.hxx), one per instruction set, hence internal linkage throughout (a linker
// must never pick one unit's copy for a caller in another). Internal (namespace itk::detail), not installed.
#ifndef itkBilateralDepthRelaxSteadyGalerkin_hxx
#define itkBilateralDepthRelaxSteadyGalerkin_hxx

#include "itkBilateralDepthRelaxSteadyGrid.h"

#include <utility>

namespace itk::detail::BilateralDepthRelaxSteady
{
namespace
{
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

/** Coarse row \a J's operator. Each coarse point's entries read the interpolation and the finer operator only and
 * write that point's own entries, so no point of the row depends on another (ivdep, in Clang assume_safety, tells the
 * vectoriser so). An inactive point has no interpolation to or from it, so its entries come out 0 without a test. */
template<bool NinePoint>
[[gnu::always_inline]] inline void
BuildGalerkinRowOf(const Level & f, Level & c, long J)
{
  const long k0 = c.At(0, J);
  const long p00 = f.At(0, 2 * J);
  const long width = c.Width;
#if defined(__clang__)
#pragma clang loop vectorize(assume_safety)
#else
#pragma GCC ivdep
#endif
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

/** BuildGalerkinRowOf from the finest (5-point) and from a 9-point level (RowKernels::BuildGalerkinRowFrom5, 9). */
void
BuildGalerkinRowFrom5(const Level & f, Level & c, long J)
{
  BuildGalerkinRowOf<false>(f, c, J);
}
void
BuildGalerkinRowFrom9(const Level & f, Level & c, long J)
{
  BuildGalerkinRowOf<true>(f, c, J);
}
} // namespace
} // namespace itk::detail::BilateralDepthRelaxSteady

#endif
