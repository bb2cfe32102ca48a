// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkCenterlineTree.h"

#include "itkMacro.h"
#include "itkTubeSpatialObject.h"

#include <cmath>
#include <set>
#include <sstream>

namespace itk
{

void
CenterlineTree::AddBranch(CenterlineBranch branch)
{
  m_Branches.push_back(std::move(branch));
}

std::size_t
CenterlineTree::GetNumberOfPoints() const
{
  std::size_t count = 0;
  for (const auto & branch : m_Branches)
  {
    count += branch.Points.size();
  }
  return count;
}

bool
CenterlineTree::HasRadii() const
{
  if (m_Branches.empty())
  {
    return false;
  }
  for (const auto & branch : m_Branches)
  {
    if (!branch.HasRadii())
    {
      return false;
    }
  }
  return true;
}

void
CenterlineTree::GetBounds(PointType & minimum, PointType & maximum) const
{
  if (IsEmpty())
  {
    itkGenericExceptionMacro(<< "CenterlineTree: the tree has no point, so it has no bounds");
  }
  minimum.Fill(std::numeric_limits<double>::infinity());
  maximum.Fill(-std::numeric_limits<double>::infinity());
  for (const auto & branch : m_Branches)
  {
    for (const auto & point : branch.Points)
    {
      for (unsigned int axis = 0; axis < 3; ++axis)
      {
        minimum[axis] = std::min(minimum[axis], point[axis]);
        maximum[axis] = std::max(maximum[axis], point[axis]);
      }
    }
  }
}

CenterlineTree::PointType
CenterlineTree::GetBoundingBoxCenter() const
{
  PointType minimum;
  PointType maximum;
  GetBounds(minimum, maximum);
  PointType center;
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    center[axis] = 0.5 * (minimum[axis] + maximum[axis]);
  }
  return center;
}

void
CenterlineTree::Validate() const
{
  if (m_Branches.empty())
  {
    itkGenericExceptionMacro(<< "CenterlineTree: the tree has no branch");
  }
  std::set<int> ids;
  for (std::size_t b = 0; b < m_Branches.size(); ++b)
  {
    const CenterlineBranch & branch = m_Branches[b];
    if (branch.Id < 1)
    {
      itkGenericExceptionMacro(<< "CenterlineTree: branch " << b << " has id " << branch.Id << "; ids must be >= 1");
    }
    if (!ids.insert(branch.Id).second)
    {
      itkGenericExceptionMacro(<< "CenterlineTree: branch id " << branch.Id << " is used twice");
    }
    if (branch.Points.empty())
    {
      itkGenericExceptionMacro(<< "CenterlineTree: branch " << branch.Id << " has no point");
    }
    if (branch.HasRadii() && branch.Radii.size() != branch.Points.size())
    {
      itkGenericExceptionMacro(<< "CenterlineTree: branch " << branch.Id << " has " << branch.Points.size()
                               << " points but " << branch.Radii.size() << " radii");
    }
    for (std::size_t p = 0; p < branch.Points.size(); ++p)
    {
      const PointType & point = branch.Points[p];
      if (!std::isfinite(point[0]) || !std::isfinite(point[1]) || !std::isfinite(point[2]))
      {
        itkGenericExceptionMacro(<< "CenterlineTree: branch " << branch.Id << ", point " << p
                                 << " has a non-finite coordinate " << point);
      }
      if (std::abs(point[0]) > MaximumCoordinate || std::abs(point[1]) > MaximumCoordinate ||
          std::abs(point[2]) > MaximumCoordinate)
      {
        itkGenericExceptionMacro(<< "CenterlineTree: branch " << branch.Id << ", point " << p << " is at " << point
                                 << " mm, farther than " << MaximumCoordinate
                                 << " mm from the origin; not a position in a scanner's frame (wrong units?)");
      }
      if (branch.HasRadii() && branch.Radii[p] > MaximumCoordinate)
      {
        itkGenericExceptionMacro(<< "CenterlineTree: branch " << branch.Id << ", point " << p << " has radius "
                                 << branch.Radii[p] << " mm, more than " << MaximumCoordinate << " mm (wrong units?)");
      }
      if (branch.HasRadii() && !(std::isfinite(branch.Radii[p]) && branch.Radii[p] >= 0.0))
      {
        itkGenericExceptionMacro(<< "CenterlineTree: branch " << branch.Id << ", point " << p << " has radius "
                                 << branch.Radii[p] << "; radii must be finite and >= 0 mm");
      }
    }
  }
}

CenterlineTree::GroupType::Pointer
CenterlineTree::ToSpatialObject() const
{
  using TubeType = TubeSpatialObject<3>;
  auto group = GroupType::New();
  for (const auto & branch : m_Branches)
  {
    auto                        tube = TubeType::New();
    TubeType::TubePointListType points;
    for (std::size_t p = 0; p < branch.Points.size(); ++p)
    {
      TubeType::TubePointType point;
      point.SetPositionInObjectSpace(branch.Points[p]);
      point.SetRadiusInObjectSpace(branch.HasRadii() ? branch.Radii[p] : 0.0);
      points.push_back(point);
    }
    tube->SetPoints(points);
    tube->SetId(branch.Id);
    tube->GetProperty().SetName(branch.Name); // MetaIO's "Name", which TubeTK's .tre files carry
    tube->Update();
    group->AddChild(tube);
  }
  group->Update();
  return group;
}

CenterlineTree
CenterlineTree::FromSpatialObject(const GroupType * group)
{
  using TubeType = TubeSpatialObject<3>;
  if (group == nullptr)
  {
    itkGenericExceptionMacro(<< "CenterlineTree: no spatial object given");
  }
  CenterlineTree                                     tree;
  const std::unique_ptr<GroupType::ChildrenListType> children(group->GetChildren(GroupType::MaximumDepth));
  int                                                nextFreeId = 1;
  for (const auto & child : *children)
  {
    const auto * tube = dynamic_cast<const TubeType *>(child.GetPointer());
    if (tube == nullptr || tube->GetNumberOfPoints() == 0)
    {
      continue;
    }
    CenterlineBranch branch;
    branch.Id = tube->GetId();
    branch.Name = tube->GetProperty().GetName();
    bool anyRadius = false;
    for (const auto & point : tube->GetPoints())
    {
      branch.Points.push_back(point.GetPositionInWorldSpace());
      branch.Radii.push_back(point.GetRadiusInWorldSpace());
      anyRadius = anyRadius || point.GetRadiusInWorldSpace() > 0.0;
    }
    if (!anyRadius)
    {
      branch.Radii.clear();
    }
    tree.AddBranch(std::move(branch));
  }
  // Tubes written without ids (-1) get fresh ones, so every branch can label its pixels.
  std::set<int> used;
  for (const auto & branch : tree.GetBranches())
  {
    used.insert(branch.Id);
  }
  std::set<int> seen;
  for (auto & branch : tree.GetBranches())
  {
    if (branch.Id < 1 || !seen.insert(branch.Id).second)
    {
      while (used.count(nextFreeId) != 0)
      {
        ++nextFreeId;
      }
      branch.Id = nextFreeId;
      used.insert(nextFreeId);
      seen.insert(nextFreeId);
    }
  }
  return tree;
}

} // namespace itk
