// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrTestImages.h"

#include "itkCPRDepthImageFilter.h"
#include "itkCPRViewGeometry.h"
#include "itkRunoffPhantomImageSource.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace vr::test
{
itk::CenterlineBranch
Branch(int id, std::vector<itk::Point<double, 3>> points, std::vector<double> radii)
{
  itk::CenterlineBranch branch;
  branch.Id = id;
  branch.Points = std::move(points);
  branch.Radii = std::move(radii);
  return branch;
}

itk::CPRViewSpecification
View(unsigned int width, unsigned int height, double sx, double sy, double angle)
{
  itk::CPRViewSpecification view;
  view.HasCenter = true;
  view.Center = P(0, 0, 0);
  view.ImageSize[0] = width;
  view.ImageSize[1] = height;
  view.PixelSpacing[0] = sx;
  view.PixelSpacing[1] = sy;
  view.AngleInDegrees = angle;
  return view;
}

namespace
{
template<typename TImage>
typename TImage::Pointer
MakeImage(unsigned int width, unsigned int height, const std::vector<typename TImage::PixelType> & values)
{
  if (values.size() != static_cast<std::size_t>(width) * height)
  {
    throw std::invalid_argument("MakeImage: value count does not match the size");
  }
  auto                        image = TImage::New();
  typename TImage::RegionType region;
  region.SetSize({ { width, height } });
  image->SetRegions(region);
  image->Allocate();
  std::copy(values.begin(), values.end(), image->GetBufferPointer());
  return image;
}
} // namespace

DepthImage::Pointer
MakeDepthImage(unsigned int width, unsigned int height, const std::vector<float> & values)
{
  return MakeImage<DepthImage>(width, height, values);
}

MaskImage::Pointer
MakeMaskImage(unsigned int width, unsigned int height, const std::vector<unsigned char> & values)
{
  return MakeImage<MaskImage>(width, height, values);
}

DepthImage::Pointer
MakeRandomDepthImage(unsigned int width, unsigned int height, float low, float high, unsigned int seed)
{
  std::mt19937                          generator(seed);
  std::uniform_real_distribution<float> distribution(low, high);
  std::vector<float>                    values(static_cast<std::size_t>(width) * height);
  for (auto & value : values)
  {
    value = distribution(generator);
  }
  return MakeDepthImage(width, height, values);
}

MaskImage::Pointer
MakeRandomMaskImage(unsigned int width, unsigned int height, double fraction, unsigned int seed)
{
  std::mt19937                generator(seed);
  std::bernoulli_distribution distribution(fraction);
  std::vector<unsigned char>  values(static_cast<std::size_t>(width) * height);
  for (auto & value : values)
  {
    value = distribution(generator) ? 1 : 0;
  }
  return MakeMaskImage(width, height, values);
}

PhantomDepthMap
MakePhantomDepthMap(unsigned int width, unsigned int height, double spacing)
{
  auto                      phantom = itk::RunoffPhantomImageSource::New();
  itk::CPRViewSpecification view;
  view.AngleInDegrees = 30.0;
  view.ImageSize = { { width, height } };
  if (spacing > 0.0)
  {
    view.PixelSpacing[0] = spacing;
    view.PixelSpacing[1] = spacing;
  }
  return MakeScanlineDepthMap(phantom->GetCenterlineTree(), view);
}

PhantomDepthMap
MakeScanlineDepthMap(const itk::CenterlineTree & tree, const itk::CPRViewSpecification & view)
{
  auto depthFilter = itk::CPRDepthImageFilter<DepthImage>::New();
  depthFilter->SetCenterlineTree(tree);
  depthFilter->SetViewSpecification(view);
  depthFilter->Update();
  PhantomDepthMap map{ depthFilter->GetDepthOutput(), depthFilter->GetFixedMaskOutput() };
  map.Depth->DisconnectPipeline();
  map.Fixed->DisconnectPipeline();
  return map;
}

std::vector<DepthStep>
FindDepthSteps(const DepthImage * depth, const MaskImage * fixed, double minimum)
{
  const auto             size = depth->GetBufferedRegion().GetSize();
  const long             width = static_cast<long>(size[0]);
  const long             height = static_cast<long>(size[1]);
  const float *          d = depth->GetBufferPointer();
  const auto *           m = fixed->GetBufferPointer();
  std::vector<DepthStep> steps;
  // Along direction (dx, dy): pair (x, y) -> (x + dx, y + dy), flanks one further out on each side.
  auto consider = [&](long x, long y, long dx, long dy)
  {
    const long qx = x + dx;
    const long qy = y + dy;
    if (qx >= width || qy >= height)
    {
      return;
    }
    const std::size_t p = static_cast<std::size_t>(y * width + x);
    const std::size_t q = static_cast<std::size_t>(qy * width + qx);
    if (m[p] || m[q])
    {
      return;
    }
    const double jump = std::abs(static_cast<double>(d[q]) - d[p]);
    if (jump < minimum)
    {
      return;
    }
    auto flank = [&](long ax, long ay, long bx, long by)
    {
      if (ax < 0 || ay < 0 || bx < 0 || by < 0 || ax >= width || bx >= width || ay >= height || by >= height)
      {
        return 0.0;
      }
      return std::abs(static_cast<double>(d[by * width + bx]) - d[ay * width + ax]);
    };
    if (flank(x - dx, y - dy, x, y) <= 0.25 * jump && flank(qx, qy, qx + dx, qy + dy) <= 0.25 * jump)
    {
      steps.push_back({ p, q, jump });
    }
  };
  for (long y = 0; y < height; ++y)
  {
    for (long x = 0; x < width; ++x)
    {
      consider(x, y, 1, 0);
      consider(x, y, 0, 1);
    }
  }
  return steps;
}

std::vector<double>
StepRatios(const std::vector<DepthStep> & steps, const DepthImage * relaxed)
{
  const float *       d = relaxed->GetBufferPointer();
  std::vector<double> ratios;
  ratios.reserve(steps.size());
  for (const auto & step : steps)
  {
    ratios.push_back(std::abs(static_cast<double>(d[step.Q]) - d[step.P]) / step.Size);
  }
  return ratios;
}

double
Median(std::vector<double> values)
{
  if (values.empty())
  {
    throw std::invalid_argument("Median of no values");
  }
  const auto middle = values.begin() + values.size() / 2;
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}
} // namespace vr::test
