// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The OpenCL resampling against the CPU filter (docs/opencl.md "The whole view on the device"): within 1e-3 of the
// display window (docs/design.md's tolerance for the image) on both phantoms and the VMTK aorta, linear and nearest,
// with slabs; every stored pixel type against the CPU filter on the same volume; a rescale against the CPU on the
// rescaled values in double; the volume uploaded once per session; the relaxed depth read on the device; cubic on
// the CPU, saying why. Skipped, with the reason, without an OpenCL device.
#include "itkCPRDepthImageFilter.h"
#include "itkCPRResampleImageFilter.h"
#include "itkCTAPhantom.h"
#include "itkOpenCLBilateralDepthRelaxFilter.h"
#include "itkOpenCLCPRDepthImageFilter.h"
#include "itkOpenCLCPRResampleImageFilter.h"
#include "vrCenterlineIO.h"
#include "vrOpenCLSession.h"
#include "vrOpenCLTestSupport.h"
#include "vrTestImages.h"
#include "vrVolumeIO.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <random>
#include <type_traits>
#include <typeinfo>
#include <string>

namespace
{
using DepthImage = itk::Image<float, 2>;
using FloatVolume = itk::Image<float, 3>;
using DepthFilter = itk::CPRDepthImageFilter<DepthImage>;

/** A volume with its centerlines and the window it is read with (W, in its intensity unit). */
struct Study
{
  std::string          Name;
  FloatVolume::Pointer Volume;
  itk::CenterlineTree  Tree;
  double               Window;
  double               Angle;
  bool                 AutomaticUp;
};

const Study &
PhantomStudy(itk::CTAPhantomKind kind)
{
  static std::map<itk::CTAPhantomKind, Study> studies;
  auto                                        found = studies.find(kind);
  if (found == studies.end())
  {
    auto phantom = itk::MakeCTAPhantom(kind, 2.0);
    phantom.Source->Update();
    FloatVolume::Pointer volume = phantom.Source->GetOutput();
    volume->DisconnectPipeline();
    found =
      studies.emplace(kind, Study{ phantom.Name, volume, phantom.Tree, 900.0, phantom.DesignAngleInDegrees, false })
        .first;
  }
  return found->second;
}

const Study &
AortaStudy()
{
  static const Study study = []
  {
    const std::filesystem::path folder = std::filesystem::path(VR_SHARED_DATA_DIR) / "vmtk-aorta-mra";
    // MR: lumen about 1850, background about 230; the window spans them.
    return Study{ "VMTK aorta",
                  vr::ReadVolume((folder / "aorta.mha").string()),
                  vr::ReadCenterlines((folder / "aorta-centerline.vtp").string()),
                  1800.0,
                  90.0,
                  true };
  }();
  return study;
}

/** The scanline depth map of \a study at W x H. */
DepthImage::Pointer
DepthMapOf(const Study & study, unsigned int width, unsigned int height)
{
  auto depth = DepthFilter::New();
  depth->SetCenterlineTree(study.Tree);
  depth->SetReferenceVolume(study.Volume);
  itk::CPRViewSpecification view;
  view.ImageSize[0] = width;
  view.ImageSize[1] = height;
  view.AngleInDegrees = study.Angle;
  view.AutomaticUp = study.AutomaticUp;
  depth->SetViewSpecification(view);
  depth->Update();
  DepthImage::Pointer map = depth->GetDepthOutput();
  map->DisconnectPipeline();
  return map;
}

template<typename TFilter, typename TVolume>
DepthImage::Pointer
Sample(TFilter *                 filter,
       const TVolume *           volume,
       const DepthImage *        depth,
       itk::CPRInterpolationMode interpolation,
       double                    slab = 0.0,
       itk::CPRSlabMode          slabMode = itk::CPRSlabMode::MIP)
{
  filter->SetVolume(volume);
  filter->SetDepth(depth);
  filter->SetInterpolation(interpolation);
  filter->SetSlabThickness(slab);
  filter->SetSlabMode(slabMode);
  filter->Update();
  DepthImage::Pointer image = filter->GetOutput();
  image->DisconnectPipeline();
  return image;
}

template<typename TVolume>
DepthImage::Pointer
SampleOnCPU(const TVolume *           volume,
            const DepthImage *        depth,
            itk::CPRInterpolationMode interpolation,
            double                    slab = 0.0,
            itk::CPRSlabMode          slabMode = itk::CPRSlabMode::MIP)
{
  auto filter = itk::CPRResampleImageFilter<TVolume, DepthImage, DepthImage>::New();
  return Sample(filter.GetPointer(), volume, depth, interpolation, slab, slabMode);
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

/** A W x H x D volume of \a TPixel with random values over the type's range (or [-1000, 3000] for floats). */
template<typename TPixel>
typename itk::Image<TPixel, 3>::Pointer
RandomVolume(unsigned int seed)
{
  using Volume = itk::Image<TPixel, 3>;
  auto                       volume = Volume::New();
  typename Volume::IndexType start{ { 3, -2, 5 } }; // a buffer that does not start at index 0
  typename Volume::SizeType  size{ { 37, 29, 23 } };
  volume->SetRegions(typename Volume::RegionType(start, size));
  typename Volume::SpacingType spacing;
  spacing[0] = 0.9;
  spacing[1] = 1.1;
  spacing[2] = 1.7;
  volume->SetSpacing(spacing);
  typename Volume::PointType origin;
  origin[0] = -20.0;
  origin[1] = -15.0;
  origin[2] = -40.0;
  volume->SetOrigin(origin);
  typename Volume::DirectionType direction;
  direction.SetIdentity();
  direction[0][0] = -1.0; // an LPS volume stored right to left, as many are
  volume->SetDirection(direction);
  volume->Allocate();
  std::mt19937 random(seed);
  double       low = -1000.0;
  double       high = 3000.0;
  if constexpr (std::is_integral_v<TPixel>)
  {
    low = std::numeric_limits<TPixel>::min();
    high = std::numeric_limits<TPixel>::max();
  }
  std::uniform_real_distribution<double> value(low, high);
  TPixel *                               voxels = volume->GetBufferPointer();
  for (std::size_t k = 0; k < volume->GetBufferedRegion().GetNumberOfPixels(); ++k)
  {
    voxels[k] = static_cast<TPixel>(std::floor(value(random)));
  }
  return volume;
}

/** A depth map for RandomVolume's space: an oblique view through it, part of it outside the volume. */
DepthImage::Pointer
ObliqueDepthMap(unsigned int width, unsigned int height, unsigned int seed)
{
  auto                      depth = vr::test::MakeRandomDepthImage(width, height, -25.0f, 25.0f, seed);
  itk::CPRViewSpecification specification;
  specification.ImageSize[0] = width;
  specification.ImageSize[1] = height;
  specification.PixelSpacing[0] = 0.8;
  specification.PixelSpacing[1] = 0.9;
  specification.AngleInDegrees = 33.0;
  specification.HasCenter = true;
  specification.Center = vr::test::P(-25.0, 0.0, -10.0);
  itk::CenterlineTree   tree;
  itk::CenterlineBranch branch;
  branch.Points = { vr::test::P(-30.0, 0.0, -30.0), vr::test::P(-20.0, 0.0, 10.0) };
  tree.AddBranch(branch);
  const auto view = itk::CPRViewGeometry::Resolve(specification, tree, nullptr);
  view.ConfigureImageInformation(depth.GetPointer()); // and the view in its metadata
  return depth;
}

template<typename TPixel>
void
ExpectStoredTypeMatchesCPU(unsigned int seed)
{
  using Volume = itk::Image<TPixel, 3>;
  const auto volume = RandomVolume<TPixel>(seed);
  const auto depth = ObliqueDepthMap(61, 47, seed);
  double     low = -1000.0;
  double     high = 3000.0;
  if constexpr (std::is_integral_v<TPixel>)
  {
    low = std::numeric_limits<TPixel>::min();
    high = std::numeric_limits<TPixel>::max();
  }
  for (const auto interpolation : { itk::CPRInterpolationMode::Linear, itk::CPRInterpolationMode::Nearest })
  {
    for (const double slab : { 0.0, 4.0 })
    {
      auto       filter = itk::OpenCLCPRResampleImageFilter<Volume>::New();
      const auto opencl = Sample(
        filter.GetPointer(), volume.GetPointer(), depth.GetPointer(), interpolation, slab, itk::CPRSlabMode::Mean);
      const auto cpu =
        SampleOnCPU(volume.GetPointer(), depth.GetPointer(), interpolation, slab, itk::CPRSlabMode::Mean);
      EXPECT_EQ(filter->GetHostReason(), "");
      // The same double arithmetic on the same stored values, rounded to float once: equal to a float's rounding.
      EXPECT_LE(MaxAbsoluteDifference(cpu, opencl), 1e-6 * (high - low))
        << typeid(TPixel).name() << ", " << interpolation << ", slab " << slab;
      // Not vacuous: samples inside and the outside value both occur.
      const auto pixels = vr::test::PixelsOf(cpu.GetPointer());
      const auto outside = std::count(pixels.begin(), pixels.end(), pixels.front());
      EXPECT_GT(pixels.size() - static_cast<std::size_t>(outside), pixels.size() / 4) << typeid(TPixel).name();
    }
  }
}
} // namespace

// --- Against the CPU on the studies ------------------------------------------------------------------------------

TEST(OpenCLCPRResample, LinearAndNearestMatchTheCPUWithinAThousandthOfTheWindowOnThePhantomsAndTheAorta)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  for (const Study * study :
       { &PhantomStudy(itk::CTAPhantomKind::Runoff), &PhantomStudy(itk::CTAPhantomKind::Thorax), &AortaStudy() })
  {
    const auto depth = DepthMapOf(*study, 256, 512);
    for (const auto interpolation : { itk::CPRInterpolationMode::Linear, itk::CPRInterpolationMode::Nearest })
    {
      for (const auto & slab : { std::make_pair(0.0, itk::CPRSlabMode::MIP),
                                 std::make_pair(5.0, itk::CPRSlabMode::MIP),
                                 std::make_pair(5.0, itk::CPRSlabMode::MinIP),
                                 std::make_pair(5.0, itk::CPRSlabMode::Mean) })
      {
        auto       filter = itk::OpenCLCPRResampleImageFilter<FloatVolume>::New();
        const auto opencl = Sample(
          filter.GetPointer(), study->Volume.GetPointer(), depth.GetPointer(), interpolation, slab.first, slab.second);
        const auto cpu =
          SampleOnCPU(study->Volume.GetPointer(), depth.GetPointer(), interpolation, slab.first, slab.second);
        const double difference = MaxAbsoluteDifference(cpu, opencl);
        EXPECT_EQ(filter->GetHostReason(), "");
        EXPECT_LE(difference, 1e-3 * study->Window)
          << study->Name << ", " << interpolation << ", slab " << slab.first << " mm " << slab.second;
        std::cout << study->Name << ", " << interpolation << ", slab " << slab.first << " " << slab.second
                  << ": largest difference " << difference << std::endl;
      }
    }
  }
}

