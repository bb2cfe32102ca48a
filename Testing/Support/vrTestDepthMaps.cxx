// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrTestDepthMaps.h"

#include "vrTestImages.h"

#include "itkCPRDepthImageFilter.h"
#include "itkCTAPhantom.h"

#include <random>

namespace vr::test
{
DepthMapBuffers
RandomDepthMapBuffers(std::size_t width, std::size_t height, float range, double fixedFraction, unsigned int seed)
{
  std::mt19937                          generator(seed);
  std::uniform_real_distribution<float> depth(0.0f, range);
  std::bernoulli_distribution           fixed(fixedFraction);
  DepthMapBuffers                       map{ {}, {}, width, height };
  for (std::size_t k = 0; k < width * height; ++k)
  {
    map.Depth.push_back(depth(generator));
    map.Fixed.push_back(fixed(generator) ? 1 : 0);
  }
  return map;
}

DepthMapBuffers
RunoffDepthMapBuffers(unsigned int width, unsigned int height)
{
  const auto map = MakePhantomDepthMap(width, height);
  return { PixelsOf(map.Depth.GetPointer()), PixelsOf(map.Fixed.GetPointer()), width, height };
}

DepthMapBuffers
ThoraxDepthMapBuffers(unsigned int width, unsigned int height)
{
  const auto phantom = itk::MakeCTAPhantom(itk::CTAPhantomKind::Thorax);
  auto       filter = itk::CPRDepthImageFilter<itk::Image<float, 2>>::New();
  filter->SetCenterlineTree(phantom.Tree);
  itk::CPRViewSpecification view;
  view.AngleInDegrees = phantom.DesignAngleInDegrees;
  view.ImageSize = { { width, height } };
  filter->SetViewSpecification(view);
  filter->Update();
  return { PixelsOf(filter->GetDepthOutput()), PixelsOf(filter->GetFixedMaskOutput()), width, height };
}
} // namespace vr::test
