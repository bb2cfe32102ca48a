// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "PlainCenterlineExtraction.h"

#include "itkSignedMaurerDistanceMapImageFilter.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

namespace vr::test
{
namespace
{
using MaskImage = itk::Image<unsigned char, 3>;
using DistanceImage = itk::Image<float, 3>;

class PlainTracer
{
public:
  explicit PlainTracer(const MaskImage * mask)
    : m_Mask(mask)
  {
    auto maurer = itk::SignedMaurerDistanceMapImageFilter<MaskImage, DistanceImage>::New();
    maurer->SetInput(mask);
    maurer->SetBackgroundValue(1); // the background is the object: foreground voxels get their distance to it
    maurer->SetInsideIsPositive(false);
    maurer->SetUseImageSpacing(true);
    maurer->SetSquaredDistance(false);
    maurer->Update();
    m_Distance = maurer->GetOutput();
    const auto size = mask->GetBufferedRegion().GetSize();
    for (unsigned int axis = 0; axis < 3; ++axis)
    {
      m_Size[axis] = static_cast<long>(size[axis]);
      m_Spacing[axis] = mask->GetSpacing()[axis];
    }
    const std::size_t count = mask->GetBufferedRegion().GetNumberOfPixels();
    m_Cost.resize(count);
    m_Parent.resize(count);
    m_Length.resize(count);
    m_Covered.resize(count);
    m_Kept.resize(count);
  }

  itk::CenterlineTree
  Run()
  {
    const unsigned char * mask = m_Mask->GetBufferPointer();
    const std::size_t     count = m_Cost.size();
    std::vector<int32_t>  component(count, -1);
    itk::CenterlineTree   tree;
    int                   label = 0;
    for (std::size_t seed = 0; seed < count; ++seed)
    {
      if (mask[seed] == 0 || component[seed] >= 0)
      {
        continue;
      }
      std::vector<std::size_t> members{ seed };
      component[seed] = label;
      for (std::size_t next = 0; next < members.size(); ++next)
      {
        ForEachNeighbour(members[next],
                         [&](std::size_t neighbour, double)
                         {
                           if (component[neighbour] < 0)
                           {
                             component[neighbour] = label;
                             members.push_back(neighbour);
                           }
                         });
      }
      ++label;
      TraceComponent(members, tree);
    }
    return tree;
  }

private:
  template<typename TVisit>
  void
  ForEachNeighbour(std::size_t voxel, TVisit && visit) const
  {
    const long x = static_cast<long>(voxel % m_Size[0]);
    const long y = static_cast<long>((voxel / m_Size[0]) % m_Size[1]);
    const long z = static_cast<long>(voxel / (m_Size[0] * m_Size[1]));
    for (long dz = -1; dz <= 1; ++dz)
    {
      for (long dy = -1; dy <= 1; ++dy)
      {
        for (long dx = -1; dx <= 1; ++dx)
        {
          const long nx = x + dx;
          const long ny = y + dy;
          const long nz = z + dz;
          if ((dx == 0 && dy == 0 && dz == 0) || nx < 0 || ny < 0 || nz < 0 || nx >= m_Size[0] || ny >= m_Size[1] ||
              nz >= m_Size[2])
          {
            continue;
          }
          const std::size_t neighbour = static_cast<std::size_t>((nz * m_Size[1] + ny) * m_Size[0] + nx);
          if (m_Mask->GetBufferPointer()[neighbour] != 0)
          {
            visit(neighbour,
                  std::sqrt(dx * dx * m_Spacing[0] * m_Spacing[0] + dy * dy * m_Spacing[1] * m_Spacing[1] +
                            dz * dz * m_Spacing[2] * m_Spacing[2]));
          }
        }
      }
    }
  }

  double
  D(std::size_t voxel) const
  {
    return m_Distance->GetBufferPointer()[voxel];
  }

  double
  Between(std::size_t a, std::size_t b) const
  {
    double squared = 0.0;
    long   ca[3] = { static_cast<long>(a % m_Size[0]),
                     static_cast<long>((a / m_Size[0]) % m_Size[1]),
                     static_cast<long>(a / (m_Size[0] * m_Size[1])) };
    long   cb[3] = { static_cast<long>(b % m_Size[0]),
                     static_cast<long>((b / m_Size[0]) % m_Size[1]),
                     static_cast<long>(b / (m_Size[0] * m_Size[1])) };
    for (unsigned int axis = 0; axis < 3; ++axis)
    {
      squared += (ca[axis] - cb[axis]) * m_Spacing[axis] * (ca[axis] - cb[axis]) * m_Spacing[axis];
    }
    return std::sqrt(squared);
  }

