// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkVesselPath.h"

#include "itkMacro.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

namespace itk
{
namespace
{
/** The nearest point of a polyline to a point: segment index, fraction along it, distance. */
struct NearestOnPolyline
{
  std::size_t Segment{ 0 };
  double      Fraction{ 0.0 };
  double      Distance{ std::numeric_limits<double>::infinity() };
};

NearestOnPolyline
Nearest(const std::vector<Point<double, 3>> & points, const Point<double, 3> & query)
{
  NearestOnPolyline best;
  if (points.size() == 1)
  {
    best.Distance = points[0].EuclideanDistanceTo(query);
    return best;
  }
  for (std::size_t k = 0; k + 1 < points.size(); ++k)
  {
    const Vector<double, 3> edge = points[k + 1] - points[k];
    const double            length2 = edge.GetSquaredNorm();
    double                  t = length2 > 0.0 ? ((query - points[k]) * edge) / length2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    const double distance = (points[k] + edge * t).EuclideanDistanceTo(query);
    if (distance < best.Distance)
    {
      best = { k, t, distance };
    }
  }
  return best;
}

double
RadiusOn(const CenterlineBranch & branch, std::size_t segment, double fraction)
{
  if (!branch.HasRadii())
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  if (segment + 1 >= branch.Radii.size())
  {
    return branch.Radii[segment];
  }
  return branch.Radii[segment] + (branch.Radii[segment + 1] - branch.Radii[segment]) * fraction;
}

std::string
IdList(const CenterlineTree & tree)
{
  std::ostringstream ids;
  for (std::size_t k = 0; k < tree.GetNumberOfBranches(); ++k)
  {
    ids << (k ? ", " : "") << tree.GetBranches()[k].Id;
  }
  return ids.str();
}
} // namespace

std::vector<int>
VesselPath::FindParents(const CenterlineTree & tree)
{
  const auto &      branches = tree.GetBranches();
  const std::size_t count = branches.size();
  struct Candidate
  {
    int               Child;
    int               Parent;
    NearestOnPolyline Where;
  };
  std::vector<Candidate> candidates;
  for (std::size_t b = 0; b < count; ++b)
  {
    Candidate best{ static_cast<int>(b), -1, {} };
    for (std::size_t p = 0; p < count; ++p)
    {
      if (p == b)
      {
        continue;
      }
      const NearestOnPolyline where = Nearest(branches[p].Points, branches[b].Points.front());
      if (where.Distance < best.Where.Distance)
      {
        best.Parent = static_cast<int>(p);
        best.Where = where;
      }
    }
    if (best.Parent >= 0)
    {
      const double radius = RadiusOn(branches[best.Parent], best.Where.Segment, best.Where.Fraction);
      const double tolerance = std::isnan(radius) ? JunctionTolerance : std::max(JunctionTolerance, radius);
      if (best.Where.Distance <= tolerance)
      {
        candidates.push_back(best);
      }
    }
  }
  // Nearest attachments first; one that would make a branch its own ancestor is left out (two branches that start at
  // the same point each lie on the other's polyline: the first in the tree's order becomes the parent).
  std::stable_sort(candidates.begin(),
                   candidates.end(),
                   [](const Candidate & a, const Candidate & b) { return a.Where.Distance < b.Where.Distance; });
  std::vector<int> parents(count, -1);
  for (const Candidate & candidate : candidates)
  {
    int ancestor = candidate.Parent;
    while (ancestor >= 0 && ancestor != candidate.Child)
    {
      ancestor = parents[ancestor];
    }
    if (ancestor != candidate.Child)
    {
      parents[candidate.Child] = candidate.Parent;
    }
  }
  return parents;
}

VesselPath
VesselPath::FromTree(const CenterlineTree & tree, int endBranchId)
{
  tree.Validate();
  const auto &           branches = tree.GetBranches();
  const std::vector<int> parents = FindParents(tree);

  // The chain from a root to branch index `end`, as indices.
  const auto chainTo = [&](int end)
  {
    std::vector<int> chain;
    for (int b = end; b >= 0; b = parents[b])
    {
      chain.push_back(b);
    }
    std::reverse(chain.begin(), chain.end());
    return chain;
  };
  const auto build = [&](const std::vector<int> & chain)
  {
    VesselPath path;
    path.m_HasRadii = tree.HasRadii();
    const auto append = [&](const PointType & point, double radius, int id)
    {
      if (!path.m_Points.empty() && path.m_Points.back().EuclideanDistanceTo(point) <= 1e-9)
      {
        return; // a repeated point would give a segment without direction
      }
      path.m_Points.push_back(point);
      path.m_Radii.push_back(path.m_HasRadii ? radius : std::numeric_limits<double>::quiet_NaN());
      path.m_BranchIds.push_back(id);
    };
    for (std::size_t m = 0; m < chain.size(); ++m)
    {
      const CenterlineBranch & branch = branches[chain[m]];
      path.m_BranchChain.push_back(branch.Id);
      std::size_t       last = branch.Points.size() - 1;
      NearestOnPolyline junction;
      const bool        hasNext = m + 1 < chain.size();
      if (hasNext)
      {
        junction = Nearest(branch.Points, branches[chain[m + 1]].Points.front());
        last = junction.Segment;
      }
      for (std::size_t k = 0; k <= last; ++k)
      {
        append(branch.Points[k], branch.HasRadii() ? branch.Radii[k] : 0.0, branch.Id);
      }
      if (hasNext && branch.Points.size() > 1)
      {
        const PointType at =
          branch.Points[junction.Segment] +
          (branch.Points[junction.Segment + 1] - branch.Points[junction.Segment]) * junction.Fraction;
        append(at, RadiusOn(branch, junction.Segment, junction.Fraction), branch.Id);
      }
    }
    path.Finish();
    return path;
  };

  if (endBranchId != 0)
  {
    const auto found = std::find_if(
      branches.begin(), branches.end(), [endBranchId](const CenterlineBranch & b) { return b.Id == endBranchId; });
    if (found == branches.end())
    {
      itkGenericExceptionMacro(<< "VesselPath: the centerline tree has no branch " << endBranchId
                               << " (its ids: " << IdList(tree) << ")");
    }
    VesselPath path = build(chainTo(static_cast<int>(found - branches.begin())));
    if (!(path.GetLength() > 0.0))
    {
      itkGenericExceptionMacro(<< "VesselPath: the path to branch " << endBranchId << " has no length");
    }
    return path;
  }

  // Every branch's far end is a leaf of the tree: a child joins its parent's polyline anywhere along it, often not
  // at its end (a trunk that goes on past the vessels leaving it), so the far end of a branch with children is
  // still an end of the tree.
  VesselPath longest;
  for (std::size_t b = 0; b < branches.size(); ++b)
  {
    VesselPath candidate = build(chainTo(static_cast<int>(b)));
    if (candidate.GetLength() > longest.GetLength())
    {
      longest = std::move(candidate);
    }
  }
  if (!(longest.GetLength() > 0.0))
  {
    itkGenericExceptionMacro(<< "VesselPath: no root-to-leaf path of the centerline tree has any length");
  }
  return longest;
}

void
VesselPath::Finish()
{
  m_ArcLengths.assign(m_Points.size(), 0.0);
  std::vector<double> spacings;
  for (std::size_t k = 1; k < m_Points.size(); ++k)
  {
    const double step = m_Points[k - 1].EuclideanDistanceTo(m_Points[k]);
    m_ArcLengths[k] = m_ArcLengths[k - 1] + step;
    spacings.push_back(step);
  }
  if (!spacings.empty())
  {
    std::nth_element(spacings.begin(), spacings.begin() + spacings.size() / 2, spacings.end());
    m_TangentHalfWindow = std::max(DefaultTangentHalfWindow, spacings[spacings.size() / 2]);
  }
}

std::size_t
VesselPath::Locate(double s, double & fraction) const
{
  const std::size_t count = m_ArcLengths.size();
  if (count < 2)
  {
    fraction = 0.0;
    return 0;
  }
  s = std::clamp(s, 0.0, m_ArcLengths.back());
  const auto  upper = std::upper_bound(m_ArcLengths.begin(), m_ArcLengths.end(), s);
  std::size_t k = upper == m_ArcLengths.begin() ? 0 : static_cast<std::size_t>(upper - m_ArcLengths.begin()) - 1;
  k = std::min(k, count - 2);
  const double length = m_ArcLengths[k + 1] - m_ArcLengths[k];
  fraction = length > 0.0 ? std::clamp((s - m_ArcLengths[k]) / length, 0.0, 1.0) : 0.0;
  return k;
}

auto
VesselPath::PointAt(double s) const -> PointType
{
  if (m_Points.size() < 2)
  {
    return m_Points.empty() ? PointType() : m_Points.front();
  }
  double            fraction;
  const std::size_t k = Locate(s, fraction);
  return m_Points[k] + (m_Points[k + 1] - m_Points[k]) * fraction;
}

auto
VesselPath::TangentAt(double s) const -> VectorType
{
  const double length = GetLength();
  VectorType   chord =
    PointAt(std::min(length, s + m_TangentHalfWindow)) - PointAt(std::max(0.0, s - m_TangentHalfWindow));
  if (chord.GetNorm() <= 1e-12)
  {
    // A hairpin tighter than the chord: the segment's own direction.
    double            fraction;
    const std::size_t k = Locate(s, fraction);
    chord = m_Points[k + 1] - m_Points[k];
  }
  chord.Normalize();
  return chord;
}

double
VesselPath::RadiusAt(double s) const
{
  if (!m_HasRadii || m_Points.size() < 2)
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  double            fraction;
  const std::size_t k = Locate(s, fraction);
  return m_Radii[k] + (m_Radii[k + 1] - m_Radii[k]) * fraction;
}

int
VesselPath::BranchIdAt(double s) const
{
  if (m_Points.size() < 2)
  {
    return m_BranchIds.empty() ? 0 : m_BranchIds.front();
  }
  double            fraction;
  const std::size_t k = Locate(s, fraction);
  return m_BranchIds[k + 1];
}

std::vector<double>
VesselPath::SampleArcLengths(double step) const
{
  if (!(std::isfinite(step) && step > 0.0))
  {
    itkGenericExceptionMacro(<< "VesselPath: the section step " << step << " mm must be finite and > 0");
  }
  const double length = GetLength();
  if (length < step)
  {
    itkGenericExceptionMacro(<< "VesselPath: the path (branches ending at " << BranchIdAt(length) << ") is " << length
                             << " mm long, shorter than one section of " << step << " mm");
  }
  const auto          count = static_cast<std::size_t>(std::floor(length / step + 1e-9)) + 1;
  std::vector<double> samples(count);
  for (std::size_t k = 0; k < count; ++k)
  {
    samples[k] = std::min(length, static_cast<double>(k) * step);
  }
  return samples;
}

double
VesselPath::ProjectPoint(const PointType & point) const
{
  if (m_Points.size() < 2)
  {
    return 0.0;
  }
  const NearestOnPolyline where = Nearest(m_Points, point);
  return m_ArcLengths[where.Segment] + (m_ArcLengths[where.Segment + 1] - m_ArcLengths[where.Segment]) * where.Fraction;
}

void
VesselPath::SetTangentHalfWindow(double halfWindow)
{
  if (!(std::isfinite(halfWindow) && halfWindow > 0.0))
  {
    itkGenericExceptionMacro(<< "VesselPath: the tangent's half-window " << halfWindow << " mm must be finite and > 0");
  }
  m_TangentHalfWindow = halfWindow;
}

VesselPath
VesselPath::Cut(double begin, double end) const
{
  const double length = GetLength();
  if (!(std::isfinite(begin) && begin >= 0.0 && begin < length))
  {
    itkGenericExceptionMacro(<< "VesselPath: the cut's start " << begin << " mm lies outside the path [0, " << length
                             << "] mm");
  }
  if (!(std::isfinite(end) && end > begin && end <= length))
  {
    itkGenericExceptionMacro(<< "VesselPath: the cut's end " << end << " mm must lie after its start " << begin
                             << " mm and within the path's length " << length << " mm");
  }
  VesselPath cut;
  cut.m_HasRadii = m_HasRadii;
  cut.m_ArcLengthOffset = m_ArcLengthOffset + begin;
  const auto add = [&](const PointType & point, double radius, int id)
  {
    if (!cut.m_Points.empty() && cut.m_Points.back().EuclideanDistanceTo(point) <= 1e-9)
    {
      return;
    }
    cut.m_Points.push_back(point);
    cut.m_Radii.push_back(radius);
    cut.m_BranchIds.push_back(id);
  };
  add(PointAt(begin), RadiusAt(begin), BranchIdAt(begin));
  for (std::size_t k = 0; k < m_Points.size(); ++k)
  {
    if (m_ArcLengths[k] > begin && m_ArcLengths[k] < end)
    {
      add(m_Points[k], m_Radii[k], m_BranchIds[k]);
    }
  }
  add(PointAt(end), RadiusAt(end), BranchIdAt(end));
  for (const int id : cut.m_BranchIds)
  {
    if (cut.m_BranchChain.empty() || cut.m_BranchChain.back() != id)
    {
      cut.m_BranchChain.push_back(id);
    }
  }
  cut.Finish();
  // Keep the whole path's tangent window, so a cut does not change the tangents it shares with its path.
  cut.m_TangentHalfWindow = m_TangentHalfWindow;
  return cut;
}

} // namespace itk
