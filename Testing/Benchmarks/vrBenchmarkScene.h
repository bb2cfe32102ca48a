// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrBenchmarkScene_h
#define vrBenchmarkScene_h

#include "itkCPRViewGeometry.h"
#include "itkCenterlineTree.h"
#include "itkImage.h"
#include "vrTestImages.h"

#include <map>
#include <utility>

/** What the benchmarks reproducing the paper's Table 1 work on. */
namespace vr::benchmarks
{
using DepthImage = itk::Image<float, 2>;
using MaskImage = itk::Image<unsigned char, 2>;
using VolumeImage = itk::Image<float, 3>;

/** The run-off phantom's design angle (degrees): small seams inside each leg, a large jump between the legs. */
constexpr double DesignAngle = 30.0;

/** The view of every benchmark: the paper's image size W x H, rotated by \a angle degrees about superior, the
 * rest at its defaults (centre of the tree, spacing that fits the tree). */
itk::CPRViewSpecification
PaperView(unsigned int width, unsigned int height, double angle = DesignAngle);

/** A scanline mpCPR depth map with its fixed mask. */
using DepthMap = vr::test::PhantomDepthMap;

/** The thoracic phantom's scanline depth map at its design angle and W x H pixels (the fit spacing), with its fixed
 * mask: seams of 2-10 mm at the aortic arch, built once per size on first use. */
const DepthMap &
ThoraxDepthMap(unsigned int width, unsigned int height);

/** The VMTK aorta MRA's scanline depth map (VR_SHARED_DATA_DIR/vmtk-aorta-mra: aorta.mha, aorta-centerline.vtp) at
 * angle 0 and W x H pixels (the fit spacing, the tree's longest axis up), with its fixed mask, built once per size on
 * first use. Throws when the data is missing. */
const DepthMap &
AortaDepthMap(unsigned int width, unsigned int height);

/** The run-off phantom (RunoffPhantomImageSource at its defaults: 1.5 mm voxels, 254 x 160 x 680) and its
 * exact centerline tree, built once per process on first use, outside any timing. */
class PhantomScene
{
public:
  static PhantomScene &
  Instance();

  const itk::CenterlineTree &
  GetCenterlineTree() const
  {
    return m_Tree;
  }
  /** The CT volume, generated on the first call (a few seconds). */
  const VolumeImage *
  GetVolume();
  /** The depth map at PaperView(width, height), computed once per size. */
  const DepthMap &
  GetDepthMap(unsigned int width, unsigned int height);

private:
  PhantomScene();

  itk::CenterlineTree                                       m_Tree;
  VolumeImage::Pointer                                      m_Volume;
  std::map<std::pair<unsigned int, unsigned int>, DepthMap> m_DepthMaps;
};
} // namespace vr::benchmarks

#endif