TEST(OpenCLCPRResample, EveryStoredPixelTypeMatchesTheCPUOnTheSameVolume)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  ExpectStoredTypeMatchesCPU<short>(1);
  ExpectStoredTypeMatchesCPU<unsigned short>(2);
  ExpectStoredTypeMatchesCPU<signed char>(3);
  ExpectStoredTypeMatchesCPU<unsigned char>(4);
  ExpectStoredTypeMatchesCPU<float>(5);
  ExpectStoredTypeMatchesCPU<double>(6);
}

// DICOM's rescale on the device: int16 stored values, slope 0.5 and intercept -1024, against the CPU on a double
// volume holding slope * stored + intercept (computed in double, as the device computes each voxel read): both sample
// the same doubles with the same arithmetic, so they agree to a float's rounding of the result.
TEST(OpenCLCPRResample, ARescaleOfStoredValuesMatchesTheCPUOnTheRescaledValuesInDouble)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const auto stored = RandomVolume<short>(11);
  auto       rescaled = itk::Image<double, 3>::New();
  rescaled->CopyInformation(stored);
  rescaled->SetRegions(stored->GetBufferedRegion());
  rescaled->Allocate();
  for (std::size_t k = 0; k < stored->GetBufferedRegion().GetNumberOfPixels(); ++k)
  {
    rescaled->GetBufferPointer()[k] = static_cast<double>(stored->GetBufferPointer()[k]) * 0.5 + -1024.0;
  }
  const auto depth = ObliqueDepthMap(50, 40, 12);
  for (const auto interpolation : { itk::CPRInterpolationMode::Linear, itk::CPRInterpolationMode::Nearest })
  {
    auto filter = itk::OpenCLCPRResampleImageFilter<itk::Image<short, 3>>::New();
    filter->SetIntensityRescale(itk::CPRIntensityRescale{ 0.5, -1024.0 });
    const auto opencl = Sample(filter.GetPointer(), stored.GetPointer(), depth.GetPointer(), interpolation);
    const auto cpu = SampleOnCPU(rescaled.GetPointer(), depth.GetPointer(), interpolation);
    EXPECT_LE(MaxAbsoluteDifference(cpu, opencl), 1e-6 * 32768.0) << interpolation;
  }
}

