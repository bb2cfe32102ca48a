// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The OpenCL variant of BilateralDepthRelaxFilter against the CPU filter and against hand-worked answers
// (docs/design.md "Relaxation", issue 4). Tests that need a device are skipped, with the reason, when no OpenCL device
// exists.
#include "itkBilateralDepthRelaxFilter.h"
#include "itkCPRViewGeometry.h"
#include "itkOpenCLBilateralDepthRelaxFilter.h"
#include "vrOpenCLDevices.h"
#include "vrOpenCLTestSupport.h"
#include "vrTestImages.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <iostream>
#include <iterator>
#include <locale>
#include <sstream>
#include <string>
#include <tuple>

namespace
{
using vr::test::DepthImage;
using vr::test::MakePhantomDepthMap;
using vr::test::MaskImage;
using vr::test::PhantomDepthMap;
using CPUFilter = itk::BilateralDepthRelaxFilter<DepthImage>;
using OpenCLFilter = itk::OpenCLBilateralDepthRelaxFilter;

constexpr double Tolerance = 1e-4; // mm, docs/design.md "Relaxation"

struct Parameters
{
  double       Relaxation;
  double       Anisotropy;
  unsigned int Iterations;
};

template<typename TFilter>
DepthImage::Pointer
Relax(typename TFilter::Pointer filter, const DepthImage * depth, const MaskImage * mask, const Parameters & p)
{
  filter->SetDepthInput(depth);
  if (mask)
  {
    filter->SetFixedMask(mask);
  }
  filter->SetRelaxation(p.Relaxation);
  filter->SetAnisotropy(p.Anisotropy);
  filter->SetNumberOfIterations(p.Iterations);
  filter->Update();
  DepthImage::Pointer result = filter->GetOutput();
  result->DisconnectPipeline();
  return result;
}

DepthImage::Pointer
RelaxOnCPU(const DepthImage * depth, const MaskImage * mask, const Parameters & p)
{
  return Relax<CPUFilter>(CPUFilter::New(), depth, mask, p);
}

DepthImage::Pointer
RelaxOnOpenCL(const DepthImage * depth, const MaskImage * mask, const Parameters & p)
{
  return Relax<OpenCLFilter>(OpenCLFilter::New(), depth, mask, p);
}

double
MaxAbsoluteDifference(const DepthImage * a, const DepthImage * b)
{
  const auto va = vr::test::PixelsOf(a);
  const auto vb = vr::test::PixelsOf(b);
  EXPECT_EQ(va.size(), vb.size());
  double largest = 0.0;
  for (std::size_t k = 0; k < std::min(va.size(), vb.size()); ++k)
  {
    const double difference = std::fabs(static_cast<double>(va[k]) - vb[k]);
    largest = std::isnan(difference) ? INFINITY : std::max(largest, difference);
  }
  return largest;
}

// --- Agreement with the CPU filter ----------------------------------------------------------------------------

class PhantomAgreement : public ::testing::TestWithParam<std::tuple<unsigned int, unsigned int, double>>
{
};

TEST_P(PhantomAgreement, OpenCLMatchesCPUWithin1e4mmAfter500Iterations)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const auto [width, height, anisotropy] = GetParam();
  const PhantomDepthMap map = MakePhantomDepthMap(width, height);
  const Parameters      parameters{ 1.0, anisotropy, 500 };

  const auto cpu = RelaxOnCPU(map.Depth, map.Fixed, parameters);
  const auto opencl = RelaxOnOpenCL(map.Depth, map.Fixed, parameters);

  // Not vacuous: the relaxation moved the depth map by millimetres somewhere.
  const double moved = MaxAbsoluteDifference(cpu, map.Depth);
  const double disagreement = MaxAbsoluteDifference(cpu, opencl);
  std::cout << "relaxation moved depths by up to " << moved << " mm; OpenCL and CPU differ by up to " << disagreement
            << " mm" << std::endl;
  EXPECT_GT(moved, 1.0);
  EXPECT_LE(disagreement, Tolerance);
}

INSTANTIATE_TEST_SUITE_P(PaperSizes,
                         PhantomAgreement,
                         ::testing::Values(std::make_tuple(256u, 768u, 0.5),
                                           std::make_tuple(256u, 768u, 0.0),
                                           std::make_tuple(512u, 1024u, 0.5),
                                           std::make_tuple(512u, 1024u, 0.0)),
                         [](const auto & info)
                         {
                           return std::to_string(std::get<0>(info.param)) + "x" +
                                  std::to_string(std::get<1>(info.param)) +
                                  (std::get<2>(info.param) > 0.0 ? "_a0_5" : "_a0");
                         });

