// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The fast CPU relax (BilateralDepthRelaxKernel behind BilateralDepthRelaxFilter<float>) against the plain
// reference, an independent double evaluation of Eq. 1: on the phantom's depth map at the paper's size and on
// random depth maps with masks at odd sizes; and bit-identical results for any number of threads.
#include "PlainBilateralDepthRelax.h"
#include "vrTestImages.h"

#include "itkBilateralDepthRelaxFilter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <sstream>
#include <string>

namespace
{
using vr::test::DepthImage;
using vr::test::MaskImage;
using RelaxFilter = itk::BilateralDepthRelaxFilter<DepthImage>;

constexpr double Tolerance = 1e-4; // mm, docs/design.md "Relaxation"

using DepthMap = vr::test::PhantomDepthMap;

DepthImage::Pointer
RelaxWithFilter(const DepthMap & map,
                double           w,
                double           a,
                unsigned int     iterations,
                unsigned int     threads,
                unsigned int     passesBetweenSynchronizations = 0)
{
  auto filter = RelaxFilter::New();
  filter->SetPassesBetweenSynchronizations(passesBetweenSynchronizations);
  filter->SetDepthInput(map.Depth);
  if (map.Fixed)
  {
    filter->SetFixedMask(map.Fixed);
  }
  filter->SetRelaxation(w);
  filter->SetAnisotropy(a);
  filter->SetNumberOfIterations(iterations);
  // The team is min(work units, the threader's threads): raise both so that the thread count is as asked even
  // on a machine with fewer cores.
  itk::MultiThreaderBase * threader = filter->GetMultiThreader();
  threader->SetMaximumNumberOfThreads(std::max(threads, threader->GetMaximumNumberOfThreads()));
  filter->SetNumberOfWorkUnits(threads);
  filter->Update();
  DepthImage::Pointer result = filter->GetOutput();
  result->DisconnectPipeline();
  return result;
}

struct Comparison
{
  double      MaximumDifference = 0.0;
  std::size_t WorstPixel = 0;
  std::size_t FixedPixelsChanged = 0;
  std::size_t NonFinite = 0;
};

Comparison
CompareWithPlain(const DepthMap & map, const DepthImage * relaxed, double w, double a, unsigned int iterations)
{
  const auto                       size = map.Depth->GetLargestPossibleRegion().GetSize();
  const auto                       input = vr::test::PixelsOf(map.Depth.GetPointer());
  const std::vector<unsigned char> fixed =
    map.Fixed ? vr::test::PixelsOf(map.Fixed.GetPointer()) : std::vector<unsigned char>();
  const std::vector<double> reference =
    vr::test::PlainBilateralDepthRelax(input, fixed, size[0], size[1], w, a, iterations);
  const float * fast = relaxed->GetBufferPointer();
  Comparison    result;
  for (std::size_t k = 0; k < reference.size(); ++k)
  {
    if (!std::isfinite(fast[k]))
    {
      ++result.NonFinite;
      continue;
    }
    const double difference = std::abs(static_cast<double>(fast[k]) - reference[k]);
    if (difference > result.MaximumDifference)
    {
      result.MaximumDifference = difference;
      result.WorstPixel = k;
    }
    if (!fixed.empty() && fixed[k] && fast[k] != input[k])
    {
      ++result.FixedPixelsChanged;
    }
  }
  return result;
}

std::string
Describe(unsigned int width, unsigned int height, double w, double a, unsigned int iterations)
{
  std::ostringstream text;
  text << width << " x " << height << ", w = " << w << ", a = " << a << ", " << iterations << " iterations";
  return text.str();
}

bool
BitIdentical(const DepthImage * first, const DepthImage * second)
{
  const auto count = first->GetBufferedRegion().GetNumberOfPixels();
  return count == second->GetBufferedRegion().GetNumberOfPixels() &&
         std::memcmp(first->GetBufferPointer(), second->GetBufferPointer(), count * sizeof(float)) == 0;
}
} // namespace

// The paper's setting: 512 x 1024, 500 iterations, w = 1, with the range kernel (a = 0.5) and without (a = 0).
TEST(BilateralDepthRelaxFilterFastPath, AgreesWithPlainReferenceOnPhantomAtPaperSize)
{
  const DepthMap map = vr::test::MakePhantomDepthMap(512, 1024, 1.5);
  for (const double a : { 0.5, 0.0 })
  {
    SCOPED_TRACE(Describe(512, 1024, 1.0, a, 500));
    const auto       relaxed = RelaxWithFilter(map, 1.0, a, 500, 2);
    const Comparison comparison = CompareWithPlain(map, relaxed, 1.0, a, 500);
    EXPECT_EQ(comparison.NonFinite, 0u);
    EXPECT_EQ(comparison.FixedPixelsChanged, 0u);
    EXPECT_LE(comparison.MaximumDifference, Tolerance) << "worst pixel " << comparison.WorstPixel;
  }
}

