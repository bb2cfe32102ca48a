// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCenterlineFormats.h"
#include "vrText.h"
#include "vrCenterlinePolyData.h"
#include "vrInputError.h"
#include "vrVTKErrorCapture.h"

#include <vtkDoubleArray.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkPolyDataWriter.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cctype>

namespace vr::detail
{
namespace
{
/** 3D Slicer writes "SPACE=RAS" or "SPACE=LPS" into the legacy header line (vtkMRMLModelStorageNode). */
CoordinateSpace
SpaceFromLegacyHeader(const char * header)
{
  const std::string text = header == nullptr ? std::string() : std::string(header);
  if (text.find("SPACE=LPS") != std::string::npos)
  {
    return CoordinateSpace::LPS;
  }
  if (text.find("SPACE=RAS") != std::string::npos)
  {
    return CoordinateSpace::RAS;
  }
  return CoordinateSpace::Auto;
}
} // namespace

itk::CenterlineTree
ReadVTKCenterlines(const std::string & path, CoordinateSpace space, CenterlineReadReport & report)
{
  vtkSmartPointer<vtkPolyData> polyData;
  CoordinateSpace              headerSpace = CoordinateSpace::Auto;
  {
    detail::VTKErrorCapture capture;
    if (HasExtension(path, ".vtp"))
    {
      report.Format = "VTK XML PolyData (.vtp)";
      auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
      capture.Observe(reader);
      reader->SetFileName(path.c_str());
      reader->Update();
      if (capture.HasErrors())
      {
        throw InputError("centerline file " + path +
                         ": not a readable VTK XML PolyData file (truncated or corrupt?): " + capture.FirstError());
      }
      polyData = reader->GetOutput();
    }
    else
    {
      report.Format = "legacy VTK PolyData (.vtk)";
      auto reader = vtkSmartPointer<vtkPolyDataReader>::New();
      capture.Observe(reader);
      reader->SetFileName(path.c_str());
      if (reader->IsFilePolyData() == 0)
      {
        throw InputError("centerline file " + path + ": not a legacy VTK file of DATASET POLYDATA" +
                         (capture.HasErrors() ? ": " + capture.FirstError() : std::string()));
      }
      reader->Update();
      if (capture.HasErrors())
      {
        throw InputError("centerline file " + path +
                         ": not a readable legacy VTK PolyData file (truncated or corrupt?): " + capture.FirstError());
      }
      headerSpace = SpaceFromLegacyHeader(reader->GetHeader());
      polyData = reader->GetOutput();
    }
  }
  if (polyData == nullptr || polyData->GetNumberOfPoints() == 0)
  {
    throw InputError("centerline file " + path + ": holds no point");
  }

  const std::string format = report.Format;
  CoordinateSpace   used = space;
  std::string       source = "override";
  if (space == CoordinateSpace::Auto && headerSpace != CoordinateSpace::Auto)
  {
    used = headerSpace;
    source = std::string("SPACE=") + ToString(headerSpace) + " in the file header";
  }
  itk::CenterlineTree tree = CenterlineTreeFromPolyData(polyData, used, "centerline file " + path, &report);
  report.Format = format;
  if (used != CoordinateSpace::Auto)
  {
    report.SpaceSource = source;
  }
  else if (report.SpaceSource == "SPACE field data")
  {
    report.SpaceSource = "SPACE field data in the file";
  }
  else
  {
    report.SpaceSource = "no SPACE in the file: RAS, the VMTK and 3D Slicer convention";
  }
  return tree;
}

void
WriteVTKCenterlines(const itk::CenterlineTree & tree,
                    const std::string &         finalPath,
                    const std::string &         temporaryPath,
                    CoordinateSpace             space)
{
  const CoordinateSpace        used = space == CoordinateSpace::LPS ? CoordinateSpace::LPS : CoordinateSpace::RAS;
  vtkSmartPointer<vtkPolyData> polyData = PolyDataFromCenterlineTree(tree, used);
  // The radius under VMTK's name as well as 3D Slicer's: vmtk scripts (vmtkcenterlineresampling,
  // vmtkbranchextractor, ...) look for MaximumInscribedSphereRadius, 3D Slicer for Radius.
  if (vtkDataArray * radius = polyData->GetPointData()->GetArray(SlicerRadiusArrayName))
  {
    auto vmtkRadius = vtkSmartPointer<vtkDoubleArray>::New();
    vmtkRadius->DeepCopy(radius);
    vmtkRadius->SetName(VMTKRadiusArrayName);
    polyData->GetPointData()->AddArray(vmtkRadius);
  }
  detail::VTKErrorCapture capture;
  int                     written = 0;
  if (HasExtension(finalPath, ".vtp"))
  {
    auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    capture.Observe(writer);
    writer->SetInputData(polyData);
    writer->SetFileName(temporaryPath.c_str());
    writer->SetDataModeToBinary();
    written = writer->Write();
  }
  else
  {
    auto writer = vtkSmartPointer<vtkPolyDataWriter>::New();
    capture.Observe(writer);
    writer->SetInputData(polyData);
    writer->SetFileName(temporaryPath.c_str());
    // Version 4.2 is what 3D Slicer writes: VMTK and VTK < 9 cannot read 5.1.
    writer->SetFileVersion(vtkPolyDataWriter::VTK_LEGACY_READER_VERSION_4_2);
    writer->SetFileTypeToBinary();
    const std::string header = std::string("VesselReformation centerlines. SPACE=") + ToString(used);
    writer->SetHeader(header.c_str());
    written = writer->Write();
  }
  if (written == 0 || capture.HasErrors())
  {
    throw InputError("centerline output " + finalPath + ": could not be written: " +
                     (capture.HasErrors() ? capture.FirstError() : std::string("the VTK writer failed")));
  }
}
} // namespace vr::detail