// Random maps stay in the regime of real depth maps, a d^2 <= 12.5 between neighbours: where every weight of a
// pixel is tiny but not zero (a d^2 of 20-87 on all sides with w = 1), the equation itself is ill-conditioned and
// one float rounding moves the result by up to 1e-2 mm, in any single-precision implementation.
TEST(OpenCLBilateralDepthRelax, RandomDepthMapsWithRandomMasksMatchCPU)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const Parameters cases[] = { { 1.0, 0.5, 200 }, { 1.0, 0.0, 200 }, { 0.6, 0.5, 200 }, { 0.25, 2.0, 100 } };
  unsigned int     seed = 1;
  for (const auto & parameters : cases)
  {
    for (const double fixedFraction : { 0.0, 0.05, 0.5 })
    {
      ++seed;
      const auto depth = vr::test::MakeRandomDepthImage(97, 61, 0.0f, 5.0f, seed);
      const auto mask = vr::test::MakeRandomMaskImage(97, 61, fixedFraction, seed + 1000);
      const auto cpu = RelaxOnCPU(depth, mask, parameters);
      const auto opencl = RelaxOnOpenCL(depth, mask, parameters);
      EXPECT_LE(MaxAbsoluteDifference(cpu, opencl), Tolerance)
        << "w = " << parameters.Relaxation << ", a = " << parameters.Anisotropy << ", fixed " << fixedFraction;
    }
  }
}

TEST(OpenCLBilateralDepthRelax, SizesThatAreNoMultipleOfAnyWorkGroupMatchCPU)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const unsigned int sizes[][2] = { { 1, 1 }, { 1, 7 }, { 7, 1 }, { 3, 5 }, { 17, 33 }, { 511, 1023 } };
  const Parameters   parameters{ 1.0, 0.5, 60 };
  unsigned int       seed = 100;
  for (const auto & size : sizes)
  {
    ++seed;
    const auto depth = vr::test::MakeRandomDepthImage(size[0], size[1], -2.0f, 3.0f, seed);
    const auto mask = vr::test::MakeRandomMaskImage(size[0], size[1], 0.1, seed + 1000);
    const auto cpu = RelaxOnCPU(depth, mask, parameters);
    const auto opencl = RelaxOnOpenCL(depth, mask, parameters);
    EXPECT_LE(MaxAbsoluteDifference(cpu, opencl), Tolerance) << size[0] << " x " << size[1];
  }
}

// The kernel is specialised by -D definitions for the device: vector width, and wide blocks per work-item (CPU
// devices) or one pixel column per work-item (GPUs). PoCL alone would only ever build one of those variants; the
// test hook forces each, so the code paths an NVIDIA, AMD or Intel GPU takes are checked here too.
class KernelLayoutAgreement : public ::testing::TestWithParam<std::tuple<unsigned int, bool>>
{
};

TEST_P(KernelLayoutAgreement, EveryVectorWidthAndLayoutMatchesCPU)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const unsigned int vectorWidth = std::get<0>(GetParam());
  const bool         gpuLayout = std::get<1>(GetParam());
  const unsigned int sizes[][2] = { { 1, 1 }, { 5, 3 }, { 37, 23 }, { 150, 70 } };
  const Parameters   cases[] = { { 1.0, 0.5, 40 }, { 0.7, 0.0, 40 } };
  unsigned int       seed = 300;
  for (const auto & size : sizes)
  {
    for (const auto & parameters : cases)
    {
      ++seed;
      const auto depth = vr::test::MakeRandomDepthImage(size[0], size[1], -2.0f, 3.0f, seed);
      const auto mask = vr::test::MakeRandomMaskImage(size[0], size[1], 0.1, seed + 1000);
      auto       filter = OpenCLFilter::New();
      filter->SetKernelLayoutForTesting(vectorWidth, gpuLayout);
      filter->SetPassesPerLaunch(1); // the one-pass kernel; MultiPassLaunches below checks the other
      const auto opencl = Relax<OpenCLFilter>(filter, depth, mask, parameters);
      const auto cpu = RelaxOnCPU(depth, mask, parameters);
      EXPECT_LE(MaxAbsoluteDifference(cpu, opencl), Tolerance)
        << size[0] << " x " << size[1] << ", a = " << parameters.Anisotropy;

      // The hook took effect: the filter reports the layout it built.
      std::ostringstream printed;
      filter->Print(printed);
      EXPECT_NE(printed.str().find("Kernel shape: " + std::to_string(vectorWidth) + "-lane vectors, " +
                                   (gpuLayout ? "1 vectors" : "8 vectors")),
                std::string::npos)
        << printed.str();
    }
  }
}

INSTANTIATE_TEST_SUITE_P(ForcedLayouts,
                         KernelLayoutAgreement,
                         ::testing::Combine(::testing::Values(1u, 2u, 4u, 8u, 16u), ::testing::Bool()),
                         [](const ::testing::TestParamInfo<std::tuple<unsigned int, bool>> & info) {
                           return std::to_string(std::get<0>(info.param)) + "lanes_" +
                                  (std::get<1>(info.param) ? "GPULayout" : "CPULayout");
                         });

TEST(OpenCLBilateralDepthRelax, AnInvalidForcedVectorWidthIsRejected)
{
  auto filter = OpenCLFilter::New();
  EXPECT_THROW(filter->SetKernelLayoutForTesting(3, false), itk::ExceptionObject);
  EXPECT_THROW(filter->SetKernelLayoutForTesting(32, true), itk::ExceptionObject);
  EXPECT_NO_THROW(filter->SetKernelLayoutForTesting(0, false));
}

