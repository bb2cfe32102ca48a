// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrBenchmarkScene.h"

#include "itkCTAPhantom.h"
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
ThoraxDepthMap(unsigned int width, unsigned int height)
{
  static std::map<std::pair<unsigned int, unsigned int>, DepthMap> maps;
  auto &                                                           map = maps[{ width, height }];
  if (!map.Depth)
  {
    const auto phantom = itk::MakeCTAPhantom(itk::CTAPhantomKind::Thorax);
    map = vr::test::MakeScanlineDepthMap(phantom.Tree, PaperView(width, height, phantom.DesignAngleInDegrees));
  }
  return map;
}

const DepthMap &
PhantomScene::GetDepthMap(unsigned int width, unsigned int height)
{
  auto & map = m_DepthMaps[{ width, height }];
  if (!map.Depth)
  {
    map = vr::test::MakeScanlineDepthMap(m_Tree, PaperView(width, height));
  }
  return map;
}
} // namespace vr::benchmarks
