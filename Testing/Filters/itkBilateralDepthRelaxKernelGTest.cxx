// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// BilateralDepthRelaxKernel on its own: answers worked by hand on tiny rows, progress reporting, a progress
// callback that throws (the team must stop, not hang), in-place use, results independent of the team size and of
// the passes between synchronizations (temporal blocking), and every instruction set this processor runs against the
// plain reference.
#include "PlainBilateralDepthRelax.h"

#include "itkBilateralDepthRelaxKernel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
using Kernel = itk::BilateralDepthRelaxKernel;

std::vector<float>
Relax(const std::vector<float> &         depth,
      const std::vector<unsigned char> & fixed,
      std::size_t                        width,
      std::size_t                        height,
      double                             w,
      double                             a,
      unsigned int                       iterations,
      unsigned int                       threads = 1,
      unsigned int                       passesBetweenSynchronizations = Kernel::AutomaticPassesBetweenSynchronizations)
{
  std::vector<float> relaxed(depth.size(), -1.0f);
  Kernel::Relax(depth.data(),
                fixed.empty() ? nullptr : fixed.data(),
                relaxed.data(),
                width,
                height,
                w,
                a,
                iterations,
                threads,
                {},
                nullptr,
                passesBetweenSynchronizations);
  return relaxed;
}

bool
BitIdentical(const std::vector<float> & first, const std::vector<float> & second)
{
  return first.size() == second.size() && std::memcmp(first.data(), second.data(), first.size() * sizeof(float)) == 0;
}

/** A depth map like a CPR's: regions 25 mm apart in depth (jumps far above J), each a slope with noise of +-1 mm,
 * and about 1 pixel in 12 fixed (the vessels' centres). */
struct MapWithJumps
{
  std::vector<float>         Depth;
  std::vector<unsigned char> Fixed;
};

MapWithJumps
MakeMapWithJumps(std::size_t width, std::size_t height, unsigned int seed)
{
  std::mt19937                          generator(seed);
  std::uniform_real_distribution<float> noise(-1.0f, 1.0f);
  std::uniform_int_distribution<int>    fixedOneIn(0, 11);
  MapWithJumps                          map;
  map.Depth.resize(width * height);
  map.Fixed.resize(width * height);
  for (std::size_t y = 0; y < height; ++y)
  {
    for (std::size_t x = 0; x < width; ++x)
    {
      const int region = (x * 3 / width + y * 4 / height) % 3;
      map.Depth[y * width + x] = 40.0f + 25.0f * region + 0.05f * static_cast<float>(x + y) + noise(generator);
      map.Fixed[y * width + x] = fixedOneIn(generator) == 0 ? 1 : 0;
    }
  }
  return map;
}
} // namespace

// One row 0, 1, 0; end pixels have one neighbour, the middle two. a = 0, w = 1: every pixel takes the mean of
// its neighbours: 1, 0, 1. w = 1/2 gives each pixel as much weight as its neighbours together: 1/2 everywhere.
TEST(BilateralDepthRelaxKernel, OneIterationOnARowWorkedByHand)
{
  const std::vector<float> row = { 0.0f, 1.0f, 0.0f };
  EXPECT_EQ(Relax(row, {}, 3, 1, 1.0, 0.0, 1), (std::vector<float>{ 1.0f, 0.0f, 1.0f }));
  EXPECT_EQ(Relax(row, {}, 3, 1, 0.5, 0.0, 1), (std::vector<float>{ 0.5f, 0.5f, 0.5f }));
  // The same row as a column: the vertical edges carry the same weights.
  EXPECT_EQ(Relax(row, {}, 1, 3, 1.0, 0.0, 1), (std::vector<float>{ 1.0f, 0.0f, 1.0f }));
  // Fixing the middle pixel keeps it; its neighbours still move to it.
  EXPECT_EQ(Relax(row, { 0, 1, 0 }, 3, 1, 1.0, 0.0, 1), (std::vector<float>{ 1.0f, 1.0f, 1.0f }));
}