// --- The view on the device ---------------------------------------------------------------------------------------

// Two resampling filters of one session (the unfiltered and the relaxed CPR) over five views: one upload of the
// volume in all; the relaxed depth read where the relaxation left it.
TEST(OpenCLCPRResample, TheVolumeIsUploadedOncePerSessionAndTheRelaxedDepthIsReadOnTheDevice)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const Study & study = PhantomStudy(itk::CTAPhantomKind::Runoff);
  const auto    session = vr::OpenCLSession::Create("", "test");
  auto          depth = itk::OpenCLCPRDepthImageFilter::New();
  depth->SetSession(session);
  depth->SetCenterlineTree(study.Tree);
  depth->SetReferenceVolume(study.Volume);
  auto relax = itk::OpenCLBilateralDepthRelaxFilter::New();
  relax->SetSession(session);
  relax->SetInput(depth->GetDepthOutput());
  relax->SetFixedMask(depth->GetFixedMaskOutput());
  relax->SetNumberOfIterations(100);
  auto unfiltered = itk::OpenCLCPRResampleImageFilter<FloatVolume>::New();
  auto relaxed = itk::OpenCLCPRResampleImageFilter<FloatVolume>::New();
  for (auto * filter : { unfiltered.GetPointer(), relaxed.GetPointer() })
  {
    filter->SetSession(session);
    filter->SetVolume(study.Volume);
  }
  unfiltered->SetDepth(depth->GetDepthOutput());
  relaxed->SetDepth(relax->GetOutput());
  for (int step = 0; step < 5; ++step)
  {
    itk::CPRViewSpecification view;
    view.ImageSize[0] = 128;
    view.ImageSize[1] = 256;
    view.AngleInDegrees = 30.0 + step;
    depth->SetViewSpecification(view);
    unfiltered->Update();
    relaxed->Update();
    EXPECT_TRUE(unfiltered->GetDepthWasOnDevice());
    EXPECT_TRUE(relaxed->GetDepthWasOnDevice());
    EXPECT_TRUE(relax->GetInputsWereOnDevice());
    const auto cpu = SampleOnCPU(study.Volume.GetPointer(), relax->GetOutput(), itk::CPRInterpolationMode::Linear);
    EXPECT_LE(MaxAbsoluteDifference(cpu, relaxed->GetOutput()), 1e-3 * study.Window) << "step " << step;
  }
  EXPECT_EQ(session->GetVolumeUploads(), 1u);
  EXPECT_EQ(session->GetVolumeBytes(), study.Volume->GetBufferedRegion().GetNumberOfPixels() * sizeof(float));

  // Another volume replaces it (one more upload), and the filters sample the new one.
  auto other = FloatVolume::New();
  other->CopyInformation(study.Volume);
  other->SetRegions(study.Volume->GetBufferedRegion());
  other->Allocate();
  other->FillBuffer(123.0f);
  relaxed->SetVolume(other);
  relaxed->Update();
  EXPECT_EQ(session->GetVolumeUploads(), 2u);
  const auto pixels = vr::test::PixelsOf(relaxed->GetOutput());
  EXPECT_GT(std::count(pixels.begin(), pixels.end(), 123.0f), static_cast<long>(pixels.size() / 2));
}

