// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrBenchmarkScene.h"

#include "itkCTAPhantom.h"
#include "itkCPRDepthImageFilter.h"
#include "itkRunoffPhantomImageSource.h"
#include "vrCenterlineIO.h"
#include "vrVolumeIO.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <tuple>

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
AortaDepthMap(unsigned int width, unsigned int height, double angle)
{
  static std::map<std::tuple<unsigned int, unsigned int, double>, DepthMap> maps;
  auto &                                                                    map = maps[{ width, height, angle }];
  if (!map.Depth)
  {
    const std::filesystem::path folder = std::filesystem::path(VR_SHARED_DATA_DIR) / "vmtk-aorta-mra";
    const auto                  volume = vr::ReadVolume((folder / "aorta.mha").string());
    const auto                  tree = vr::ReadCenterlines((folder / "aorta-centerline.vtp").string());
    auto                        depth = itk::CPRDepthImageFilter<DepthImage>::New();
    depth->SetCenterlineTree(tree);
    itk::CPRViewSpecification view = PaperView(width, height, angle);
    view.AutomaticUp = true;
    depth->SetViewSpecification(view);
    depth->SetReferenceVolume(volume);
    depth->Update();
    map.Depth = depth->GetDepthOutput();
    map.Fixed = depth->GetFixedMaskOutput();
  }
  return map;
}

namespace
{
/** The geometry of a full-size study of the thoracic phantom: 512 x 512 x 1200 voxels of 0.5 mm around the tree, no
 * voxels (the depth filter reads only the geometry). */
itk::ImageBase<3>::Pointer
FullSizeGeometry(const itk::CenterlineTree & tree)
{
  auto                              geometry = itk::Image<short, 3>::New();
  const itk::Size<3>                size{ { 512, 512, 1200 } };
  itk::Image<short, 3>::SpacingType spacing;
  spacing.Fill(0.5);
  itk::Point<double, 3> low;
  itk::Point<double, 3> high;
  low.Fill(1e300);
  high.Fill(-1e300);
  for (const auto & branch : tree.GetBranches())
  {
    for (const auto & point : branch.Points)
    {
      for (unsigned int k = 0; k < 3; ++k)
      {
        low[k] = std::min(low[k], point[k]);
        high[k] = std::max(high[k], point[k]);
      }
    }
  }
  itk::Point<double, 3> origin;
  for (unsigned int k = 0; k < 3; ++k)
  {
    origin[k] = 0.5 * (low[k] + high[k]) - 0.5 * spacing[k] * (size[k] - 1);
  }
  geometry->SetRegions(size);
  geometry->SetSpacing(spacing);
  geometry->SetOrigin(origin);
  return geometry.GetPointer();
}

itk::CPRViewSpecification
FullSizeSpecification(double spacing)
{
  itk::CPRViewSpecification view;
  view.AutomaticUp = true;
  view.AngleInDegrees = itk::MakeCTAPhantom(itk::CTAPhantomKind::Thorax).DesignAngleInDegrees;
  view.PixelSpacing.Fill(spacing);
  return view;
}

const itk::CenterlineTree &
ThoraxTree()
{
  static const itk::CenterlineTree tree = itk::MakeCTAPhantom(itk::CTAPhantomKind::Thorax).Tree;
  return tree;
}
} // namespace

std::vector<FullSizeView>
FullSizeViews()
{
  std::vector<FullSizeView> views;
  const auto                geometry = FullSizeGeometry(ThoraxTree());
  for (const double spacing : { 1.0, 0.5, 0.25 })
  {
    const auto view = itk::CPRViewGeometry::Resolve(FullSizeSpecification(spacing), ThoraxTree(), geometry);
    views.push_back(
      { spacing, static_cast<unsigned int>(view.GetSize()[0]), static_cast<unsigned int>(view.GetSize()[1]) });
  }
  return views;
}

const DepthMap &
FullSizeDepthMap(unsigned int width, unsigned int height)
{
  static std::map<std::pair<unsigned int, unsigned int>, DepthMap> maps;
  auto &                                                           map = maps[{ width, height }];
  if (!map.Depth)
  {
    for (const auto & view : FullSizeViews())
    {
      if (view.Width == width && view.Height == height)
      {
        auto depth = itk::CPRDepthImageFilter<DepthImage>::New();
        depth->SetCenterlineTree(ThoraxTree());
        depth->SetViewSpecification(FullSizeSpecification(view.Spacing));
        depth->SetReferenceVolume(FullSizeGeometry(ThoraxTree()));
        depth->Update();
        map.Depth = depth->GetDepthOutput();
        map.Fixed = depth->GetFixedMaskOutput();
      }
    }
    if (!map.Depth)
    {
      throw std::invalid_argument("no full-size view of " + std::to_string(width) + " x " + std::to_string(height) +
                                  " pixels");
    }
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
