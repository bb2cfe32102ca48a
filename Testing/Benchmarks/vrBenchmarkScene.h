// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrBenchmarkScene_h
#define vrBenchmarkScene_h

#include "itkCPRViewGeometry.h"
#include "itkCenterlineTree.h"
#include "itkImage.h"
#include "vrTestImages.h"

#include <map>
#include <utility>
#include <vector>

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
 * \a angle degrees and W x H pixels (the fit spacing, the tree's longest axis up), with its fixed mask, built once per
 * size and angle on first use. Throws when the data is missing. */
const DepthMap &
AortaDepthMap(unsigned int width, unsigned int height, double angle = 0.0);

/** The view of the aorta (degrees about its automatic up axis) where its two iliac arteries cross in the image, 7
 * degrees from the side view in which they lie exactly in front of each other (90, an easy map: the two iliacs' zones
 * are 20-30 mm apart and the solver keeps the jump): their scanline zones meet along rows and columns with depth
 * steps of 3-20 mm, and rows below the iliacs copy them (issue 40's second real-anatomy case; from 95 to 100 degrees
 * the steady solve is 1 to 10 times the 500 passes at 512 x 1024, docs/measurements/2026-11-28-steady-real-anatomy.md).
 */
constexpr double AortaIliacsOverlapAngle = 97.0;

/** A view of the thoracic phantom as the module makes it for a full-size study of it (512 x 512 x 1200 voxels of
 * 0.5 mm, docs/measurements/2026-11-28-steady-real-anatomy.md): the automatic up axis, the size that fits the tree at
 * \a spacing mm a pixel (0.5: the study's own). */
struct FullSizeView
{
  double       Spacing;
  unsigned int Width;
  unsigned int Height;
};
/** The full-size views at 1, 0.5 and 0.25 mm a pixel (each x 4 the pixels of the one before). */
std::vector<FullSizeView>
FullSizeViews();
/** The thoracic phantom's scanline depth map in the full-size view of W x H pixels (one of FullSizeViews()). */
const DepthMap &
FullSizeDepthMap(unsigned int width, unsigned int height);

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