// Row 0, 0, 2 with a = ln 2 / 4: R(2) = exp(-ln 2) = 1/2, R(0) = 1. w = 1:
// middle: (1 * 0 + 1/2 * 2) / (1 + 1/2) = 2/3; right end: its one neighbour 0, so 0; left end: 0.
TEST(BilateralDepthRelaxKernel, RangeWeightWorkedByHand)
{
  const std::vector<float> relaxed = Relax({ 0.0f, 0.0f, 2.0f }, {}, 3, 1, 1.0, std::log(2.0) / 4.0, 1);
  EXPECT_EQ(relaxed[0], 0.0f);
  EXPECT_NEAR(relaxed[1], 2.0 / 3.0, 1e-6);
  EXPECT_EQ(relaxed[2], 0.0f);
}

// A 1 x 1 image has no neighbours: the denominator is 0 at w = 1 and the pixel keeps its value. So does a
// pixel whose every weight underflows (a x^2 = 0.5 * 100^2 far beyond -ln FLT_MIN).
TEST(BilateralDepthRelaxKernel, ZeroDenominatorKeepsTheValue)
{
  EXPECT_EQ(Relax({ 42.0f }, {}, 1, 1, 1.0, 0.5, 10), (std::vector<float>{ 42.0f }));
  EXPECT_EQ(Relax({ 0.0f, 100.0f, 0.0f }, {}, 3, 1, 1.0, 0.5, 1), (std::vector<float>{ 0.0f, 100.0f, 0.0f }));
}

TEST(BilateralDepthRelaxKernel, ReportsEveryIterationInOrder)
{
  std::vector<float>        depth(40 * 30, 1.0f);
  std::vector<unsigned int> reported;
  Kernel::Relax(
    depth.data(), nullptr, depth.data(), 40, 30, 1.0, 0.5, 25, 2, [&](unsigned int done) { reported.push_back(done); });
  ASSERT_EQ(reported.size(), 25u);
  for (unsigned int k = 0; k < 25; ++k)
  {
    EXPECT_EQ(reported[k], k + 1);
  }
}

// An observer that aborts (throws) must stop every thread of the team and reach the caller.
TEST(BilateralDepthRelaxKernel, ThrowingProgressStopsTheTeam)
{
  std::vector<float> depth(64 * 64, 0.0f);
  std::vector<float> relaxed(depth.size());
  for (const unsigned int threads : { 1u, 2u, 4u })
  {
    unsigned int calls = 0;
    EXPECT_THROW(Kernel::Relax(depth.data(),
                               nullptr,
                               relaxed.data(),
                               64,
                               64,
                               1.0,
                               0.5,
                               1000,
                               threads,
                               [&](unsigned int done)
                               {
                                 ++calls;
                                 if (done == 3)
                                 {
                                   throw std::runtime_error("aborted");
                                 }
                               }),
                 std::runtime_error)
      << threads << " threads";
    EXPECT_EQ(calls, 3u) << threads << " threads";
  }
}

TEST(BilateralDepthRelaxKernel, InPlaceEqualsOutOfPlaceAndTeamSizeChangesNoBit)
{
  const std::size_t                     width = 45;
  const std::size_t                     height = 23;
  std::mt19937                          generator(3);
  std::uniform_real_distribution<float> distribution(-8.0f, 8.0f);
  std::vector<float>                    depth(width * height);
  std::vector<unsigned char>            fixed(width * height, 0);
  for (std::size_t k = 0; k < depth.size(); ++k)
  {
    depth[k] = distribution(generator);
    fixed[k] = (k % 11 == 0) ? 1 : 0;
  }
  const std::vector<float> reference = Relax(depth, fixed, width, height, 0.9, 0.3, 77, 1);
  for (const unsigned int threads : { 2u, 3u, 7u, 23u, 100u })
  {
    EXPECT_EQ(Relax(depth, fixed, width, height, 0.9, 0.3, 77, threads), reference) << threads << " threads";
  }
  // A taller image: bands of many rows that start on even and odd rows, so that the rows relaxed two at a time
  // pair up differently for each team size.
  const std::size_t          tallHeight = 203;
  std::vector<float>         tall(width * tallHeight);
  std::vector<unsigned char> tallFixed(tall.size(), 0);
  for (std::size_t k = 0; k < tall.size(); ++k)
  {
    tall[k] = distribution(generator);
    tallFixed[k] = (k % 17 == 3) ? 1 : 0;
  }
  const std::vector<float> tallReference = Relax(tall, tallFixed, width, tallHeight, 1.0, 0.5, 77, 1);
  for (const unsigned int threads : { 2u, 3u, 7u })
  {
    EXPECT_EQ(Relax(tall, tallFixed, width, tallHeight, 1.0, 0.5, 77, threads), tallReference) << threads << " threads";
  }

  std::vector<float> inPlace = depth;
  Kernel::Relax(inPlace.data(), fixed.data(), inPlace.data(), width, height, 0.9, 0.3, 77, 2);
  EXPECT_EQ(inPlace, reference);
}