// --- Several passes per launch (GPUs) --------------------------------------------------------------------------

/** The OpenCL filter with the GPU layout forced and \a passesPerLaunch passes a launch. */
OpenCLFilter::Pointer
MultiPassFilter(unsigned int passesPerLaunch)
{
  auto filter = OpenCLFilter::New();
  filter->SetKernelLayoutForTesting(1, true);
  filter->SetPassesPerLaunch(passesPerLaunch);
  return filter;
}

// Each tile computes its border pixels again instead of exchanging them between passes: the pixels a tile keeps
// must not depend on how many passes a launch runs (bits), and must be the CPU's (1e-4 mm). Sizes around the tile
// (96 x 48 pixels with the border) and below it, iterations that are no multiple of the passes per launch.
TEST(OpenCLBilateralDepthRelax, MultiPassLaunchesGiveTheSameBitsForEveryPassCountAndMatchTheCPU)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const unsigned int sizes[][2] = { { 1, 1 }, { 3, 70 }, { 95, 47 }, { 200, 130 } };
  const Parameters   cases[] = { { 1.0, 0.5, 37 }, { 0.7, 0.0, 20 }, { 1.0, 1.0 / 9.0, 50 } };
  unsigned int       seed = 700;
  for (const auto & size : sizes)
  {
    for (const auto & parameters : cases)
    {
      ++seed;
      const auto                depth = vr::test::MakeRandomDepthImage(size[0], size[1], -2.0f, 3.0f, seed);
      const auto                mask = vr::test::MakeRandomMaskImage(size[0], size[1], 0.1, seed + 1000);
      const auto                cpu = RelaxOnCPU(depth, mask, parameters);
      const DepthImage::Pointer first = Relax<OpenCLFilter>(MultiPassFilter(2), depth, mask, parameters);
      EXPECT_LE(MaxAbsoluteDifference(cpu, first), Tolerance) << size[0] << " x " << size[1];
      // The one-pass kernel computes the same expressions; whether its bits are the same depends on the compiler
      // contracting the same products into fused multiply-adds in both, so it is reported, not required.
      const DepthImage::Pointer onePass = Relax<OpenCLFilter>(MultiPassFilter(1), depth, mask, parameters);
      std::cout << size[0] << " x " << size[1] << ", " << parameters.Iterations << " iterations: several passes a "
                << "launch differ from one pass a launch by " << MaxAbsoluteDifference(onePass, first) << " mm"
                << std::endl;
      for (const unsigned int passes : { 3u, 4u, 8u, 13u, 16u })
      {
        auto       filter = MultiPassFilter(passes);
        const auto opencl = Relax<OpenCLFilter>(filter, depth, mask, parameters);
        EXPECT_EQ(vr::test::PixelsOf(opencl.GetPointer()), vr::test::PixelsOf(first.GetPointer()))
          << size[0] << " x " << size[1] << ", " << passes << " passes a launch, " << parameters.Iterations
          << " iterations";
        EXPECT_EQ(filter->GetEffectivePassesPerLaunch(), passes);
        // One launch per block of passes, and the one that joins the depth pairs.
        EXPECT_EQ(filter->GetNumberOfLaunches(), (parameters.Iterations + passes - 1) / passes + 1);
      }
    }
  }
}

// 500 passes at the paper's size in 63 launches instead of 500, still within 1e-4 mm of the CPU.
TEST(OpenCLBilateralDepthRelax, MultiPassLaunchesMatchTheCPUOnThePhantomAt512x1024)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const PhantomDepthMap map = MakePhantomDepthMap(512, 1024);
  const Parameters      parameters{ 1.0, 0.5, 500 };
  auto                  filter = MultiPassFilter(8);
  const auto            opencl = Relax<OpenCLFilter>(filter, map.Depth, map.Fixed, parameters);
  const auto            cpu = RelaxOnCPU(map.Depth, map.Fixed, parameters);
  EXPECT_LE(MaxAbsoluteDifference(cpu, opencl), Tolerance);
  EXPECT_EQ(filter->GetNumberOfLaunches(), 63u + 1u);
  std::ostringstream printed;
  filter->Print(printed);
  EXPECT_NE(printed.str().find("Kernel shape: 8 passes a launch on tiles of 80 x 32 pixels"), std::string::npos)
    << printed.str();
}

TEST(OpenCLBilateralDepthRelax, TheDevicesChoiceIsOnePassALaunchOnACPUDeviceAndSeveralOnAGPU)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const auto depth = vr::test::MakeRandomDepthImage(40, 30, -2.0f, 3.0f, 5);
  auto       filter = OpenCLFilter::New();
  Relax<OpenCLFilter>(filter, depth, nullptr, { 1.0, 0.5, 24 });
  const bool cpuDevice = filter->GetDeviceLabel().find(", CPU)") != std::string::npos;
  EXPECT_EQ(filter->GetEffectivePassesPerLaunch(), cpuDevice ? 1u : OpenCLFilter::DefaultPassesPerLaunchOnGPUs)
    << filter->GetDeviceLabel();
  EXPECT_EQ(filter->GetNumberOfLaunches(), cpuDevice ? 25u : 3u + 1u);
}

