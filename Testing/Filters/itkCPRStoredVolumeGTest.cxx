// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The reformation filters read a volume in its stored pixel type (docs/design.md "Volumes in their stored type"):
// through itk::ImageBase<3> any of the stored types, with an intensity rescale applied to each value read. These tests
// compare, bit for bit where the arithmetic is the same, with the filters on a float or double copy of the values,
// and with ITK's own interpolators on a double volume of the rescaled values.
#include "itkCPRVectorHelpers.h"
#include "vrTestImages.h"

#include "itkBSplineInterpolateImageFunction.h"
#include "itkCPRResampleImageFilter.h"
#include "itkCrossSectionStackImageFilter.h"
#include "itkLinearInterpolateImageFunction.h"
#include "itkNearestNeighborInterpolateImageFunction.h"
#include "itkStraightenedCPRImageFilter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <type_traits>

namespace
{
using vr::test::DepthImage;
using StoredResample = itk::CPRResampleImageFilter<itk::ImageBase<3>, DepthImage>;
template<typename TPixel>
using Volume = itk::Image<TPixel, 3>;

/** A random volume of TPixel with unequal spacing, an oblique direction and a buffered region that does not start at
 * index 0 (every term of the index arithmetic matters), values in [low, high] (whole numbers for integer types). */
template<typename TPixel>
typename Volume<TPixel>::Pointer
MakeObliqueVolume(double low, double high, unsigned int seed)
{
  auto                                volume = Volume<TPixel>::New();
  typename Volume<TPixel>::RegionType region;
  region.SetIndex({ { 2, -3, 1 } });
  region.SetSize({ { 23, 17, 11 } });
  volume->SetRegions(region);
  volume->SetSpacing(itk::detail::MakeVector3(0.7, 1.1, 1.3));
  typename Volume<TPixel>::PointType origin;
  origin[0] = -4.0;
  origin[1] = 3.0;
  origin[2] = 2.5;
  volume->SetOrigin(origin);
  typename Volume<TPixel>::DirectionType direction;
  direction.SetIdentity();
  direction(0, 0) = std::cos(0.4);
  direction(0, 1) = -std::sin(0.4);
  direction(1, 0) = std::sin(0.4);
  direction(1, 1) = std::cos(0.4);
  volume->SetDirection(direction);
  volume->Allocate();
  std::mt19937                           generator(seed);
  std::uniform_real_distribution<double> values(low, high);
  std::generate_n(volume->GetBufferPointer(),
                  region.GetNumberOfPixels(),
                  [&]
                  {
                    const double value = values(generator);
                    return static_cast<TPixel>(std::is_integral_v<TPixel> ? std::round(value) : value);
                  });
  return volume;
}

/** \a volume's values as TTarget, through \a rescale (slope x stored + intercept, in double). */
template<typename TTarget, typename TPixel>
typename Volume<TTarget>::Pointer
Converted(const Volume<TPixel> * volume, const itk::CPRIntensityRescale & rescale = {})
{
  auto copy = Volume<TTarget>::New();
  copy->CopyInformation(volume);
  copy->SetRegions(volume->GetBufferedRegion());
  copy->Allocate();
  const std::size_t count = volume->GetBufferedRegion().GetNumberOfPixels();
  for (std::size_t k = 0; k < count; ++k)
  {
    copy->GetBufferPointer()[k] =
      static_cast<TTarget>(rescale.Slope * static_cast<double>(volume->GetBufferPointer()[k]) + rescale.Intercept);
  }
  return copy;
}

/** A view larger than the volume (pixels outside, on the half-voxel borders and inside) with a random depth map. */
struct Scene
{
  itk::CPRViewGeometry View;
  DepthImage::Pointer  Depth;
};

Scene
MakeScene(const itk::ImageBase<3> * volume)
{
  itk::ContinuousIndex<double, 3> index;
  index[0] = 13.0;
  index[1] = 5.0;
  index[2] = 6.0;
  itk::Point<double, 3> centre;
  volume->TransformContinuousIndexToPhysicalPoint(index, centre);
  Scene scene{
    itk::CPRViewGeometry(
      itk::detail::MakeVector3(0.1, 0.2, 1.0), 33.0, centre, { { 27, 23 } }, itk::detail::MakeVector2(0.9, 0.8)),
    vr::test::MakeRandomDepthImage(27, 23, -4.0f, 4.0f, 3)
  };
  scene.View.ConfigureImage(scene.Depth.GetPointer());
  return scene;
}

struct Sampling
{
  itk::CPRInterpolationMode Interpolation;
  double                    SlabThickness;
  itk::CPRSlabMode          SlabMode;
};

const Sampling Samplings[] = { { itk::CPRInterpolationMode::Linear, 0.0, itk::CPRSlabMode::MIP },
                               { itk::CPRInterpolationMode::Linear, 3.0, itk::CPRSlabMode::Mean },
                               { itk::CPRInterpolationMode::Nearest, 0.0, itk::CPRSlabMode::MIP },
                               { itk::CPRInterpolationMode::Nearest, 2.0, itk::CPRSlabMode::MinIP },
                               { itk::CPRInterpolationMode::Cubic, 0.0, itk::CPRSlabMode::MIP },
                               { itk::CPRInterpolationMode::Cubic, 3.0, itk::CPRSlabMode::MIP } };

std::string
Describe(const Sampling & sampling)
{
  std::ostringstream text;
  text << sampling.Interpolation << ", slab " << sampling.SlabThickness << " mm " << sampling.SlabMode;
  return text.str();
}

/** The CPR of \a volume (any image type the filter takes) on \a scene. */
template<typename TVolume>
std::vector<float>
CPR(const TVolume *                  volume,
    const Scene &                    scene,
    const Sampling &                 sampling,
    const itk::CPRIntensityRescale & rescale = {})
{
  auto filter = itk::CPRResampleImageFilter<TVolume, DepthImage>::New();
  filter->SetVolume(volume);
  filter->SetDepth(scene.Depth);
  filter->SetInterpolation(sampling.Interpolation);
  filter->SetSlabThickness(sampling.SlabThickness);
  filter->SetSlabMode(sampling.SlabMode);
  filter->SetIntensityRescale(rescale);
  filter->Update();
  return vr::test::PixelsOf(filter->GetOutput());
}

bool
SameBits(const std::vector<float> & a, const std::vector<float> & b)
{
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

/** Every integer stored type sampled as itself equals the float filter on its values (exact in float), bit for bit:
 * the filters read the stored type without converting the volume, and nothing else changes. */
template<typename TPixel>
void
ExpectStoredTypeSamplesAsFloat(double low, double high)
{
  const auto volume = MakeObliqueVolume<TPixel>(low, high, 11);
  const auto asFloat = Converted<float>(volume.GetPointer());
  const auto scene = MakeScene(volume);
  for (const Sampling & sampling : Samplings)
  {
    SCOPED_TRACE(Describe(sampling));
    const auto stored = CPR<itk::ImageBase<3>>(volume, scene, sampling);
    EXPECT_TRUE(SameBits(stored, CPR(asFloat.GetPointer(), scene, sampling)));
    EXPECT_TRUE(SameBits(stored, CPR(volume.GetPointer(), scene, sampling))) << "the typed filter of the stored type";
  }
}
} // namespace

TEST(CPRStoredVolume, IntegerVolumesSampleAsTheirFloatValuesBitForBit)
{
  {
    SCOPED_TRACE("int16");
    ExpectStoredTypeSamplesAsFloat<short>(-1024.0, 3071.0);
  }
  {
    SCOPED_TRACE("uint16");
    ExpectStoredTypeSamplesAsFloat<unsigned short>(0.0, 65535.0);
  }
  {
    SCOPED_TRACE("int8");
    ExpectStoredTypeSamplesAsFloat<signed char>(-128.0, 127.0);
  }
  {
    SCOPED_TRACE("uint8");
    ExpectStoredTypeSamplesAsFloat<unsigned char>(0.0, 255.0);
  }
}

TEST(CPRStoredVolume, FloatAndDoubleVolumesSampleAsTheTypedFilter)
{
  const auto floats = MakeObliqueVolume<float>(-1000.0, 2000.0, 5);
  const auto doubles = MakeObliqueVolume<double>(-1000.0, 2000.0, 6);
  const auto scene = MakeScene(floats);
  for (const Sampling & sampling : Samplings)
  {
    SCOPED_TRACE(Describe(sampling));
    EXPECT_TRUE(SameBits(CPR<itk::ImageBase<3>>(floats, scene, sampling), CPR(floats.GetPointer(), scene, sampling)));
    EXPECT_TRUE(SameBits(CPR<itk::ImageBase<3>>(doubles, scene, sampling), CPR(doubles.GetPointer(), scene, sampling)));
  }
}

// A CT of 16-bit integers with DICOM's rescale against the same CT rescaled to double first (the reference a float
// copy of the volume used to stand for). Linear and nearest sampling: tolerance 0, because the filter rescales each
// voxel it reads with the same double arithmetic (slope x stored + intercept) before interpolating exactly as on the
// double volume. Cubic: ITK keeps B-spline coefficients as float, computed here from the stored values and rescaled
// after sampling, there from the rescaled values; the two roundings of a coefficient differ by at most a float epsilon
// (2^-23) of its size, about |slope| x |stored| + |intercept| (4 700 HU here), so the samples agree within 2^-23 x
// 4 700 x 8 (the spline sums 64 weighted coefficients whose weights add up to 1, with little cancellation on smooth
// data; 8 is a bound the random data here respects), 4.5e-3 HU.
TEST(CPRStoredVolume, RescaledInt16EqualsTheRescaledValuesSampledInDouble)
{
  const auto volume = MakeObliqueVolume<short>(0.0, 4095.0, 23);
  const auto scene = MakeScene(volume);
  for (const itk::CPRIntensityRescale rescale :
       { itk::CPRIntensityRescale{ 1.0, -1024.0 }, itk::CPRIntensityRescale{ 0.3125, -1024.5 } })
  {
    SCOPED_TRACE("rescale " + std::to_string(rescale.Slope) + ", " + std::to_string(rescale.Intercept));
    const auto rescaled = Converted<double>(volume.GetPointer(), rescale);
    for (const Sampling & sampling : Samplings)
    {
      SCOPED_TRACE(Describe(sampling));
      const auto stored = CPR<itk::ImageBase<3>>(volume, scene, sampling, rescale);
      const auto reference = CPR(rescaled.GetPointer(), scene, sampling);
      if (sampling.Interpolation != itk::CPRInterpolationMode::Cubic)
      {
        EXPECT_TRUE(SameBits(stored, reference));
        continue;
      }
      double largest = 0.0;
      for (std::size_t k = 0; k < stored.size(); ++k)
      {
        largest = std::max(largest, std::abs(static_cast<double>(stored[k]) - reference[k]));
      }
      std::cout << "cubic, largest difference " << largest << " HU\n";
      EXPECT_LE(largest, 4.5e-3);
    }
  }
}

// The same against ITK's own interpolators on the double volume of rescaled values, sample by sample: independent of
// the filters' fast path.
TEST(CPRStoredVolume, RescaledSamplesEqualITKInterpolatorsOnTheRescaledVolume)
{
  const auto                     volume = MakeObliqueVolume<short>(0.0, 4095.0, 29);
  const itk::CPRIntensityRescale rescale{ 0.3125, -1024.5 };
  const auto                     rescaled = Converted<double>(volume.GetPointer(), rescale);
  for (const auto mode : { itk::CPRInterpolationMode::Linear, itk::CPRInterpolationMode::Nearest })
  {
    SCOPED_TRACE(mode == itk::CPRInterpolationMode::Linear ? "linear" : "nearest");
    itk::CPRVolumeSampler<itk::ImageBase<3>> sampler;
    sampler.Prepare(volume, mode, rescale);
    itk::InterpolateImageFunction<Volume<double>, double>::Pointer reference;
    if (mode == itk::CPRInterpolationMode::Linear)
    {
      reference = itk::LinearInterpolateImageFunction<Volume<double>, double>::New();
    }
    else
    {
      reference = itk::NearestNeighborInterpolateImageFunction<Volume<double>, double>::New();
    }
    reference->SetInputImage(rescaled);
    std::mt19937                           generator(4);
    std::uniform_real_distribution<double> i(1.0, 26.0);
    std::uniform_real_distribution<double> j(-4.0, 15.0);
    std::uniform_real_distribution<double> k(0.0, 13.0);
    int                                    inside = 0;
    for (int n = 0; n < 20000; ++n)
    {
      itk::ContinuousIndex<double, 3> index;
      index[0] = i(generator);
      index[1] = j(generator);
      index[2] = k(generator);
      ASSERT_EQ(sampler.IsInside(index), reference->IsInsideBuffer(index));
      if (reference->IsInsideBuffer(index))
      {
        ++inside;
        ASSERT_EQ(sampler.Evaluate(index), reference->EvaluateAtContinuousIndex(index)) << index;
      }
    }
    EXPECT_GT(inside, 10000);
  }
}

// Outside the volume: its smallest intensity, through the rescale (for a negative slope, the largest stored value).
TEST(CPRStoredVolume, OutsideValueIsTheSmallestRescaledIntensity)
{
  const auto volume = MakeObliqueVolume<unsigned short>(100.0, 3000.0, 31);
  const auto first = volume->GetBufferPointer();
  const auto last = first + volume->GetBufferedRegion().GetNumberOfPixels();
  const auto lowest = static_cast<double>(*std::min_element(first, last));
  const auto highest = static_cast<double>(*std::max_element(first, last));
  auto       scene = MakeScene(volume);
  scene.Depth->FillBuffer(1000.0f); // every pixel far outside
  for (const itk::CPRIntensityRescale rescale :
       { itk::CPRIntensityRescale{ 2.0, -1024.0 }, itk::CPRIntensityRescale{ -0.5, 10.0 } })
  {
    const auto   cpr = CPR<itk::ImageBase<3>>(volume, scene, Samplings[0], rescale);
    const double expected = std::min(rescale.Apply(lowest), rescale.Apply(highest));
    EXPECT_EQ(cpr.front(), static_cast<float>(expected)) << rescale;
    EXPECT_EQ(cpr.back(), static_cast<float>(expected)) << rescale;
  }
}

// The one-vessel filters share the sampler: a 16-bit volume through ImageBase<3> gives the float filter's bits.
TEST(CPRStoredVolume, VesselPathFiltersSampleTheStoredType)
{
  auto                  volume = MakeObliqueVolume<short>(-1024.0, 3071.0, 37);
  const auto            asFloat = Converted<float>(volume.GetPointer());
  itk::CenterlineBranch branch;
  branch.Id = 1;
  for (int k = 0; k <= 20; ++k)
  {
    itk::ContinuousIndex<double, 3> index;
    index[0] = 4.0 + 0.8 * k;
    index[1] = -1.0 + 0.5 * k;
    index[2] = 2.0 + 0.3 * k;
    itk::Point<double, 3> point;
    volume->TransformContinuousIndexToPhysicalPoint(index, point);
    branch.Points.push_back(point);
  }
  itk::CenterlineTree tree;
  tree.AddBranch(branch);
  const itk::VesselPath path = itk::VesselPath::FromTree(tree);
  for (const Sampling & sampling : Samplings)
  {
    SCOPED_TRACE(Describe(sampling));
    auto straightened = [&](auto * input)
    {
      using InputType = std::remove_const_t<std::remove_pointer_t<decltype(input)>>;
      auto filter = itk::StraightenedCPRImageFilter<InputType>::New();
      filter->SetVolume(input);
      filter->SetPath(path);
      filter->SetWidth(12.0);
      filter->SetPixelSpacing(0.4);
      filter->SetInterpolation(sampling.Interpolation);
      filter->SetSlabThickness(sampling.SlabThickness);
      filter->SetSlabMode(sampling.SlabMode);
      filter->Update();
      return vr::test::PixelsOf(filter->GetOutput());
    };
    auto sections = [&](auto * input)
    {
      using InputType = std::remove_const_t<std::remove_pointer_t<decltype(input)>>;
      auto filter = itk::CrossSectionStackImageFilter<InputType>::New();
      filter->SetVolume(input);
      filter->SetPath(path);
      filter->SetSectionStep(1.0);
      filter->SetSectionSize({ { 15, 15 } });
      filter->SetSectionSpacing(itk::Vector<double, 2>(0.5));
      filter->SetInterpolation(sampling.Interpolation);
      filter->SetSlabThickness(sampling.SlabThickness);
      filter->SetSlabMode(sampling.SlabMode);
      filter->Update();
      return vr::test::PixelsOf(filter->GetOutput());
    };
    const itk::ImageBase<3> * stored = volume;
    EXPECT_TRUE(SameBits(straightened(stored), straightened(asFloat.GetPointer())));
    EXPECT_TRUE(SameBits(sections(stored), sections(asFloat.GetPointer())));
  }
}

TEST(CPRStoredVolume, AnotherPixelTypeOrABadRescaleIsRefusedByName)
{
  auto                           ints = itk::Image<int, 3>::New();
  itk::Image<int, 3>::RegionType region;
  region.SetSize({ { 4, 4, 4 } });
  ints->SetRegions(region);
  ints->Allocate(true);
  const auto scene = MakeScene(ints);
  auto       filter = StoredResample::New();
  filter->SetVolume(ints);
  filter->SetDepth(scene.Depth);
  try
  {
    filter->Update();
    FAIL() << "no error";
  }
  catch (const itk::ExceptionObject & error)
  {
    EXPECT_NE(std::string(error.GetDescription()).find("not a 3D image of a pixel type the reformation samples"),
              std::string::npos)
      << error.GetDescription();
  }

  const auto shorts = MakeObliqueVolume<short>(0.0, 10.0, 2);
  filter->SetVolume(shorts);
  for (const itk::CPRIntensityRescale rescale : { itk::CPRIntensityRescale{ 0.0, 1.0 },
                                                  itk::CPRIntensityRescale{ std::nan(""), 0.0 },
                                                  itk::CPRIntensityRescale{ 1.0, INFINITY } })
  {
    filter->SetIntensityRescale(rescale);
    try
    {
      filter->Update();
      FAIL() << "no error for " << rescale;
    }
    catch (const itk::ExceptionObject & error)
    {
      EXPECT_NE(std::string(error.GetDescription()).find("IntensityRescale = "), std::string::npos)
        << error.GetDescription();
    }
  }
}
