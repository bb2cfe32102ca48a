// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrSurfaceIO.h"
#include "vrText.h"

#include "vrAtomicOutput.h"
#include "vrInputError.h"
#include "vrVTKErrorCapture.h"

#include <vtkFieldData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataWriter.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cctype>

namespace vr
{
namespace
{
void
WriteSurfaceIn(vtkPolyData * surface, const std::string & path, CoordinateSpace pointSpace)
{
  const bool xml = HasExtension(path, ".vtp");
  if (!xml && !HasExtension(path, ".vtk"))
  {
    throw InputError("surface output " + path + ": unknown extension; use .vtp (VTK XML) or .vtk (legacy VTK)");
  }
  if (surface == nullptr || surface->GetNumberOfPoints() == 0)
  {
    throw InputError("surface output " + path + ": the surface has no point; nothing written");
  }
  // Mark the space on a shallow copy, leaving the caller's polydata as it was.
  auto marked = vtkSmartPointer<vtkPolyData>::New();
  marked->ShallowCopy(surface);
  if (pointSpace != CoordinateSpace::Auto && xml)
  {
    auto fieldData = vtkSmartPointer<vtkFieldData>::New();
    fieldData->ShallowCopy(surface->GetFieldData());
    fieldData->RemoveArray("SPACE");
    auto spaceArray = vtkSmartPointer<vtkStringArray>::New();
    spaceArray->SetName("SPACE");
    spaceArray->InsertNextValue(ToString(pointSpace));
    fieldData->AddArray(spaceArray);
    marked->SetFieldData(fieldData);
  }

  AtomicOutput            output(path);
  detail::VTKErrorCapture capture;
  int                     written = 0;
  if (xml)
  {
    auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    capture.Observe(writer);
    writer->SetInputData(marked);
    writer->SetFileName(output.TemporaryPath().c_str());
    writer->SetDataModeToBinary();
    written = writer->Write();
  }
  else
  {
    auto writer = vtkSmartPointer<vtkPolyDataWriter>::New();
    capture.Observe(writer);
    writer->SetInputData(marked);
    writer->SetFileName(output.TemporaryPath().c_str());
    writer->SetFileVersion(vtkPolyDataWriter::VTK_LEGACY_READER_VERSION_4_2);
    writer->SetFileTypeToBinary();
    const std::string header = pointSpace == CoordinateSpace::Auto
                                 ? std::string("VesselReformation cut surface")
                                 : std::string("VesselReformation cut surface. SPACE=") + ToString(pointSpace);
    writer->SetHeader(header.c_str());
    written = writer->Write();
  }
  if (written == 0 || capture.HasErrors())
  {
    throw InputError("surface output " + path + ": could not be written: " +
                     (capture.HasErrors() ? capture.FirstError() : std::string("the VTK writer failed")));
  }
  output.Commit();
}
} // namespace

void
WriteSurface(vtkPolyData * surface, const std::string & path)
{
  WriteSurfaceIn(surface, path, CoordinateSpace::Auto);
}

void
WriteSurface(vtkPolyData * surface, const std::string & path, CoordinateSpace pointSpace)
{
  WriteSurfaceIn(surface, path, pointSpace);
}
} // namespace vr