TEST(OpenCLBilateralDepthRelax, TooManyPassesPerLaunchAreRejectedNamingTheParameter)
{
  const auto depth = vr::test::MakeRandomDepthImage(8, 8, 0.0f, 1.0f, 3);
  auto       filter = OpenCLFilter::New();
  filter->SetInput(depth);
  filter->SetPassesPerLaunch(OpenCLFilter::MaximumPassesPerLaunch + 1);
  try
  {
    filter->Update();
    FAIL() << "17 passes a launch were accepted";
  }
  catch (const itk::ExceptionObject & error)
  {
    EXPECT_NE(std::string(error.GetDescription()).find("PassesPerLaunch = 17"), std::string::npos)
      << error.GetDescription();
  }
}

// --- Answers worked out by hand -------------------------------------------------------------------------------

TEST(OpenCLBilateralDepthRelax, OneIterationOnThreePixelsMatchesHandCalculation)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const auto depth = vr::test::MakeDepthImage(3, 1, { 0.0f, 1.0f, 3.0f });

  // a = 0, w = 1: each pixel becomes the mean of its neighbours: (1, (0 + 3) / 2, 1).
  const auto linear = vr::test::PixelsOf(RelaxOnOpenCL(depth, nullptr, { 1.0, 0.0, 1 }).GetPointer());
  EXPECT_NEAR(linear[0], 1.0, 1e-6);
  EXPECT_NEAR(linear[1], 1.5, 1e-6);
  EXPECT_NEAR(linear[2], 1.0, 1e-6);

  // a = ln 2, w = 1: R(1) = 1/2, R(2) = 1/16. The middle pixel: 1 + (1/2 (0 - 1) + 1/16 (3 - 1)) / (1/2 + 1/16)
  // = 1 - 2/3. The ends have one neighbour each, so they take its value whatever its weight.
  const auto bilateral = vr::test::PixelsOf(RelaxOnOpenCL(depth, nullptr, { 1.0, std::log(2.0), 1 }).GetPointer());
  EXPECT_NEAR(bilateral[0], 1.0, 1e-6);
  EXPECT_NEAR(bilateral[1], 1.0 / 3.0, 1e-6);
  EXPECT_NEAR(bilateral[2], 1.0, 1e-6);

  // w = 1/2, a = 0, middle pixel: ((1 - w) 2 D_p + w (0 + 3)) / ((1 - w) 2 + w 2) = (1 + 1.5) / 2.
  const auto half = vr::test::PixelsOf(RelaxOnOpenCL(depth, nullptr, { 0.5, 0.0, 1 }).GetPointer());
  EXPECT_NEAR(half[1], 1.25, 1e-6);
}

TEST(OpenCLBilateralDepthRelax, ZeroRelaxationLeavesTheImageUnchanged)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const auto depth = vr::test::MakeRandomDepthImage(45, 29, -100.0f, 100.0f, 7);
  const auto relaxed = RelaxOnOpenCL(depth, nullptr, { 0.0, 0.5, 25 });
  EXPECT_EQ(vr::test::PixelsOf(relaxed.GetPointer()), vr::test::PixelsOf(depth.GetPointer()));
}

TEST(OpenCLBilateralDepthRelax, FixedPixelsNeverChange)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const auto  depth = vr::test::MakeRandomDepthImage(64, 40, 0.0f, 5.0f, 11);
  const auto  mask = vr::test::MakeRandomMaskImage(64, 40, 0.2, 12);
  const auto  before = vr::test::PixelsOf(depth.GetPointer());
  const auto  fixed = vr::test::PixelsOf(mask.GetPointer());
  const auto  after = vr::test::PixelsOf(RelaxOnOpenCL(depth, mask, { 1.0, 0.5, 100 }).GetPointer());
  std::size_t fixedCount = 0;
  std::size_t freeChanged = 0;
  for (std::size_t k = 0; k < before.size(); ++k)
  {
    if (fixed[k])
    {
      ++fixedCount;
      EXPECT_EQ(after[k], before[k]) << "fixed pixel " << k;
    }
    else
    {
      freeChanged += after[k] != before[k];
    }
  }
  EXPECT_GT(fixedCount, 0u);
  EXPECT_GT(freeChanged, before.size() / 2); // the free pixels did move
}

// A checkerboard of 0 and 1000 mm: with a = 0.5 every weight is exp(-500000), below float's range, and w = 1 leaves
// nothing in the denominator. Every pixel must keep its value: no 0/0, no NaN.
TEST(OpenCLBilateralDepthRelax, AllWeightsUnderflowingKeepsEveryValueAndGivesNoNaN)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  std::vector<float> values(13 * 9);
  for (std::size_t k = 0; k < values.size(); ++k)
  {
    values[k] = ((k % 13) + (k / 13)) % 2 ? 1000.0f : 0.0f;
  }
  const auto depth = vr::test::MakeDepthImage(13, 9, values);
  const auto after = vr::test::PixelsOf(RelaxOnOpenCL(depth, nullptr, { 1.0, 0.5, 10 }).GetPointer());
  for (std::size_t k = 0; k < values.size(); ++k)
  {
    ASSERT_FALSE(std::isnan(after[k])) << "pixel " << k;
    EXPECT_EQ(after[k], values[k]) << "pixel " << k;
  }
}

