// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrPathSegments_h
#define vrPathSegments_h

#include "itkCenterlineTree.h"
#include "itkVesselPath.h"

#include <limits>
#include <string>
#include <vector>

namespace vr
{
/** \class PathJunction
 * \brief A junction of the tree on a vessel path (docs/lumen-measurement.md, "Segments"): where the path runs on
 * into the next branch of its chain, or where a side branch leaves the path.
 * \ingroup VesselReformation
 */
struct PathJunction
{
  /** Arc length on the path read, mm. */
  double ArcLength{ 0.0 };
  /** The branch that starts here: the path's next branch, or the side branch. */
  int BranchId{ 0 };
  /** True where the path runs on into that branch; false for a side branch. */
  bool OnPath{ false };
  /** The parent's centerline radius at the junction (the vessel the branch leaves), mm; NaN without radii. */
  double ParentRadius{ std::numeric_limits<double>::quiet_NaN() };
};

/** \class PathSegment
 * \brief A stretch of a vessel path between two junctions (or a junction and an end of the path): one vessel of one
 * size, where a reference diameter means something.
 * \ingroup VesselReformation
 */
struct PathSegment
{
  double Begin{ 0.0 };
  double End{ 0.0 };
  int    BranchId{ 0 };
  /** The branch's name; empty when the tree names none. */
  std::string Name;
};

/** \class PathLayout
 * \brief The junctions along a path and the segments they cut it into, in order of arc length.
 * \ingroup VesselReformation
 */
struct PathLayout
{
  std::vector<PathJunction> Junctions;
  std::vector<PathSegment>  Segments;
  /** Whether the path's first and last points are ends of the tree's vessels (not where a range cut the path): only
   * those ends are margins where the lumen is not graded. */
  bool StartIsVesselEnd{ true };
  bool EndIsVesselEnd{ true };
};

/** The junctions on \a path (a path of \a tree, perhaps cut) and its segments. A junction is where the path's branch
 * changes, or where a branch whose parent (itk::VesselPath::FindParents) lies on the path starts within
 * max(itk::VesselPath::JunctionTolerance, the path's radius there) of the path, on the part of the path that runs
 * along that parent. Junctions closer than 0.5 mm to each other cut one segment boundary; segments shorter than that
 * are not made. \a startCut and \a endCut say that the path was cut there (its ends are then no vessel ends). */
PathLayout
FindPathLayout(const itk::CenterlineTree & tree, const itk::VesselPath & path, bool startCut, bool endCut);

/** The names of a path's branches joined by " → ", each run of a repeated name once ("aorta", "aorta", "celiac
 * trunk" -> "aorta → celiac trunk"). */
std::string
JoinPathNames(const std::vector<std::string> & names);
} // namespace vr

#endif
