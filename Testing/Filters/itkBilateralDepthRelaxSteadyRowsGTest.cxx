// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The steady solver's grid, bands and row kernels alone: the range weight against std::exp and its underflow rule,
// a row's weights and their signature, the operator and residual rows against the stencil written out (with the
// kernels of every instruction set the processor runs), and the bands' sums, which must not depend on the team's
// size.
#include "itkBilateralDepthRelaxRangeWeight.h"
#include "itkBilateralDepthRelaxSteadyGrid.h"
#include "itkBilateralDepthRelaxSteadyRows.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cfloat>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

namespace
{
namespace Steady = itk::detail::BilateralDepthRelaxSteady;

constexpr double Anisotropy = 1.0 / 9.0;

/** The row kernels of every instruction set this processor runs, widest first, with a name for messages. */
std::vector<std::pair<const char *, const Steady::RowKernels *>>
EveryRunnableRowKernels()
{
  std::vector<std::pair<const char *, const Steady::RowKernels *>> kernels;
  for (const auto set : itk::detail::RunnableInstructionSets())
  {
    const char * name = set == itk::detail::InstructionSet::AVX512 ? "AVX-512"
                        : set == itk::detail::InstructionSet::AVX2 ? "AVX2"
                                                                   : "baseline";
    kernels.emplace_back(name, &Steady::RowsFor(set));
  }
  return kernels;
}

float
ScaleOf(double anisotropy)
{
  return static_cast<float>(std::sqrt(anisotropy / std::log(2.0)));
}
} // namespace

// R(x) = exp(-a x^2) where a x^2 <= -ln(FLT_MIN) (about 87.34), exactly 0 beyond (the filter's underflow rule).
// The polynomial's error is 3e-7 relative; forming u = -(scale x)^2 in float (scale, the product and the square
// each rounded) moves u by up to about 3e-7 |u|, so R by 3e-7 |u| ln 2 relative.
TEST(BilateralDepthRelaxSteadyRows, RangeWeightIsTheGaussianAndVanishesBeyondTheUnderflow)
{
  const float  scale = ScaleOf(Anisotropy);
  const double limit = std::sqrt(-std::log(static_cast<double>(FLT_MIN)) / Anisotropy);
  for (double x = -40.0; x <= 40.0; x += 0.01)
  {
    const float  weight = itk::detail::RangeWeight(static_cast<float>(x), scale);
    const double exact = std::exp(-Anisotropy * static_cast<float>(x) * static_cast<float>(x));
    if (std::abs(x) < limit - 0.01)
    {
      const double u = Anisotropy * x * x / std::log(2.0);
      EXPECT_NEAR(weight, exact, (3e-7 + 3e-7 * u * std::log(2.0)) * exact) << "x = " << x;
    }
    else if (std::abs(x) > limit + 0.01)
    {
      EXPECT_EQ(weight, 0.0f) << "x = " << x;
    }
  }
  EXPECT_FLOAT_EQ(itk::detail::RangeWeight(0.0f, scale), 1.0f); // 1.000000072 rounded, one ulp above 1
}

// Weights to the right and to the row below; the last column has no right edge; a missing row below gives none; an
// isotropic row weighs every edge 1. The signature counts the vanishing edges and sums their columns (2x + 1 right,
// 2x + 2 down).
TEST(BilateralDepthRelaxSteadyRows, WeightRowAndItsSignature)
{
  for (const auto & [name, kernels] : EveryRunnableRowKernels())
  {
    const Steady::RowKernels & rows = *kernels;
    const long                 width = 5;
    std::vector<double>        d{ 0.0, 0.0, 50.0, 50.0, 50.0 };
    std::vector<double>        below{ 0.0, 1.0, 50.0, 0.0, 50.0 };
    std::vector<float>         right(width, -1.0f), down(width, -1.0f);
    const float                scale = ScaleOf(Anisotropy);
    const auto signature = rows.WeightRow(right.data(), down.data(), d.data(), below.data(), scale, false, width);
    EXPECT_FLOAT_EQ(right[0], 1.0f);
    EXPECT_EQ(right[1], 0.0f) << name << ": a 50 mm jump";
    EXPECT_FLOAT_EQ(right[2], 1.0f);
    EXPECT_EQ(right[4], 0.0f) << name << ": no edge beyond the last column";
    EXPECT_NEAR(down[1], std::exp(-Anisotropy), 3e-7);
    EXPECT_EQ(down[3], 0.0f);
    // Vanishing: right edge at x = 1 (column sum 3), down at x = 3 (8).
    EXPECT_EQ(signature, (std::uint64_t{ 2 } << 32) + 3 + 8);
    rows.WeightRow(right.data(), down.data(), d.data(), nullptr, scale, true, width);
    EXPECT_EQ(right, (std::vector<float>{ 1.0f, 1.0f, 1.0f, 1.0f, 0.0f }));
    EXPECT_EQ(down, std::vector<float>(width, 0.0f));
  }
}

