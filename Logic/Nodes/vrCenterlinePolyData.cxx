// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCenterlinePolyData.h"

#include "vrInputError.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIdList.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStaticPointLocator.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace vr
{
namespace
{
using PointType = itk::CenterlineBranch::PointType;

/** One line cell of the input, in LPS. */
struct Polyline
{
  vtkIdType              CellId{ 0 }; // the polydata cell id (verts come before lines)
  std::vector<PointType> Points;
  std::vector<double>    Radii; // empty when the input has no radius array
};

std::string
FormatPoint(const double xyz[3])
{
  std::ostringstream text;
  text << "(" << xyz[0] << ", " << xyz[1] << ", " << xyz[2] << ")";
  return text.str();
}

double
Distance(const PointType & a, const PointType & b)
{
  return a.EuclideanDistanceTo(b);
}

/** The 3D Slicer "SPACE" field-data string array ("RAS" or "LPS"), Auto when absent. */
CoordinateSpace
SpaceFromFieldData(vtkPolyData * polyData)
{
  vtkFieldData * fieldData = polyData->GetFieldData();
  auto *         spaceArray =
    fieldData == nullptr ? nullptr : vtkStringArray::SafeDownCast(fieldData->GetAbstractArray("SPACE"));
  if (spaceArray == nullptr || spaceArray->GetNumberOfValues() < 1)
  {
    return CoordinateSpace::Auto;
  }
  const std::string value = spaceArray->GetValue(0);
  if (value.find("LPS") != std::string::npos)
  {
    return CoordinateSpace::LPS;
  }
  if (value.find("RAS") != std::string::npos)
  {
    return CoordinateSpace::RAS;
  }
  return CoordinateSpace::Auto;
}

vtkDataArray *
FindRadiusArray(vtkPolyData * polyData, const std::string & sourceName, std::string & arrayName)
{
  for (const char * name : { VMTKRadiusArrayName, SlicerRadiusArrayName })
  {
    vtkAbstractArray * array = polyData->GetPointData()->GetAbstractArray(name);
    if (array == nullptr)
    {
      continue;
    }
    auto * numbers = vtkDataArray::SafeDownCast(array);
    if (numbers == nullptr)
    {
      throw InputError(sourceName + ": point array \"" + name + "\" (radius) holds " + array->GetDataTypeAsString() +
                       " values, not numbers");
    }
    if (numbers->GetNumberOfComponents() != 1)
    {
      throw InputError(sourceName + ": point array \"" + name + "\" (radius) has " +
                       std::to_string(numbers->GetNumberOfComponents()) + " components per point; it needs 1");
    }
    if (numbers->GetNumberOfTuples() != polyData->GetNumberOfPoints())
    {
      throw InputError(sourceName + ": point array \"" + name + "\" (radius) has " +
                       std::to_string(numbers->GetNumberOfTuples()) + " values but the polydata has " +
                       std::to_string(polyData->GetNumberOfPoints()) + " points");
    }
    arrayName = name;
    return numbers;
  }
  arrayName.clear();
  return nullptr;
}

std::vector<Polyline>
ExtractPolylines(vtkPolyData * polyData, bool rasPoints, vtkDataArray * radii, const std::string & sourceName)
{
  vtkCellArray * lines = polyData->GetLines();
  if (lines == nullptr || lines->GetNumberOfCells() == 0)
  {
    std::string what = sourceName + ": holds no polyline (no line cell)";
    if (polyData->GetNumberOfPolys() > 0)
    {
      what += "; it has " + std::to_string(polyData->GetNumberOfPolys()) +
              " polygons, so it looks like a surface, not centerlines";
    }
    throw InputError(what);
  }
  const vtkIdType       firstLineCellId = polyData->GetNumberOfVerts();
  std::vector<Polyline> polylines;
  auto                  cells = vtk::TakeSmartPointer(lines->NewIterator());
  vtkIdType             lineIndex = 0;
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell(), ++lineIndex)
  {
    vtkIdType         count = 0;
    const vtkIdType * ids = nullptr;
    cells->GetCurrentCell(count, ids);
    if (count == 0)
    {
      continue;
    }
    Polyline polyline;
    polyline.CellId = firstLineCellId + lineIndex;
    for (vtkIdType k = 0; k < count; ++k)
    {
      const vtkIdType id = ids[k];
      if (id < 0 || id >= polyData->GetNumberOfPoints())
      {
        throw InputError(sourceName + ": polyline " + std::to_string(lineIndex) + " refers to point " +
                         std::to_string(id) + " but there are " + std::to_string(polyData->GetNumberOfPoints()) +
                         " points");
      }
      double xyz[3];
      polyData->GetPoint(id, xyz);
      if (!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2]))
      {
        throw InputError(sourceName + ": point " + std::to_string(id) + " (polyline " + std::to_string(lineIndex) +
                         ", vertex " + std::to_string(k) + ") has a non-finite coordinate " + FormatPoint(xyz));
      }
      PointType point;
      point[0] = xyz[0];
      point[1] = xyz[1];
      point[2] = xyz[2];
      polyline.Points.push_back(rasPoints ? RASToLPS(point) : point);
      if (radii != nullptr)
      {
        const double radius = radii->GetTuple1(id);
        if (!std::isfinite(radius) || radius < 0.0)
        {
          std::ostringstream what;
          what << sourceName << ": point " << id << " (polyline " << lineIndex << ", vertex " << k << ") has radius "
               << radius << " in point array \"" << radii->GetName() << "\"; radii must be finite and >= 0 mm";
          throw InputError(what.str());
        }
        polyline.Radii.push_back(radius);
      }
    }
    polylines.push_back(std::move(polyline));
  }
  if (polylines.empty())
  {
    throw InputError(sourceName + ": holds no polyline with points (every line cell is empty)");
  }
  return polylines;
}