TEST(OpenCLBilateralDepthRelax, ZeroIterationsReturnsTheInput)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const auto depth = vr::test::MakeRandomDepthImage(20, 30, -5.0f, 5.0f, 3);
  const auto after = RelaxOnOpenCL(depth, nullptr, { 1.0, 0.5, 0 });
  EXPECT_EQ(vr::test::PixelsOf(after.GetPointer()), vr::test::PixelsOf(depth.GetPointer()));
}

TEST(OpenCLBilateralDepthRelax, ReportsProgressWhileIteratingAndCanBeAborted)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const auto depth = vr::test::MakeRandomDepthImage(40, 30, 0.0f, 5.0f, 21);
  auto       filter = OpenCLFilter::New();
  filter->SetDepthInput(depth);
  filter->SetNumberOfIterations(100);
  OpenCLFilter *     observed = filter.GetPointer();
  std::vector<float> progress;
  bool               abortEarly = false;
  filter->AddObserver(itk::ProgressEvent(),
                      [&](const itk::EventObject &)
                      {
                        progress.push_back(observed->GetProgress());
                        if (abortEarly && observed->GetProgress() >= 0.3f)
                        {
                          observed->AbortGenerateDataOn();
                        }
                      });

  filter->Update();
  ASSERT_FALSE(progress.empty());
  EXPECT_FLOAT_EQ(progress.back(), 1.0f);
  EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end()));
  EXPECT_GE(std::count_if(progress.begin(), progress.end(), [](float p) { return p > 0.0f && p < 1.0f; }), 5);

  progress.clear();
  abortEarly = true;
  filter->Modified();
  EXPECT_THROW(filter->Update(), itk::ProcessAborted);
  ASSERT_FALSE(progress.empty());
  EXPECT_LT(progress.back(), 1.0f);
}

// --- The output contract of the base class --------------------------------------------------------------------

TEST(OpenCLBilateralDepthRelax, OutputCarriesTheViewAndTheGridOfTheInput)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const PhantomDepthMap map = MakePhantomDepthMap(64, 96);
  ASSERT_TRUE(itk::CPRViewGeometry::DictionaryHasView(map.Depth->GetMetaDataDictionary()));
  const auto relaxed = RelaxOnOpenCL(map.Depth, map.Fixed, { 1.0, 0.5, 5 });
  ASSERT_TRUE(itk::CPRViewGeometry::DictionaryHasView(relaxed->GetMetaDataDictionary()));
  EXPECT_EQ(itk::CPRViewGeometry::ReadFromDictionary(relaxed->GetMetaDataDictionary()),
            itk::CPRViewGeometry::ReadFromDictionary(map.Depth->GetMetaDataDictionary()));
  EXPECT_EQ(relaxed->GetSpacing(), map.Depth->GetSpacing());
  EXPECT_EQ(relaxed->GetOrigin(), map.Depth->GetOrigin());
  EXPECT_EQ(relaxed->GetLargestPossibleRegion(), map.Depth->GetLargestPossibleRegion());
}

TEST(OpenCLBilateralDepthRelax, BadParametersAndInputsAreRejectedLikeOnTheCPU)
{
  const auto depth = vr::test::MakeRandomDepthImage(8, 6, 0.0f, 1.0f, 5);

  auto badRelaxation = OpenCLFilter::New();
  badRelaxation->SetDepthInput(depth);
  badRelaxation->SetRelaxation(1.5);
  try
  {
    badRelaxation->Update();
    FAIL() << "w = 1.5 was accepted";
  }
  catch (const itk::ExceptionObject & error)
  {
    EXPECT_NE(std::string(error.GetDescription()).find("Relaxation w = 1.5"), std::string::npos)
      << error.GetDescription();
  }

  auto badMask = OpenCLFilter::New();
  badMask->SetDepthInput(depth);
  badMask->SetFixedMask(vr::test::MakeRandomMaskImage(7, 6, 0.5, 1));
  EXPECT_THROW(badMask->Update(), itk::ExceptionObject);

  // The non-finite check runs before any device is needed.
  auto values = vr::test::PixelsOf(depth.GetPointer());
  values[8 * 2 + 3] = std::nanf("");
  auto notFinite = OpenCLFilter::New();
  notFinite->SetDepthInput(vr::test::MakeDepthImage(8, 6, values));
  try
  {
    notFinite->Update();
    FAIL() << "a NaN depth was accepted";
  }
  catch (const itk::ExceptionObject & error)
  {
    EXPECT_NE(std::string(error.GetDescription()).find("[3, 2]"), std::string::npos) << error.GetDescription();
  }
}

// --- Failures: program build and device choice ---------------------------------------------------------------