  void
  Sweep(std::size_t source, bool penalized, double deepest)
  {
    std::fill(m_Cost.begin(), m_Cost.end(), std::numeric_limits<double>::infinity());
    std::fill(m_Parent.begin(), m_Parent.end(), -1);
    std::fill(m_Length.begin(), m_Length.end(), 0.0);
    const auto penalty = [&](std::size_t voxel)
    { return penalized ? std::pow(std::max(1e-3, D(voxel) / deepest), -2.0) : 1.0; };
    using Entry = std::pair<double, std::size_t>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
    m_Cost[source] = 0.0;
    queue.emplace(0.0, source);
    while (!queue.empty())
    {
      // Plain variables, not a structured binding: the lambda below captures them (C++20 for bindings; clang 14).
      const double cost = queue.top().first;
      const auto   voxel = queue.top().second;
      queue.pop();
      if (cost > m_Cost[voxel])
      {
        continue;
      }
      ForEachNeighbour(voxel,
                       [&](std::size_t neighbour, double step)
                       {
                         const double next = cost + 0.5 * step * (penalty(voxel) + penalty(neighbour));
                         if (next < m_Cost[neighbour])
                         {
                           m_Cost[neighbour] = next;
                           m_Parent[neighbour] = static_cast<int64_t>(voxel);
                           m_Length[neighbour] = m_Length[voxel] + step;
                           queue.emplace(next, neighbour);
                         }
                       });
    }
  }

  void
  Cover(const std::vector<std::size_t> & path)
  {
    for (const std::size_t voxel : path)
    {
      const double radius = 1.5 * D(voxel) + std::max({ m_Spacing[0], m_Spacing[1], m_Spacing[2] });
      const long   c[3] = { static_cast<long>(voxel % m_Size[0]),
                            static_cast<long>((voxel / m_Size[0]) % m_Size[1]),
                            static_cast<long>(voxel / (m_Size[0] * m_Size[1])) };
      long         reach[3];
      for (unsigned int axis = 0; axis < 3; ++axis)
      {
        reach[axis] = static_cast<long>(radius / m_Spacing[axis]);
      }
      for (long z = std::max(0L, c[2] - reach[2]); z <= std::min(m_Size[2] - 1, c[2] + reach[2]); ++z)
      {
        for (long y = std::max(0L, c[1] - reach[1]); y <= std::min(m_Size[1] - 1, c[1] + reach[1]); ++y)
        {
          for (long x = std::max(0L, c[0] - reach[0]); x <= std::min(m_Size[0] - 1, c[0] + reach[0]); ++x)
          {
            const double dx = (x - c[0]) * m_Spacing[0];
            const double dy = (y - c[1]) * m_Spacing[1];
            const double dz = (z - c[2]) * m_Spacing[2];
            if (dx * dx + dy * dy + dz * dz <= radius * radius)
            {
              m_Covered[static_cast<std::size_t>((z * m_Size[1] + y) * m_Size[0] + x)] = 1;
            }
          }
        }
      }
    }
  }

  /** The farthest path voxel (from the end at \a fromFront) whose sphere of radius 1.75 D holds that end. */
  std::size_t
  Trim(const std::vector<std::size_t> & path, bool fromFront) const
  {
    const std::size_t end = fromFront ? path.front() : path.back();
    std::size_t       kept = 0;
    for (std::size_t k = 0; k < path.size(); ++k)
    {
      const std::size_t voxel = fromFront ? path[k] : path[path.size() - 1 - k];
      if (Between(voxel, end) <= 1.75 * D(voxel))
      {
        kept = k;
      }
    }
    return fromFront ? kept : path.size() - 1 - kept;
  }

  /** The TEASAR loop from \a root; false when nothing survives trimming. */
  bool
  Trace(const std::vector<std::size_t> & members, std::size_t root, double deepest)
  {
    Sweep(root, true, deepest);
    std::fill(m_Covered.begin(), m_Covered.end(), 0);
    std::fill(m_Kept.begin(), m_Kept.end(), 0);
    m_Ends.clear();
    std::vector<std::size_t> order(members);
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return m_Length[a] > m_Length[b]; });
    bool first = true;
    for (const std::size_t target : order)
    {
      if (m_Covered[target])
      {
        continue;
      }
      std::vector<std::size_t> path;
      for (std::size_t voxel = target;; voxel = static_cast<std::size_t>(m_Parent[voxel]))
      {
        path.push_back(voxel);
        if (m_Kept[voxel] || voxel == root)
        {
          break;
        }
      }
      Cover(path);
      const std::size_t tip = Trim(path, true);
      if (first)
      {
        const std::size_t base = Trim(path, false);
        if (base <= tip)
        {
          return false;
        }
        for (std::size_t k = tip; k <= base; ++k)
        {
          m_Kept[path[k]] = 1;
        }
        m_RootEnd = path[base];
        m_Ends.emplace_back(path[base], root);
        m_Ends.emplace_back(path[tip], target);
        first = false;
        continue;
      }
      const std::size_t join = path.back();
      if (!m_Kept[join] || tip + 1 >= path.size())
      {
        continue;
      }
      std::vector<double> radii;
      for (std::size_t k = tip; k + 1 < path.size(); ++k)
      {
        radii.push_back(D(path[k]));
      }
      std::nth_element(radii.begin(), radii.begin() + static_cast<long>(radii.size() / 2), radii.end());
      if (m_Length[path[tip]] - m_Length[join] - D(join) < 2.0 * radii[radii.size() / 2])
      {
        continue;
      }
      for (std::size_t k = tip; k < path.size(); ++k)
      {
        m_Kept[path[k]] = 1;
      }
      m_Ends.emplace_back(path[tip], target);
    }
    return true;
  }