/** The cell array of branch names: "BranchNames" (what PolyDataFromCenterlineTree writes) or a string cell array
 * other tools name a vessel with ("BranchName", "Name", "Names", "GroupNames"); null when there is none or its
 * length is not the cell count. */
vtkStringArray *
CellNameArray(vtkPolyData * polyData)
{
  for (const char * name : { BranchNamesArrayName, "BranchName", "Name", "Names", "GroupNames" })
  {
    auto * array = vtkStringArray::SafeDownCast(polyData->GetCellData()->GetAbstractArray(name));
    if (array != nullptr && array->GetNumberOfComponents() == 1 &&
        array->GetNumberOfValues() == polyData->GetNumberOfCells())
    {
      return array;
    }
  }
  return nullptr;
}

/** The name a cell carries, or empty. */
std::string
CellName(vtkStringArray * names, vtkIdType cellId)
{
  return names != nullptr && cellId >= 0 && cellId < names->GetNumberOfValues() ? names->GetValue(cellId)
                                                                                : std::string();
}

/** A polyline under construction: indices into the table of all input vertices. */
struct Piece
{
  std::vector<std::size_t> Vertices;
  /** Where each vertex's radius comes from: an attachment takes the shared position but keeps the radius its own
   * polyline gives there (a child's lumen at its start, not the parent's). */
  std::vector<std::size_t> RadiusVertices;
  vtkIdType                CellId{ 0 };
  bool                     Whole{ true }; // exactly one input polyline, not cut
};