/** Random blocks of 8 x 8 pixels, each at its own depth in [-60, 60) mm, plus noise in [0, 1) mm: flat zones,
 * small steps and jumps so large that every weight across them underflows, like a scanline mpCPR depth map. */
DepthImage::Pointer
MakeBlockDepthImage(unsigned int width, unsigned int height, unsigned int seed)
{
  std::mt19937                          generator(seed);
  std::uniform_real_distribution<float> blockDepth(-60.0f, 60.0f);
  std::uniform_real_distribution<float> noise(0.0f, 1.0f);
  const unsigned int                    blocksPerRow = width / 8 + 1;
  std::vector<float>                    blocks(static_cast<std::size_t>(blocksPerRow) * (height / 8 + 1));
  for (auto & block : blocks)
  {
    block = blockDepth(generator);
  }
  std::vector<float> values(static_cast<std::size_t>(width) * height);
  for (unsigned int y = 0; y < height; ++y)
  {
    for (unsigned int x = 0; x < width; ++x)
    {
      values[static_cast<std::size_t>(y) * width + x] = blocks[(y / 8) * blocksPerRow + x / 8] + noise(generator);
    }
  }
  return vr::test::MakeDepthImage(width, height, values);
}

// Odd sizes exercise the padding of rows to whole vectors, the borders (|Omega| = 2, 3) and one-row and
// one-column images; masks, w and a vary. Noise within a few mm keeps the weights in the kernel's core; blocks
// add jumps across which every weight underflows (w = 1 there leaves some pixels with no weight at all).
//
// Not tested: white noise spread over the Gaussian's far tail (say +-10 mm at a = 0.5, w = 1), where a pixel's
// new value is a ratio of weights all near 1e-20. There, Eq. 1 itself is ill-conditioned: changing a by one part
// in 10^7, less than a float can resolve, moves the double-precision reference by 0.05 mm, so no float
// implementation can promise 1e-4 mm.
TEST(BilateralDepthRelaxFilterFastPath, AgreesWithPlainReferenceOnRandomMapsAtOddSizes)
{
  enum class Kind
  {
    Noise,
    Blocks
  };
  struct Case
  {
    Kind         Map;
    unsigned int Width, Height;
    float        Low, High;
    double       FixedFraction;
    double       W, A;
    unsigned int Iterations;
  };
  const Case cases[] = {
    { Kind::Noise, 1, 1, 0.0f, 4.0f, 0.0, 1.0, 0.5, 20 },
    { Kind::Noise, 1, 7, 0.0f, 4.0f, 0.0, 1.0, 0.5, 50 },
    { Kind::Noise, 7, 1, 0.0f, 4.0f, 0.2, 0.7, 0.5, 50 },
    { Kind::Noise, 3, 5, 0.0f, 4.0f, 0.3, 1.0, 2.0, 100 },
    { Kind::Noise, 17, 13, 0.0f, 4.0f, 0.1, 0.5, 0.5, 200 },
    { Kind::Noise, 16, 16, 0.0f, 4.0f, 0.05, 1.0, 2.0, 300 },
    { Kind::Noise, 33, 2, 0.0f, 4.0f, 0.1, 0.25, 0.0, 100 },
    { Kind::Noise, 2, 33, 0.0f, 4.0f, 0.1, 0.9, 1.0, 100 },
    { Kind::Noise, 129, 77, 0.0f, 4.0f, 0.02, 0.5, 0.5, 300 },
    { Kind::Noise, 65, 31, -60.0f, 60.0f, 0.05, 1.0, 0.0, 300 },
    { Kind::Noise, 31, 29, -1.0f, 1.0f, 0.0, 0.0, 0.5, 10 },
    { Kind::Blocks, 1, 7, 0.0f, 0.0f, 0.0, 1.0, 0.5, 300 },
    { Kind::Blocks, 64, 40, 0.0f, 0.0f, 0.01, 1.0, 0.5, 300 },
    { Kind::Noise, 511, 1023, 0.0f, 4.0f, 0.01, 1.0, 0.5, 150 },
    { Kind::Noise, 511, 1023, -60.0f, 60.0f, 0.01, 1.0, 1e-3, 150 },
    { Kind::Blocks, 511, 1023, 0.0f, 0.0f, 0.01, 1.0, 0.5, 150 },
    { Kind::Blocks, 511, 1023, 0.0f, 0.0f, 0.01, 0.9, 0.05, 150 },
  };
  unsigned int seed = 1;
  for (const auto & c : cases)
  {
    SCOPED_TRACE(std::string(c.Map == Kind::Blocks ? "blocks, " : "noise, ") +
                 Describe(c.Width, c.Height, c.W, c.A, c.Iterations));
    DepthMap map;
    map.Depth = c.Map == Kind::Blocks ? MakeBlockDepthImage(c.Width, c.Height, ++seed)
                                      : vr::test::MakeRandomDepthImage(c.Width, c.Height, c.Low, c.High, ++seed);
    if (c.FixedFraction > 0.0)
    {
      map.Fixed = vr::test::MakeRandomMaskImage(c.Width, c.Height, c.FixedFraction, ++seed);
    }
    const auto       relaxed = RelaxWithFilter(map, c.W, c.A, c.Iterations, 2);
    const Comparison comparison = CompareWithPlain(map, relaxed, c.W, c.A, c.Iterations);
    EXPECT_EQ(comparison.NonFinite, 0u);
    EXPECT_EQ(comparison.FixedPixelsChanged, 0u);
    EXPECT_LE(comparison.MaximumDifference, Tolerance) << "worst pixel " << comparison.WorstPixel;
  }
}

