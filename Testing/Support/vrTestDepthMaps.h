// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrTestDepthMaps_h
#define vrTestDepthMaps_h

#include <cstddef>
#include <vector>

/** Depth maps as the steady solver takes them, plain row-major buffers: random ones and both phantoms' scan-line
 * maps, shared by the solver's tests and the tool that checksums its results. */
namespace vr::test
{
/** A depth map (mm) and its fixed mask (non-zero = fixed), Width x Height, row-major. */
struct DepthMapBuffers
{
  std::vector<float>         Depth;
  std::vector<unsigned char> Fixed;
  std::size_t                Width;
  std::size_t                Height;
};

/** Depths uniform in [0, range), each pixel fixed with probability \a fixedFraction, from std::mt19937(\a seed): the
 * same map on every platform for the same arguments. */
DepthMapBuffers
RandomDepthMapBuffers(std::size_t width, std::size_t height, float range, double fixedFraction, unsigned int seed);

/** The run-off phantom's depth map and fixed mask (MakePhantomDepthMap) on a W x H grid. */
DepthMapBuffers
RunoffDepthMapBuffers(unsigned int width, unsigned int height);

/** The thoracic phantom's scan-line depth map and fixed mask at its design angle on a W x H grid. */
DepthMapBuffers
ThoraxDepthMapBuffers(unsigned int width, unsigned int height);
} // namespace vr::test

#endif
