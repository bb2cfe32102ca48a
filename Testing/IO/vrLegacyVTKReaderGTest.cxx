// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The legacy .vtk polyline reader (issue 25) against VTK's own vtkPolyDataReader, the independent reference here
// (and only here): every valid .vtk of the fuzz corpus, what the centerline writer writes, hand-written files with
// every section the reader accepts, and VMTK's aorta centerlines written by vtkPolyDataWriter in ASCII and binary,
// versions 4.2 and 5.1. Then the files it must refuse, by name.
#include "vrCenterlineIO.h"
#include "vrInputError.h"
#include "vrLegacyVTKReader.h"
#include "vrTestFiles.h"
#include "vrTestImages.h"

#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkIdList.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkPolyDataWriter.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace
{
using vr::test::InputErrorOf;

#define EXPECT_MESSAGE_HAS(message, part)                                                                              \
  EXPECT_NE((message).find(part), std::string::npos) << "message: " << (message) << "\nmissing: " << (part)

/** VTK's reader, keeping every array (by default it keeps only the first SCALARS, VECTORS, ... of a section). */
vtkSmartPointer<vtkPolyData>
ReadWithVTK(const std::string & path)
{
  auto reader = vtkSmartPointer<vtkPolyDataReader>::New();
  reader->SetFileName(path.c_str());
  reader->ReadAllScalarsOn();
  reader->ReadAllVectorsOn();
  reader->ReadAllNormalsOn();
  reader->ReadAllTensorsOn();
  reader->ReadAllTCoordsOn();
  reader->ReadAllFieldsOn();
  reader->Update();
  return reader->GetOutput();
}

void
ExpectSameArrays(vtkFieldData * ours, vtkFieldData * reference, const std::string & where)
{
  ASSERT_EQ(ours->GetNumberOfArrays(), reference->GetNumberOfArrays()) << where;
  for (int a = 0; a < reference->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray * expected = reference->GetAbstractArray(a);
    ASSERT_NE(expected->GetName(), nullptr) << where;
    const std::string  name = expected->GetName();
    vtkAbstractArray * actual = ours->GetAbstractArray(name.c_str());
    ASSERT_NE(actual, nullptr) << where << ": no array \"" << name << "\"";
    EXPECT_EQ(actual->GetDataType(), expected->GetDataType()) << where << " " << name;
    ASSERT_EQ(actual->GetNumberOfComponents(), expected->GetNumberOfComponents()) << where << " " << name;
    ASSERT_EQ(actual->GetNumberOfTuples(), expected->GetNumberOfTuples()) << where << " " << name;
    auto * expectedStrings = vtkStringArray::SafeDownCast(expected);
    auto * actualStrings = vtkStringArray::SafeDownCast(actual);
    auto * expectedNumbers = vtkDataArray::SafeDownCast(expected);
    auto * actualNumbers = vtkDataArray::SafeDownCast(actual);
    if (expectedStrings != nullptr)
    {
      ASSERT_NE(actualStrings, nullptr) << where << " " << name;
      for (vtkIdType k = 0; k < expected->GetNumberOfValues(); ++k)
      {
        EXPECT_EQ(actualStrings->GetValue(k), expectedStrings->GetValue(k)) << where << " " << name << " value " << k;
      }
      continue;
    }
    ASSERT_NE(expectedNumbers, nullptr) << where << " " << name;
    ASSERT_NE(actualNumbers, nullptr) << where << " " << name;
    int differences = 0;
    for (vtkIdType t = 0; t < expected->GetNumberOfTuples(); ++t)
    {
      for (int c = 0; c < expected->GetNumberOfComponents(); ++c)
      {
        // NaN read as NaN is the same value (a file may hold "nan"; NaN != NaN would call it a difference).
        const double ourValue = actualNumbers->GetComponent(t, c);
        const double vtkValue = expectedNumbers->GetComponent(t, c);
        const bool   same = ourValue == vtkValue || (std::isnan(ourValue) && std::isnan(vtkValue));
        if (!same && differences++ < 5)
        {
          ADD_FAILURE() << where << " " << name << " tuple " << t << " component " << c << ": "
                        << actualNumbers->GetComponent(t, c) << " instead of " << expectedNumbers->GetComponent(t, c);
        }
      }
    }
    EXPECT_EQ(differences, 0) << where << " " << name;
  }
}

/** The same points (type and values), the same polylines, the same point, cell and field arrays. */
void
ExpectSamePolyData(vtkPolyData * ours, vtkPolyData * reference, const std::string & where)
{
  ASSERT_NE(ours, nullptr) << where;
  ASSERT_NE(reference->GetPoints(), nullptr) << where << ": VTK's reader read no point";
  ASSERT_NE(ours->GetPoints(), nullptr) << where;
  EXPECT_EQ(ours->GetPoints()->GetDataType(), reference->GetPoints()->GetDataType()) << where;
  ASSERT_EQ(ours->GetNumberOfPoints(), reference->GetNumberOfPoints()) << where;
  int differences = 0;
  for (vtkIdType p = 0; p < reference->GetNumberOfPoints(); ++p)
  {
    double a[3];
    double b[3];
    ours->GetPoint(p, a);
    reference->GetPoint(p, b);
    // NaN read as NaN is the same reading (a fuzzed file's point can be one; the centerline checks refuse it later).
    const auto same = [](double x, double y) { return x == y || (std::isnan(x) && std::isnan(y)); };
    differences += same(a[0], b[0]) && same(a[1], b[1]) && same(a[2], b[2]) ? 0 : 1;
  }
  EXPECT_EQ(differences, 0) << where << ": points differ";
  EXPECT_EQ(ours->GetNumberOfVerts() + ours->GetNumberOfPolys() + ours->GetNumberOfStrips(), 0) << where;
  ASSERT_EQ(ours->GetNumberOfLines(), reference->GetNumberOfLines()) << where;
  auto ourCell = vtkSmartPointer<vtkIdList>::New();
  auto referenceCell = vtkSmartPointer<vtkIdList>::New();
  for (vtkIdType c = 0; c < reference->GetNumberOfLines(); ++c)
  {
    ours->GetLines()->GetCellAtId(c, ourCell);
    reference->GetLines()->GetCellAtId(c, referenceCell);
    ASSERT_EQ(ourCell->GetNumberOfIds(), referenceCell->GetNumberOfIds()) << where << " line " << c;
    for (vtkIdType k = 0; k < referenceCell->GetNumberOfIds(); ++k)
    {
      EXPECT_EQ(ourCell->GetId(k), referenceCell->GetId(k)) << where << " line " << c << " id " << k;
    }
  }
  ExpectSameArrays(ours->GetPointData(), reference->GetPointData(), where + " point data");
  ExpectSameArrays(ours->GetCellData(), reference->GetCellData(), where + " cell data");
  ExpectSameArrays(ours->GetFieldData(), reference->GetFieldData(), where + " field data");
  for (vtkDataSetAttributes * data : { static_cast<vtkDataSetAttributes *>(reference->GetPointData()),
                                       static_cast<vtkDataSetAttributes *>(reference->GetCellData()) })
  {
    vtkDataSetAttributes * mine = data == reference->GetPointData()
                                    ? static_cast<vtkDataSetAttributes *>(ours->GetPointData())
                                    : static_cast<vtkDataSetAttributes *>(ours->GetCellData());
    if (data->GetScalars() != nullptr)
    {
      ASSERT_NE(mine->GetScalars(), nullptr) << where << ": no active scalars";
      EXPECT_STREQ(mine->GetScalars()->GetName(), data->GetScalars()->GetName()) << where;
    }
  }
}

void
ExpectSameAsVTK(const std::string & path)
{
  SCOPED_TRACE(path);
  const vr::detail::LegacyVTKPolyData ours = vr::detail::ReadLegacyVTKPolyData(path, "centerline file " + path);
  ExpectSamePolyData(ours.PolyData, ReadWithVTK(path), path);
}

std::string
CorpusFolder()
{
  return std::string(VR_FUZZ_CORPUS_DIR) + "/vtk";
}

// ---------------------------------------------------------------------------------------------------------------

TEST(LegacyVTKReader, EveryValidCorpusFileReadsAsVTKReadsIt)
{
  // The named seeds are valid and must be read; the inputs fuzzing added (fuzz-<SHA-1>, scripts/fuzz.sh) are mostly
  // not, and are compared with VTK's reading where ours accepts them.
  int files = 0;
  int fuzzed = 0;
  for (const auto & entry : std::filesystem::directory_iterator(CorpusFolder()))
  {
    const std::string name = entry.path().filename().string();
    if (name.rfind("crash-", 0) == 0)
    {
      continue;
    }
    if (name.rfind("fuzz-", 0) == 0)
    {
      try
      {
        vr::detail::ReadLegacyVTKPolyData(entry.path().string(), "centerline file " + entry.path().string());
      }
      catch (const vr::InputError &)
      {
        continue;
      }
      ++fuzzed;
    }
    ExpectSameAsVTK(entry.path().string());
    ++files;
  }
  EXPECT_GE(files - fuzzed, 4);
}

TEST(LegacyVTKReader, WhatTheCenterlineWriterWritesReadsAsVTKReadsIt)
{
  vr::test::ScopedTemporaryFolder folder;
  itk::CenterlineTree             tree;
  itk::CenterlineBranch           trunk;
  trunk.Id = 4;
  trunk.Points = { vr::test::P(10.25, -20.5, 30.125), vr::test::P(10.5, -20.0, 25.0), vr::test::P(11.0, -19.75, 20.0) };
  trunk.Radii = { 6.5, 6.25, 6.0 };
  itk::CenterlineBranch child;
  child.Id = 9;
  child.Points = { vr::test::P(11.0, -19.75, 20.0), vr::test::P(7.0, -20.0, 15.5), vr::test::P(3.0, -20.25, 11.0) };
  child.Radii = { 4.0, 3.75, 3.25 };
  tree.AddBranch(trunk);
  tree.AddBranch(child);
  vr::WriteCenterlines(tree, folder.File("ras.vtk"));
  vr::WriteCenterlines(tree, folder.File("lps.vtk"), vr::CoordinateSpace::LPS);
  ExpectSameAsVTK(folder.File("ras.vtk"));
  ExpectSameAsVTK(folder.File("lps.vtk"));
}

/** Every section and array type the reader accepts, in ASCII, against VTK's reader: a dataset FIELD with a string
 * (with an encoded space), CELL_DATA before POINT_DATA, SCALARS of two components, VECTORS, NORMALS,
 * TEXTURE_COORDINATES, a FIELD with NULL_ARRAY, METADATA blocks, Windows line ends, and version 5.1 cells. */
TEST(LegacyVTKReader, HandWrittenSectionsReadAsVTKReadsThem)
{
  vr::test::ScopedTemporaryFolder folder;
  const std::string               v42 = "# vtk DataFile Version 4.2\n"
                                        "hand written\n"
                                        "ascii\n"
                                        "DATASET POLYDATA\n"
                                        "FIELD FieldData 2\n"
                                        "SPACE 1 1 string\n"
                                        "LPS\n"
                                        "Note%20text 1 2 string\n"
                                        "first%20note\n"
                                        "second\n"
                                        "POINTS 4 double\n"
                                        "0 0 0 1.5 0 0\n"
                                        "3 0.25 0 4.5 1e-3 -2\n"
                                        "METADATA\n"
                                        "COMPONENT_NAMES\n"
                                        "x\n"
                                        "y\n"
                                        "z\n"
                                        "\n"
                                        "LINES 2 7\n"
                                        "3 0 1 2\n"
                                        "2 2 3\n"
                                        "CELL_DATA 2\n"
                                        "SCALARS GroupIds int\n"
                                        "LOOKUP_TABLE default\n"
                                        "0 1\n"
                                        "POINT_DATA 4\n"
                                        "SCALARS Radius float 1\n"
                                        "LOOKUP_TABLE default\n"
                                        "2 2.5 3 3.25\n"
                                        "SCALARS Pair double 2\n"
                                        "LOOKUP_TABLE my_table\n"
                                        "1 2 3 4 5 6 7 8\n"
                                        "VECTORS Tangent float\n"
                                        "1 0 0 1 0 0 1 0 0 1 0 0\n"
                                        "NORMALS Normal double\n"
                                        "0 1 0 0 1 0 0 1 0 0 1 0\n"
                                        "TEXTURE_COORDINATES Abscissa 1 float\n"
                                        "0 1.5 3.01 4.9\n"
                                        "FIELD FieldData 3\n"
                                        "MaximumInscribedSphereRadius 1 4 double\n"
                                        "1 2 3 4\n"
                                        "METADATA\n"
                                        "INFORMATION 1\n"
                                        "NAME L2_NORM_RANGE LOCATION vtkDataArray\n"
                                        "DATA 2 1 4\n"
                                        "\n"
                                        "NULL_ARRAY\n"
                                        "Ids 1 4 vtkIdType\n"
                                        "7 8 9 10\n";
  vr::test::WriteTextFile(folder.File("v42.vtk"), v42);
  ExpectSameAsVTK(folder.File("v42.vtk"));

  // Windows line ends (without the strings, which VTK would read with their '\r').
  const std::string fieldBlock =
    "FIELD FieldData 2\nSPACE 1 1 string\nLPS\nNote%20text 1 2 string\nfirst%20note\nsecond\n";
  std::string withoutStrings = v42;
  withoutStrings.erase(withoutStrings.find(fieldBlock), fieldBlock.size());
  std::string crlf;
  for (const char c : withoutStrings)
  {
    crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  }
  vr::test::WriteTextFile(folder.File("crlf.vtk"), crlf);
  ExpectSameAsVTK(folder.File("crlf.vtk"));

  vr::test::WriteTextFile(folder.File("v51.vtk"),
                          "# vtk DataFile Version 5.1\n"
                          "vtk output\n"
                          "ASCII\n"
                          "DATASET POLYDATA\n"
                          "POINTS 4 float\n"
                          "0 0 0 1 0 0 2 0 0 3 0 0\n"
                          "LINES 3 5\n"
                          "OFFSETS vtktypeint64\n"
                          "0 3 5\n"
                          "CONNECTIVITY vtktypeint64\n"
                          "0 1 2 2 3\n"
                          "POINT_DATA 4\n"
                          "SCALARS Radius double 1\n"
                          "LOOKUP_TABLE default\n"
                          "1 2 3 4\n");
  ExpectSameAsVTK(folder.File("v51.vtk"));
  const auto polyData = vr::detail::ReadLegacyVTKPolyData(folder.File("v51.vtk"), "test").PolyData;
  // By hand: two polylines, 0-1-2 and 2-3.
  ASSERT_EQ(polyData->GetNumberOfLines(), 2);
  auto ids = vtkSmartPointer<vtkIdList>::New();
  polyData->GetLines()->GetCellAtId(1, ids);
  ASSERT_EQ(ids->GetNumberOfIds(), 2);
  EXPECT_EQ(ids->GetId(0), 2);
  EXPECT_EQ(ids->GetId(1), 3);
}

/** VMTK's aorta centerlines (read from .vtp by VTK's XML reader) written by vtkPolyDataWriter in ASCII and binary,
 * versions 4.2 and 5.1, with extra arrays that exercise the encodings: a field-data string, a name with a space,
 * a three-component array with component names (a METADATA block), integer and id cell arrays. */
TEST(LegacyVTKReader, AortaWrittenByVTKInEveryFormReadsAsVTKReadsIt)
{
  const std::string data = vr::test::AortaDataFolder();
  if (data.empty())
  {
    GTEST_FAIL() << "VMTK's aorta (vmtk-aorta-mra) is missing from VR_SHARED_DATA_DIR (Testing/Data by default)";
  }
  vr::test::ScopedTemporaryFolder folder;
  for (const std::string name : { "aorta-centerline.vtp", "aorta-centerline-branches.vtp" })
  {
    auto xml = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    xml->SetFileName((data + "/" + name).c_str());
    xml->Update();
    auto polyData = vtkSmartPointer<vtkPolyData>::New();
    polyData->DeepCopy(xml->GetOutput());
    ASSERT_GT(polyData->GetNumberOfLines(), 0) << name;

    auto space = vtkSmartPointer<vtkStringArray>::New();
    space->SetName("SPACE");
    space->InsertNextValue("RAS");
    polyData->GetFieldData()->AddArray(space);
    auto tangent = vtkSmartPointer<vtkFloatArray>::New();
    tangent->SetName("Frenet tangent");
    tangent->SetNumberOfComponents(3);
    tangent->SetComponentName(0, "x");
    tangent->SetComponentName(1, "y");
    tangent->SetComponentName(2, "z");
    tangent->SetNumberOfTuples(polyData->GetNumberOfPoints());
    for (vtkIdType p = 0; p < polyData->GetNumberOfPoints(); ++p)
    {
      tangent->SetTuple3(p, 0.5 * static_cast<double>(p), -1.0 / (1.0 + static_cast<double>(p)), 3.0);
    }
    polyData->GetPointData()->AddArray(tangent);
    auto ids = vtkSmartPointer<vtkIdTypeArray>::New();
    ids->SetName("CellIds");
    for (vtkIdType c = 0; c < polyData->GetNumberOfCells(); ++c)
    {
      ids->InsertNextValue(100 + c);
    }
    polyData->GetCellData()->AddArray(ids);

    for (const bool binary : { false, true })
    {
      for (const int version :
           { vtkPolyDataWriter::VTK_LEGACY_READER_VERSION_4_2, vtkPolyDataWriter::VTK_LEGACY_READER_VERSION_5_1 })
      {
        const std::string path =
          folder.File(name + (binary ? ".binary" : ".ascii") + ".v" + std::to_string(version) + ".vtk");
        auto writer = vtkSmartPointer<vtkPolyDataWriter>::New();
        writer->SetInputData(polyData);
        writer->SetFileName(path.c_str());
        writer->SetFileVersion(version);
        if (binary)
        {
          writer->SetFileTypeToBinary();
        }
        ASSERT_EQ(writer->Write(), 1) << path;
        ExpectSameAsVTK(path);
        // And the whole reader path: a tree as from VTK's own reading of the .vtp.
        EXPECT_EQ(vr::ReadCenterlines(path).GetNumberOfPoints(),
                  vr::ReadCenterlines(data + "/" + name).GetNumberOfPoints())
          << path;
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Refused, by name.

TEST(LegacyVTKReader, FuzzFindingsAreRefusedNamingTheFile)
{
  for (const std::string name : { "crash-two-lines-sections.vtk", "crash-metadata-lines-segv-2.vtk" })
  {
    const std::string path = CorpusFolder() + "/" + name;
    const std::string message = InputErrorOf([&] { vr::ReadCenterlines(path); });
    EXPECT_MESSAGE_HAS(message, "centerline file " + path);
    EXPECT_MESSAGE_HAS(message, "(legacy VTK, line 7)"); // the METADATA block that swallows a LINES section
  }
}

/** A valid ASCII file with \a points (x y z ...) and \a body after the POINTS section. */
std::string
Legacy(const std::string & version, const std::string & afterPoints)
{
  return "# vtk DataFile Version " + version +
         "\nvtk output\nASCII\nDATASET POLYDATA\nPOINTS 3 float\n0 0 0 0 0 10 0 0 20\n" + afterPoints;
}

TEST(LegacyVTKReader, FilesOutsideTheSubsetAreRefusedNamingTheSection)
{
  vr::test::ScopedTemporaryFolder folder;
  const std::string               lines = "LINES 1 4\n3 0 1 2\n";
  const struct
  {
    std::string Text;
    std::string Expected;
  } cases[] = {
    { Legacy("4.2", lines + lines), "a second LINES section (legacy VTK, line 9)" },
    { Legacy("4.2", lines + "POLYGONS 1 4\n3 0 1 2\n"), "POLYGONS are not part of a centerline file" },
    { Legacy("4.2", "VERTICES 1 2\n1 0\n"), "VERTICES are not part of a centerline file" },
    { "# vtk DataFile Version 4.2\nx\nASCII\nDATASET STRUCTURED_POINTS\n",
      "DATASET STRUCTURED_POINTS is not POLYDATA" },
    { "# vtk DataFile Version 6.0\nx\nASCII\nDATASET POLYDATA\n", "the file version \"6.0\"" },
    { "# vtk DataFile Version 4.2\nx\nUTF8\nDATASET POLYDATA\n", "the third line must be ASCII or BINARY" },
    { Legacy("4.2", "POINTS 3 float\n0 0 0 0 0 10 0 0 20\n" + lines), "a second POINTS section" },
    { Legacy("4.2", "LINES 1 4\n3 0 1 7\n"), "LINES: cell 0 uses point 7 of 3" },
    { Legacy("4.2", "LINES 2 4\n3 0 1 2\n"), "LINES: cell 0 declares 3 points, more than the values left" },
    { Legacy("4.2", "LINES 5 4\n3 0 1 2\n"), "LINES: 5 cells cannot fit in 4 values" },
    { Legacy("4.2", "LINES 1 4\n-1 0 1 2\n"), "LINES: cell 0 declares -1 points" },
    { Legacy("4.2", "LINES 1 1000000000\n3 0 1 2\n"), "LINES: 1000000000 values declared, more than the" },
    { Legacy("4.2", "LINES 1 4\n3 0 1 2 5\n"), "LINES: more values than the 4 declared" },
    { Legacy("4.2", "LINES 1 4\n3 0 1 x\n"), "LINES: value 3 \"x\" is not a finite number" },
    { Legacy("5.1", "LINES 2 3\nOFFSETS vtktypeint64\n0 4\nCONNECTIVITY vtktypeint64\n0 1 2\n"),
      "OFFSETS must start at 0 and end at the CONNECTIVITY size 3" },
    { Legacy("5.1", "LINES 3 3\nOFFSETS vtktypeint64\n0 2 1\nCONNECTIVITY vtktypeint64\n0 1 2\n"),
      "LINES: OFFSETS must start at 0 and end" },
    { Legacy("5.1", "LINES 3 3\nOFFSETS vtktypeint64\n0 2 1 3\nCONNECTIVITY vtktypeint64\n0 1 2\n"),
      "LINES OFFSETS: more values than the 3 declared" },
    { Legacy("5.1", "LINES 4 3\nOFFSETS vtktypeint64\n0 2 1 3\nCONNECTIVITY vtktypeint64\n0 1 2\n"),
      "LINES: OFFSETS decrease at entry 2" },
    { Legacy("5.1", "LINES 2 3\nOFFSETS float\n0 3\nCONNECTIVITY vtktypeint64\n0 1 2\n"),
      "LINES OFFSETS: not an integer array" },
    { Legacy("4.2", lines + "POINT_DATA 2\n"), "POINT_DATA 2, but the file has 3 points" },
    { Legacy("4.2", lines + "CELL_DATA 3\n"), "CELL_DATA 3, but the file has 1 cells" },
    { Legacy("4.2", lines + "POINT_DATA 3\nSCALARS r bit\nLOOKUP_TABLE default\n0 1 0\n"), "data type \"bit\"" },
    { Legacy("4.2", lines + "POINT_DATA 3\nSCALARS r float\n1 2 3\n"), "SCALARS r: \"LOOKUP_TABLE name\" expected" },
    { Legacy("4.2", lines + "POINT_DATA 3\nCOLOR_SCALARS c 3\n1 0 0 1 0 0 1 0 0\n"),
      "\"COLOR_SCALARS\" is not a section this reader accepts" },
    { Legacy("4.2", lines + "POINT_DATA 3\nFIELD f 1\na 1 2 float\n1 2\n"),
      "FIELD array a: 2 tuples, but POINT_DATA has 3" },
    { Legacy("4.2",
             lines + "POINT_DATA 3\nSCALARS a float\nLOOKUP_TABLE default\n1 2 3\nFIELD f 1\na 1 3 float\n1 2 3\n"),
      "POINT_DATA: a second array named \"a\"" },
    { Legacy("4.2", lines + "POINT_DATA 3\nSCALARS r float\nLOOKUP_TABLE default\n1 2 3\nMETADATA\nLINES 1 4\n"),
      "METADATA: \"LINES 1 4\" is neither COMPONENT_NAMES nor INFORMATION" },
    { Legacy("4.2", lines + "POINT_DATA 3\nSCALARS r float\nLOOKUP_TABLE default\n1 nan 3\n"),
      "SCALARS r: value 1 \"nan\" is not a finite number" },
    { Legacy("4.2", lines + "POINT_DATA 3\nSCALARS r%2 float\nLOOKUP_TABLE default\n1 2 3\n"),
      "\"%2\" is not a %XX escape" },
    { Legacy("4.2", "POINT_DATA 3\n" + lines), "LINES after POINT_DATA or CELL_DATA" },
    { Legacy("4.2", ""), "no LINES section" },
    { "# vtk DataFile Version 4.2\nx\nASCII\nDATASET POLYDATA\n", "no POINTS section" },
    { Legacy("4.2", "LINES 1 4\n3 0 1\n"), "LINES: 4 values declared, more than the 6 bytes left" },
    { Legacy("4.2", "LINES 1 4\n3 0 1\n\n\n\n"), "LINES: 4 values declared, the file ends after 3" },
  };
  int index = 0;
  for (const auto & c : cases)
  {
    const std::string path = folder.File("case" + std::to_string(index++) + ".vtk");
    vr::test::WriteTextFile(path, c.Text);
    const std::string message = InputErrorOf([&] { vr::ReadCenterlines(path); });
    EXPECT_MESSAGE_HAS(message, "centerline file " + path + ": ");
    EXPECT_MESSAGE_HAS(message, c.Expected);
    EXPECT_MESSAGE_HAS(message, "(legacy VTK, line ");
  }
}

TEST(LegacyVTKReader, BinaryCountsAreCheckedAgainstTheBytesLeft)
{
  vr::test::ScopedTemporaryFolder folder;
  const std::string               header = "# vtk DataFile Version 4.2\nx\nBINARY\nDATASET POLYDATA\n";
  const std::string               points(36, '\0'); // 3 float points, all 0
  const struct
  {
    std::string Text;
    std::string Expected;
  } cases[] = {
    { header + "POINTS 4 float\n" + points, "POINTS: 12 values declared, more than the 36 bytes left" },
    { header + "POINTS 3 float\n" + points + "\nLINES 1 4\n" + std::string("\0\0\0\3\0\0\0\0\0\0\0\1", 12),
      "LINES: 4 values declared, more than the 12 bytes left" },
    { header + "POINTS 3 float\n" + points + "\nLINES 1 4\n" + std::string("\0\0\0\3\0\0\0\0\0\0\0\1\0\0\0\3", 16),
      "LINES: cell 0 uses point 3 of 3" },
    { header + "FIELD FieldData 1\nSPACE 1 1 string\n" + std::string("\xff", 1) + "LPS\n",
      "FIELD array SPACE: string 0 declares 63 bytes, more than remain" },
    { header + "FIELD FieldData 1\nSPACE 1 1 string\n" + std::string("\x00\x00\x01", 3),
      "FIELD array SPACE: string 0 is cut off" },
  };
  int index = 0;
  for (const auto & c : cases)
  {
    const std::string path = folder.File("binary" + std::to_string(index++) + ".vtk");
    vr::test::WriteTextFile(path, c.Text);
    const std::string message = InputErrorOf([&] { vr::ReadCenterlines(path); });
    EXPECT_MESSAGE_HAS(message, "centerline file " + path + ": ");
    EXPECT_MESSAGE_HAS(message, c.Expected);
  }
}
} // namespace
