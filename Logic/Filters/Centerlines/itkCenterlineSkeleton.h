// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCenterlineSkeleton_h
#define itkCenterlineSkeleton_h

#include "itkCenterlineForeground.h"

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace itk
{
namespace detail
{
/** \class SkeletonParameters
 * \brief Settings of the TEASAR skeleton (Sato et al. 2000). Lengths in mm, ratios dimensionless.
 * \ingroup VesselReformation
 */
struct SkeletonParameters
{
  /** The cost of a unit of path length through a voxel is (Dmax / D)^PenaltyExponent, D its distance to the
   * background and Dmax the largest in its component: a minimal path under it is a minimal path of the speed
   * D^PenaltyExponent (Deschamps and Cohen's vessel paths), which keeps to the ridge of D, the middle of the lumen,
   * wherever the vessel bends less sharply than its radius over the exponent. TEASAR's own penalty,
   * 5000 (1 - D / Dmax)^16, is flat in the core of the widest vessel, and paths there cut corners by a voxel. */
  double PenaltyExponent{ 2.0 };
  /** Around each new path, voxels within InvalidationScale D + InvalidationMargin of a path voxel are covered. */
  double InvalidationScale{ 1.5 };
  double InvalidationMargin{ 1.0 };
  /** A path's free end is trimmed back to the first voxel q whose sphere of radius TipTrimScale D(q) holds the
   * end voxel: the end of a minimal path leaves the middle of the lumen to reach the surface. */
  double TipTrimScale{ 1.75 };
  /** A terminal branch reaching less than SpurRadiusRatio times its own radius beyond its parent's lumen, or
   * shorter than MinimumBranchLength (mm), is a spur and dropped. */
  double SpurRadiusRatio{ 2.0 };
  double MinimumBranchLength{ 0.0 };
};

/** \class SkeletonTree
 * \brief A centerline tree as chains of foreground voxels. Each branch runs from its parent's end (the junction
 * voxel, shared) or the root to a junction or a free end.
 * \ingroup VesselReformation
 */
struct SkeletonTree
{
  struct Branch
  {
    std::vector<uint32_t> Voxels;
    /** Index of the parent branch, or -1 for a branch that starts at the root. */
    int Parent{ -1 };
  };
  std::vector<Branch> Branches;
  /** The root voxel. */
  uint32_t Root{ 0 };
};

/** \class SkeletonTracer
 * \brief Traces the TEASAR skeleton (Sato et al., "TEASAR: tree-structure extraction algorithm for accurate and
 * robust skeletons", Pacific Graphics 2000) of the components of a CenterlineForeground.
 *
 * For one component: from a root (a given voxel, or else the far end of the component found by a geodesic
 * sweep) one Dijkstra sweep with the penalty of SkeletonParameters gives every voxel its minimal path to the root
 * and that path's length. Repeatedly the voxel farthest along its path that no path covers yet is taken, its path
 * followed back to the tree so far, its free end trimmed, and every voxel within the invalidation radius of it
 * covered; the path joins the tree unless it is a spur. The tree is then rooted at the given voxel, or else at its
 * free end of largest radius (the most proximal end of a vessel tree), split into branches at junctions with
 * larger-radius children first, and internal branches shorter than their junction's radius are contracted.
 *
 * Work arrays over the foreground are allocated once, by the constructor, and only a component's voxels are
 * touched per trace.
 *
 * \ingroup VesselReformation
 */
class SkeletonTracer
{
public:
  explicit SkeletonTracer(const CenterlineForeground & foreground);

  /** \param component the compact indices of one connected component.
   * \param parameters the TEASAR settings.
   * \param rootVoxel a voxel of the component to root the tree at (its end is then not trimmed), or -1.
   * \return the tree; empty when the component yields no path that survives trimming (a blob, a speck). */
  SkeletonTree
  Trace(const std::vector<uint32_t> & component, const SkeletonParameters & parameters, int64_t rootVoxel = -1);

private:
  /** The penalty of every voxel of \a component, relative to its deepest voxel. */
  void
  PreparePenalty(const std::vector<uint32_t> & component, const SkeletonParameters & parameters);
  /** Dijkstra from \a source over \a component; the cost of a step is its length times the mean penalty of its two
   * voxels (all 1 when \a penalized is false). Fills m_Cost, m_Parent and m_PathLength. */
  void
  Sweep(const std::vector<uint32_t> & component, uint32_t source, bool penalized);
  /** The TEASAR loop from \a root: marks the voxels of the kept paths in m_InTree, sets m_RootEnd and m_TipOfEnd.
   * \return false when the first path trims away (no centerline). */
  bool
  TracePaths(const std::vector<uint32_t> & component,
             const SkeletonParameters &    parameters,
             uint32_t                      root,
             bool                          trimRoot);
  /** Marks every foreground voxel within InvalidationScale D + InvalidationMargin of a voxel of \a path covered. */
  void
  Cover(const std::vector<uint32_t> & path, const SkeletonParameters & parameters);
  /** The index in \a path of the voxel its end (front or back) is trimmed back to (see SkeletonParameters). */
  std::size_t
  TrimIndex(const std::vector<uint32_t> & path, bool fromFront, double scale) const;
  /** The kept voxels as an undirected tree: each linked to its sweep parent. */
  void
  LinkTree(const std::vector<uint32_t> & component);
  const std::vector<uint32_t> &
  Links(uint32_t voxel) const
  {
    return m_Links[m_Slot[voxel]];
  }
  /** The free end whose last stretch has the largest median radius. */
  uint32_t
  WidestEnd() const;
  /** The branches of the linked tree walked from \a treeRoot, split at junctions. */
  SkeletonTree
  SplitBranches(uint32_t treeRoot) const;

  const CenterlineForeground & m_Foreground;
  std::vector<double>          m_Penalty;
  std::vector<double>          m_Cost;
  std::vector<int32_t>         m_Parent;
  std::vector<double>          m_PathLength;
  std::vector<uint8_t>         m_Covered;
  std::vector<uint8_t>         m_InTree;
  std::vector<uint8_t>         m_Done;
  std::vector<uint32_t>        m_Slot;
  /** The deepest voxel of the component being traced, and its distance to the background (mm). */
  uint32_t m_Deepest{ 0 };
  double   m_DeepestDistance{ 0.0 };
  /** The kept voxels, their links, the root end of the first path, and each trimmed end's untrimmed voxel. */
  std::vector<uint32_t>                      m_TreeVoxels;
  std::vector<std::vector<uint32_t>>         m_Links;
  uint32_t                                   m_RootEnd{ 0 };
  std::vector<std::pair<uint32_t, uint32_t>> m_TipOfEnd;
};
} // namespace detail
} // namespace itk

#endif
