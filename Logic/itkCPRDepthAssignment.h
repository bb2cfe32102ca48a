#ifndef itkCPRDepthAssignment_h
#define itkCPRDepthAssignment_h

#include "itkCPRCenterlineRasterizer.h"
#include "itkMultiThreaderBase.h"

namespace itk
{

/** How pixels away from the centerlines take their depth (DESIGN 3.4). */
enum class CPRDepthMode
{
  /** mpCPR: the nearest centerline pixel in the pixel's own row; empty rows copy the nearest filled row. */
  Scanline,
  /** Centerline-reformation-like: the nearest centerline pixel in 2D (a Voronoi partition of the plane). */
  Nearest
};

/** Prints "Scanline" or "Nearest". */
std::ostream &
operator<<(std::ostream & os, CPRDepthMode mode);

/** A depth map with its fixed mask and owner labels, row-major W x H. */
struct CPRDepthAssignment
{
  std::vector<float>         Depth;
  std::vector<unsigned char> Fixed;
  std::vector<uint32_t>      Owner;
};

/** Gives every pixel the depth and owner of its nearest centerline pixel, in its row (Scanline) or in 2D by
 * millimetre distance (Nearest). Ties go to the smaller depth (nearer the viewer), then the smaller branch id,
 * then (scanline) the left or (rows) the upper candidate. Centerline pixels are fixed; with \a fixLumen, so are
 * pixels whose distance in mm to their owner's centerline pixel (along the row in Scanline mode, in 2D in
 * Nearest mode) is at most that pixel's lumen radius. \a spacing is (sx, sy) in mm. Rows are processed in
 * parallel by \a threader. Throws when no centerline pixel lies in the image. */
CPRDepthAssignment
AssignDepth(const CPRCenterlinePixels & pixels,
            CPRDepthMode                mode,
            const Vector<double, 2> &   spacing,
            bool                        fixLumen,
            MultiThreaderBase *         threader);
/** As above, into \a result, reusing its memory (a view that rotates needs no new allocation). */
void
AssignDepth(const CPRCenterlinePixels & pixels,
            CPRDepthMode                mode,
            const Vector<double, 2> &   spacing,
            bool                        fixLumen,
            MultiThreaderBase *         threader,
            CPRDepthAssignment &        result);

} // namespace itk

#endif
