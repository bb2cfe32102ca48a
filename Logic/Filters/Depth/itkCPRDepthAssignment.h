// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCPRDepthAssignment_h
#define itkCPRDepthAssignment_h

#include "itkCPRCenterlineRasterizer.h"
#include "itkCPRDepthMode.h"
#include "itkMultiThreaderBase.h"

namespace itk::detail
{

/** A depth map with its fixed mask and owner labels, row-major W x H; in Visibility mode also the hidden labels
 * (AssignVisibility; left empty by AssignDepth).
 * \ingroup VesselReformation
 */
struct CPRDepthAssignment
{
  std::vector<float>         Depth;
  std::vector<unsigned char> Fixed;
  std::vector<uint32_t>      Owner;
  std::vector<uint32_t>      Hidden;
};

/** Gives every pixel the depth and owner of its nearest centerline pixel, in its row (Scanline) or in 2D by
 * millimetre distance (Nearest; Visibility mode is AssignVisibility's). Ties go to the smaller depth (nearer the
 * viewer), then the smaller branch id, then (scanline) the left or (rows) the upper candidate. Centerline pixels are
 * fixed; with \a fixLumen, so are pixels whose distance in mm to their owner's centerline pixel (along the row in
 * Scanline mode, in 2D in Nearest mode) is at most that pixel's lumen radius. \a spacing is (sx, sy) in mm. Rows are
 * processed in parallel by \a threader. Throws when no centerline pixel lies in the image. The result goes into \a
 * result, reusing its memory (a view that rotates needs no new allocation). */
void
AssignDepth(const CPRCenterlinePixels & pixels,
            CPRDepthMode                mode,
            const Vector<double, 2> &   spacing,
            bool                        fixLumen,
            MultiThreaderBase *         threader,
            CPRDepthAssignment &        result);

} // namespace itk::detail

#endif
