// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCPRCenterlineRasterizer_h
#define itkCPRCenterlineRasterizer_h

#include "itkCPRViewGeometry.h"
#include "itkCenterlineTree.h"

#include <cstdint>
#include <vector>

namespace itk::detail
{

/** \class CPRCenterlinePixels
 * \brief The centerline pixels of a view (docs/design.md 3.4, step 1), row-major W x H.
 *
 * Owner is the branch id (0 where no centerline passes), Depth the depth along v in mm and Radius the lumen
 * radius in mm (NaN when the tree has no radii), both interpolated along the projected segment.
 * \ingroup VesselReformation
 */
struct CPRCenterlinePixels
{
  SizeValueType         Width{ 0 };
  SizeValueType         Height{ 0 };
  std::vector<double>   Depth;
  std::vector<double>   Radius;
  std::vector<uint32_t> Owner;

  bool
  IsCenterline(std::size_t k) const
  {
    return Owner[k] != 0;
  }
  std::size_t
  CountCenterlinePixels() const;
};

/** One centerline pixel of a view: its row-major index k = row * W + column and what CPRCenterlinePixels holds
 * there. */
struct CPRCenterlinePixel
{
  std::size_t Index{ 0 };
  double      Depth{ 0.0 };
  double      Radius{ 0.0 };
  uint32_t    Owner{ 0 };
};

/** Projects every centerline point into \a view and marks each pixel that a projected segment passes through
 * (an exact cell traversal, 8-connected through exact corners). A pixel's depth and radius are interpolated at
 * the segment point nearest the pixel centre. Where segments of two vessels meet in a pixel, the smaller depth
 * (nearer the viewer) wins, then the smaller branch id. */
CPRCenterlinePixels
RasterizeCenterlines(const CenterlineTree & tree, const CPRViewGeometry & view);
/** As above, into \a pixels, reusing its memory (a view that rotates needs no new allocation). */
void
RasterizeCenterlines(const CenterlineTree & tree, const CPRViewGeometry & view, CPRCenterlinePixels & pixels);
/** The same centerline pixels as a list in increasing Index, without the W x H arrays: what a device computes the
 * depth map from (the OpenCL depth filter uploads this list, a few KB, per view). \a pixels is reused. */
void
RasterizeCenterlines(const CenterlineTree &            tree,
                     const CPRViewGeometry &           view,
                     std::vector<CPRCenterlinePixel> & pixels);

} // namespace itk::detail

#endif
