// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The steady solver's last few pixels (issue 40) alone, on maps worked by hand: a ramp between two fixed columns is
// the fixed point, so a few pixels pushed off it are settled back onto it, below the tolerance by the plain reference
// residual, and the field is then exactly the one a whole assembly at the settled depths gives; more pixels above the
// tolerance than the limit, or a window whose settling would change which weights vanish, leave the depths and the
// field as they were, bit for bit.
#include "PlainBilateralDepthRelax.h"

#include "itkBilateralDepthRelaxRangeWeight.h"
#include "itkBilateralDepthRelaxSteadyField.h"
#include "itkBilateralDepthRelaxSteadyMultigrid.h"
#include "itkBilateralDepthRelaxSteadyStragglers.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <utility>
#include <vector>

namespace
{
namespace Steady = itk::detail::BilateralDepthRelaxSteady;

/** The jump threshold J = 3 mm of the filter's default, as the anisotropy a = 1/J^2. */
constexpr double Anisotropy = 1.0 / 9.0;
constexpr double Tolerance = 1e-4;

/** A field loaded from a row-major map, its weights, regions and operator as an outer iteration leaves them. */
struct Problem
{
  long                       Width;
  long                       Height;
  std::vector<unsigned char> Fixed;
  Steady::BandBuffers        BandBuffers;
  Steady::MultigridBuffers   MultigridBuffers;
  Steady::FieldBuffers       FieldBuffers;
  Steady::StragglerBuffers   StragglerBuffers;
  Steady::Bands              Bands;
  Steady::Multigrid          Multigrid;
  Steady::Field              Field;

  Problem(long width, long height, const std::vector<float> & depth, std::vector<unsigned char> fixed)
    : Width(width)
    , Height(height)
    , Fixed(std::move(fixed))
    , Bands(BandBuffers, 1, height, Steady::PaddedStride(width))
    , Multigrid(MultigridBuffers, Bands, width, height)
    , Field(FieldBuffers, Bands, Multigrid.Finest(), width, height, Anisotropy)
  {
    Field.Load(depth.data(), Fixed.data());
    Field.ComputeWeights();
    bool changed = false;
    Field.ClassifyRegions(changed);
    Field.ComputeWeights();
    StragglerBuffers.Reserve(width, height);
  }

  double
  Settle(double residual)
  {
    return Steady::SettleStragglers(Field, StragglerBuffers, residual, Tolerance, false);
  }

  /** The depths, row-major. */
  std::vector<double>
  Depths() const
  {
    std::vector<double> depths;
    for (long y = 0; y < Height; ++y)
    {
      for (long x = 0; x < Width; ++x)
      {
        depths.push_back(Field.Depth[Field.At(x, y)]);
      }
    }
    return depths;
  }

  /** Every array an assembly writes, and the rows' maxima, as bytes. */
  std::vector<unsigned char>
  Assembled()
  {
    std::vector<unsigned char> bytes;
    const std::size_t          size = Steady::PaddedSize(Width, Height) * sizeof(float);
    for (const float * array :
         { Field.WeightRight, Field.WeightDown, Field.Finest.C, Field.Finest.E, Field.Finest.N, Field.Residual })
    {
      const auto * begin = reinterpret_cast<const unsigned char *>(array);
      bytes.insert(bytes.end(), begin, begin + size);
    }
    const auto & maxima = Field.RowMaxima();
    const auto * begin = reinterpret_cast<const unsigned char *>(maxima.data());
    bytes.insert(bytes.end(), begin, begin + maxima.size() * sizeof(double));
    return bytes;
  }
};

/** A W x H ramp D = Slope x mm between fixed columns x = 0 and x = W - 1: every free pixel is the mean of its
 * neighbours with equal weights, the fixed point. */
constexpr long   RampWidth = 48;
constexpr long   RampHeight = 32;
constexpr double Slope = 0.05;

std::vector<unsigned char>
RampFixed()
{
  std::vector<unsigned char> fixed(RampWidth * RampHeight, 0);
  for (long y = 0; y < RampHeight; ++y)
  {
    fixed[y * RampWidth] = fixed[y * RampWidth + RampWidth - 1] = 1;
  }
  return fixed;
}

std::vector<float>
Ramp()
{
  std::vector<float> depth(RampWidth * RampHeight);
  for (long y = 0; y < RampHeight; ++y)
  {
    for (long x = 0; x < RampWidth; ++x)
    {
      depth[y * RampWidth + x] = static_cast<float>(Slope * x);
    }
  }
  return depth;
}

/** The ramp with \a pixels (x, y) raised by \a by mm. */
std::vector<float>
RampRaisedAt(const std::vector<std::pair<long, long>> & pixels, float by)
{
  std::vector<float> depth = Ramp();
  for (const auto & [x, y] : pixels)
  {
    depth[y * RampWidth + x] += by;
  }
  return depth;
}
} // namespace