// A v and b - A v on a 5-point row, against the stencil (A v)_p = C_p v_p - sum_q w_pq v_q written out.
TEST(BilateralDepthRelaxSteadyRows, OperatorAndResidualRowsFollowTheStencil)
{
  const long                            width = 7;
  const long                            stride = Steady::PaddedStride(width);
  std::mt19937                          generator(3);
  std::uniform_real_distribution<float> value(-1.0f, 1.0f);
  std::vector<float> v(3 * stride, 0.0f), c(3 * stride), e(3 * stride, 0.0f), n(3 * stride), b(3 * stride);
  for (long k = 0; k < 3 * stride; ++k)
  {
    v[k] = value(generator);
    c[k] = 4.0f + value(generator);
    e[k] = value(generator);
    n[k] = value(generator);
    b[k] = value(generator);
  }
  const long p = stride + 1; // (0, 1): the middle row, one ghost column on the left
  e[p - 1] = 0.0f;           // no coupling to the ghost column
  e[p + width - 1] = 0.0f;   // nor beyond the last column
  for (const auto & [name, kernels] : EveryRunnableRowKernels())
  {
    const Steady::RowKernels & rows = *kernels;
    std::vector<float>         product(width), residual(width);
    rows.ApplyRow5(product.data(), &v[p], &v[p + stride], &v[p - stride], &c[p], &e[p], &n[p], &n[p - stride], width);
    rows.ResidualRow5(
      residual.data(), &v[p], &v[p + stride], &v[p - stride], &b[p], &c[p], &e[p], &n[p], &n[p - stride], width);
    for (long x = 0; x < width; ++x)
    {
      const long   q = p + x;
      const double expected = static_cast<double>(c[q]) * v[q] - static_cast<double>(e[q]) * v[q + 1] -
                              static_cast<double>(e[q - 1]) * v[q - 1] - static_cast<double>(n[q]) * v[q + stride] -
                              static_cast<double>(n[q - stride]) * v[q - stride];
      EXPECT_NEAR(product[x], expected, 1e-5) << name << ", x = " << x;
      EXPECT_NEAR(residual[x], b[q] - expected, 1e-5) << name << ", x = " << x;
    }
  }
}

// Right after a red-black sweep from x = 0 the residual is 0 at the second colour and the couplings to the second
// colour at the first: the kernel that forms it so, against b - A x written out, on a row whose first colour was set
// to b / C and whose second colour solved its own equation (both in double), for either colour first.
TEST(BilateralDepthRelaxSteadyRows, ResidualAfterASweepFromZeroIsBMinusAX)
{
  const long                            width = 9;
  const long                            stride = Steady::PaddedStride(width);
  std::mt19937                          generator(5);
  std::uniform_real_distribution<float> value(-1.0f, 1.0f);
  std::uniform_real_distribution<float> weight(0.0f, 1.0f);
  for (const long first : { 0L, 1L })
  {
    std::vector<float> x(3 * stride, 0.0f), c(3 * stride, 0.0f), e(3 * stride, 0.0f), n(3 * stride, 0.0f),
      b(3 * stride, 0.0f);
    const long p = stride + 1; // (0, 1): the middle row
    for (long k = 0; k < 3 * stride; ++k)
    {
      x[k] = value(generator); // the rows above and below: any values
      e[k] = weight(generator);
      n[k] = weight(generator);
    }
    e[p - 1] = 0.0f;
    e[p + width - 1] = 0.0f;
    for (long i = 0; i < width; ++i)
    {
      b[p + i] = value(generator);
      c[p + i] = e[p + i] + e[p + i - 1] + n[p + i] + n[p + i - stride] + weight(generator);
    }
    auto couplings = [&](long q)
    {
      return static_cast<double>(e[q]) * x[q + 1] + static_cast<double>(e[q - 1]) * x[q - 1] +
             static_cast<double>(n[q]) * x[q + stride] + static_cast<double>(n[q - stride]) * x[q - stride];
    };
    for (long i = first; i < width; i += 2)
    {
      x[p + i] = static_cast<float>(static_cast<double>(b[p + i]) / c[p + i]);
    }
    for (long i = 1 - first; i < width; i += 2)
    {
      x[p + i] = static_cast<float>((b[p + i] + couplings(p + i)) / c[p + i]);
    }
    for (const auto & [name, kernels] : EveryRunnableRowKernels())
    {
      std::vector<float> residual(width, -7.0f);
      kernels->ResidualAfterSweepFromZeroRow5(
        residual.data(), &x[p], &x[p + stride], &x[p - stride], &e[p], &n[p], &n[p - stride], first, width);
      for (long i = 0; i < width; ++i)
      {
        const long   q = p + i;
        const double expected = b[q] - static_cast<double>(c[q]) * x[q] + couplings(q);
        EXPECT_NEAR(residual[i], expected, 1e-5) << name << ", first colour at " << first << ", x = " << i;
        if ((i & 1) != first)
        {
          EXPECT_EQ(residual[i], 0.0f) << name << ": the second colour's residual is 0 by construction";
        }
      }
    }
  }
}