TEST(OpenCLCPRResample, CubicInterpolationIsSampledOnTheCPUAndSaysWhy)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const Study & study = PhantomStudy(itk::CTAPhantomKind::Thorax);
  const auto    depth = DepthMapOf(study, 64, 128);
  auto          filter = itk::OpenCLCPRResampleImageFilter<FloatVolume>::New();
  const auto    opencl =
    Sample(filter.GetPointer(), study.Volume.GetPointer(), depth.GetPointer(), itk::CPRInterpolationMode::Cubic);
  const auto cpu = SampleOnCPU(study.Volume.GetPointer(), depth.GetPointer(), itk::CPRInterpolationMode::Cubic);
  EXPECT_NE(filter->GetHostReason().find("cubic interpolation has no OpenCL kernel"), std::string::npos)
    << filter->GetHostReason();
  EXPECT_EQ(vr::test::PixelsOf(opencl.GetPointer()), vr::test::PixelsOf(cpu.GetPointer()));

  // With a rescale the CPU that samples instead applies it too: twice the values, less one (within a float's rounding).
  filter->SetIntensityRescale(itk::CPRIntensityRescale{ 2.0, -1.0 });
  filter->Update();
  const DepthImage * rescaled = filter->GetOutput();
  double             largest = 0.0;
  for (std::size_t k = 0; k < rescaled->GetBufferedRegion().GetNumberOfPixels(); ++k)
  {
    const double expected = 2.0 * cpu->GetBufferPointer()[k] - 1.0;
    largest = std::max(largest, std::abs(rescaled->GetBufferPointer()[k] - expected) / std::max(1.0, std::abs(expected)));
  }
  EXPECT_LE(largest, 1e-6);
}

