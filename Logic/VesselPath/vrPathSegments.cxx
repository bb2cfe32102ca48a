// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrPathSegments.h"

#include <algorithm>
#include <cmath>

namespace vr
{
namespace
{
/** Junctions closer than this (mm) cut the path at one place: two branches leaving together, or a side branch at
 * the point where the path changes branch. */
constexpr double SameJunction = 0.5;

const itk::CenterlineBranch *
BranchWithId(const itk::CenterlineTree & tree, int id)
{
  for (const auto & branch : tree.GetBranches())
  {
    if (branch.Id == id)
    {
      return &branch;
    }
  }
  return nullptr;
}
} // namespace

PathLayout
FindPathLayout(const itk::CenterlineTree & tree, const itk::VesselPath & path, bool startCut, bool endCut)
{
  PathLayout layout;
  layout.StartIsVesselEnd = !startCut;
  layout.EndIsVesselEnd = !endCut;
  const double length = path.GetLength();
  const auto & arcLengths = path.GetArcLengths();
  if (arcLengths.size() < 2 || !(length > 0.0))
  {
    return layout;
  }

  // Where the path runs on into the next branch of its chain: segment k (points k to k + 1) belongs to a branch,
  // and the branch changes at the first point of a segment of another branch.
  int previous = path.BranchIdAt(0.5 * (arcLengths[0] + arcLengths[1]));
  for (std::size_t k = 1; k + 1 < arcLengths.size(); ++k)
  {
    const int id = path.BranchIdAt(0.5 * (arcLengths[k] + arcLengths[k + 1]));
    if (id != previous)
    {
      PathJunction junction;
      junction.ArcLength = arcLengths[k];
      junction.BranchId = id;
      junction.OnPath = true;
      // The parent's side: just before the junction.
      junction.ParentRadius = path.RadiusAt(std::max(0.0, arcLengths[k] - 1e-6));
      layout.Junctions.push_back(junction);
      previous = id;
    }
  }

  // Side branches: every other branch whose parent runs along the path and whose start lies on the path there.
  const auto &           branches = tree.GetBranches();
  const std::vector<int> parents = itk::VesselPath::FindParents(tree);
  const auto &           chain = path.GetBranchChain();
  for (std::size_t b = 0; b < branches.size(); ++b)
  {
    const auto & branch = branches[b];
    if (parents[b] < 0 || branch.Points.empty() || std::find(chain.begin(), chain.end(), branch.Id) != chain.end())
    {
      continue;
    }
    const int    parentId = branches[static_cast<std::size_t>(parents[b])].Id;
    const double s = path.ProjectPoint(branch.Points.front());
    if (path.BranchIdAt(s) != parentId)
    {
      continue; // its parent goes on beyond the path's part of it
    }
    const double radius = path.RadiusAt(s);
    const double tolerance =
      std::isnan(radius) ? itk::VesselPath::JunctionTolerance : std::max(itk::VesselPath::JunctionTolerance, radius);
    if (path.PointAt(s).EuclideanDistanceTo(branch.Points.front()) > tolerance)
    {
      continue; // it leaves its parent where the path does not run (a cut path), or only passes near it
    }
    PathJunction junction;
    junction.ArcLength = s;
    junction.BranchId = branch.Id;
    junction.OnPath = false;
    junction.ParentRadius = radius;
    layout.Junctions.push_back(junction);
  }
  std::stable_sort(layout.Junctions.begin(),
                   layout.Junctions.end(),
                   [](const PathJunction & a, const PathJunction & b) { return a.ArcLength < b.ArcLength; });

  // Segments between the junctions (those within SameJunction of each other or of an end cut nothing new).
  std::vector<double> cuts = { 0.0 };
  for (const auto & junction : layout.Junctions)
  {
    if (junction.ArcLength - cuts.back() >= SameJunction && length - junction.ArcLength >= SameJunction)
    {
      cuts.push_back(junction.ArcLength);
    }
  }
  cuts.push_back(length);
  for (std::size_t k = 0; k + 1 < cuts.size(); ++k)
  {
    PathSegment segment;
    segment.Begin = cuts[k];
    segment.End = cuts[k + 1];
    segment.BranchId = path.BranchIdAt(0.5 * (segment.Begin + segment.End));
    if (const itk::CenterlineBranch * branch = BranchWithId(tree, segment.BranchId))
    {
      segment.Name = branch->Name;
    }
    layout.Segments.push_back(segment);
  }
  return layout;
}

std::string
JoinPathNames(const std::vector<std::string> & names)
{
  std::string         joined;
  const std::string * last = nullptr;
  for (const std::string & name : names)
  {
    if (last != nullptr && *last == name)
    {
      continue;
    }
    joined += (last != nullptr ? " → " : "") + name;
    last = &name;
  }
  return joined;
}
} // namespace vr