// A mask of another pixel type goes through the byte conversion; non-zero means fixed whatever the value.
TEST(BilateralDepthRelaxFilterFastPath, AcceptsMasksOfOtherPixelTypes)
{
  using ShortMask = itk::Image<unsigned short, 2>;
  const unsigned int width = 23;
  const unsigned int height = 9;
  DepthMap           map;
  map.Depth = vr::test::MakeRandomDepthImage(width, height, 0.0f, 5.0f, 7);
  map.Fixed = vr::test::MakeRandomMaskImage(width, height, 0.2, 8);
  auto shortMask = ShortMask::New();
  shortMask->SetRegions(map.Fixed->GetLargestPossibleRegion());
  shortMask->Allocate();
  for (std::size_t k = 0; k < map.Fixed->GetBufferedRegion().GetNumberOfPixels(); ++k)
  {
    shortMask->GetBufferPointer()[k] =
      map.Fixed->GetBufferPointer()[k] ? static_cast<unsigned short>(256 * (k + 1)) : 0;
  }
  // Multiples of 256: a plain cast to a byte would lose these.
  auto filter = itk::BilateralDepthRelaxFilter<DepthImage, ShortMask>::New();
  filter->SetDepthInput(map.Depth);
  filter->SetFixedMask(shortMask);
  filter->SetRelaxation(1.0);
  filter->SetAnisotropy(0.5);
  filter->SetNumberOfIterations(50);
  filter->Update();
  const Comparison comparison = CompareWithPlain(map, filter->GetOutput(), 1.0, 0.5, 50);
  EXPECT_EQ(comparison.FixedPixelsChanged, 0u);
  EXPECT_LE(comparison.MaximumDifference, Tolerance);
}

// Pixel types other than float take the generic loop; it must agree with the reference too.
TEST(BilateralDepthRelaxFilterFastPath, GenericPathForDoubleAgreesWithPlainReference)
{
  using DoubleImage = itk::Image<double, 2>;
  const unsigned int width = 19;
  const unsigned int height = 11;
  DepthMap           map;
  map.Depth = vr::test::MakeRandomDepthImage(width, height, -3.0f, 3.0f, 21);
  map.Fixed = vr::test::MakeRandomMaskImage(width, height, 0.1, 22);
  auto depth = DoubleImage::New();
  depth->SetRegions(map.Depth->GetLargestPossibleRegion());
  depth->Allocate();
  std::copy_n(map.Depth->GetBufferPointer(), width * height, depth->GetBufferPointer());

  auto filter = itk::BilateralDepthRelaxFilter<DoubleImage>::New();
  filter->SetDepthInput(depth);
  filter->SetFixedMask(map.Fixed);
  filter->SetRelaxation(0.9);
  filter->SetAnisotropy(0.3);
  filter->SetNumberOfIterations(80);
  filter->Update();
  const std::vector<double> reference = vr::test::PlainBilateralDepthRelax(vr::test::PixelsOf(map.Depth.GetPointer()),
                                                                           vr::test::PixelsOf(map.Fixed.GetPointer()),
                                                                           width,
                                                                           height,
                                                                           0.9,
                                                                           0.3,
                                                                           80);
  for (std::size_t k = 0; k < reference.size(); ++k)
  {
    EXPECT_NEAR(filter->GetOutput()->GetBufferPointer()[k], reference[k], 1e-9) << "pixel " << k;
  }
}

