// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// An ITK pipeline of someone else's: phantom -> CPR depth -> bilateral relax (from the logic's backend factory) ->
// resample, connected output to input and updated once at the end. Exits 0 when every pixel is finite and the
// centerline pixels show the phantom's contrast-filled lumen (their median; a pixel centre of a thin tibial artery
// may lie just outside its lumen).

#include "itkCPRDepthImageFilter.h"
#include "itkCPRResampleImageFilter.h"
#include "itkRunoffPhantomImageSource.h"
#include "vrRelaxBackend.h"

#include <algorithm>
#include <cmath>
#include <vector>
#include <iostream>

int
main()
{
  auto phantom = itk::RunoffPhantomImageSource::New();
  phantom->SetScale(0.5);
  phantom->SetSpacing(1.5);
  phantom->SetNoiseStandardDeviation(0.0);
  phantom->UpdateOutputInformation();

  using DepthFilter = itk::CPRDepthImageFilter<itk::Image<float, 2>>;
  auto depth = DepthFilter::New();
  depth->SetCenterlineTree(phantom->GetCenterlineTree());
  depth->SetReferenceVolume(phantom->GetOutput());
  depth->SetFixLumen(false);

  std::string notice;
  auto        relax = vr::CreateRelaxFilter(vr::RelaxBackend::CPU, "", notice);
  relax->SetInput(depth->GetOutput());
  relax->SetFixedMask(depth->GetFixedMaskOutput());
  relax->SetNumberOfIterations(50);

  using ResampleFilter = itk::CPRResampleImageFilter<itk::Image<float, 3>, itk::Image<float, 2>>;
  auto resample = ResampleFilter::New();
  resample->SetVolume(phantom->GetOutput());
  resample->SetDepth(relax->GetOutput());
  resample->Update();

  const auto *       cpr = resample->GetOutput();
  const auto *       mask = depth->GetFixedMaskOutput();
  const auto         count = cpr->GetBufferedRegion().GetNumberOfPixels();
  std::vector<float> centerline;
  for (std::size_t k = 0; k < count; ++k)
  {
    if (!std::isfinite(cpr->GetBufferPointer()[k]))
    {
      std::cerr << "pixel " << k << " is not finite" << std::endl;
      return 1;
    }
    if (mask->GetBufferPointer()[k])
    {
      centerline.push_back(cpr->GetBufferPointer()[k]);
    }
  }
  if (centerline.size() < 50)
  {
    std::cerr << "only " << centerline.size() << " centerline pixels" << std::endl;
    return 1;
  }
  std::nth_element(centerline.begin(), centerline.begin() + centerline.size() / 2, centerline.end());
  const float median = centerline[centerline.size() / 2];
  std::cout << "CPR " << cpr->GetBufferedRegion().GetSize() << ", " << centerline.size()
            << " centerline pixels, median " << median << " HU" << std::endl;
  // The phantom's lumen is 300-400 HU; muscle and fat around the vessels are below 100 HU.
  return median > 250.0f ? 0 : 1;
}