// A consumer that asks for part of the image gets that part, sampled as the CPU samples it.
TEST(OpenCLCPRResample, ARequestedPartOfTheImageIsThatPartOfTheCPUsImage)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const Study & study = PhantomStudy(itk::CTAPhantomKind::Runoff);
  const auto    depth = DepthMapOf(study, 100, 200);
  const auto    whole = SampleOnCPU(study.Volume.GetPointer(), depth.GetPointer(), itk::CPRInterpolationMode::Linear);
  auto          filter = itk::OpenCLCPRResampleImageFilter<FloatVolume>::New();
  filter->SetVolume(study.Volume);
  filter->SetDepth(depth);
  filter->UpdateOutputInformation();
  const DepthImage::RegionType part({ { 17, 40 } }, { { 50, 33 } });
  filter->GetOutput()->SetRequestedRegion(part);
  filter->Update();
  const DepthImage * output = filter->GetOutput();
  ASSERT_EQ(output->GetBufferedRegion(), part);
  for (unsigned int y = 0; y < 33; ++y)
  {
    for (unsigned int x = 0; x < 50; ++x)
    {
      const DepthImage::IndexType index{ { 17 + x, 40 + y } };
      EXPECT_NEAR(output->GetPixel(index), whole->GetPixel(index), 1e-3 * study.Window) << x << ", " << y;
    }
  }
}

TEST(OpenCLCPRResample, ANonFiniteRescaleIsRejectedNamingIt)
{
  const Study & study = PhantomStudy(itk::CTAPhantomKind::Runoff);
  auto          filter = itk::OpenCLCPRResampleImageFilter<FloatVolume>::New();
  filter->SetVolume(study.Volume);
  filter->SetDepth(DepthMapOf(study, 16, 16));
  filter->SetIntensityRescale(itk::CPRIntensityRescale{ std::numeric_limits<double>::quiet_NaN(), 0.0 });
  try
  {
    filter->Update();
    FAIL() << "a NaN slope was accepted";
  }
  catch (const itk::ExceptionObject & error)
  {
    EXPECT_NE(std::string(error.GetDescription()).find("both must be finite"), std::string::npos)
      << error.GetDescription();
  }
}