  void
  TraceComponent(const std::vector<std::size_t> & members, itk::CenterlineTree & tree)
  {
    std::size_t deepest = members.front();
    for (const std::size_t voxel : members)
    {
      deepest = D(voxel) > D(deepest) ? voxel : deepest;
    }
    Sweep(deepest, false, D(deepest));
    std::size_t farEnd = deepest;
    for (const std::size_t voxel : members)
    {
      farEnd = m_Cost[voxel] > m_Cost[farEnd] ? voxel : farEnd;
    }
    if (!Trace(members, farEnd, D(deepest)))
    {
      return;
    }
    // Again from the widest free end, when that is another.
    auto widest = m_Ends.front();
    for (const auto & end : m_Ends)
    {
      widest = D(end.first) > D(widest.first) ? end : widest;
    }
    if (widest.first != m_RootEnd && !Trace(members, widest.second, D(deepest)))
    {
      return;
    }
    // The kept voxels as a tree, walked from the root end and split where it forks.
    std::vector<std::size_t> kept;
    for (const std::size_t voxel : members)
    {
      if (m_Kept[voxel])
      {
        kept.push_back(voxel);
      }
    }
    std::sort(kept.begin(), kept.end());
    const auto slot = [&](std::size_t voxel)
    { return static_cast<std::size_t>(std::lower_bound(kept.begin(), kept.end(), voxel) - kept.begin()); };
    std::vector<std::vector<std::size_t>> links(kept.size());
    for (const std::size_t voxel : kept)
    {
      const int64_t parent = m_Parent[voxel];
      if (parent >= 0 && m_Kept[static_cast<std::size_t>(parent)])
      {
        links[slot(voxel)].push_back(static_cast<std::size_t>(parent));
        links[slot(static_cast<std::size_t>(parent))].push_back(voxel);
      }
    }
    std::vector<std::pair<std::size_t, std::size_t>> starts; // (from, next)
    for (const std::size_t next : links[slot(m_RootEnd)])
    {
      starts.emplace_back(m_RootEnd, next);
    }
    while (!starts.empty())
    {
      auto [from, current] = starts.back();
      starts.pop_back();
      itk::CenterlineBranch branch;
      branch.Id = static_cast<int>(tree.GetNumberOfBranches()) + 1;
      std::vector<std::size_t> voxels{ from };
      std::size_t              previous = from;
      for (;;)
      {
        voxels.push_back(current);
        const auto & next = links[slot(current)];
        if (next.size() != 2)
        {
          for (const std::size_t child : next)
          {
            if (child != previous)
            {
              starts.emplace_back(current, child);
            }
          }
          break;
        }
        const std::size_t following = next[0] != previous ? next[0] : next[1];
        previous = current;
        current = following;
      }
      for (const std::size_t voxel : voxels)
      {
        MaskImage::IndexType index;
        index[0] = static_cast<long>(voxel % m_Size[0]);
        index[1] = static_cast<long>((voxel / m_Size[0]) % m_Size[1]);
        index[2] = static_cast<long>(voxel / (m_Size[0] * m_Size[1]));
        index += m_Mask->GetBufferedRegion().GetIndex() - MaskImage::IndexType{ { 0, 0, 0 } };
        itk::Point<double, 3> point;
        m_Mask->TransformIndexToPhysicalPoint(index, point);
        branch.Points.push_back(point);
        branch.Radii.push_back(D(voxel));
      }
      tree.AddBranch(std::move(branch));
    }
  }

  const MaskImage *                                m_Mask;
  DistanceImage::Pointer                           m_Distance;
  long                                             m_Size[3]{};
  double                                           m_Spacing[3]{};
  std::vector<double>                              m_Cost;
  std::vector<int64_t>                             m_Parent;
  std::vector<double>                              m_Length;
  std::vector<uint8_t>                             m_Covered;
  std::vector<uint8_t>                             m_Kept;
  std::size_t                                      m_RootEnd{ 0 };
  std::vector<std::pair<std::size_t, std::size_t>> m_Ends; // (trimmed end, untrimmed end)
};
} // namespace

itk::CenterlineTree
PlainCenterlineExtraction(const itk::Image<unsigned char, 3> * mask)
{
  return PlainTracer(mask).Run();
}
} // namespace vr::test
