// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCenterlineTree_h
#define itkCenterlineTree_h

#include "itkGroupSpatialObject.h"
#include "itkPoint.h"

#include <string>
#include <vector>

namespace itk
{

/** \class CenterlineBranch
 * \brief One vessel section: an ordered polyline in LPS millimetres, an optional lumen radius per point (mm),
 * an integer id >= 1 that labels the pixels it owns in the reformation, and the vessel's name when one is known.
 *
 * The name travels with the branch through every conversion (node, polydata, files), so that whatever renumbers
 * the ids on the way (merging overlapping paths, splitting a trunk where a child leaves it) cannot attach a name to
 * the wrong vessel.
 * \ingroup VesselReformation
 */
struct CenterlineBranch
{
  using PointType = Point<double, 3>;

  int                    Id{ 1 };
  std::vector<PointType> Points;
  /** What the vessel is called ("left common iliac artery", a curve's name, a mask file's name); empty when the
   * source names nothing. Not part of the geometry: operator== ignores it. */
  std::string Name;
  /** Lumen radius per point, in mm; empty when unknown. */
  std::vector<double> Radii;

  bool
  HasRadii() const
  {
    return !Radii.empty();
  }

  /** Same id, points and radii, exactly (the name is a label, not geometry: renaming changes no output). */
  bool
  operator==(const CenterlineBranch & other) const
  {
    return Id == other.Id && Points == other.Points && Radii == other.Radii;
  }
  bool
  operator!=(const CenterlineBranch & other) const
  {
    return !(*this == other);
  }
};

/** \class CenterlineTree
 * \brief The centerlines of a vessel tree (docs/design.md "Centerline tree"): branches in LPS millimetres.
 *
 * A small value type that the reformation filters take as a parameter. It converts to and from the
 * ITK-native representation, itk::TubeSpatialObject branches under an itk::GroupSpatialObject, which is what
 * TubeTK's .tre files hold.
 *
 * \sa CPRDepthImageFilter, CPRViewGeometry
 * \ingroup VesselReformation
 */
class CenterlineTree
{
public:
  using PointType = CenterlineBranch::PointType;
  using BranchContainer = std::vector<CenterlineBranch>;
  using GroupType = GroupSpatialObject<3>;

  /** Appends a branch; Validate() checks it. */
  void
  AddBranch(CenterlineBranch branch);

  const BranchContainer &
  GetBranches() const
  {
    return m_Branches;
  }
  BranchContainer &
  GetBranches()
  {
    return m_Branches;
  }

  std::size_t
  GetNumberOfBranches() const
  {
    return m_Branches.size();
  }
  std::size_t
  GetNumberOfPoints() const;
  bool
  IsEmpty() const
  {
    return GetNumberOfPoints() == 0;
  }
  /** True when every branch carries a radius per point. */
  bool
  HasRadii() const;

  /** Axis-aligned bounds of all points (LPS mm). Throws on an empty tree. */
  void
  GetBounds(PointType & minimum, PointType & maximum) const;
  /** The centre of the bounding box, the default view centre. */
  PointType
  GetBoundingBoxCenter() const;

  /** Throws itk::ExceptionObject naming the branch and point when the tree is empty, a branch has no point,
   * an id is < 1 or repeated, a coordinate or radius is not finite, a coordinate lies farther than
   * MaximumCoordinate from the origin, a radius is negative or above MaximumCoordinate, or the radius count
   * differs from the point count. */
  void
  Validate() const;

  /** The largest coordinate magnitude and radius accepted, in mm: 10 km, far beyond any scanner's frame, and far
   * below where view coordinates in pixels could overflow an integer. */
  static constexpr double MaximumCoordinate = 1e7;

  /** Tube spatial objects (one per branch, id = branch id) under a group; positions in world (LPS) space. */
  GroupType::Pointer
  ToSpatialObject() const;
  /** Reads every itk::TubeSpatialObject below \a group, in world space. Radii are kept when any is non-zero. */
  static CenterlineTree
  FromSpatialObject(const GroupType * group);

  /** Same branches in the same order, exactly (filters compare trees so that setting the same one again changes
   * nothing). */
  bool
  operator==(const CenterlineTree & other) const
  {
    return m_Branches == other.m_Branches;
  }
  bool
  operator!=(const CenterlineTree & other) const
  {
    return !(*this == other);
  }

private:
  BranchContainer m_Branches;
};

} // namespace itk

#endif