// The line number of the first "name:line:column:" location in a compiler's log line (the name may be empty, as
// at the start of a line), 0 if it has none.
int
LineOfLocation(const std::string & logLine)
{
  const std::string line = ":" + logLine;
  const auto        digitsFrom = [&line](std::size_t from)
  {
    std::size_t end = from;
    while (end < line.size() && std::isdigit(static_cast<unsigned char>(line[end])))
    {
      ++end;
    }
    return end;
  };
  for (std::size_t colon = line.find(':'); colon != std::string::npos; colon = line.find(':', colon + 1))
  {
    const std::size_t lineEnd = digitsFrom(colon + 1);
    if (lineEnd == colon + 1 || lineEnd >= line.size() || line[lineEnd] != ':')
    {
      continue;
    }
    const std::size_t columnEnd = digitsFrom(lineEnd + 1);
    if (columnEnd > lineEnd + 1 && columnEnd < line.size() && line[columnEnd] == ':')
    {
      return std::stoi(line.substr(colon + 1, lineEnd - colon - 1));
    }
  }
  return 0;
}

TEST(OpenCLBilateralDepthRelax, AFailedProgramBuildThrowsWithTheCompilersLog)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const auto depth = vr::test::MakeRandomDepthImage(8, 6, 0.0f, 1.0f, 5);
  {
    // Line 4 uses every definition (so they must reach the compiler); the undeclared name is on line 6. The
    // compiler's message for it must name line 6: clang-based compilers (PoCL, AMD, Intel) and NVIDIA's all print
    // file:line:column, and NVIDIA's ignores #line, so only a source handed over unchanged gets this right there.
    const vr::test::ScopedKernelSource broken("// a broken kernel\n"
                                              "__kernel void RelaxIteration(__global float * depth)\n"
                                              "{\n"
                                              "  depth[0] = VECTOR_WIDTH + VECTORS_PER_ITEM + ROWS_PER_ITEM + "
                                              "LOCAL_WIDTH + LOCAL_HEIGHT + WEIGHT_UNDERFLOW_POWER;\n"
                                              "\n"
                                              "  depth[1] = undeclared_name_in_kernel;\n"
                                              "}\n");
    auto                               filter = OpenCLFilter::New();
    filter->SetDepthInput(depth);
    try
    {
      filter->Update();
      FAIL() << "the broken kernel built";
    }
    catch (const itk::ExceptionObject & error)
    {
      const std::string message = error.GetDescription();
      EXPECT_NE(message.find("failed to build"), std::string::npos) << message;
      // Every log line that names the undeclared identifier with a location (file:line:column) names line 6, and
      // at least one does; no diagnostic points at line 4, where the definitions are used.
      std::istringstream lines(message);
      int                located = 0;
      for (std::string line; std::getline(lines, line);)
      {
        const int lineNumber = LineOfLocation(line);
        if (line.find("undeclared_name_in_kernel") != std::string::npos && lineNumber > 0)
        {
          ++located;
          EXPECT_EQ(lineNumber, 6) << line << "\n(the whole message:)\n" << message;
        }
        EXPECT_NE(lineNumber, 4) << "a diagnostic where the definitions are used:\n" << message;
      }
      EXPECT_GE(located, 1) << "no line:column for the undeclared name in\n" << message;
    }
  }
  // With the real kernel back, a filter builds and runs again.
  EXPECT_NO_THROW(RelaxOnOpenCL(depth, nullptr, { 1.0, 0.5, 2 }));
}

// A numeric punctuation that would spoil a float a stream writes with it: a decimal comma. Installed as the global
// locale, it must not reach the build options. (No digit grouping: PoCL 3.1 writes its own -D options with the
// global locale, so with grouping it fails to build any program, "1.2.0" for 120.)
class HostileNumberPunctuation : public std::numpunct<char>
{
protected:
  char
  do_decimal_point() const override
  {
    return ',';
  }
  char
  do_thousands_sep() const override
  {
    return '.';
  }
  std::string
  do_grouping() const override
  {
    return "";
  }
};

class ScopedGlobalLocale
{
public:
  explicit ScopedGlobalLocale(const std::locale & locale)
    : m_Old(std::locale::global(locale))
  {
  }
  ~ScopedGlobalLocale() { std::locale::global(m_Old); }
  ScopedGlobalLocale(const ScopedGlobalLocale &) = delete;
  ScopedGlobalLocale &
  operator=(const ScopedGlobalLocale &) = delete;

private:
  std::locale m_Old;
};

// Two texts are equal; otherwise says where they first differ (not the whole kernel twice).
void
ExpectSameText(const std::string & actual, const std::string & expected)
{
  if (actual == expected)
  {
    return;
  }
  const auto        firstDifference = std::mismatch(actual.begin(), actual.end(), expected.begin(), expected.end());
  const std::size_t at = static_cast<std::size_t>(firstDifference.first - actual.begin());
  ADD_FAILURE() << "the texts differ from character " << at << " on (lengths " << actual.size() << " and "
                << expected.size() << "): \"" << actual.substr(at, 60) << "\" instead of \"" << expected.substr(at, 60)
                << "\"";
}