// ForRows hands each row to exactly one band; SumRows gives the same bits whatever the team's size (rows summed
// alone, then added in row order), and its RowDot sums a row in a fixed order of lanes.
TEST(BilateralDepthRelaxSteadyRows, BandsCoverEveryRowOnceAndSumTheSameForAnyTeam)
{
  const long                            height = 203;
  const long                            width = 37;
  const long                            stride = Steady::PaddedStride(width);
  std::mt19937                          generator(11);
  std::uniform_real_distribution<float> value(-1.0f, 1.0f);
  std::vector<float>                    a(stride * height), b(stride * height);
  for (auto & x : a)
    x = value(generator);
  for (auto & x : b)
    x = value(generator);
  double reference = 0.0;
  for (const unsigned int threads : { 1u, 2u, 3u, 7u, 16u })
  {
    Steady::BandBuffers           buffers;
    Steady::Bands                 bands(buffers, threads, height, stride);
    std::vector<std::atomic<int>> visits(height);
    bands.ForRows(height,
                  true,
                  [&](long y0, long y1)
                  {
                    for (long y = y0; y < y1; ++y)
                      ++visits[static_cast<std::size_t>(y)];
                  });
    for (long y = 0; y < height; ++y)
      ASSERT_EQ(visits[static_cast<std::size_t>(y)].load(), 1) << threads << " threads, row " << y;
    const double sum =
      bands.SumRows([&](long y, float *) { return Steady::Rows().RowDot(&a[y * stride], &b[y * stride], width); });
    if (threads == 1)
    {
      reference = sum;
      double plain = 0.0;
      for (long y = 0; y < height; ++y)
        for (long x = 0; x < width; ++x)
          plain += static_cast<double>(a[y * stride + x]) * b[y * stride + x];
      EXPECT_NEAR(sum, plain, 1e-9);
    }
    EXPECT_EQ(sum, reference) << threads << " threads";
  }
}

// The solver's kernels are those of the widest instruction set the processor runs (the same choice as the Jacobi
// sweep's), and each runnable set has a table of its own, every entry filled.
TEST(BilateralDepthRelaxSteadyRows, TheSolverRunsTheWidestInstructionSet)
{
  const auto kernels = EveryRunnableRowKernels();
  ASSERT_FALSE(kernels.empty());
  EXPECT_EQ(&Steady::Rows(), kernels.front().second);
  EXPECT_EQ(itk::detail::RunnableInstructionSets().back(), itk::detail::InstructionSet::Baseline);
  for (std::size_t k = 0; k < kernels.size(); ++k)
  {
    for (std::size_t j = 0; j < k; ++j)
    {
      EXPECT_NE(kernels[j].second, kernels[k].second) << kernels[j].first << " and " << kernels[k].first;
    }
    const Steady::RowKernels & rows = *kernels[k].second;
    for (const void * entry : { reinterpret_cast<const void *>(rows.SmoothRow5),
                                reinterpret_cast<const void *>(rows.SmoothRow9),
                                reinterpret_cast<const void *>(rows.RestrictRow),
                                reinterpret_cast<const void *>(rows.ProlongRow),
                                reinterpret_cast<const void *>(rows.EnergyChangeRow),
                                reinterpret_cast<const void *>(rows.RowMaximumOverDiagonal),
                                reinterpret_cast<const void *>(rows.BuildGalerkinRowFrom9) })
    {
      EXPECT_NE(entry, nullptr) << kernels[k].first;
    }
  }
}
