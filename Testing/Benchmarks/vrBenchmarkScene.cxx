// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrBenchmarkScene.h"

#include "itkCPRDepthImageFilter.h"
#include "itkRunoffPhantomImageSource.h"

namespace vr::benchmarks
{
itk::CPRViewSpecification
PaperView(unsigned int width, unsigned int height, double angle)
{
  itk::CPRViewSpecification view;
  view.AngleInDegrees = angle;
  view.ImageSize[0] = width;
  view.ImageSize[1] = height;
  return view;
}

PhantomScene &
PhantomScene::Instance()
{
  static PhantomScene scene;
  return scene;
}

PhantomScene::PhantomScene()
  : m_Tree(itk::RunoffPhantomImageSource::New()->GetCenterlineTree())
{
}

const VolumeImage *
PhantomScene::GetVolume()
{
  if (!m_Volume)
  {
    auto phantom = itk::RunoffPhantomImageSource::New();
    phantom->Update();
    m_Volume = phantom->GetOutput();
    m_Volume->DisconnectPipeline();
  }
  return m_Volume;
}

const DepthMap &
PhantomScene::GetDepthMap(unsigned int width, unsigned int height)
{
  auto & map = m_DepthMaps[{ width, height }];
  if (!map.Depth)
  {
    auto filter = itk::CPRDepthImageFilter<DepthImage>::New();
    filter->SetCenterlineTree(m_Tree);
    filter->SetViewSpecification(PaperView(width, height));
    filter->Update();
    map.Depth = filter->GetDepthOutput();
    map.Fixed = filter->GetFixedMaskOutput();
    map.Depth->DisconnectPipeline();
    map.Fixed->DisconnectPipeline();
  }
  return map;
}
} // namespace vr::benchmarks