// A workspace kept across calls of other sizes, masks, team sizes and blocks of passes holds stale values where a
// call does not write (rows of its rings, edges of passes a shorter block does not run): none may reach a result.
TEST(BilateralDepthRelaxKernel, ReusedWorkspaceChangesNoBit)
{
  struct Call
  {
    std::size_t  Width, Height;
    unsigned int Threads;
    bool         Masked;
    unsigned int Passes;
  };
  const Call        calls[] = { { 70, 40, 2, true, 1 }, { 33, 17, 3, false, 9 }, { 70, 40, 2, false, 4 },
                                { 129, 9, 1, true, 2 }, { 5, 61, 4, true, 12 },  { 70, 40, 2, true, 3 },
                                { 70, 40, 2, true, 1 } };
  Kernel::Workspace workspace;
  unsigned int      seed = 40;
  for (const auto & call : calls)
  {
    std::mt19937                          generator(++seed);
    std::uniform_real_distribution<float> distribution(-3.0f, 3.0f);
    std::vector<float>                    depth(call.Width * call.Height);
    std::vector<unsigned char>            fixed(call.Masked ? depth.size() : 0, 0);
    for (std::size_t k = 0; k < depth.size(); ++k)
    {
      depth[k] = distribution(generator);
      if (call.Masked)
      {
        fixed[k] = (k % 7 == 2) ? 1 : 0;
      }
    }
    const std::vector<float> fresh = Relax(depth, fixed, call.Width, call.Height, 1.0, 0.5, 40, call.Threads, 1);
    std::vector<float>       reused(depth.size());
    Kernel::Relax(depth.data(),
                  call.Masked ? fixed.data() : nullptr,
                  reused.data(),
                  call.Width,
                  call.Height,
                  1.0,
                  0.5,
                  40,
                  call.Threads,
                  {},
                  &workspace,
                  call.Passes);
    EXPECT_TRUE(BitIdentical(reused, fresh)) << call.Width << " x " << call.Height << ", " << call.Passes << " passes";
  }
}

// w = 0 and N = 0 change nothing (not even by rounding).
TEST(BilateralDepthRelaxKernel, NoRelaxationOrNoIterationsCopies)
{
  const std::vector<float> depth = { 1.5f, -2.25f, 1e7f, 3.0f, 0.1f, 7.0f };
  EXPECT_EQ(Relax(depth, {}, 3, 2, 0.0, 0.5, 100), depth);
  EXPECT_EQ(Relax(depth, {}, 3, 2, 1.0, 0.5, 0), depth);
}

TEST(BilateralDepthRelaxKernel, NamesItsInstructionSets)
{
  const std::vector<std::string> supported = Kernel::GetSupportedInstructionSets();
  ASSERT_FALSE(supported.empty());
  EXPECT_EQ(Kernel::GetInstructionSet(), supported.front());
  EXPECT_THROW(Kernel::SetInstructionSet("SSE1"), std::invalid_argument);
  EXPECT_EQ(Kernel::GetInstructionSet(), supported.front());
}

