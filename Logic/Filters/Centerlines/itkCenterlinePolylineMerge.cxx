// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkCenterlinePolylineMerge.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <unordered_map>

namespace itk
{
namespace
{
using PointType = CenterlinePolyline::PointType;

/** The points within a distance of a query point, among those inserted so far: a hash of cubic cells of that
 * distance's size, so that a query looks at the 27 cells around it. With a distance of 0, only equal points. */
class PointNeighbourhood
{
public:
  explicit PointNeighbourhood(double distance)
    : m_Distance(distance)
    , m_Cell(distance > 0.0 ? distance : 1.0)
  {
  }

  void
  Insert(const PointType & point, std::size_t index)
  {
    m_Cells[Key(CellOf(point))].push_back({ point, index });
  }

  /** Calls \a visit(index, distance) for each inserted point within the distance of \a point, by cell. */
  template<typename TVisit>
  void
  Visit(const PointType & point, TVisit visit) const
  {
    const std::array<long long, 3> centre = CellOf(point);
    for (long long dx = -1; dx <= 1; ++dx)
    {
      for (long long dy = -1; dy <= 1; ++dy)
      {
        for (long long dz = -1; dz <= 1; ++dz)
        {
          const auto found = m_Cells.find(Key({ centre[0] + dx, centre[1] + dy, centre[2] + dz }));
          if (found == m_Cells.end())
          {
            continue;
          }
          for (const Entry & entry : found->second)
          {
            const double distance = entry.Point.EuclideanDistanceTo(point);
            if (distance <= m_Distance)
            {
              visit(entry.Index, distance);
            }
          }
        }
      }
    }
  }

private:
  struct Entry
  {
    PointType   Point;
    std::size_t Index;
  };

  std::array<long long, 3>
  CellOf(const PointType & point) const
  {
    // Cells are clamped to +-2^40 (and NaN goes to 0) so that any coordinate a file holds converts to an
    // integer; far points then share a border cell, which only makes its bucket longer, never a wrong answer,
    // because every candidate's true distance is still measured.
    constexpr double         limit = 1099511627776.0;
    std::array<long long, 3> cell{};
    for (unsigned int axis = 0; axis < 3; ++axis)
    {
      const double index = std::floor(point[axis] / m_Cell);
      cell[axis] = std::isnan(index) ? 0LL : static_cast<long long>(std::clamp(index, -limit, limit));
    }
    return cell;
  }

  static std::size_t
  Key(const std::array<long long, 3> & cell)
  {
    // Large odd multipliers spread neighbouring cells; collisions only cost a longer bucket.
    // Unsigned arithmetic: the products wrap by definition instead of overflowing a signed type.
    const auto part = [](long long value, std::uint64_t factor) { return static_cast<std::uint64_t>(value) * factor; };
    return static_cast<std::size_t>(part(cell[0], 73856093U) ^ part(cell[1], 19349663U) ^ part(cell[2], 83492791U));
  }