// Rows are split into bands, one per thread; a band boundary must not change a single bit.
TEST(BilateralDepthRelaxFilterFastPath, BitIdenticalForAnyNumberOfThreads)
{
  const DepthMap phantom = vr::test::MakePhantomDepthMap(512, 1024, 1.5);
  const auto     one = RelaxWithFilter(phantom, 1.0, 0.5, 500, 1);
  const auto     two = RelaxWithFilter(phantom, 1.0, 0.5, 500, 2);
  const auto     three = RelaxWithFilter(phantom, 1.0, 0.5, 500, 3);
  EXPECT_TRUE(BitIdentical(one, two));
  EXPECT_TRUE(BitIdentical(one, three));

  DepthMap randomMap;
  randomMap.Depth = vr::test::MakeRandomDepthImage(37, 19, -10.0f, 10.0f, 5);
  randomMap.Fixed = vr::test::MakeRandomMaskImage(37, 19, 0.1, 6);
  const auto reference = RelaxWithFilter(randomMap, 0.8, 0.2, 60, 1);
  // More threads than rows: the team is capped at one row each.
  for (const unsigned int threads : { 2u, 5u, 19u, 40u })
  {
    EXPECT_TRUE(BitIdentical(reference, RelaxWithFilter(randomMap, 0.8, 0.2, 60, threads))) << threads << " threads";
  }
}

// Temporal blocking through the filter, on the phantom's depth map (fixed centrelines, jumps between vessels) at an
// odd height: teams of 1, 2, 3, 8 and 16 threads, each running 1, 2, 6 or 40 passes (more than a band of 16 threads
// has rows) before the team meets, and the kernel's choice, all give the bits of one thread meeting after every
// pass; the fixed pixels keep their input bits.
TEST(BilateralDepthRelaxFilterFastPath, BitIdenticalForAnyPassesBetweenSynchronizations)
{
  const DepthMap phantom = vr::test::MakePhantomDepthMap(160, 301);
  const auto     reference = RelaxWithFilter(phantom, 1.0, 0.5, 120, 1, 1);
  const auto     input = vr::test::PixelsOf(phantom.Depth.GetPointer());
  const auto     fixed = vr::test::PixelsOf(phantom.Fixed.GetPointer());
  std::size_t    fixedCount = 0;
  for (std::size_t k = 0; k < fixed.size(); ++k)
  {
    if (fixed[k])
    {
      ++fixedCount;
      EXPECT_EQ(std::memcmp(reference->GetBufferPointer() + k, &input[k], sizeof(float)), 0) << "fixed pixel " << k;
    }
  }
  ASSERT_GT(fixedCount, 0u);
  // The relax does move the free pixels (so that matching bits say something).
  EXPECT_NE(std::memcmp(reference->GetBufferPointer(), input.data(), input.size() * sizeof(float)), 0);
  for (const unsigned int threads : { 1u, 2u, 3u, 8u, 16u })
  {
    for (const unsigned int passes : { 0u, 1u, 2u, 6u, 40u })
    {
      EXPECT_TRUE(BitIdentical(reference, RelaxWithFilter(phantom, 1.0, 0.5, 120, threads, passes)))
        << threads << " threads, " << passes << " passes between synchronizations";
    }
  }
}

// Depths near the float limit would overflow the kernel's float differences; such maps take the generic loop and
// still give finite values that agree with the reference.
TEST(BilateralDepthRelaxFilterFastPath, HugeDepthsStayFinite)
{
  for (const double a : { 0.0, 0.5 })
  {
    DepthMap map;
    map.Depth = vr::test::MakeRandomDepthImage(20, 10, -1e38f, 1e38f, 31);
    const auto       relaxed = RelaxWithFilter(map, 1.0, a, 20, 2);
    const Comparison comparison = CompareWithPlain(map, relaxed, 1.0, a, 20);
    EXPECT_EQ(comparison.NonFinite, 0u) << "a = " << a;
    // Relative to depths of 1e38 mm, one float rounding is 1e31 mm.
    EXPECT_LE(comparison.MaximumDifference, 1e32) << "a = " << a;
  }
}