// Each instruction set the processor runs (AVX-512, AVX2+FMA, baseline x86-64 on a recent x86 machine) must
// agree with the plain reference, and give the same bits for any number of threads.
TEST(BilateralDepthRelaxKernel, EveryInstructionSetAgreesWithPlainReference)
{
  struct Case
  {
    std::size_t  Width, Height;
    double       W, A;
    unsigned int Iterations;
  };
  const Case cases[] = { { 1, 1, 1.0, 0.5, 10 },    { 5, 1, 1.0, 0.5, 40 },    { 1, 9, 0.6, 2.0, 40 },
                         { 17, 13, 1.0, 0.5, 150 }, { 40, 33, 0.8, 0.0, 150 }, { 77, 45, 1.0, 1.0, 200 } };
  for (const std::string & instructionSet : Kernel::GetSupportedInstructionSets())
  {
    Kernel::SetInstructionSet(instructionSet);
    unsigned int seed = 11;
    for (const auto & c : cases)
    {
      SCOPED_TRACE(instructionSet + ", " + std::to_string(c.Width) + " x " + std::to_string(c.Height) +
                   ", w = " + std::to_string(c.W) + ", a = " + std::to_string(c.A));
      std::mt19937                          generator(++seed);
      std::uniform_real_distribution<float> distribution(0.0f, 4.0f);
      std::vector<float>                    depth(c.Width * c.Height);
      std::vector<unsigned char>            fixed(depth.size(), 0);
      for (std::size_t k = 0; k < depth.size(); ++k)
      {
        depth[k] = distribution(generator);
        fixed[k] = (k % 13 == 5) ? 1 : 0;
      }
      const std::vector<double> reference =
        vr::test::PlainBilateralDepthRelax(depth, fixed, c.Width, c.Height, c.W, c.A, c.Iterations);
      const std::vector<float> one = Relax(depth, fixed, c.Width, c.Height, c.W, c.A, c.Iterations, 1);
      for (std::size_t k = 0; k < reference.size(); ++k)
      {
        ASSERT_NEAR(one[k], reference[k], 1e-4) << "pixel " << k;
      }
      EXPECT_EQ(Relax(depth, fixed, c.Width, c.Height, c.W, c.A, c.Iterations, 3), one);
    }
  }
  Kernel::SetInstructionSet("");
}

// Temporal blocking: each thread runs several passes on its band, computing again the rows its neighbours own,
// before the team meets. Every pixel must come out bit for bit as with one thread meeting after every pass: for
// teams of 1, 2, 3, 8 and 16 threads (more threads than cores is fine), blocks of 1, 2, 3, 5 and 8 passes and of
// more passes than a band has rows (40, and more than the iterations), odd heights, a single row, bands of one
// row, and an iteration count that leaves a shorter last block. Fixed pixels keep their input bits.
TEST(BilateralDepthRelaxKernel, PassesBetweenSynchronizationsChangeNoBit)
{
  struct Size
  {
    std::size_t Width, Height;
  };
  const Size         sizes[] = { { 45, 203 }, { 33, 17 }, { 130, 9 }, { 64, 1 }, { 7, 31 } };
  const unsigned int iterations = 37;
  unsigned int       seed = 70;
  for (const auto & size : sizes)
  {
    const MapWithJumps map = MakeMapWithJumps(size.Width, size.Height, ++seed);
    for (const double a : { 0.5, 0.0 })
    {
      const std::vector<float> reference =
        Relax(map.Depth, map.Fixed, size.Width, size.Height, 1.0, a, iterations, 1, 1);
      for (std::size_t k = 0; k < reference.size(); ++k)
      {
        if (map.Fixed[k])
        {
          ASSERT_EQ(std::memcmp(&reference[k], &map.Depth[k], sizeof(float)), 0) << "fixed pixel " << k << " moved";
        }
      }
      for (const unsigned int threads : { 1u, 2u, 3u, 8u, 16u })
      {
        for (const unsigned int passes : { 1u, 2u, 3u, 5u, 8u, 40u, 100u })
        {
          EXPECT_TRUE(BitIdentical(
            Relax(map.Depth, map.Fixed, size.Width, size.Height, 1.0, a, iterations, threads, passes), reference))
            << size.Width << " x " << size.Height << ", a = " << a << ", " << threads << " threads, " << passes
            << " passes between synchronizations";
        }
        EXPECT_TRUE(
          BitIdentical(Relax(map.Depth, map.Fixed, size.Width, size.Height, 1.0, a, iterations, threads), reference))
          << size.Width << " x " << size.Height << ", a = " << a << ", " << threads << " threads, the kernel's choice";
      }
    }
  }
}