  double                                              m_Distance;
  double                                              m_Cell;
  std::unordered_map<std::size_t, std::vector<Entry>> m_Cells;
};

/** A polyline under construction: indices into the table of all input vertices. */
struct Piece
{
  std::vector<std::size_t> Vertices;
  /** Where each vertex's radius comes from (see MergeOverlappingPaths). */
  std::vector<std::size_t> RadiusVertices;
  std::size_t              Source{ 0 };
  bool                     Whole{ true };
};

/** Appends \a tail to \a head, dropping the first point of \a tail when it repeats the last of \a head. */
void
AppendPolyline(CenterlinePolyline & head, const CenterlinePolyline & tail, double tolerance)
{
  std::size_t skip = 0;
  if (!head.Points.empty() && !tail.Points.empty() &&
      head.Points.back().EuclideanDistanceTo(tail.Points.front()) <= tolerance)
  {
    skip = 1;
  }
  head.Points.insert(head.Points.end(), tail.Points.begin() + static_cast<std::ptrdiff_t>(skip), tail.Points.end());
  if (!tail.Radii.empty())
  {
    head.Radii.insert(head.Radii.end(), tail.Radii.begin() + static_cast<std::ptrdiff_t>(skip), tail.Radii.end());
  }
}

/** The tracts of one group averaged as vmtkcenterlinemerge does: common count, weights radius^2. */
CenterlinePolyline
AverageTracts(const std::vector<const CenterlinePolyline *> & tracts)
{
  if (tracts.size() == 1)
  {
    return *tracts.front();
  }
  std::size_t count = 0;
  for (const CenterlinePolyline * tract : tracts)
  {
    count = std::max(count, tract->Points.size());
  }
  std::vector<CenterlinePolyline> resampled(tracts.size());
  for (std::size_t k = 0; k < tracts.size(); ++k)
  {
    ResamplePolylineEvenly(tracts[k]->Points, tracts[k]->Radii, count, resampled[k].Points, resampled[k].Radii);
  }
  const bool         hasRadii = !tracts.front()->Radii.empty();
  CenterlinePolyline average;
  average.Source = tracts.front()->Source;
  for (std::size_t j = 0; j < count; ++j)
  {
    double    weightSum = 0.0;
    double    radiusSum = 0.0;
    PointType point;
    point.Fill(0.0);
    for (const auto & tract : resampled)
    {
      const double weight = hasRadii ? tract.Radii[j] * tract.Radii[j] : 1.0;
      weightSum += weight;
      for (unsigned int axis = 0; axis < 3; ++axis)
      {
        point[axis] += weight * tract.Points[j][axis];
      }
      radiusSum += hasRadii ? tract.Radii[j] : 0.0;
    }
    if (weightSum > 0.0)
    {
      for (unsigned int axis = 0; axis < 3; ++axis)
      {
        point[axis] /= weightSum;
      }
    }
    else
    {
      // Every radius zero: a plain mean.
      point.Fill(0.0);
      for (const auto & tract : resampled)
      {
        for (unsigned int axis = 0; axis < 3; ++axis)
        {
          point[axis] += tract.Points[j][axis] / static_cast<double>(resampled.size());
        }
      }
    }
    average.Points.push_back(point);
    if (hasRadii)
    {
      average.Radii.push_back(radiusSum / static_cast<double>(resampled.size()));
    }
  }
  return average;
}
} // namespace

std::vector<CenterlineMergedBranch>
MergeOverlappingPaths(const std::vector<CenterlinePolyline> & polylines, double tolerance, std::size_t & mergedPoints)
{
  mergedPoints = 0;
  std::vector<CenterlineMergedBranch> branches;
  if (polylines.empty())
  {
    return branches;
  }
  // Every vertex of every polyline, with the polyline it belongs to.
  std::vector<PointType>   positions;
  std::vector<double>      radii;
  std::vector<std::size_t> owner;
  std::vector<std::size_t> firstVertex;
  for (std::size_t line = 0; line < polylines.size(); ++line)
  {
    firstVertex.push_back(positions.size());
    for (std::size_t k = 0; k < polylines[line].Points.size(); ++k)
    {
      positions.push_back(polylines[line].Points[k]);
      radii.push_back(polylines[line].Radii.empty() ? 0.0 : polylines[line].Radii[k]);
      owner.push_back(line);
    }
  }
  firstVertex.push_back(positions.size());
  const bool hasRadii = !polylines.front().Radii.empty();

  // canonical[g]: the first vertex (of an earlier polyline) that vertex g repeats, or g itself. The nearest earlier
  // vertex within the tolerance wins, the lowest index among equally near ones.
  std::vector<std::size_t> canonical(positions.size());
  std::vector<bool>        repeated(positions.size(), false);
  PointNeighbourhood       earlier(tolerance);
  for (std::size_t line = 0; line < polylines.size(); ++line)
  {
    for (std::size_t g = firstVertex[line]; g < firstVertex[line + 1]; ++g)
    {
      canonical[g] = g;
      double      best = std::numeric_limits<double>::infinity();
      std::size_t bestIndex = std::numeric_limits<std::size_t>::max();
      earlier.Visit(positions[g],
                    [&](std::size_t candidate, double distance)
                    {
                      if (distance < best || (distance == best && candidate < bestIndex))
                      {
                        best = distance;
                        bestIndex = candidate;
                      }
                    });
      if (bestIndex != std::numeric_limits<std::size_t>::max())
      {
        canonical[g] = canonical[bestIndex];
        repeated[g] = true;
      }
    }
    // A polyline's own points become candidates for the later polylines only.
    for (std::size_t g = firstVertex[line]; g < firstVertex[line + 1]; ++g)
    {
      earlier.Insert(positions[g], g);
    }
  }

  // Each run of new vertices becomes a piece, attached to the shared vertices around it.
  std::vector<Piece> pieces;
  std::vector<bool>  splitHere(positions.size(), false);
  for (std::size_t line = 0; line < polylines.size(); ++line)
  {
    const std::size_t begin = firstVertex[line];
    const std::size_t end = firstVertex[line + 1];
    for (std::size_t g = begin; g < end;)
    {
      if (repeated[g])
      {
        ++mergedPoints;
        ++g;
        continue;
      }
      std::size_t runEnd = g;
      while (runEnd < end && !repeated[runEnd])
      {
        ++runEnd;
      }
      Piece piece;
      piece.Source = polylines[line].Source;
      // Whole: the piece is its polyline, at most an end point replaced by the identical earlier one.
      piece.Whole = (g <= begin + 1 && runEnd + 1 >= end);
      if (g > begin)
      {
        piece.Vertices.push_back(canonical[g - 1]);
        piece.RadiusVertices.push_back(g - 1);
        splitHere[canonical[g - 1]] = true;
      }
      for (std::size_t k = g; k < runEnd; ++k)
      {
        piece.Vertices.push_back(k);
        piece.RadiusVertices.push_back(k);
      }
      if (runEnd < end)
      {
        piece.Vertices.push_back(canonical[runEnd]);
        piece.RadiusVertices.push_back(runEnd);
        splitHere[canonical[runEnd]] = true;
      }
      pieces.push_back(std::move(piece));
      g = runEnd;
    }
  }

  // Cut earlier pieces where a later path leaves or rejoins them.
  std::vector<Piece> cut;
  for (auto & piece : pieces)
  {
    std::size_t start = 0;
    for (std::size_t k = 1; k + 1 < piece.Vertices.size(); ++k)
    {
      if (splitHere[piece.Vertices[k]])
      {
        Piece part;
        part.Source = piece.Source;
        part.Whole = false;
        part.Vertices.assign(piece.Vertices.begin() + start, piece.Vertices.begin() + k + 1);
        part.RadiusVertices.assign(piece.RadiusVertices.begin() + start, piece.RadiusVertices.begin() + k + 1);
        cut.push_back(std::move(part));
        start = k;
      }
    }
    if (start > 0)
    {
      piece.Vertices.erase(piece.Vertices.begin(), piece.Vertices.begin() + start);
      piece.RadiusVertices.erase(piece.RadiusVertices.begin(), piece.RadiusVertices.begin() + start);
      piece.Whole = false;
    }
    cut.push_back(std::move(piece));
  }

  for (const Piece & piece : cut)
  {
    CenterlineMergedBranch branch;
    branch.Polyline.Source = piece.Source;
    branch.Whole = piece.Whole;
    for (std::size_t k = 0; k < piece.Vertices.size(); ++k)
    {
      branch.Polyline.Points.push_back(positions[piece.Vertices[k]]);
      if (hasRadii)
      {
        branch.Polyline.Radii.push_back(radii[piece.RadiusVertices[k]]);
      }
    }
    branches.push_back(std::move(branch));
  }
  return branches;
}

std::vector<CenterlineMergedBranch>
MergeBranchGroups(const std::vector<CenterlinePolyline> &    polylines,
                  const std::vector<CenterlineTractLabels> & labels,
                  double                                     tolerance,
                  std::size_t &                              mergedPoints)
{
  struct Tract
  {
    std::size_t Polyline;
    long        Group;
    bool        Blanked;
  };
  // The tracts of each path in tract order.
  std::map<long, std::map<long, Tract>> paths;
  std::size_t                           inputPoints = 0;
  for (std::size_t line = 0; line < polylines.size() && line < labels.size(); ++line)
  {
    paths[labels[line].Path][labels[line].Tract] = Tract{ line, labels[line].Group, labels[line].Blanked };
    inputPoints += polylines[line].Points.size();
  }

  // Give each blanked tract to the tract after it; note each tract's upstream group.
  std::vector<CenterlinePolyline>          extended(polylines.size());
  std::map<long, std::vector<std::size_t>> groupTracts;
  std::map<long, long>                     upstreamGroup;
  for (const auto & path : paths)
  {
    std::vector<Tract> order;
    for (const auto & tract : path.second)
    {
      order.push_back(tract.second);
    }
    long previousGroup = -1;
    bool hasPrevious = false;
    for (std::size_t k = 0; k < order.size(); ++k)
    {
      if (order[k].Blanked)
      {
        continue;
      }
      CenterlinePolyline & target = extended[order[k].Polyline];
      if (k > 0 && order[k - 1].Blanked)
      {
        target = polylines[order[k - 1].Polyline];
        AppendPolyline(target, polylines[order[k].Polyline], tolerance);
      }
      else
      {
        target = polylines[order[k].Polyline];
      }
      groupTracts[order[k].Group].push_back(order[k].Polyline);
      if (hasPrevious && upstreamGroup.count(order[k].Group) == 0 && previousGroup != order[k].Group)
      {
        upstreamGroup[order[k].Group] = previousGroup;
      }
      previousGroup = order[k].Group;
      hasPrevious = true;
    }
  }

  std::map<long, CenterlinePolyline> merged;
  for (const auto & group : groupTracts)
  {
    std::vector<const CenterlinePolyline *> tracts;
    for (const std::size_t line : group.second)
    {
      tracts.push_back(&extended[line]);
    }
    merged[group.first] = AverageTracts(tracts);
  }
  // Start each child at the end of its (merged) parent so the tree stays connected.
  for (auto & group : merged)
  {
    const auto upstream = upstreamGroup.find(group.first);
    if (upstream == upstreamGroup.end() || merged.count(upstream->second) == 0)
    {
      continue;
    }
    CenterlinePolyline joint;
    joint.Points.push_back(merged[upstream->second].Points.back());
    if (!merged[upstream->second].Radii.empty())
    {
      joint.Radii.push_back(merged[upstream->second].Radii.back());
    }
    AppendPolyline(joint, group.second, tolerance);
    group.second.Points = std::move(joint.Points);
    group.second.Radii = std::move(joint.Radii);
  }

  // A group is named after its first tract (vmtkbranchextractor copies a path's cell data to its tracts).
  std::vector<CenterlineMergedBranch> branches;
  std::size_t                         outputPoints = 0;
  for (auto & group : merged)
  {
    CenterlineMergedBranch branch;
    branch.Polyline = std::move(group.second);
    branch.Polyline.Source = polylines[groupTracts[group.first].front()].Source;
    branch.Whole = false;
    outputPoints += branch.Polyline.Points.size();
    branches.push_back(std::move(branch));
  }
  mergedPoints = inputPoints > outputPoints ? inputPoints - outputPoints : 0;
  return branches;
}
} // namespace itk
