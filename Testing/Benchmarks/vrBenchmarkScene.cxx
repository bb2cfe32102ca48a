// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrBenchmarkScene.h"

#include "itkCTAPhantom.h"
#include "itkCPRDepthImageFilter.h"
#include "itkRunoffPhantomImageSource.h"
#include "vrCenterlineIO.h"
#include "vrVolumeIO.h"

#include <filesystem>

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
AortaDepthMap(unsigned int width, unsigned int height)
{
  static std::map<std::pair<unsigned int, unsigned int>, DepthMap> maps;
  auto &                                                           map = maps[{ width, height }];
  if (!map.Depth)
  {
    const std::filesystem::path folder = std::filesystem::path(VR_SHARED_DATA_DIR) / "vmtk-aorta-mra";
    const auto                  volume = vr::ReadVolume((folder / "aorta.mha").string());
    const auto                  tree = vr::ReadCenterlines((folder / "aorta-centerline.vtp").string());
    auto                        depth = itk::CPRDepthImageFilter<DepthImage>::New();
    depth->SetCenterlineTree(tree);
    itk::CPRViewSpecification view = PaperView(width, height, 0.0);
    view.AutomaticUp = true;
    depth->SetViewSpecification(view);
    depth->SetReferenceVolume(volume);
    depth->Update();
    map.Depth = depth->GetDepthOutput();
    map.Fixed = depth->GetFixedMaskOutput();
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