// The driver holds the .cl file byte for byte as the program's source (nothing put before it), and the layout
// comes as -D options written exactly, whatever the global locale; a changed layout rebuilds with its own options.
TEST(OpenCLBilateralDepthRelax, TheProgramIsTheClFileWithItsDefinitionsAsBuildOptions)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  std::ifstream file(VR_OPENCL_KERNEL_FILE, std::ios::binary);
  ASSERT_TRUE(file) << VR_OPENCL_KERNEL_FILE;
  const std::string onDisk((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());

  const ScopedGlobalLocale hostile(std::locale(std::locale::classic(), new HostileNumberPunctuation));
  auto                     filter = OpenCLFilter::New();
  EXPECT_EQ(filter->GetBuildOptions(), "");
  EXPECT_EQ(filter->GetProgramSource(), "");
  filter->SetKernelLayoutForTesting(16, false);
  filter->PrepareDevice();
  ExpectSameText(filter->GetProgramSource(), onDisk);
  // The CPU layout: 16 lanes, 8 vectors x 16 rows per work-item, work-groups of 1 x 4 (within every device's
  // limits); -log2(FLT_MIN) = 126 as a float literal.
  EXPECT_EQ(filter->GetBuildOptions(),
            "-D VECTOR_WIDTH=16 -D VECTORS_PER_ITEM=8 -D ROWS_PER_ITEM=16 -D LOCAL_WIDTH=1 "
            "-D LOCAL_HEIGHT=4 -D WEIGHT_UNDERFLOW_POWER=126.0f");

  filter->SetKernelLayoutForTesting(2, true);
  filter->SetPassesPerLaunch(1);
  filter->PrepareDevice();
  ExpectSameText(filter->GetProgramSource(), onDisk);
  const std::string gpuOptions = filter->GetBuildOptions();
  EXPECT_EQ(gpuOptions.rfind("-D VECTOR_WIDTH=2 -D VECTORS_PER_ITEM=1 -D ROWS_PER_ITEM=4 -D LOCAL_WIDTH=", 0), 0)
    << gpuOptions;
  EXPECT_NE(gpuOptions.find(" -D WEIGHT_UNDERFLOW_POWER=126.0f"), std::string::npos) << gpuOptions;
  EXPECT_EQ(gpuOptions.find("PASSES_PER_LAUNCH"), std::string::npos) << gpuOptions;

  // Several passes a launch (a GPU's default): the multi-pass kernel's tile and passes, scalar, work-groups of
  // 32 x 8, tiles of 96 x 48 pixels with a border of 6 (the passes) on each side.
  filter->SetPassesPerLaunch(6);
  filter->PrepareDevice();
  ExpectSameText(filter->GetProgramSource(), onDisk);
  EXPECT_EQ(filter->GetBuildOptions(),
            "-D VECTOR_WIDTH=1 -D VECTORS_PER_ITEM=1 -D ROWS_PER_ITEM=1 -D LOCAL_WIDTH=32 -D LOCAL_HEIGHT=8 "
            "-D WEIGHT_UNDERFLOW_POWER=126.0f -D PASSES_PER_LAUNCH=6 -D TILE_WIDTH=84 -D TILE_HEIGHT=36");

  // The rebuilt program still relaxes as the CPU does.
  const auto depth = vr::test::MakeRandomDepthImage(37, 23, -2.0f, 3.0f, 77);
  const auto opencl = Relax<OpenCLFilter>(filter, depth, nullptr, { 1.0, 0.5, 20 });
  EXPECT_LE(MaxAbsoluteDifference(RelaxOnCPU(depth, nullptr, { 1.0, 0.5, 20 }), opencl), Tolerance);
}

// The build embeds the .cl file byte for byte (a raw string literal starting on its first line), so the compiler's
// line numbers are those of the file. Needs no device.
TEST(OpenCLBilateralDepthRelax, TheEmbeddedKernelIsTheClFileByteForByte)
{
  std::ifstream file(VR_OPENCL_KERNEL_FILE, std::ios::binary);
  ASSERT_TRUE(file) << VR_OPENCL_KERNEL_FILE;
  const std::string onDisk((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
  EXPECT_EQ(OpenCLFilter::GetKernelSource(), onDisk);
  {
    const vr::test::ScopedKernelSource replaced("__kernel void RelaxIteration() {}\n");
    EXPECT_EQ(OpenCLFilter::GetKernelSource(), "__kernel void RelaxIteration() {}\n");
  }
  EXPECT_EQ(OpenCLFilter::GetKernelSource(), onDisk);
}

TEST(OpenCLBilateralDepthRelax, ARequestForAMissingDeviceNamesTheDevicesThatExist)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const auto devices = vr::ListOpenCLDevices();
  const auto depth = vr::test::MakeRandomDepthImage(8, 6, 0.0f, 1.0f, 5);
  for (const std::string request : { "no-such-opencl-device", "99:0" })
  {
    auto filter = OpenCLFilter::New();
    filter->SetDepthInput(depth);
    filter->SetDeviceRequest(request);
    try
    {
      filter->Update();
      FAIL() << "device \"" << request << "\" was accepted";
    }
    catch (const itk::ExceptionObject & error)
    {
      const std::string message = error.GetDescription();
      EXPECT_NE(message.find("\"" + request + "\""), std::string::npos) << message;
      for (const auto & device : devices)
      {
        EXPECT_NE(message.find(device.Label()), std::string::npos) << message;
      }
    }
  }
}

TEST(OpenCLBilateralDepthRelax, TheEnvironmentVariablePicksTheDeviceUnlessTheParameterDoes)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const auto                 depth = vr::test::MakeRandomDepthImage(8, 6, 0.0f, 1.0f, 5);
  const vr::OpenCLDeviceInfo first = vr::ChooseOpenCLDevice(vr::ListOpenCLDevices(), "", "");
  const std::string          byIndex = std::to_string(first.PlatformIndex) + ":" + std::to_string(first.DeviceIndex);

  {
    const vr::test::ScopedEnvironment environment(vr::OpenCLDeviceEnvironmentVariable, "no-such-opencl-device");
    auto                              filter = OpenCLFilter::New();
    filter->SetDepthInput(depth);
    try
    {
      filter->Update();
      FAIL() << "VR_OPENCL_DEVICE naming no device was accepted";
    }
    catch (const itk::ExceptionObject & error)
    {
      EXPECT_NE(std::string(error.GetDescription()).find("VR_OPENCL_DEVICE"), std::string::npos)
        << error.GetDescription();
    }

    filter->SetDeviceRequest(byIndex); // the parameter wins over the environment
    EXPECT_NO_THROW(filter->Update());
    EXPECT_EQ(filter->GetDeviceLabel(), first.Label());
  }
  {
    const vr::test::ScopedEnvironment environment(vr::OpenCLDeviceEnvironmentVariable, byIndex.c_str());
    auto                              filter = OpenCLFilter::New();
    filter->SetDepthInput(depth);
    EXPECT_NO_THROW(filter->Update());
    EXPECT_EQ(filter->GetDeviceLabel(), first.Label());
  }
}

