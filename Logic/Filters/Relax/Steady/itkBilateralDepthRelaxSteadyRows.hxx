// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The steady solver's row kernels (RowKernels, itkBilateralDepthRelaxSteadyRows.h), defined for the unit that includes
// this file: itkBilateralDepthRelaxSteadyRows{Baseline,AVX2,AVX512}.cxx, each compiled for its instruction set, the
// same mechanism as the Jacobi sweep's (itkBilateralDepthRelaxRows.hxx). Each kernel works on one row of a padded
// grid (itkBilateralDepthRelaxSteadyGrid.h) through raw pointers and plain numbers only, so that the compiler sees
// unit strides, no aliasing and loop-invariant bounds, and turns each into vector operations. Everything has internal
// linkage: a linker must never pick one unit's copy for a caller in another. Internal, not installed.
#ifndef itkBilateralDepthRelaxSteadyRows_hxx
#define itkBilateralDepthRelaxSteadyRows_hxx

#include "itkBilateralDepthRelaxRangeWeight.h"
#include "itkBilateralDepthRelaxSteadyGalerkin.hxx"
#include "itkBilateralDepthRelaxSteadyGrid.h"
#include "itkBilateralDepthRelaxSteadyRows.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace itk::detail::BilateralDepthRelaxSteady
{
namespace
{
// Each row kernel's comment is at its RowKernels member.

/** value / C_p at an active point (C_p > 0; one below FLT_MIN taken as FLT_MIN, so that nothing overflows), 0 at an
 * inactive one (C_p = 0). Divided where needed rather than multiplied by stored inverses: the solver is bound by
 * memory traffic, and an array of inverses per level cost more to stream than the divisions. */
inline float
DividedByDiagonal(float value, float diagonal)
{
  const float quotient = value / std::max(diagonal, std::numeric_limits<float>::min());
  return diagonal > 0.0f ? quotient : 0.0f;
}

/** term(0) + ... + term(count - 1) by \a combine, in Lanes partial results: term(i) goes into lane i mod Lanes, and the
 * lanes are combined in order at the end, so the result has the same bits on any machine and for any vector width
 * the compiler picks. \a combine is a sum or a maximum; TValue{} is its identity for the values summed here. */
template<typename TValue, typename TTerm, typename TCombine>
inline __attribute__((always_inline)) TValue
CombineInLanes(long count, TTerm term, TCombine combine)
{
  TValue lanes[Lanes] = {};
  long   i = 0;
  for (; i + Lanes <= count; i += Lanes)
  {
    for (long j = 0; j < Lanes; ++j)
    {
      lanes[j] = combine(lanes[j], term(i + j));
    }
  }
  for (long j = 0; i < count; ++i, ++j)
  {
    lanes[j] = combine(lanes[j], term(i));
  }
  TValue result{};
  for (long j = 0; j < Lanes; ++j)
  {
    result = combine(result, lanes[j]);
  }
  return result;
}

inline double
Plus(double a, double b)
{
  return a + b;
}

inline float
Larger(float a, float b)
{
  return a > b ? a : b;
}

void
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

void
SmoothRowFromZero(float * __restrict x, const float * __restrict b, const float * __restrict c, long first, long width)
{
  for (long i = first; i < width; i += 2)
  {
    x[i] = DividedByDiagonal(b[i], c[i]);
  }
}

void
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

void
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

void
ResidualAfterSweepFromZeroRow5(float * __restrict r,
                               const float * __restrict x,
                               const float * __restrict above,
                               const float * __restrict below,
                               const float * __restrict e,
                               const float * __restrict n,
                               const float * __restrict nBelow,
                               long first,
                               long width)
{
  for (long i = 0; i < width; ++i)
  {
    const float couplings = e[i] * x[i + 1] + e[i - 1] * x[i - 1] + n[i] * above[i] + nBelow[i] * below[i];
    r[i] = (i & 1) == first ? couplings : 0.0f;
  }
}

void
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

void
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

void
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

void
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

std::uint64_t
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

/** One row of the finest level's operator and residual (see Field::Assemble), and with \a Hessian the energy's
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

void
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
void
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

void
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

void
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

/** (1 - R(from + step)) - (1 - R(from)) = R(from) - R(from + step): an edge's share of the energy change, times 2a,
 * with \a weight = R(from) as the field holds it (the same bits as computed here: one exponential less per edge).
 * Where the exponent's change u = -a step (2 from + step) is small, as R(from) (-expm1(u)), which keeps its digits
 * when the step is much smaller than the difference; elsewhere as the plain difference of the two weights. */
inline float
EdgeEnergyChange(float from, float weight, float step, float anisotropy, float scale)
{
  const float to = from + step;
  const float u = -anisotropy * step * (from + to);
  const float near = -weight * SmallExpMinusOne(std::clamp(u, -0.5f, 0.5f));
  const float far = weight - RangeWeight(to, scale);
  return std::abs(u) <= 0.5f ? near : far;
}

double
EnergyChangeRow(const double * __restrict d,
                const double * __restrict below,
                const float * __restrict right,
                const float * __restrict down,
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
    scratch[x] = EdgeEnergyChange(
      static_cast<float>(d[x + 1] - d[x]), right[x], step * (delta[x + 1] - delta[x]), anisotropy, scale);
  }
  scratch[width - 1] = 0.0f;
  if (below)
  {
    for (long x = 0; x < width; ++x)
    {
      scratch[x] += EdgeEnergyChange(
        static_cast<float>(below[x] - d[x]), down[x], step * (deltaBelow[x] - delta[x]), anisotropy, scale);
    }
  }
  return CombineInLanes<double>(
    width, [scratch](long i) { return static_cast<double>(scratch[i]); }, Plus);
}

void
ProlongStartRow(double * __restrict depth,
                const float * __restrict active,
                const float * __restrict own,
                const float * __restrict other,
                long  coarseWidth,
                float scale,
                long  width)
{
  // The fine pixel's centre lies a quarter of a coarse pixel from its own coarse pixel's, towards the neighbour on
  // that side (clamped at the border): bilinear weights 3/4 and 1/4 per axis. Written without branches, so that the
  // row becomes vector operations.
  const bool weighted = scale > 0.0f;
  for (long x = 0; x < width; ++x)
  {
    const long  i = x / 2;
    const long  in = std::clamp(x % 2 ? i + 1 : i - 1, 0L, coarseWidth - 1);
    const float centre = own[i];
    const float across = own[in];
    const float beside = other[i];
    const float diagonal = other[in];
    const float w0 = 3.0f / 16.0f * (weighted ? RangeWeight(across - centre, scale) : 1.0f);
    const float w1 = 3.0f / 16.0f * (weighted ? RangeWeight(beside - centre, scale) : 1.0f);
    const float w2 = 1.0f / 16.0f * (weighted ? RangeWeight(diagonal - centre, scale) : 1.0f);
    float       sum = 9.0f / 16.0f * centre;
    float       weights = 9.0f / 16.0f;
    sum += w0 * across;
    weights += w0;
    sum += w1 * beside;
    weights += w1;
    sum += w2 * diagonal;
    weights += w2;
    depth[x] = active[x] != 0.0f ? static_cast<double>(sum / weights) : depth[x];
  }
}

void
AddRow(double * __restrict depth, const float * __restrict delta, float step, double low, double high, long width)
{
  for (long x = 0; x < width; ++x)
  {
    const double moved = depth[x] + static_cast<double>(step * delta[x]);
    depth[x] = std::min(std::max(moved, low), high);
  }
}

double
RowDot(const float * __restrict a, const float * __restrict b, long count)
{
  return CombineInLanes<double>(
    count, [a, b](long i) { return static_cast<double>(a[i]) * b[i]; }, Plus);
}

float
RowMaximum(const float * __restrict r, const float * __restrict s, long count)
{
  return CombineInLanes<float>(
    count, [r, s](long i) { return std::abs(r[i]) * s[i]; }, Larger);
}

float
RowMaximumOverDiagonal(const float * __restrict r, const float * __restrict c, long count)
{
  return CombineInLanes<float>(
    count, [r, c](long i) { return DividedByDiagonal(std::abs(r[i]), c[i]); }, Larger);
}

/** The kernels above, for the including unit's RowKernels table (by name, not by position). */
constexpr RowKernels
AllRowKernels()
{
  RowKernels kernels{};
  kernels.SmoothRow5 = SmoothRow5;
  kernels.SmoothRowFromZero = SmoothRowFromZero;
  kernels.SmoothRow9 = SmoothRow9;
  kernels.ResidualRow5 = ResidualRow5;
  kernels.ResidualAfterSweepFromZeroRow5 = ResidualAfterSweepFromZeroRow5;
  kernels.ResidualRow9 = ResidualRow9;
  kernels.ApplyRow5 = ApplyRow5;
  kernels.RestrictRow = RestrictRow;
  kernels.ProlongRow = ProlongRow;
  kernels.WeightRow = WeightRow;
  kernels.AssembleOperatorRow = AssembleOperatorRow;
  kernels.AssembleOperatorAndHessianRow = AssembleOperatorAndHessianRow;
  kernels.UpdateRow = UpdateRow;
  kernels.DirectionRow = DirectionRow;
  kernels.EnergyChangeRow = EnergyChangeRow;
  kernels.ProlongStartRow = ProlongStartRow;
  kernels.AddRow = AddRow;
  kernels.RowDot = RowDot;
  kernels.RowMaximum = RowMaximum;
  kernels.RowMaximumOverDiagonal = RowMaximumOverDiagonal;
  kernels.BuildGalerkinRowFrom5 = BuildGalerkinRowFrom5;
  kernels.BuildGalerkinRowFrom9 = BuildGalerkinRowFrom9;
  return kernels;
}
} // namespace
} // namespace itk::detail::BilateralDepthRelaxSteady

#endif
