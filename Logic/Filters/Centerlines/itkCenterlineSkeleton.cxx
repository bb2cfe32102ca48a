// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkCenterlineSkeleton.h"

#include "itkMacro.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>

namespace itk
{
namespace detail
{
SkeletonTracer::SkeletonTracer(const CenterlineForeground & foreground)
  : m_Foreground(foreground)
  , m_Penalty(foreground.Size(), 1.0)
  , m_Cost(foreground.Size(), 0.0)
  , m_Parent(foreground.Size(), -1)
  , m_PathLength(foreground.Size(), 0.0)
  , m_Covered(foreground.Size(), 0)
  , m_InTree(foreground.Size(), 0)
  , m_Done(foreground.Size(), 0)
  , m_Slot(foreground.Size(), 0)
{
}

void
SkeletonTracer::Sweep(const std::vector<uint32_t> & component, uint32_t source, bool penalized)
{
  for (const uint32_t voxel : component)
  {
    m_Cost[voxel] = std::numeric_limits<double>::infinity();
    m_Parent[voxel] = -1;
    m_PathLength[voxel] = 0.0;
    m_Done[voxel] = 0;
  }
  using Entry = std::pair<double, uint32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  m_Cost[source] = 0.0;
  queue.emplace(0.0, source);
  while (!queue.empty())
  {
    // Plain variables, not a structured binding: the lambda below captures them (C++20 for bindings; clang 14).
    const double cost = queue.top().first;
    const auto   voxel = queue.top().second;
    queue.pop();
    if (m_Done[voxel])
    {
      continue;
    }
    m_Done[voxel] = 1;
    const double penalty = penalized ? m_Penalty[voxel] : 1.0;
    m_Foreground.ForEachNeighbour(voxel,
                                  [&](uint32_t neighbour, double step)
                                  {
                                    if (m_Done[neighbour])
                                    {
                                      return;
                                    }
                                    const double stepCost =
                                      penalized ? 0.5 * step * (penalty + m_Penalty[neighbour]) : step;
                                    if (cost + stepCost < m_Cost[neighbour])
                                    {
                                      m_Cost[neighbour] = cost + stepCost;
                                      m_Parent[neighbour] = static_cast<int32_t>(voxel);
                                      m_PathLength[neighbour] = m_PathLength[voxel] + step;
                                      queue.emplace(cost + stepCost, neighbour);
                                    }
                                  });
  }
}

void
SkeletonTracer::Cover(const std::vector<uint32_t> & path, const SkeletonParameters & parameters)
{
  const auto &         f = m_Foreground;
  const std::ptrdiff_t nx = static_cast<std::ptrdiff_t>(f.BufferSize[0]);
  const std::ptrdiff_t ny = static_cast<std::ptrdiff_t>(f.BufferSize[1]);
  const std::ptrdiff_t nz = static_cast<std::ptrdiff_t>(f.BufferSize[2]);
  for (const uint32_t voxel : path)
  {
    const double         radius = parameters.InvalidationScale * f.Distance[voxel] + parameters.InvalidationMargin;
    const double         radiusSquared = radius * radius;
    const std::ptrdiff_t offset = f.Offset[voxel];
    const std::ptrdiff_t cx = offset % nx;
    const std::ptrdiff_t cy = (offset / nx) % ny;
    const std::ptrdiff_t cz = offset / (nx * ny);
    const std::ptrdiff_t ry = static_cast<std::ptrdiff_t>(radius / f.Spacing[1]);
    const std::ptrdiff_t rz = static_cast<std::ptrdiff_t>(radius / f.Spacing[2]);
    for (std::ptrdiff_t z = std::max<std::ptrdiff_t>(0, cz - rz); z <= std::min(nz - 1, cz + rz); ++z)
    {
      const double dz2 = (z - cz) * f.Spacing[2] * (z - cz) * f.Spacing[2];
      for (std::ptrdiff_t y = std::max<std::ptrdiff_t>(0, cy - ry); y <= std::min(ny - 1, cy + ry); ++y)
      {
        const double dyz2 = dz2 + (y - cy) * f.Spacing[1] * (y - cy) * f.Spacing[1];
        if (dyz2 > radiusSquared)
        {
          continue;
        }
        // The x extent of the ball on this row, then a straight run over it.
        const std::ptrdiff_t half = static_cast<std::ptrdiff_t>(std::sqrt(radiusSquared - dyz2) / f.Spacing[0]);
        const std::ptrdiff_t row = (z * ny + y) * nx;
        const std::ptrdiff_t x0 = std::max<std::ptrdiff_t>(0, cx - half);
        const std::ptrdiff_t x1 = std::min(nx - 1, cx + half);
        for (std::ptrdiff_t x = x0; x <= x1; ++x)
        {
          const int32_t neighbour = f.CompactIndex[static_cast<std::size_t>(row + x)];
          if (neighbour >= 0)
          {
            m_Covered[static_cast<std::size_t>(neighbour)] = 1;
          }
        }
      }
    }
  }
}

std::size_t
SkeletonTracer::TrimIndex(const std::vector<uint32_t> & path, bool fromFront, double scale) const
{
  // The farthest voxel (along the path) whose sphere of radius scale D still holds the end voxel. No sphere of the
  // component reaches farther than scale Dmax, so the scan stops a little beyond that.
  const std::size_t count = path.size();
  const uint32_t    end = fromFront ? path.front() : path.back();
  const double      limit = 2.0 * (scale * m_DeepestDistance + m_Foreground.NeighbourStep[0]);
  std::size_t       kept = 0;
  for (std::size_t k = 0; k < count; ++k)
  {
    const uint32_t voxel = fromFront ? path[k] : path[count - 1 - k];
    const double   distance = m_Foreground.DistanceBetween(voxel, end);
    if (distance <= scale * m_Foreground.Distance[voxel])
    {
      kept = k;
    }
    else if (distance > limit)
    {
      break;
    }
  }
  return fromFront ? kept : count - 1 - kept;
}

namespace
{
double
Median(std::vector<double> values)
{
  if (values.empty())
  {
    return 0.0;
  }
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}
} // namespace

void
SkeletonTracer::PreparePenalty(const std::vector<uint32_t> & component, const SkeletonParameters & parameters)
{
  const auto & f = m_Foreground;
  m_Deepest = component.front();
  for (const uint32_t voxel : component)
  {
    m_Deepest = f.Distance[voxel] > f.Distance[m_Deepest] ? voxel : m_Deepest;
  }
  m_DeepestDistance = std::max(1e-12, static_cast<double>(f.Distance[m_Deepest]));
  for (const uint32_t voxel : component)
  {
    const double depth = std::max(1e-3, f.Distance[voxel] / m_DeepestDistance);
    m_Penalty[voxel] = std::pow(depth, -parameters.PenaltyExponent);
  }
}

bool
SkeletonTracer::TracePaths(const std::vector<uint32_t> & component,
                           const SkeletonParameters &    parameters,
                           uint32_t                      root,
                           bool                          trimRoot)
{
  const auto & f = m_Foreground;
  for (const uint32_t voxel : component)
  {
    m_Covered[voxel] = 0;
    m_InTree[voxel] = 0;
  }
  m_TipOfEnd.clear();
  Sweep(component, root, true);

  std::vector<uint32_t> order(component);
  std::sort(order.begin(),
            order.end(),
            [this](uint32_t a, uint32_t b)
            { return m_PathLength[a] > m_PathLength[b] || (m_PathLength[a] == m_PathLength[b] && a < b); });

  bool                  first = true;
  std::vector<uint32_t> path;
  for (const uint32_t target : order)
  {
    if (m_Covered[target])
    {
      continue;
    }
    path.clear();
    for (int32_t voxel = static_cast<int32_t>(target);; voxel = m_Parent[static_cast<std::size_t>(voxel)])
    {
      path.push_back(static_cast<uint32_t>(voxel));
      if (m_InTree[static_cast<std::size_t>(voxel)] || static_cast<uint32_t>(voxel) == root)
      {
        break;
      }
    }
    Cover(path, parameters);
    const std::size_t tip = TrimIndex(path, true, parameters.TipTrimScale);
    if (first)
    {
      // The first path runs from the farthest voxel to the root: both of its ends are free, unless the root was
      // given.
      const std::size_t base = trimRoot ? TrimIndex(path, false, parameters.TipTrimScale) : path.size() - 1;
      if (base <= tip || m_PathLength[path[tip]] - m_PathLength[path[base]] < parameters.MinimumBranchLength)
      {
        return false; // nothing longer than its own radius: a blob or a speck
      }
      for (std::size_t k = tip; k <= base; ++k)
      {
        m_InTree[path[k]] = 1;
      }
      m_RootEnd = path[base];
      m_TipOfEnd.emplace_back(path[base], root);
      m_TipOfEnd.emplace_back(path[tip], target);
      first = false;
      continue;
    }
    const uint32_t join = path.back();
    if (!m_InTree[join] || tip + 1 >= path.size())
    {
      continue; // ends in the trimmed end at the root, or trims away entirely
    }
    const double        length = m_PathLength[path[tip]] - m_PathLength[join];
    std::vector<double> radii;
    for (std::size_t k = tip; k + 1 < path.size(); ++k)
    {
      radii.push_back(f.Distance[path[k]]);
    }
    const double reachBeyondParent = length - f.Distance[join];
    if (reachBeyondParent < parameters.SpurRadiusRatio * Median(radii) || length < parameters.MinimumBranchLength)
    {
      continue; // a spur
    }
    for (std::size_t k = tip; k < path.size(); ++k)
    {
      m_InTree[path[k]] = 1;
    }
    m_TipOfEnd.emplace_back(path[tip], target);
  }
  return true;
}

void
SkeletonTracer::LinkTree(const std::vector<uint32_t> & component)
{
  m_TreeVoxels.clear();
  for (const uint32_t voxel : component)
  {
    if (m_InTree[voxel])
    {
      m_Slot[voxel] = static_cast<uint32_t>(m_TreeVoxels.size());
      m_TreeVoxels.push_back(voxel);
    }
  }
  m_Links.assign(m_TreeVoxels.size(), {});
  for (const uint32_t voxel : m_TreeVoxels)
  {
    const int32_t parent = m_Parent[voxel];
    if (parent >= 0 && m_InTree[static_cast<std::size_t>(parent)])
    {
      m_Links[m_Slot[voxel]].push_back(static_cast<uint32_t>(parent));
      m_Links[m_Slot[static_cast<uint32_t>(parent)]].push_back(voxel);
    }
  }
}

uint32_t
SkeletonTracer::WidestEnd() const
{
  const auto & f = m_Foreground;
  uint32_t     widest = m_RootEnd;
  double       largest = -1.0;
  for (const uint32_t leaf : m_TreeVoxels)
  {
    if (Links(leaf).size() != 1)
    {
      continue;
    }
    // The median radius over the last stretch (two radii and a voxel) before the end, stopping at a junction.
    std::vector<double> radii;
    const double        reach = 2.0 * f.Distance[leaf] + 2.0 * f.NeighbourStep.back();
    uint32_t            previous = leaf;
    uint32_t            current = leaf;
    double              walked = 0.0;
    while (walked <= reach)
    {
      radii.push_back(f.Distance[current]);
      uint32_t    following = current;
      std::size_t candidates = 0;
      for (const uint32_t next : Links(current))
      {
        if (current == leaf || next != previous)
        {
          following = next;
          ++candidates;
        }
      }
      if (candidates != 1)
      {
        break;
      }
      walked += f.DistanceBetween(current, following);
      previous = current;
      current = following;
    }
    const double radius = Median(radii);
    if (radius > largest)
    {
      largest = radius;
      widest = leaf;
    }
  }
  return widest;
}

SkeletonTree
SkeletonTracer::SplitBranches(uint32_t treeRoot) const
{
  const auto & f = m_Foreground;
  SkeletonTree tree;
  tree.Root = treeRoot;
  struct Start
  {
    uint32_t From;
    uint32_t Next;
    int      Parent;
  };
  std::vector<Start> starts;
  const auto         pushChildren = [&](uint32_t voxel, uint32_t previous, bool hasPrevious, int parent)
  {
    std::vector<uint32_t> children;
    for (const uint32_t next : Links(voxel))
    {
      if (!hasPrevious || next != previous)
      {
        children.push_back(next);
      }
    }
    // Reversed, as starts is a stack: the widest child is walked (and numbered) first.
    std::sort(children.begin(),
              children.end(),
              [&f](uint32_t a, uint32_t b)
              { return f.Distance[a] < f.Distance[b] || (f.Distance[a] == f.Distance[b] && a > b); });
    for (const uint32_t child : children)
    {
      starts.push_back({ voxel, child, parent });
    }
  };
  pushChildren(treeRoot, treeRoot, false, -1);
  while (!starts.empty())
  {
    const Start start = starts.back();
    starts.pop_back();
    SkeletonTree::Branch branch;
    branch.Parent = start.Parent;
    branch.Voxels.push_back(start.From);
    uint32_t previous = start.From;
    uint32_t current = start.Next;
    for (;;)
    {
      branch.Voxels.push_back(current);
      const auto & next = Links(current);
      if (next.size() != 2)
      {
        break;
      }
      const uint32_t following = next[0] != previous ? next[0] : next[1];
      previous = current;
      current = following;
    }
    const int index = static_cast<int>(tree.Branches.size());
    tree.Branches.push_back(std::move(branch));
    pushChildren(current, previous, true, index);
  }
  return tree;
}

namespace
{
SkeletonTree
ContractShortInternalBranches(SkeletonTree tree, const CenterlineForeground & f)
{
  // An internal branch shorter than the radius at its start joins two paths that met the tree a few voxels apart:
  // its children start at its start instead. Parents come before their children, so one pass suffices.
  for (std::size_t b = 0; b < tree.Branches.size(); ++b)
  {
    auto & branch = tree.Branches[b];
    if (branch.Parent < 0 || branch.Voxels.size() < 2)
    {
      continue;
    }
    std::vector<std::size_t> children;
    for (std::size_t c = b + 1; c < tree.Branches.size(); ++c)
    {
      if (tree.Branches[c].Parent == static_cast<int>(b))
      {
        children.push_back(c);
      }
    }
    double length = 0.0;
    for (std::size_t k = 1; k < branch.Voxels.size(); ++k)
    {
      length += f.DistanceBetween(branch.Voxels[k - 1], branch.Voxels[k]);
    }
    if (children.empty() || length >= f.Distance[branch.Voxels.front()])
    {
      continue;
    }
    for (const std::size_t c : children)
    {
      auto &                voxels = tree.Branches[c].Voxels;
      std::vector<uint32_t> joined(branch.Voxels);
      joined.insert(joined.end(), voxels.begin() + 1, voxels.end());
      voxels = std::move(joined);
      tree.Branches[c].Parent = branch.Parent;
    }
    branch.Voxels.clear();
  }
  std::vector<int> renumbered(tree.Branches.size(), -1);
  SkeletonTree     contracted;
  contracted.Root = tree.Root;
  for (std::size_t b = 0; b < tree.Branches.size(); ++b)
  {
    if (!tree.Branches[b].Voxels.empty())
    {
      renumbered[b] = static_cast<int>(contracted.Branches.size());
      contracted.Branches.push_back(std::move(tree.Branches[b]));
    }
  }
  for (auto & branch : contracted.Branches)
  {
    branch.Parent = branch.Parent < 0 ? -1 : renumbered[static_cast<std::size_t>(branch.Parent)];
  }
  return contracted;
}
} // namespace

SkeletonTree
SkeletonTracer::Trace(const std::vector<uint32_t> & component, const SkeletonParameters & parameters, int64_t rootVoxel)
{
  if (component.empty())
  {
    return {};
  }
  PreparePenalty(component, parameters);
  if (rootVoxel >= 0)
  {
    const auto root = static_cast<uint32_t>(rootVoxel);
    if (!TracePaths(component, parameters, root, false))
    {
      return {};
    }
    LinkTree(component);
    return ContractShortInternalBranches(SplitBranches(root), m_Foreground);
  }
  // A first trace from the far end of the component (from its deepest voxel) finds the ends; where the widest end
  // is another, a second trace starts there, so that paths leave the root as blood flows and junctions form where
  // branches leave their parent, not where one child turns into another.
  Sweep(component, m_Deepest, false);
  uint32_t farEnd = m_Deepest;
  for (const uint32_t voxel : component)
  {
    farEnd = m_Cost[voxel] > m_Cost[farEnd] ? voxel : farEnd;
  }
  if (!TracePaths(component, parameters, farEnd, true))
  {
    return {};
  }
  LinkTree(component);
  const uint32_t widest = WidestEnd();
  if (widest != m_RootEnd)
  {
    uint32_t start = widest;
    for (const auto & [end, tip] : m_TipOfEnd)
    {
      start = end == widest ? tip : start;
    }
    if (!TracePaths(component, parameters, start, true))
    {
      return {};
    }
    LinkTree(component);
  }
  return ContractShortInternalBranches(SplitBranches(m_RootEnd), m_Foreground);
}
} // namespace detail
} // namespace itk