// The same with every instruction set the processor runs (the row kernels are compiled once for each), on a map
// tall enough for the kernel's own choice of passes to exceed 1 with 8 threads (2 with 301 rows), and w < 1.
TEST(BilateralDepthRelaxKernel, PassesBetweenSynchronizationsChangeNoBitWithEveryInstructionSet)
{
  const std::size_t  width = 77;
  const std::size_t  height = 301;
  const MapWithJumps map = MakeMapWithJumps(width, height, 5);
  for (const std::string & instructionSet : Kernel::GetSupportedInstructionSets())
  {
    Kernel::SetInstructionSet(instructionSet);
    const std::vector<float> reference = Relax(map.Depth, map.Fixed, width, height, 0.8, 0.5, 50, 1, 1);
    for (const unsigned int threads : { 2u, 3u, 8u, 16u })
    {
      for (const unsigned int passes : { 0u, 4u, 19u })
      {
        EXPECT_TRUE(BitIdentical(Relax(map.Depth, map.Fixed, width, height, 0.8, 0.5, 50, threads, passes), reference))
          << instructionSet << ", " << threads << " threads, " << passes << " passes between synchronizations";
      }
    }
  }
  Kernel::SetInstructionSet("");
}

// The kernel's choice (docs/design.md "Relaxation"): teams of up to 4 threads meet after every pass whatever the height
// (measured on 2 cores: the blocks' row-by-row wavefront costs more there than the barriers it saves); larger teams
// take band height / 16 passes, at least 1 and at most 16. References worked by hand from the rule.
TEST(BilateralDepthRelaxKernel, KernelChoosesOnePassForSmallTeamsAndBlocksForLargeOnes)
{
  for (const unsigned int team : { 1u, 2u, 3u, 4u })
  {
    for (const std::size_t height : { std::size_t{ 1 }, std::size_t{ 1024 }, std::size_t{ 100000 } })
    {
      EXPECT_EQ(Kernel::ChoosePassesBetweenSynchronizations(height, team), 1u) << team << " threads, " << height;
    }
  }
  EXPECT_EQ(Kernel::ChoosePassesBetweenSynchronizations(1024, 5), 12u);    // band 204 rows
  EXPECT_EQ(Kernel::ChoosePassesBetweenSynchronizations(1024, 8), 8u);     // band 128 rows
  EXPECT_EQ(Kernel::ChoosePassesBetweenSynchronizations(1024, 16), 4u);    // band 64 rows
  EXPECT_EQ(Kernel::ChoosePassesBetweenSynchronizations(1024, 64), 1u);    // band 16 rows
  EXPECT_EQ(Kernel::ChoosePassesBetweenSynchronizations(100, 8), 1u);      // band 12 rows: below 1, so 1
  EXPECT_EQ(Kernel::ChoosePassesBetweenSynchronizations(100000, 16), 16u); // band 6250 rows: at most 16
}

// Progress is reported after every pass, in order, whatever the block; an observer that throws inside a block
// stops the whole team (no thread left waiting) and is not called again.
TEST(BilateralDepthRelaxKernel, BlocksOfPassesReportEveryPassAndStopWhenAborted)
{
  std::vector<float> depth(40 * 90, 1.0f);
  for (const unsigned int passes : { 2u, 4u, 7u, 30u })
  {
    std::vector<unsigned int> reported;
    Kernel::Relax(
      depth.data(),
      nullptr,
      depth.data(),
      40,
      90,
      1.0,
      0.5,
      25,
      3,
      [&](unsigned int done) { reported.push_back(done); },
      nullptr,
      passes);
    ASSERT_EQ(reported.size(), 25u) << passes << " passes between synchronizations";
    for (unsigned int k = 0; k < 25; ++k)
    {
      EXPECT_EQ(reported[k], k + 1) << passes << " passes between synchronizations";
    }
  }
  std::vector<float> relaxed(depth.size());
  for (const unsigned int threads : { 1u, 2u, 4u })
  {
    for (const unsigned int passes : { 4u, 16u })
    {
      unsigned int calls = 0;
      EXPECT_THROW(Kernel::Relax(
                     depth.data(),
                     nullptr,
                     relaxed.data(),
                     40,
                     90,
                     1.0,
                     0.5,
                     1000,
                     threads,
                     [&](unsigned int done)
                     {
                       ++calls;
                       if (done == 6)
                       {
                         throw std::runtime_error("aborted");
                       }
                     },
                     nullptr,
                     passes),
                   std::runtime_error)
        << threads << " threads, " << passes << " passes";
      EXPECT_EQ(calls, 6u) << threads << " threads, " << passes << " passes";
    }
  }
}