TEST(BilateralDepthRelaxSteadyStragglers, AFewPixelsOffTheFixedPointAreSettledOntoItAndTheFieldIsAssembledAnew)
{
  // Five pixels 0.3 mm off the ramp: each and its four neighbours (0.3 / 4 mm) are above the tolerance, 25 pixels.
  const std::vector<std::pair<long, long>> raised{ { 10, 8 }, { 30, 20 }, { 20, 5 }, { 40, 28 }, { 12, 25 } };
  Problem                                  problem(RampWidth, RampHeight, RampRaisedAt(raised, 0.3f), RampFixed());
  const double                             before = problem.Field.Assemble(false);
  ASSERT_GT(before, 0.05) << "the raised pixels are far above the tolerance";

  const double after = problem.Settle(before);

  EXPECT_LE(after, Tolerance);
  // Independently: the plain reference's fixed-point residual of the settled depths, and their distance to the ramp
  // (the windows' solution, their edges being on it).
  const std::vector<double> settled = problem.Depths();
  EXPECT_LE(vr::test::PlainFixedPointResidual(settled, problem.Fixed, RampWidth, RampHeight, Anisotropy),
            1.01 * Tolerance);
  double farthest = 0.0;
  for (long y = 0; y < RampHeight; ++y)
  {
    for (long x = 0; x < RampWidth; ++x)
    {
      farthest = std::max(farthest, std::abs(settled[y * RampWidth + x] - static_cast<float>(Slope * x)));
    }
  }
  EXPECT_LT(farthest, 1e-3) << "mm from the ramp";
  EXPECT_GT(farthest, 0.0) << "the settled depths are the sweeps' iterate, not the ramp copied back";

  // The field is the one a whole assembly at the settled depths gives, bit for bit, and so is the residual.
  const std::vector<unsigned char> field = problem.Assembled();
  problem.Field.ComputeWeights();
  const double assembled = problem.Field.Assemble(false);
  EXPECT_EQ(after, assembled);
  EXPECT_TRUE(field == problem.Assembled()) << "weights, operator, residual or row maxima differ from an assembly";
}

TEST(BilateralDepthRelaxSteadyStragglers, MorePixelsAboveTheToleranceThanTheLimitLeaveTheFieldAsItWas)
{
  // Twenty raised pixels, each with its four neighbours above the tolerance: 100 pixels, over the 64 of this grid.
  ASSERT_EQ(Steady::StragglerBuffers::MostStragglers(RampWidth, RampHeight), 64u);
  std::vector<std::pair<long, long>> raised;
  for (long k = 0; k < 20; ++k)
  {
    raised.emplace_back(4 + (k % 5) * 9, 4 + (k / 5) * 7);
  }
  Problem                          problem(RampWidth, RampHeight, RampRaisedAt(raised, 0.3f), RampFixed());
  const double                     before = problem.Field.Assemble(false);
  const std::vector<double>        depths = problem.Depths();
  const std::vector<unsigned char> field = problem.Assembled();

  EXPECT_EQ(problem.Settle(before), before);
  EXPECT_TRUE(depths == problem.Depths());
  EXPECT_TRUE(field == problem.Assembled());
}

TEST(BilateralDepthRelaxSteadyStragglers, SettlingThatWouldChangeWhichWeightsVanishIsUndone)
{
  // 17 x 9 pixels at 75 mm between fixed columns at 75 mm; pixel S = (8, 4) at 71.5 mm, far above the tolerance;
  // above it a fixed pixel F = (8, 5) at 100 mm, 28.5 mm from S: a x^2 = 90.25 > -ln(FLT_MIN) = 87.3, a weight that
  // vanishes. Settled near 75 mm, S would be 25 mm from F, a weight that does not (the floating regions would need
  // classifying again): the round is undone.
  constexpr long             width = 17;
  constexpr long             height = 9;
  std::vector<float>         depth(width * height, 75.0f);
  std::vector<unsigned char> fixed(width * height, 0);
  for (long y = 0; y < height; ++y)
  {
    fixed[y * width] = fixed[y * width + width - 1] = 1;
  }
  depth[4 * width + 8] = 71.5f;
  depth[5 * width + 8] = 100.0f;
  fixed[5 * width + 8] = 1;
  Problem problem(width, height, depth, fixed);
  ASSERT_EQ(problem.Field.WeightDown[problem.Field.At(8, 4)], 0.0f) << "S to F vanishes at the start";
  ASSERT_GT(itk::detail::RangeWeight(25.0f, problem.Field.Scale), 0.0f) << "S to F would not once settled";
  const double before = problem.Field.Assemble(false);
  ASSERT_GT(before, 1.0);
  const std::vector<double>        depths = problem.Depths();
  const std::vector<unsigned char> field = problem.Assembled();

  EXPECT_EQ(problem.Settle(before), before);
  EXPECT_TRUE(depths == problem.Depths());
  EXPECT_TRUE(field == problem.Assembled());
}
