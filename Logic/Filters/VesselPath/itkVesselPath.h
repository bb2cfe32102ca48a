// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkVesselPath_h
#define itkVesselPath_h

#include "itkCenterlineTree.h"
#include "itkPoint.h"
#include "itkVector.h"

#include <vector>

namespace itk
{

/** \class VesselPath
 * \brief One vessel read from the tree's root to a chosen branch's far end (docs/vessel-path.md "Path"), parametrised
 * by arc length s in mm, LPS.
 *
 * The branches' topology comes from their geometry, not from their order or ids: a branch's parent is the other
 * branch whose polyline passes nearest to the branch's first point, when that distance is within
 * max(JunctionTolerance, the parent's radius there); attachments are made nearest first and one that would close a
 * loop is left out. A branch whose start attaches to nothing is a root. The path to a branch follows the parents up to
 * a root: it runs along each ancestor from its start to the point where the next branch of the chain joins it (the
 * nearest point of its polyline, not necessarily its end), then along the chosen branch to its end, so it is
 * continuous across junctions (the gap it bridges there is at most the tolerance). The default path is the longest
 * path from the root to any branch's far end (the first branch in the tree's order on ties): every far end is an end
 * of the tree, since a child may join its parent anywhere along it.
 *
 * The path is the polyline through those points: its position and radius are interpolated linearly in s; its tangent
 * at s is the chord from s - h to s + h (clamped to the path), h = max(DefaultTangentHalfWindow, the median spacing
 * of its points) unless set: continuous in s where a polyline's own segment direction is not, and blind to the
 * sub-millimetre wiggle of real centerlines that would otherwise bend the frame (and fold a straightened CPR) at
 * every point. Radius is NaN when the tree carries none.
 *
 * Errors (itk::ExceptionObject) name the branch id or arc length at fault.
 * \sa RotationMinimizingFrame, VesselPathSection
 * \ingroup VesselReformation
 */
class VesselPath
{
public:
  using PointType = Point<double, 3>;
  using VectorType = Vector<double, 3>;

  /** The smallest gap (mm) between a branch's first point and its parent's polyline that still attaches it. */
  static constexpr double JunctionTolerance = 2.0;
  /** The least half-width of the tangent's chord, mm. */
  static constexpr double DefaultTangentHalfWindow = 2.0;

  /** An empty path (length 0); FromTree makes real ones. */
  VesselPath() = default;

  /** The path from the root to the far end of branch \a endBranchId; 0 takes the longest root-to-leaf path. Throws
   * when the tree is invalid, has no branch \a endBranchId, or the path has no length. */
  static VesselPath
  FromTree(const CenterlineTree & tree, int endBranchId = 0);

  /** The parent of every branch, by index into tree.GetBranches() (-1 for a root), found as the class comment says;
   * what FromTree uses. */
  static std::vector<int>
  FindParents(const CenterlineTree & tree);

  /** The part of this path between arc lengths \a begin and \a end (mm, 0 <= begin < end <= length); its arc length
   * starts again at 0, and GetArcLengthOffset() adds \a begin to the offset this path had. Throws naming the bad
   * value. */
  VesselPath
  Cut(double begin, double end) const;

  /** Total length, mm. */
  double
  GetLength() const
  {
    return m_ArcLengths.empty() ? 0.0 : m_ArcLengths.back();
  }
  /** The arc length of this path's start on the path it was cut from (0 for a whole path). */
  double
  GetArcLengthOffset() const
  {
    return m_ArcLengthOffset;
  }
  /** The branch ids from the root to the chosen branch. */
  const std::vector<int> &
  GetBranchChain() const
  {
    return m_BranchChain;
  }
  /** The polyline's points, their arc lengths and the radius there (NaN without radii). */
  const std::vector<PointType> &
  GetPoints() const
  {
    return m_Points;
  }
  const std::vector<double> &
  GetArcLengths() const
  {
    return m_ArcLengths;
  }
  bool
  HasRadii() const
  {
    return m_HasRadii;
  }
  /** The half-width h of the tangent's chord, mm; setting it (finite, > 0, else it throws) trades noise for detail:
   * analytic curves sampled finely may take their point spacing. */
  double
  GetTangentHalfWindow() const
  {
    return m_TangentHalfWindow;
  }
  void
  SetTangentHalfWindow(double halfWindow);

  /** Position, unit tangent, radius (NaN without radii) and branch id at arc length \a s, clamped to [0, length]. */
  PointType
  PointAt(double s) const;
  VectorType
  TangentAt(double s) const;
  double
  RadiusAt(double s) const;
  int
  BranchIdAt(double s) const;

  /** 0, step, 2 step, ... up to the length (the end itself only when the length is a multiple of the step). Throws
   * when \a step is not finite and > 0 or the path is shorter than one step. */
  std::vector<double>
  SampleArcLengths(double step) const;

  /** The arc length of the path's point nearest to \a point. */
  double
  ProjectPoint(const PointType & point) const;

private:
  /** Segment k with arc lengths [k, k+1] holding s, and the fraction along it. */
  std::size_t
  Locate(double s, double & fraction) const;
  void
  Finish();

  std::vector<PointType> m_Points;
  std::vector<double>    m_ArcLengths;
  std::vector<double>    m_Radii;
  /** The branch of each point; segment k belongs to point k + 1's branch. */
  std::vector<int> m_BranchIds;
  std::vector<int> m_BranchChain;
  bool             m_HasRadii{ false };
  double           m_TangentHalfWindow{ DefaultTangentHalfWindow };
  double           m_ArcLengthOffset{ 0.0 };
};

} // namespace itk

#endif
