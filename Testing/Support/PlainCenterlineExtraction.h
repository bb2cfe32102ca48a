// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef PlainCenterlineExtraction_h
#define PlainCenterlineExtraction_h

#include "itkCenterlineTree.h"
#include "itkImage.h"

namespace vr::test
{
/** The plain reference for the centerline extraction benchmark: the same TEASAR skeleton as
 * itk::CenterlineExtractionFilter, written the straightforward way, on the whole grid.
 *
 * ITK's SignedMaurerDistanceMapImageFilter over the whole image; per-voxel arrays over the whole grid (cost, parent,
 * path length, covered, kept) indexed by buffer offset, neighbours found with bounds checks; connected components by
 * a breadth-first search over the grid; per component a geodesic sweep from the deepest voxel to a far end, a
 * Dijkstra sweep from it with the filter's cost (Dmax / D)^2 per unit length, the farthest-uncovered-voxel loop with
 * the filter's trimming, covering and spur rules, and a second trace from the widest free end. The branches are the
 * kept voxel paths split at junctions, at voxel centres, radius D; no smoothing or centring (cheap next to the
 * rest). Single-threaded but for the distance map.
 *
 * \param mask non-zero voxels are the vessels.
 * \return the tree, LPS mm. */
itk::CenterlineTree
PlainCenterlineExtraction(const itk::Image<unsigned char, 3> * mask);
} // namespace vr::test

#endif
