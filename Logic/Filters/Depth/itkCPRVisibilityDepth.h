// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCPRVisibilityDepth_h
#define itkCPRVisibilityDepth_h

#include "itkCPRBranchOcclusion.h"
#include "itkCPRCenterlineRasterizer.h"
#include "itkCPRDepthAssignment.h"
#include "itkCPRNearestFill.h"

namespace itk::detail
{
/** A centerline cell a segment's footprint passed through (TraverseSegmentCells): its pixel, the branch id, the
 * centerline depth there and the front of the segment's lumen. */
struct CPRFootprintCell
{
  std::size_t Index;
  uint32_t    Owner;
  double      Depth;
  float       Front;
};

/** The buffers of AssignVisibility, kept between updates (a view that rotates allocates nothing new). Per pixel: the
 * branch index + 1 of the visible lumen (0 outside every footprint) and the nearest lumen back (min depth + radius),
 * which the hidden lengths read after the footprints (Back only where Branch is not 0); the rest of the footprint
 * samples live per band of rows, with the thread that computes the band. Only Branch is cleared for an update. The
 * branches' projected points lie one after another. */
struct CPRVisibilityWorkspace
{
  std::vector<uint32_t>          Branch;
  std::vector<float>             Back;
  std::vector<CPRProjectedPoint> Projected;
  std::vector<std::size_t>       FirstPoint;
  /** Per band of rows, the centerline cells of its segments, in the tree's order. */
  std::vector<std::vector<CPRFootprintCell>> BandCells;
  CPRNearestFillWorkspace                    Fill;
};

/** Visibility mode (docs/design.md "Depth"): every segment of every branch has a lumen footprint, the pixels whose
 * distance in mm to the projected segment is at most the radius interpolated at the closest point, and the cells its
 * centerline passes through (all a branch without radii has). A pixel inside footprints shows the lumen the view ray
 * meets first (smallest depth minus half chord), with that segment's centerline depth at the closest point; on its
 * own centerline pixels (those of \a pixels, the rasteriser's) a visible vessel keeps the rasteriser's depth, exactly
 * as in the other modes. Fixed: the visible centerline pixels and, with \a fixLumen, every footprint pixel of a
 * branch with radii. Pixels outside every footprint take the nearest footprint pixel in 2D (FillFromNearestSeeds) and
 * are free. \a result gets Depth, Fixed, Owner and Hidden (the nearest lumen wholly behind the visible one,
 * itkCPROcclusionRule.h, as the segments arrive in the tree's order: a lumen that lay in one with the visible one
 * before a nearer one came is not looked at again; 0 where none); \a occlusion one entry per branch, in the tree's
 * order. Throws when no footprint lies in the image. */
void
AssignVisibility(const CenterlineTree &            tree,
                 const CPRViewGeometry &           view,
                 const CPRCenterlinePixels &       pixels,
                 bool                              fixLumen,
                 MultiThreaderBase *               threader,
                 CPRVisibilityWorkspace &          workspace,
                 CPRDepthAssignment &              result,
                 std::vector<CPRBranchOcclusion> & occlusion);
} // namespace itk::detail

#endif
