// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCenterlineFormats.h"
#include "vrText.h"
#include "vrCenterlinePolyData.h"
#include "vrInputError.h"
#include "vrText.h"
#include "vrVTKErrorCapture.h"

#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkPolyDataWriter.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
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
/** An attribute of \a element as a whole number in [low, high]; \a fallback when absent. */
long long
WholeAttribute(vtkXMLDataElement * element,
               const char *        name,
               long long           low,
               long long           high,
               long long           fallback,
               const std::string & where)
{
  const char * text = element->GetAttribute(name);
  if (text == nullptr)
  {
    return fallback;
  }
  long long value = 0;
  if (!ParseWholeInteger(Trim(text), value) || value < low || value > high)
  {
    throw InputError(where + ": " + std::string(element->GetName() ? element->GetName() : "element") + " " + name +
                     "=\"" + std::string(text).substr(0, 20) + "\" must be a whole number from " + std::to_string(low) +
                     " to " + std::to_string(high));
  }
  return value;
}

/** Checks the parsed XML of a .vtp before VTK's reader reads its arrays: VTK 9.1 trusts the declared counts and
 * component numbers (Points of 6 components make it leak the points it read; negative or huge counts size its
 * buffers). Every Piece's counts, the Points array's 3 components, and every data array's 1 to 64 components. */
void
CheckVTPStructure(vtkXMLDataElement * root, const std::string & where)
{
  constexpr long long MaximumCount = 100000000;
  if (root == nullptr || root->GetName() == nullptr || std::string(root->GetName()) != "VTKFile")
  {
    throw InputError(where + ": not a VTK XML file (no VTKFile element)");
  }
  const char * type = root->GetAttribute("type");
  if (type == nullptr || std::string(type) != "PolyData")
  {
    throw InputError(where + ": VTKFile type is not PolyData");
  }
  for (int d = 0; d < root->GetNumberOfNestedElements(); ++d)
  {
    vtkXMLDataElement * dataSet = root->GetNestedElement(d);
    if (dataSet->GetName() == nullptr || std::string(dataSet->GetName()) != "PolyData")
    {
      continue;
    }
    for (int p = 0; p < dataSet->GetNumberOfNestedElements(); ++p)
    {
      vtkXMLDataElement * piece = dataSet->GetNestedElement(p);
      if (piece->GetName() == nullptr || std::string(piece->GetName()) != "Piece")
      {
        continue;
      }
      for (const char * count :
           { "NumberOfPoints", "NumberOfVerts", "NumberOfLines", "NumberOfStrips", "NumberOfPolys" })
      {
        WholeAttribute(piece, count, 0, MaximumCount, 0, where);
      }
      for (int s = 0; s < piece->GetNumberOfNestedElements(); ++s)
      {
        vtkXMLDataElement * section = piece->GetNestedElement(s);
        const std::string   sectionName = section->GetName() ? section->GetName() : "";
        for (int a = 0; a < section->GetNumberOfNestedElements(); ++a)
        {
          vtkXMLDataElement * array = section->GetNestedElement(a);
          if (array->GetName() == nullptr || std::string(array->GetName()) != "DataArray")
          {
            continue;
          }
          const long long components = WholeAttribute(array, "NumberOfComponents", 1, 64, 1, where);
          if (sectionName == "Points" && components != 3)
          {
            throw InputError(where + ": the Points array has " + std::to_string(components) +
                             " components; points have 3");
          }
          WholeAttribute(array, "NumberOfTuples", 0, MaximumCount, 0, where);
        }
      }
    }
  }
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
      // The XML first; its declarations are checked before the reader reads the arrays they describe.
      reader->UpdateInformation();
      if (capture.HasErrors())
      {
        throw InputError("centerline file " + path +
                         ": not a readable VTK XML PolyData file (truncated or corrupt?): " + capture.FirstError());
      }
      CheckVTPStructure(reader->GetXMLParser() ? reader->GetXMLParser()->GetRootElement() : nullptr,
                        "centerline file " + path);
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
      CheckLegacyVTKPolyData(path);
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
  detail::VTKErrorCapture      capture;
  int                          written = 0;
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