/** The VMTK overlapping-paths rule (see the header). */
itk::CenterlineTree
MergeOverlappingPolylines(const std::vector<Polyline> & polylines,
                          vtkPolyData *                 polyData,
                          double                        tolerance,
                          CenterlineReadReport &        report)
{
  // Every vertex of every polyline, with the polyline it belongs to.
  std::vector<PointType>   positions;
  std::vector<double>      radii;
  std::vector<std::size_t> owner;
  std::vector<std::size_t> firstVertex;
  auto                     points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  for (std::size_t line = 0; line < polylines.size(); ++line)
  {
    firstVertex.push_back(positions.size());
    for (std::size_t k = 0; k < polylines[line].Points.size(); ++k)
    {
      positions.push_back(polylines[line].Points[k]);
      radii.push_back(polylines[line].Radii.empty() ? 0.0 : polylines[line].Radii[k]);
      owner.push_back(line);
      points->InsertNextPoint(positions.back().GetDataPointer());
    }
  }
  firstVertex.push_back(positions.size());
  const bool hasRadii = !polylines.front().Radii.empty();

  auto cloud = vtkSmartPointer<vtkPolyData>::New();
  cloud->SetPoints(points);
  auto locator = vtkSmartPointer<vtkStaticPointLocator>::New();
  locator->SetDataSet(cloud);
  locator->BuildLocator();

  // canonical[g]: the first vertex (of an earlier polyline) that vertex g repeats, or g itself.
  std::vector<std::size_t> canonical(positions.size());
  std::vector<bool>        repeated(positions.size(), false);
  auto                     nearby = vtkSmartPointer<vtkIdList>::New();
  for (std::size_t g = 0; g < positions.size(); ++g)
  {
    canonical[g] = g;
    if (owner[g] == 0)
    {
      continue;
    }
    locator->FindPointsWithinRadius(tolerance, positions[g].GetDataPointer(), nearby);
    double best = std::numeric_limits<double>::infinity();
    for (vtkIdType n = 0; n < nearby->GetNumberOfIds(); ++n)
    {
      const auto candidate = static_cast<std::size_t>(nearby->GetId(n));
      if (owner[candidate] < owner[g] && Distance(positions[candidate], positions[g]) < best)
      {
        best = Distance(positions[candidate], positions[g]);
        canonical[g] = canonical[candidate];
        repeated[g] = true;
      }
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
        ++report.MergedPoints;
        ++g;
        continue;
      }
      std::size_t runEnd = g;
      while (runEnd < end && !repeated[runEnd])
      {
        ++runEnd;
      }
      Piece piece;
      piece.CellId = polylines[line].CellId;
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
        part.CellId = piece.CellId;
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

  // Branch ids from the writer's cell array when every polyline came back as exactly one branch.
  std::vector<int> ids;
  auto *        branchIds = vtkDataArray::SafeDownCast(polyData->GetCellData()->GetAbstractArray(BranchIdsArrayName));
  bool          useStoredIds = branchIds != nullptr && branchIds->GetNumberOfComponents() == 1;
  std::set<int> seen;
  for (std::size_t p = 0; p < cut.size(); ++p)
  {
    if (useStoredIds && cut[p].Whole && cut[p].CellId < branchIds->GetNumberOfTuples())
    {
      const double stored = branchIds->GetTuple1(cut[p].CellId);
      useStoredIds = stored >= 1.0 && stored == std::floor(stored) && stored < std::numeric_limits<int>::max() &&
                     seen.insert(static_cast<int>(stored)).second;
      ids.push_back(static_cast<int>(stored));
    }
    else
    {
      useStoredIds = false;
    }
  }

  // Each piece keeps the name of the polyline it came from: a trunk cut where a child leaves stays that vessel.
  vtkStringArray *    names = CellNameArray(polyData);
  itk::CenterlineTree tree;
  int                 nextId = 1;
  std::size_t         kept = 0;
  for (std::size_t p = 0; p < cut.size(); ++p)
  {
    itk::CenterlineBranch branch;
    branch.Id = useStoredIds ? ids[kept] : nextId++;
    branch.Name = CellName(names, cut[p].CellId);
    ++kept;
    for (std::size_t k = 0; k < cut[p].Vertices.size(); ++k)
    {
      branch.Points.push_back(positions[cut[p].Vertices[k]]);
      if (hasRadii)
      {
        branch.Radii.push_back(radii[cut[p].RadiusVertices[k]]);
      }
    }
    tree.AddBranch(std::move(branch));
  }
  return tree;
}

/** \a points resampled to \a count points evenly spaced in arc length (the ends kept). */
Polyline
ResampleByArcLength(const Polyline & input, std::size_t count)
{
  Polyline output;
  output.CellId = input.CellId;
  std::vector<double> arc(input.Points.size(), 0.0);
  for (std::size_t k = 1; k < input.Points.size(); ++k)
  {
    arc[k] = arc[k - 1] + Distance(input.Points[k - 1], input.Points[k]);
  }
  const double length = arc.back();
  for (std::size_t j = 0; j < count; ++j)
  {
    const double target = count == 1 ? 0.0 : length * static_cast<double>(j) / static_cast<double>(count - 1);
    std::size_t  segment = static_cast<std::size_t>(std::upper_bound(arc.begin(), arc.end(), target) - arc.begin());
    segment = std::min(std::max<std::size_t>(segment, 1), input.Points.size() - 1);
    if (input.Points.size() == 1)
    {
      output.Points.push_back(input.Points[0]);
      if (!input.Radii.empty())
      {
        output.Radii.push_back(input.Radii[0]);
      }
      continue;
    }
    const double span = arc[segment] - arc[segment - 1];
    const double t = span > 0.0 ? std::min(1.0, std::max(0.0, (target - arc[segment - 1]) / span)) : 0.0;
    PointType    point;
    for (unsigned int axis = 0; axis < 3; ++axis)
    {
      point[axis] = (1.0 - t) * input.Points[segment - 1][axis] + t * input.Points[segment][axis];
    }
    output.Points.push_back(point);
    if (!input.Radii.empty())
    {
      output.Radii.push_back((1.0 - t) * input.Radii[segment - 1] + t * input.Radii[segment]);
    }
  }
  return output;
}

/** The tracts of one group averaged as vmtkcenterlinemerge does: common count, weights radius^2. */
Polyline
AverageTracts(const std::vector<const Polyline *> & tracts)
{
  if (tracts.size() == 1)
  {
    return *tracts.front();
  }
  std::size_t count = 0;
  for (const Polyline * tract : tracts)
  {
    count = std::max(count, tract->Points.size());
  }
  std::vector<Polyline> resampled;
  for (const Polyline * tract : tracts)
  {
    resampled.push_back(ResampleByArcLength(*tract, count));
  }
  const bool hasRadii = !tracts.front()->Radii.empty();
  Polyline   average;
  average.CellId = tracts.front()->CellId;
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

/** Appends \a tail to \a head, dropping the first point of \a tail when it repeats the last of \a head. */
void
AppendPolyline(Polyline & head, const Polyline & tail, double tolerance)
{
  std::size_t skip = 0;
  if (!head.Points.empty() && !tail.Points.empty() && Distance(head.Points.back(), tail.Points.front()) <= tolerance)
  {
    skip = 1;
  }
  head.Points.insert(head.Points.end(), tail.Points.begin() + static_cast<std::ptrdiff_t>(skip), tail.Points.end());
  if (!tail.Radii.empty())
  {
    head.Radii.insert(head.Radii.end(), tail.Radii.begin() + static_cast<std::ptrdiff_t>(skip), tail.Radii.end());
  }
}

vtkDataArray *
CellArray(vtkPolyData * polyData, const char * name)
{
  auto * array = vtkDataArray::SafeDownCast(polyData->GetCellData()->GetAbstractArray(name));
  return array != nullptr && array->GetNumberOfComponents() == 1 &&
             array->GetNumberOfTuples() == polyData->GetNumberOfCells()
           ? array
           : nullptr;
}

/** The vmtkbranchextractor rule (see the header). */
itk::CenterlineTree
MergeBranchGroups(const std::vector<Polyline> & polylines,
                  vtkPolyData *                 polyData,
                  double                        tolerance,
                  CenterlineReadReport &        report)
{
  vtkDataArray * groupIds = CellArray(polyData, "GroupIds");
  vtkDataArray * blanking = CellArray(polyData, "Blanking");
  vtkDataArray * centerlineIds = CellArray(polyData, "CenterlineIds");
  vtkDataArray * tractIds = CellArray(polyData, "TractIds");

  struct Tract
  {
    std::size_t Polyline;
    long        Group;
    bool        Blanked;
  };
  // The tracts of each path (CenterlineIds) in TractIds order.
  std::map<long, std::map<long, Tract>> paths;
  std::size_t                           inputPoints = 0;
  for (std::size_t line = 0; line < polylines.size(); ++line)
  {
    const vtkIdType cell = polylines[line].CellId;
    const auto      path = static_cast<long>(centerlineIds->GetTuple1(cell));
    const auto      tract = static_cast<long>(tractIds->GetTuple1(cell));
    paths[path][tract] = Tract{ line, static_cast<long>(groupIds->GetTuple1(cell)), blanking->GetTuple1(cell) != 0.0 };
    inputPoints += polylines[line].Points.size();
  }

  // Give each blanked tract to the tract after it; note each tract's upstream group.
  std::vector<Polyline>                    extended(polylines.size());
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
      Polyline & target = extended[order[k].Polyline];
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

  std::map<long, Polyline> merged;
  for (const auto & group : groupTracts)
  {
    std::vector<const Polyline *> tracts;
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
    Polyline joint;
    joint.Points.push_back(merged[upstream->second].Points.back());
    if (!merged[upstream->second].Radii.empty())
    {
      joint.Radii.push_back(merged[upstream->second].Radii.back());
    }
    AppendPolyline(joint, group.second, tolerance);
    group.second.Points = std::move(joint.Points);
    group.second.Radii = std::move(joint.Radii);
  }

  // A group is named after its first tract's cell (vmtkbranchextractor copies a path's cell data to its tracts).
  vtkStringArray *    names = CellNameArray(polyData);
  itk::CenterlineTree tree;
  int                 nextId = 1;
  std::size_t         outputPoints = 0;
  for (auto & group : merged)
  {
    itk::CenterlineBranch branch;
    branch.Id = nextId++;
    branch.Name = CellName(names, polylines[groupTracts[group.first].front()].CellId);
    branch.Points = std::move(group.second.Points);
    branch.Radii = std::move(group.second.Radii);
    outputPoints += branch.Points.size();
    tree.AddBranch(std::move(branch));
  }
  report.MergedPoints = inputPoints > outputPoints ? inputPoints - outputPoints : 0;
  report.UsedBranchGroups = true;
  return tree;
}
} // namespace

itk::CenterlineTree
CenterlineTreeFromPolyData(vtkPolyData *                     polyData,
                           CoordinateSpace                   space,
                           const std::string &               sourceName,
                           CenterlineReadReport *            report,
                           const CenterlinePolyDataOptions & options)
{
  if (polyData == nullptr)
  {
    throw InputError(sourceName + ": no polydata given");
  }
  if (!(options.SharedPointTolerance >= 0.0) || !std::isfinite(options.SharedPointTolerance))
  {
    std::ostringstream what;
    what << sourceName << ": SharedPointTolerance " << options.SharedPointTolerance << " mm must be finite and >= 0";
    throw InputError(what.str());
  }
  CenterlineReadReport found;
  found.Format = "polydata";
  if (space == CoordinateSpace::Auto)
  {
    space = SpaceFromFieldData(polyData);
    found.SpaceSource = space == CoordinateSpace::Auto ? "default for centerline polydata (RAS)" : "SPACE field data";
    if (space == CoordinateSpace::Auto)
    {
      space = CoordinateSpace::RAS;
    }
  }
  else
  {
    found.SpaceSource = "given";
  }
  found.FileSpace = space;

  vtkDataArray *              radii = FindRadiusArray(polyData, sourceName, found.RadiusArray);
  const std::vector<Polyline> polylines = ExtractPolylines(polyData, space == CoordinateSpace::RAS, radii, sourceName);
  found.InputPolylines = polylines.size();

  const bool hasBranchGroups =
    CellArray(polyData, "GroupIds") != nullptr && CellArray(polyData, "Blanking") != nullptr &&
    CellArray(polyData, "CenterlineIds") != nullptr && CellArray(polyData, "TractIds") != nullptr;
  itk::CenterlineTree tree = hasBranchGroups
                               ? MergeBranchGroups(polylines, polyData, options.SharedPointTolerance, found)
                               : MergeOverlappingPolylines(polylines, polyData, options.SharedPointTolerance, found);
  if (tree.IsEmpty())
  {
    throw InputError(sourceName + ": no branch left after merging (every polyline is a blanked bifurcation tract)");
  }
  if (report != nullptr)
  {
    const std::string format = report->Format;
    *report = found;
    if (!format.empty())
    {
      report->Format = format;
    }
  }
  return tree;
}

vtkSmartPointer<vtkPolyData>
PolyDataFromCenterlineTree(const itk::CenterlineTree & tree, CoordinateSpace space)
{
  const bool ras = space != CoordinateSpace::LPS;
  auto       points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  auto radii = vtkSmartPointer<vtkDoubleArray>::New();
  radii->SetName(SlicerRadiusArrayName);
  auto ids = vtkSmartPointer<vtkIntArray>::New();
  ids->SetName(BranchIdsArrayName);
  auto names = vtkSmartPointer<vtkStringArray>::New();
  names->SetName(BranchNamesArrayName);
  bool       named = false;
  const bool withRadii = tree.HasRadii();
  for (const auto & branch : tree.GetBranches())
  {
    lines->InsertNextCell(static_cast<vtkIdType>(branch.Points.size()));
    for (std::size_t k = 0; k < branch.Points.size(); ++k)
    {
      const PointType point = ras ? LPSToRAS(branch.Points[k]) : branch.Points[k];
      lines->InsertCellPoint(points->InsertNextPoint(point.GetDataPointer()));
      if (withRadii)
      {
        radii->InsertNextValue(branch.Radii[k]);
      }
    }
    ids->InsertNextValue(branch.Id);
    names->InsertNextValue(branch.Name);
    named = named || !branch.Name.empty();
  }
  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetLines(lines);
  if (withRadii)
  {
    polyData->GetPointData()->AddArray(radii);
  }
  polyData->GetCellData()->AddArray(ids);
  if (named)
  {
    polyData->GetCellData()->AddArray(names);
  }
  auto spaceArray = vtkSmartPointer<vtkStringArray>::New();
  spaceArray->SetName("SPACE");
  spaceArray->InsertNextValue(ras ? "RAS" : "LPS");
  polyData->GetFieldData()->AddArray(spaceArray);
  return polyData;
}
} // namespace vr
