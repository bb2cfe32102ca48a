// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCenterlinePolylineMerge_h
#define itkCenterlinePolylineMerge_h

#include "itkPoint.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace itk
{
/** \class CenterlinePolyline
 * \brief One polyline of a centerline file (a VTK line cell, a path of VMTK's), in LPS mm, before it becomes
 * branches of an itk::CenterlineTree.
 * \ingroup VesselReformation
 */
struct CenterlinePolyline
{
  using PointType = Point<double, 3>;

  /** Which input polyline this is (its index among the file's polylines, or a cell id): a branch made from it
   * carries it, so that a reader can give the branch the name or id the file stored for that polyline. */
  std::size_t            Source{ 0 };
  std::vector<PointType> Points;
  /** Lumen radius per point, mm; empty when the file has none (then for every polyline). */
  std::vector<double> Radii;
};

/** \class CenterlineMergedBranch
 * \brief A branch made of input polylines: its points and radii, the polyline it came from, and whether it is that
 * polyline whole (at most an end point replaced by the identical point of an earlier polyline).
 * \ingroup VesselReformation
 */
struct CenterlineMergedBranch
{
  CenterlinePolyline Polyline;
  bool               Whole{ true };
};

/** \class CenterlineTractLabels
 * \brief The labels vmtkbranchextractor gives each polyline (a tract): its group (the vessel section), whether it is
 * blanked (a bifurcation region), the path it belongs to (CenterlineIds) and its order along that path (TractIds).
 * \ingroup VesselReformation
 */
struct CenterlineTractLabels
{
  long Group{ 0 };
  bool Blanked{ false };
  long Path{ 0 };
  long Tract{ 0 };
};

/** VMTK's overlapping paths made into branches. vmtkcenterlines writes one polyline per source-to-target path,
 * overlapping along shared trunks. Each point of a polyline that lies within \a tolerance (mm) of a point of an
 * earlier polyline is dropped as a repeat; each remaining run of new points becomes a branch, starting (ending) at the
 * shared point where it leaves (rejoins) the earlier paths, and an earlier branch is split where a later one leaves
 * it. So two paths sharing a trunk give three branches: the trunk, and each path's own part from the bifurcation.
 * Polylines that only touch at their ends stay separate branches. An attachment point takes the shared position but
 * keeps the radius its own polyline gives there (a child's lumen at its start, not the parent's).
 *
 * \param polylines    at least one, each with at least one point; radii on all or none.
 * \param tolerance    mm, >= 0.
 * \param mergedPoints receives the number of points dropped as repeats.
 * \return the branches in order of appearance. */
std::vector<CenterlineMergedBranch>
MergeOverlappingPaths(const std::vector<CenterlinePolyline> & polylines, double tolerance, std::size_t & mergedPoints);

/** vmtkbranchextractor's groups made into branches, as vmtkcenterlinemerge does: each non-blanked group becomes one
 * branch, its tracts (one per path through it) resampled to a common count by arc length and averaged with weights
 * radius^2 (a plain mean where every radius is 0). A blanked tract (the bifurcation region) is given to the tract
 * that follows it on its path, so each child branch runs from the end of its parent through the bifurcation instead
 * of leaving a gap; a blanked tract that ends its path is dropped. Each child starts at the end of its merged parent,
 * so the tree stays connected.
 *
 * \param polylines    the tracts; \a labels holds one entry per polyline.
 * \param tolerance    mm: a joined tract's first point within it of the previous end is not repeated.
 * \param mergedPoints receives how many fewer points the branches have than the polylines.
 * \return one branch per group, in increasing group order; each names as its source the first tract of its group.
 *         Never Whole. Empty when every tract is blanked. */
std::vector<CenterlineMergedBranch>
MergeBranchGroups(const std::vector<CenterlinePolyline> &    polylines,
                  const std::vector<CenterlineTractLabels> & labels,
                  double                                     tolerance,
                  std::size_t &                              mergedPoints);

/** \a points (any type indexed [0], [1], [2], in mm) resampled to \a count points at equal steps of arc length, its
 * two ends kept; \a radii (empty, or one per point) likewise, linearly. A single input point is repeated; a count of
 * 1 gives the first point. The one polyline resampler of the centerline code: branch groups are averaged on it and
 * extracted centerlines are spaced by it. */
template<typename TPoint>
void
ResamplePolylineEvenly(const std::vector<TPoint> & points,
                       const std::vector<double> & radii,
                       std::size_t                 count,
                       std::vector<TPoint> &       resampledPoints,
                       std::vector<double> &       resampledRadii)
{
  resampledPoints.clear();
  resampledRadii.clear();
  if (points.empty() || count == 0)
  {
    return;
  }
  const bool withRadii = !radii.empty();
  if (points.size() == 1 || count == 1)
  {
    resampledPoints.assign(count, points.front());
    if (withRadii)
    {
      resampledRadii.assign(count, radii.front());
    }
    return;
  }
  std::vector<double> arc(points.size(), 0.0);
  for (std::size_t k = 1; k < points.size(); ++k)
  {
    double squared = 0.0;
    for (unsigned int axis = 0; axis < 3; ++axis)
    {
      const double step = points[k][axis] - points[k - 1][axis];
      squared += step * step;
    }
    arc[k] = arc[k - 1] + std::sqrt(squared);
  }
  const double      length = arc.back();
  const std::size_t steps = count - 1;
  resampledPoints.reserve(count);
  std::size_t segment = 0;
  for (std::size_t k = 0; k <= steps; ++k)
  {
    const double s = k == steps ? length : length * static_cast<double>(k) / static_cast<double>(steps);
    while (segment + 2 < points.size() && arc[segment + 1] < s)
    {
      ++segment;
    }
    const double span = arc[segment + 1] - arc[segment];
    const double t = span > 0.0 ? std::min(1.0, std::max(0.0, (s - arc[segment]) / span)) : 0.0;
    TPoint       point = points[segment];
    for (unsigned int axis = 0; axis < 3; ++axis)
    {
      point[axis] = points[segment][axis] + t * (points[segment + 1][axis] - points[segment][axis]);
    }
    resampledPoints.push_back(point);
    if (withRadii)
    {
      resampledRadii.push_back(radii[segment] + t * (radii[segment + 1] - radii[segment]));
    }
  }
}
} // namespace itk

#endif
