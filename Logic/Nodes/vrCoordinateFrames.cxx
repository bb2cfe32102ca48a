// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCoordinateFrames.h"
#include "vrText.h"

#include "vrInputError.h"

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cctype>

namespace vr
{
namespace
{
/** Negates the first two components of every tuple of \a array. */
void
NegateXY(vtkDataArray * array)
{
  for (vtkIdType k = 0; k < array->GetNumberOfTuples(); ++k)
  {
    array->SetComponent(k, 0, -array->GetComponent(k, 0));
    array->SetComponent(k, 1, -array->GetComponent(k, 1));
  }
}
} // namespace

vtkSmartPointer<vtkPolyData>
ConvertPolyDataSpace(vtkPolyData * polyData, CoordinateSpace from, CoordinateSpace to)
{
  if (polyData == nullptr)
  {
    return nullptr;
  }
  auto converted = vtkSmartPointer<vtkPolyData>::New();
  converted->ShallowCopy(polyData);
  if (from == CoordinateSpace::Auto || to == CoordinateSpace::Auto || from == to)
  {
    return converted;
  }
  if (polyData->GetPoints() != nullptr)
  {
    auto points = vtkSmartPointer<vtkPoints>::New();
    points->DeepCopy(polyData->GetPoints());
    NegateXY(points->GetData());
    converted->SetPoints(points);
  }
  // As 3D Slicer's vtkMRMLModelStorageNode (a vtkTransformPolyDataFilter scaling by (-1, -1, 1)): normals and
  // vectors turn with the points. The copy has attribute containers of its own (ShallowCopy shares the arrays only).
  const auto negated = [](vtkDataArray * array)
  {
    vtkSmartPointer<vtkDataArray> copy;
    copy.TakeReference(array->NewInstance());
    copy->DeepCopy(array);
    NegateXY(copy);
    return copy;
  };
  if (vtkDataArray * normals = polyData->GetPointData()->GetNormals())
  {
    converted->GetPointData()->SetNormals(negated(normals));
  }
  if (vtkDataArray * vectors = polyData->GetPointData()->GetVectors())
  {
    converted->GetPointData()->SetVectors(negated(vectors));
  }
  if (vtkDataArray * normals = polyData->GetCellData()->GetNormals())
  {
    converted->GetCellData()->SetNormals(negated(normals));
  }
  return converted;
}

const char *
ToString(CoordinateSpace space)
{
  switch (space)
  {
    case CoordinateSpace::RAS:
      return "RAS";
    case CoordinateSpace::LPS:
      return "LPS";
    default:
      return "auto";
  }
}

CoordinateSpace
ParseCoordinateSpace(const std::string & text, const std::string & what)
{
  const std::string upper = ToUpper(text);
  if (upper == "RAS")
  {
    return CoordinateSpace::RAS;
  }
  if (upper == "LPS")
  {
    return CoordinateSpace::LPS;
  }
  if (upper == "AUTO")
  {
    return CoordinateSpace::Auto;
  }
  throw InputError(what + ": \"" + text + "\" is not a coordinate system; use RAS, LPS or auto");
}
} // namespace vr
