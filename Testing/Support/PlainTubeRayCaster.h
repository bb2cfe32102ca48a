// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef PlainTubeRayCaster_h
#define PlainTubeRayCaster_h

#include "itkCPRViewGeometry.h"
#include "itkCenterlineTree.h"

#include <cstdint>
#include <vector>

/** The visibility oracle of the depth filter's tests (docs/design.md "Depth", Visibility mode), written apart from the
 * filter's code: each segment of the tree is a tube as the phantoms draw it (a capsule whose radius varies linearly
 * from end to end: a point X is inside when its distance to the segment is at most the radius interpolated at the
 * segment point nearest X), and each pixel's ray B(i, j) + s v (docs/design.md "View") is intersected with every tube
 * in 3D, in closed form (the quadratics of the two end spheres and of the cone between). */
namespace vr::test
{
/** Where one ray enters and leaves one branch's tubes (depth s along v, mm). */
struct TubeCrossing
{
  uint32_t Branch;
  double   Entry;
  double   Exit;
};

/** The first tube hit per pixel, row-major W x H. */
struct TubeHits
{
  unsigned int Width{ 0 };
  unsigned int Height{ 0 };
  /** The branch id of the first tube the ray meets; 0 where it meets none. */
  std::vector<uint32_t> FirstBranch;
  /** Its entry depth, mm (NaN where none). */
  std::vector<double> EntryDepth;

  uint32_t
  At(unsigned int column, unsigned int row) const
  {
    return FirstBranch[static_cast<std::size_t>(row) * Width + column];
  }
};

/** Casts one ray per pixel of \a view through the tubes of \a tree (radii required). */
TubeHits
CastTubeRays(const itk::CenterlineTree & tree, const itk::CPRViewGeometry & view);

/** Every tube the ray through the continuous pixel position (\a column, \a row) of \a view crosses, one entry per
 * segment, in no particular order. */
std::vector<TubeCrossing>
CrossTubes(const itk::CenterlineTree & tree, const itk::CPRViewGeometry & view, double column, double row);

/** True when \a point lies inside a tube of the branch \a branchId of \a tree (its lumen). */
bool
IsInsideBranch(const itk::CenterlineTree & tree, uint32_t branchId, const itk::CenterlineTree::PointType & point);

/** True when the centerline point \a point of \a tree, of lumen radius \a radius, lies behind a tube that the ray
 * through it leaves before reaching the point's own lumen (exit < depth - radius): another vessel hides it. */
bool
IsCenterlinePointHidden(const itk::CenterlineTree &            tree,
                        const itk::CPRViewGeometry &           view,
                        const itk::CenterlineTree::PointType & point,
                        double                                 radius);
} // namespace vr::test

#endif
