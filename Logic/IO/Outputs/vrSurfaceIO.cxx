// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrSurfaceIO.h"
#include "vrText.h"

#include "vrAtomicOutput.h"
#include "vrInputError.h"
#include "vrVTKErrorCapture.h"

#include <vtkFieldData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkPolyDataWriter.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace vr
{
namespace
{
/** The space a 3D Slicer marker names: "LPS" or "RAS" anywhere in \a text (Slicer matches substrings too). */
CoordinateSpace
SpaceNamedIn(const std::string & text)
{
  if (text.find("LPS") != std::string::npos)
  {
    return CoordinateSpace::LPS;
  }
  if (text.find("RAS") != std::string::npos)
  {
    return CoordinateSpace::RAS;
  }
  return CoordinateSpace::Auto;
}

/** Writes \a surface, whose points are in \a fileSpace already, marking \a fileSpace (nothing for Auto). */
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
WriteSurface(vtkPolyData * surface, const std::string & path, CoordinateSpace pointSpace, CoordinateSpace fileSpace)
{
  if (fileSpace == CoordinateSpace::Auto)
  {
    fileSpace = pointSpace;
  }
  WriteSurfaceIn(ConvertPolyDataSpace(surface, pointSpace, fileSpace), path, fileSpace);
}

vtkSmartPointer<vtkPolyData>
ReadSurface(const std::string & path, CoordinateSpace pointSpace, CoordinateSpace * fileSpace)
{
  const bool xml = HasExtension(path, ".vtp");
  if (!xml && !HasExtension(path, ".vtk"))
  {
    throw InputError("surface " + path + ": unknown extension; use .vtp (VTK XML) or .vtk (legacy VTK)");
  }
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
  {
    throw InputError("surface " + path + ": no such file");
  }
  vtkSmartPointer<vtkPolyData> surface;
  CoordinateSpace              marked = CoordinateSpace::Auto;
  detail::VTKErrorCapture      capture;
  if (xml)
  {
    auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    capture.Observe(reader);
    reader->SetFileName(path.c_str());
    reader->Update();
    surface = reader->GetOutput();
    auto * space = surface ? vtkStringArray::SafeDownCast(surface->GetFieldData()->GetAbstractArray("SPACE")) : nullptr;
    if (space != nullptr && space->GetNumberOfValues() > 0)
    {
      marked = SpaceNamedIn(space->GetValue(0));
      surface->GetFieldData()->RemoveArray("SPACE");
    }
  }
  else
  {
    auto reader = vtkSmartPointer<vtkPolyDataReader>::New();
    capture.Observe(reader);
    reader->SetFileName(path.c_str());
    if (reader->IsFilePolyData() == 0)
    {
      throw InputError("surface " + path + ": not a legacy VTK file of DATASET POLYDATA");
    }
    reader->Update();
    surface = reader->GetOutput();
    const char *      header = reader->GetHeader();
    const std::string text = header ? header : "";
    marked = text.find("SPACE=LPS") != std::string::npos   ? CoordinateSpace::LPS
             : text.find("SPACE=RAS") != std::string::npos ? CoordinateSpace::RAS
                                                           : CoordinateSpace::Auto;
  }
  if (capture.HasErrors())
  {
    throw InputError("surface " + path + ": not readable (truncated or corrupt?): " + capture.FirstError());
  }
  if (surface == nullptr || surface->GetNumberOfPoints() == 0)
  {
    throw InputError("surface " + path + ": holds no point");
  }
  // 3D Slicer reads a model without a marker as LPS (vtkMRMLModelStorageNode's default).
  const CoordinateSpace stored = marked == CoordinateSpace::Auto ? CoordinateSpace::LPS : marked;
  if (fileSpace != nullptr)
  {
    *fileSpace = stored;
  }
  return ConvertPolyDataSpace(surface, stored, pointSpace == CoordinateSpace::Auto ? stored : pointSpace);
}
} // namespace vr