TEST(OpenCLBilateralDepthRelax, ReusedFilterFollowsNewParametersAndSizes)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  auto filter = OpenCLFilter::New();
  for (const auto & [width, height, anisotropy] : { std::make_tuple(31u, 17u, 0.5),
                                                    std::make_tuple(31u, 17u, 0.0),
                                                    std::make_tuple(64u, 5u, 1.0),
                                                    std::make_tuple(31u, 17u, 0.5) })
  {
    const auto       depth = vr::test::MakeRandomDepthImage(width, height, 0.0f, 4.0f, width + height);
    const auto       mask = vr::test::MakeRandomMaskImage(width, height, 0.1, width * height);
    const Parameters parameters{ 1.0, anisotropy, 40 };
    filter->SetDepthInput(depth);
    filter->SetFixedMask(mask);
    filter->SetAnisotropy(anisotropy);
    filter->SetRelaxation(1.0);
    filter->SetNumberOfIterations(40);
    filter->Update();
    EXPECT_LE(MaxAbsoluteDifference(filter->GetOutput(), RelaxOnCPU(depth, mask, parameters)), Tolerance);
  }
}

TEST(OpenCLBilateralDepthRelax, PrintSelfNamesTheDeviceAndEveryParameter)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  auto filter = OpenCLFilter::New();
  filter->SetDeviceRequest(std::string());
  filter->PrepareDevice();
  std::ostringstream text;
  filter->Print(text);
  for (const char * expected : { "Relaxation (w)",
                                 "JumpThreshold (J, mm)",
                                 "Anisotropy (a = 1/J^2, mm^-2)",
                                 "NumberOfIterations (N)",
                                 "Solver: Jacobi",
                                 "SteadyTolerance (mm)",
                                 "DeviceRequest",
                                 "Device: ",
                                 "Kernel shape" })
  {
    EXPECT_NE(text.str().find(expected), std::string::npos) << expected;
  }
  EXPECT_NE(text.str().find(filter->GetDeviceLabel()), std::string::npos);
}

// The steady solver has no OpenCL kernel: the OpenCL filter relaxes on the CPU then, explicitly, and gives the CPU
// filter's bits. It needs no device for it.
TEST(OpenCLBilateralDepthRelax, SteadySolverRunsOnTheCPUWithTheCPUFiltersBits)
{
  const auto depth = vr::test::MakeRandomDepthImage(45, 33, 0.0f, 8.0f, 5);
  const auto mask = vr::test::MakeRandomMaskImage(45, 33, 0.05, 6);
  auto       cpu = itk::BilateralDepthRelaxFilter<vr::test::DepthImage>::New();
  auto       opencl = OpenCLFilter::New();
  for (itk::BilateralDepthRelaxFilter<vr::test::DepthImage> * filter :
       { cpu.GetPointer(), static_cast<itk::BilateralDepthRelaxFilter<vr::test::DepthImage> *>(opencl.GetPointer()) })
  {
    filter->SetDepthInput(depth);
    filter->SetFixedMask(mask);
    filter->SetSolver(itk::BilateralDepthRelaxSolver::Steady);
    filter->Update();
  }
  EXPECT_EQ(vr::test::PixelsOf(opencl->GetOutput()), vr::test::PixelsOf(cpu->GetOutput()));
  EXPECT_GT(opencl->GetSteadyReport().OuterIterations, 0u);
  EXPECT_EQ(opencl->GetDeviceLabel(), "") << "the steady solve must not have touched an OpenCL device";
}
} // namespace
