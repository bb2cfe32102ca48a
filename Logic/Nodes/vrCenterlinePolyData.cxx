// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCenterlinePolyData.h"

#include "itkCenterlinePolylineMerge.h"
#include "vrInputError.h"

#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>

namespace vr
{
namespace
{
using PointType = itk::CenterlineBranch::PointType;

std::string
FormatPoint(const double xyz[3])
{
  std::ostringstream text;
  text << "(" << xyz[0] << ", " << xyz[1] << ", " << xyz[2] << ")";
  return text.str();
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

std::vector<itk::CenterlinePolyline>
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
  const vtkIdType                      firstLineCellId = polyData->GetNumberOfVerts();
  std::vector<itk::CenterlinePolyline> polylines;
  auto                                 cells = vtk::TakeSmartPointer(lines->NewIterator());
  vtkIdType                            lineIndex = 0;
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell(), ++lineIndex)
  {
    vtkIdType         count = 0;
    const vtkIdType * ids = nullptr;
    cells->GetCurrentCell(count, ids);
    if (count == 0)
    {
      continue;
    }
    itk::CenterlinePolyline polyline;
    polyline.Source = static_cast<std::size_t>(firstLineCellId + lineIndex);
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

vtkDataArray *
CellArray(vtkPolyData * polyData, const char * name)
{
  auto * array = vtkDataArray::SafeDownCast(polyData->GetCellData()->GetAbstractArray(name));
  return array != nullptr && array->GetNumberOfComponents() == 1 &&
             array->GetNumberOfTuples() == polyData->GetNumberOfCells()
           ? array
           : nullptr;
}

/** The vmtkbranchextractor labels of each polyline, from the cell arrays GroupIds, Blanking, CenterlineIds and
 * TractIds; empty when one of them is missing. */
std::vector<itk::CenterlineTractLabels>
TractLabels(vtkPolyData * polyData, const std::vector<itk::CenterlinePolyline> & polylines)
{
  vtkDataArray *                          groupIds = CellArray(polyData, "GroupIds");
  vtkDataArray *                          blanking = CellArray(polyData, "Blanking");
  vtkDataArray *                          centerlineIds = CellArray(polyData, "CenterlineIds");
  vtkDataArray *                          tractIds = CellArray(polyData, "TractIds");
  std::vector<itk::CenterlineTractLabels> labels;
  if (groupIds == nullptr || blanking == nullptr || centerlineIds == nullptr || tractIds == nullptr)
  {
    return labels;
  }
  for (const auto & polyline : polylines)
  {
    const auto cell = static_cast<vtkIdType>(polyline.Source);
    labels.push_back({ static_cast<long>(groupIds->GetTuple1(cell)),
                       blanking->GetTuple1(cell) != 0.0,
                       static_cast<long>(centerlineIds->GetTuple1(cell)),
                       static_cast<long>(tractIds->GetTuple1(cell)) });
  }
  return labels;
}

/** The merged branches as a tree: ids from the writer's cell array "BranchIds" when every polyline came back as
 * exactly one branch with a distinct id >= 1, else 1, 2, ...; each branch named after the polyline it came from (a
 * trunk cut where a child leaves stays that vessel). */
itk::CenterlineTree
TreeOfBranches(std::vector<itk::CenterlineMergedBranch> merged, vtkPolyData * polyData)
{
  std::vector<int> ids;
  auto *        branchIds = vtkDataArray::SafeDownCast(polyData->GetCellData()->GetAbstractArray(BranchIdsArrayName));
  bool          useStoredIds = branchIds != nullptr && branchIds->GetNumberOfComponents() == 1;
  std::set<int> seen;
  for (const auto & branch : merged)
  {
    const auto cell = static_cast<vtkIdType>(branch.Polyline.Source);
    if (useStoredIds && branch.Whole && cell < branchIds->GetNumberOfTuples())
    {
      const double stored = branchIds->GetTuple1(cell);
      useStoredIds = stored >= 1.0 && stored == std::floor(stored) && stored < std::numeric_limits<int>::max() &&
                     seen.insert(static_cast<int>(stored)).second;
      ids.push_back(static_cast<int>(stored));
    }
    else
    {
      useStoredIds = false;
    }
  }
  vtkStringArray *    names = CellNameArray(polyData);
  itk::CenterlineTree tree;
  for (std::size_t b = 0; b < merged.size(); ++b)
  {
    itk::CenterlineBranch branch;
    branch.Id = useStoredIds ? ids[b] : static_cast<int>(b) + 1;
    branch.Name = CellName(names, static_cast<vtkIdType>(merged[b].Polyline.Source));
    branch.Points = std::move(merged[b].Polyline.Points);
    branch.Radii = std::move(merged[b].Polyline.Radii);
    tree.AddBranch(std::move(branch));
  }
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

  vtkDataArray *                             radii = FindRadiusArray(polyData, sourceName, found.RadiusArray);
  const std::vector<itk::CenterlinePolyline> polylines =
    ExtractPolylines(polyData, space == CoordinateSpace::RAS, radii, sourceName);
  found.InputPolylines = polylines.size();

  // The topology is the tree's business (itkCenterlinePolylineMerge.h); here only VTK's arrays are read.
  const std::vector<itk::CenterlineTractLabels> labels = TractLabels(polyData, polylines);
  found.UsedBranchGroups = !labels.empty();
  itk::CenterlineTree tree = TreeOfBranches(
    labels.empty() ? itk::MergeOverlappingPaths(polylines, options.SharedPointTolerance, found.MergedPoints)
                   : itk::MergeBranchGroups(polylines, labels, options.SharedPointTolerance, found.MergedPoints),
    polyData);
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
