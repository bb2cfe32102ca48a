// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Centerline files written by hand (issue 3, docs/design.md "Centerline tree"): each coordinate convention and format,
// then the bad inputs, each a vr::InputError naming the file and what is wrong in it.
#include "vrCenterlineIOTestSupport.h"

namespace
{
using namespace vr::test::centerlineio;

// ---------------------------------------------------------------------------------------------------------------
// Hand-written files.

TEST(HandWrittenCenterlines, LegacyVTKHeaderSpaceDecidesTheFrame)
{
  vr::test::ScopedTemporaryFolder folder;
  auto                            legacy = [](const std::string & header)
  {
    return "# vtk DataFile Version 4.2\n" + header +
           "\nASCII\nDATASET POLYDATA\nPOINTS 4 double\n1 2 3\n4 5 6\n7 8 9\n-1 -2 -3\nLINES 2 7\n3 0 1 2\n2 2 3\n"
           "POINT_DATA 4\nSCALARS Radius double 1\nLOOKUP_TABLE default\n1.5 2.5 3.5 4.5\n";
  };
  vr::test::WriteTextFile(folder.File("lps.vtk"), legacy("3D Slicer output. SPACE=LPS"));
  vr::test::WriteTextFile(folder.File("ras.vtk"), legacy("3D Slicer output. SPACE=RAS"));
  vr::test::WriteTextFile(folder.File("plain.vtk"), legacy("vtk output"));

  vr::CenterlineReadReport  report;
  const itk::CenterlineTree lps = vr::ReadCenterlines(folder.File("lps.vtk"), CoordinateSpace::Auto, &report);
  EXPECT_EQ(report.FileSpace, CoordinateSpace::LPS);
  EXPECT_EQ(report.RadiusArray, "Radius");
  // Two polylines sharing point 2 only: two branches, no merging, points as written.
  ASSERT_EQ(lps.GetNumberOfBranches(), 2U);
  EXPECT_EQ(lps.GetBranches()[0].Points[1], P(4, 5, 6));
  EXPECT_EQ(lps.GetBranches()[1].Points[1], P(-1, -2, -3));
  EXPECT_EQ(lps.GetBranches()[1].Radii[1], 4.5);

  for (const std::string name : { "ras.vtk", "plain.vtk" })
  {
    const itk::CenterlineTree ras = vr::ReadCenterlines(folder.File(name));
    EXPECT_EQ(ras.GetBranches()[0].Points[1], P(-4, -5, 6)) << name;
  }
  // The override wins over the header.
  EXPECT_EQ(vr::ReadCenterlines(folder.File("lps.vtk"), CoordinateSpace::RAS).GetBranches()[0].Points[1], P(-4, -5, 6));
}

TEST(HandWrittenCenterlines, AModelInSlicersOwnLayoutReadsAsCenterlines)
{
  // A VMTK-style centerline model as 3D Slicer's model storage writes it for a command-line module: the points in
  // LPS, the space recorded (a "SPACE" field-data array in .vtp, appended and zlib-compressed; "3D Slicer output.
  // SPACE=LPS" in the binary version 4.2 .vtk header), one polyline per path from the root, overlapping along the
  // trunk, and the maximum inscribed sphere radius as the point array "Radius" (SlicerVMTK's ExtractCenterline).
  vr::test::ScopedTemporaryFolder folder;
  auto                            points = vtkSmartPointer<vtkPoints>::New();
  auto                            lines = vtkSmartPointer<vtkCellArray>::New();
  auto                            radius = vtkSmartPointer<vtkDoubleArray>::New();
  radius->SetName("Radius");
  // Trunk from (10, 20, 0) up to z = 10, then one path bends to +x, the other to -x (LPS mm).
  for (const double side : { 1.0, -1.0 })
  {
    lines->InsertNextCell(21);
    for (int k = 0; k <= 20; ++k)
    {
      const double z = k;
      const double x = 10.0 + (k > 10 ? side * (k - 10) : 0.0);
      lines->InsertCellPoint(points->InsertNextPoint(x, 20.0, z));
      radius->InsertNextValue(k > 10 ? 1.0 : 2.0);
    }
  }
  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetLines(lines);
  polyData->GetPointData()->AddArray(radius);
  {
    auto copy = vtkSmartPointer<vtkPolyData>::New();
    copy->ShallowCopy(polyData);
    auto space = vtkSmartPointer<vtkStringArray>::New();
    space->SetName("SPACE");
    space->InsertNextValue("LPS");
    copy->GetFieldData()->AddArray(space);
    auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    writer->SetInputData(copy);
    writer->SetFileName(folder.File("centerline-model.vtp").c_str());
    writer->SetCompressorType(vtkXMLWriter::ZLIB);
    writer->SetDataMode(vtkXMLWriter::Appended);
    ASSERT_EQ(writer->Write(), 1);
  }
  {
    auto writer = vtkSmartPointer<vtkPolyDataWriter>::New();
    writer->SetInputData(polyData);
    writer->SetFileName(folder.File("centerline-model.vtk").c_str());
    writer->SetFileVersion(42);
    writer->SetFileType(VTK_BINARY);
    writer->SetHeader("3D Slicer output. SPACE=LPS");
    ASSERT_EQ(writer->Write(), 1);
  }
  for (const std::string name : { "centerline-model.vtp", "centerline-model.vtk" })
  {
    vr::CenterlineReadReport  report;
    const itk::CenterlineTree tree = vr::ReadCenterlines(folder.File(name), CoordinateSpace::Auto, &report);
    EXPECT_EQ(report.FileSpace, CoordinateSpace::LPS) << name;
    EXPECT_EQ(report.RadiusArray, "Radius") << name;
    // The shared trunk is one branch, the two bends two more; the points stay where they are (LPS), radii kept.
    ASSERT_EQ(tree.GetNumberOfBranches(), 3U) << name;
    std::size_t trunkPoints = 0;
    for (const auto & branch : tree.GetBranches())
    {
      for (std::size_t k = 0; k < branch.Points.size(); ++k)
      {
        const auto & point = branch.Points[k];
        EXPECT_EQ(point[1], 20.0) << name;
        if (point[2] < 10.0)
        {
          ++trunkPoints;
          EXPECT_EQ(point[0], 10.0) << name;
          EXPECT_EQ(branch.Radii[k], 2.0) << name;
        }
        else if (point[2] > 10.0)
        {
          EXPECT_EQ(std::abs(point[0] - 10.0), point[2] - 10.0) << name;
          EXPECT_EQ(branch.Radii[k], 1.0) << name;
        }
      }
    }
    EXPECT_EQ(trunkPoints, 10U) << name << ": the trunk was not merged into one branch";
  }
}

TEST(HandWrittenCenterlines, CSVInEachHeaderForm)
{
  vr::test::ScopedTemporaryFolder folder;
  vr::test::WriteTextFile(folder.File("lps.csv"),
                          "branch,x,y,z,radius\n1,1,2,3,0.5\n1,4,5,6,0.75\n2,4,5,6,1\n2,7,8,9,2\n");
  vr::test::WriteTextFile(folder.File("ras.csv"), "# a comment\nBranch, R, A, S\n3, 1, 2, 3\n\n3, 4, 5, 6\n");

  const itk::CenterlineTree lps = vr::ReadCenterlines(folder.File("lps.csv"));
  ASSERT_EQ(lps.GetNumberOfBranches(), 2U);
  EXPECT_EQ(lps.GetBranches()[0].Id, 1);
  EXPECT_EQ(lps.GetBranches()[0].Points[1], P(4, 5, 6));
  EXPECT_EQ(lps.GetBranches()[1].Radii[1], 2.0);

  vr::CenterlineReadReport  report;
  const itk::CenterlineTree ras = vr::ReadCenterlines(folder.File("ras.csv"), CoordinateSpace::Auto, &report);
  EXPECT_EQ(report.FileSpace, CoordinateSpace::RAS);
  ASSERT_EQ(ras.GetNumberOfBranches(), 1U);
  EXPECT_EQ(ras.GetBranches()[0].Id, 3);
  EXPECT_EQ(ras.GetBranches()[0].Points[0], P(-1, -2, 3));
  EXPECT_FALSE(ras.HasRadii());

  // The space argument overrides what the header says.
  EXPECT_EQ(vr::ReadCenterlines(folder.File("ras.csv"), CoordinateSpace::LPS).GetBranches()[0].Points[0], P(1, 2, 3));
}

/** A 3D Slicer markups file: curves "A" and "B" in LPS, "C" in RAS, and a point list that is not a branch. */
const char * const ThreeCurves = R"json({
  "@schema": "https://raw.githubusercontent.com/slicer/slicer/master/Modules/Loadable/Markups/Resources/Schema/markups-schema-v1.0.3.json#",
  "markups": [
    { "type": "Curve", "name": "A", "coordinateSystem": "LPS", "coordinateUnits": "mm",
      "controlPoints": [
        { "id": "1", "position": [0.0, 0.0, 0.0], "positionStatus": "defined" },
        { "id": "2", "position": [10.0, 10.0, 0.0], "positionStatus": "defined" },
        { "id": "3", "position": [20.0, 0.0, 0.0], "positionStatus": "defined" } ],
      "measurements": [
        { "name": "length", "enabled": false },
        { "name": "Radius", "enabled": false, "units": "mm", "controlPointValues": [2.0, 4.0, 3.0] } ] },
    { "type": "Fiducial", "name": "F", "coordinateSystem": "LPS",
      "controlPoints": [ { "id": "1", "position": [100.0, 100.0, 100.0] } ] },
    { "type": "Curve", "name": "B", "coordinateSystem": "LPS",
      "controlPoints": [
        { "id": "1", "position": [0.0, 0.0, 5.0] },
        { "id": "2", "position": [0.0, 3.0, 9.0] },
        { "id": "3", "position": [0.0, 6.0, 13.0] },
        { "id": "4", "position": [0.0, 9.0, 17.0] } ] },
    { "type": "Curve", "name": "C", "coordinateSystem": "RAS",
      "controlPoints": [
        { "id": "1", "position": [1.0, 2.0, 3.0] },
        { "id": "2", "position": [5.0, 2.0, 3.0], "positionStatus": "undefined" },
        { "id": "3", "position": [4.0, 6.0, 3.0] } ] }
  ]
})json";

TEST(HandWrittenCenterlines, MarkupsCurvesFollowSlicersSplineInTheirOwnFrames)
{
  vr::test::ScopedTemporaryFolder folder;
  vr::test::WriteTextFile(folder.File("curves.mrk.json"), ThreeCurves);
  vr::CenterlineReadReport  report;
  const itk::CenterlineTree tree = vr::ReadCenterlines(folder.File("curves.mrk.json"), CoordinateSpace::Auto, &report);
  ASSERT_EQ(tree.GetNumberOfBranches(), 3U);
  EXPECT_EQ(report.SpaceSource, "each curve's coordinateSystem (LPS, LPS, RAS)");
  // Each curve's name is its vessel's (the fiducial list between them is no branch).
  EXPECT_EQ(tree.GetBranches()[0].Name, "A");
  EXPECT_EQ(tree.GetBranches()[1].Name, "B");
  EXPECT_EQ(tree.GetBranches()[2].Name, "C");

  const auto & a = tree.GetBranches()[0];
  // Curve A: 3D Slicer interpolates each coordinate with a cardinal spline over the control point index, ends
  // clamped to zero slope. Through x = 0, 10, 20 and y = 0, 10, 0 that is, on the first interval t in [0, 1]
  // (worked by hand: C2 at t = 1 and the curve's symmetry), x = 15 t^2 - 5 t^3 and y = 30 t^2 - 20 t^3; the
  // second interval mirrors it about x = 10.
  ASSERT_GT(a.Points.size(), 20U);
  EXPECT_EQ(a.Points.front(), P(0, 0, 0));
  EXPECT_EQ(a.Points.back(), P(20, 0, 0));
  bool sawApex = false;
  for (const auto & point : a.Points)
  {
    const double x = point[0] <= 10.0 ? point[0] : 20.0 - point[0];
    double       low = 0.0;
    double       high = 1.0;
    for (int iteration = 0; iteration < 200; ++iteration)
    {
      const double t = 0.5 * (low + high);
      (15 * t * t - 5 * t * t * t < x ? low : high) = t;
    }
    const double t = 0.5 * (low + high);
    EXPECT_NEAR(point[1], 30 * t * t - 20 * t * t * t, 1e-6) << "at x = " << point[0];
    EXPECT_EQ(point[2], 0.0);
    sawApex = sawApex || point.EuclideanDistanceTo(P(10, 10, 0)) < 1e-9;
  }
  EXPECT_TRUE(sawApex) << "the middle control point must be a vertex of the curve";
  for (std::size_t k = 0; k + 1 < a.Points.size(); ++k)
  {
    EXPECT_LE(a.Points[k].EuclideanDistanceTo(a.Points[k + 1]), 0.5 + 1e-9);
  }
  // Radii from the "Radius" measurement: 2 and 4 mm at the first two control points, between them in between.
  ASSERT_EQ(a.Radii.size(), a.Points.size());
  EXPECT_EQ(a.Radii.front(), 2.0);
  EXPECT_EQ(a.Radii.back(), 3.0);
  for (std::size_t k = 0; k < a.Points.size(); ++k)
  {
    if (a.Points[k][0] < 10.0 - 1e-9)
    {
      EXPECT_GE(a.Radii[k], 2.0);
      EXPECT_LE(a.Radii[k], 4.0);
    }
  }

  // Curve B: equally spaced collinear control points give a curve on their line.
  const auto & b = tree.GetBranches()[1];
  EXPECT_FALSE(b.HasRadii());
  EXPECT_EQ(b.Points.front(), P(0, 0, 5));
  EXPECT_EQ(b.Points.back(), P(0, 9, 17));
  for (const auto & point : b.Points)
  {
    EXPECT_NEAR(point[0], 0.0, 1e-9);
    EXPECT_NEAR(point[2] - 5.0, point[1] * 4.0 / 3.0, 1e-9);
  }

  // Curve C: RAS positions, LPS in the tree; the "undefined" control point is not part of it.
  const auto & c = tree.GetBranches()[2];
  EXPECT_EQ(c.Points.front(), P(-1, -2, 3));
  EXPECT_EQ(c.Points.back(), P(-4, -6, 3));
  for (const auto & point : c.Points)
  {
    EXPECT_NEAR(DistanceToPolyline(point, { P(-1, -2, 3), P(-4, -6, 3) }), 0.0, 1e-9);
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Bad input: a vr::InputError naming the file and what is wrong in it.

TEST(BadCenterlineInput, MissingEmptyAndUnknownFiles)
{
  vr::test::ScopedTemporaryFolder folder;
  for (const std::string name : { "missing.vtp", "missing.vtk", "missing.mrk.json", "missing.tre", "missing.csv" })
  {
    const std::string message = InputErrorOf([&] { vr::ReadCenterlines(folder.File(name)); });
    EXPECT_MESSAGE_HAS(message, folder.File(name));
    EXPECT_MESSAGE_HAS(message, "no such file");
  }
  for (const std::string name : { "empty.vtp", "empty.mrk.json", "empty.csv", "empty.tre" })
  {
    vr::test::WriteTextFile(folder.File(name), "");
    const std::string message = InputErrorOf([&] { vr::ReadCenterlines(folder.File(name)); });
    EXPECT_MESSAGE_HAS(message, folder.File(name));
    EXPECT_MESSAGE_HAS(message, "is empty");
  }
  vr::test::WriteTextFile(folder.File("tree.obj"), "v 1 2 3\n");
  EXPECT_MESSAGE_HAS(InputErrorOf([&] { vr::ReadCenterlines(folder.File("tree.obj")); }), "unknown centerline format");
}

TEST(BadCenterlineInput, MarkupsThatAreNotJSONHaveNoCurveOrABadPosition)
{
  vr::test::ScopedTemporaryFolder folder;
  const std::string               notJSON = folder.File("broken.mrk.json");
  vr::test::WriteTextFile(notJSON, "{ \"markups\": [ { \"type\": \"Curve\", ");
  std::string message = InputErrorOf([&] { vr::ReadCenterlines(notJSON); });
  EXPECT_MESSAGE_HAS(message, notJSON);
  EXPECT_MESSAGE_HAS(message, "not valid JSON");

  const std::string noCurve = folder.File("points.mrk.json");
  vr::test::WriteTextFile(noCurve, R"({"markups": [{"type": "Fiducial", "controlPoints": []}]})");
  message = InputErrorOf([&] { vr::ReadCenterlines(noCurve); });
  EXPECT_MESSAGE_HAS(message, noCurve);
  EXPECT_MESSAGE_HAS(message, "no markup of type \"Curve\"");
  EXPECT_MESSAGE_HAS(message, "Fiducial");

  const std::string badPosition = folder.File("position.mrk.json");
  vr::test::WriteTextFile(badPosition, R"({"markups": [{"type": "Curve", "name": "LAD", "controlPoints": [
      {"position": [1, 2, 3]}, {"position": [1, "two", 3]}]}]})");
  message = InputErrorOf([&] { vr::ReadCenterlines(badPosition); });
  EXPECT_MESSAGE_HAS(message, badPosition);
  EXPECT_MESSAGE_HAS(message, "markups[0] (\"LAD\").controlPoints[1].position");

  const std::string twoNumbers = folder.File("short.mrk.json");
  vr::test::WriteTextFile(twoNumbers, R"({"markups": [{"type": "Curve", "controlPoints": [
      {"position": [1, 2, 3]}, {"position": [1, 2]}]}]})");
  EXPECT_MESSAGE_HAS(InputErrorOf([&] { vr::ReadCenterlines(twoNumbers); }), "controlPoints[1].position");

  const std::string badSpace = folder.File("space.mrk.json");
  vr::test::WriteTextFile(badSpace, R"({"markups": [{"type": "Curve", "coordinateSystem": "XYZ", "controlPoints": [
      {"position": [1, 2, 3]}, {"position": [1, 2, 4]}]}]})");
  EXPECT_MESSAGE_HAS(InputErrorOf([&] { vr::ReadCenterlines(badSpace); }), "coordinateSystem");
}

TEST(BadCenterlineInput, CSVWithAMissingColumnOrANonNumericValue)
{
  vr::test::ScopedTemporaryFolder folder;
  const std::string               missing = folder.File("missing-z.csv");
  vr::test::WriteTextFile(missing, "branch,x,y\n1,2,3\n");
  std::string message = InputErrorOf([&] { vr::ReadCenterlines(missing); });
  EXPECT_MESSAGE_HAS(message, missing);
  EXPECT_MESSAGE_HAS(message, "no \"z\" column");

  const std::string text = folder.File("text.csv");
  vr::test::WriteTextFile(text, "branch,x,y,z\n1,0,0,0\n1,0,abc,0\n");
  message = InputErrorOf([&] { vr::ReadCenterlines(text); });
  EXPECT_MESSAGE_HAS(message, text);
  EXPECT_MESSAGE_HAS(message, "line 3, column 3 (y)");
  EXPECT_MESSAGE_HAS(message, "\"abc\" is not a number");

  const std::string nan = folder.File("nan.csv");
  vr::test::WriteTextFile(nan, "branch,x,y,z\n1,0,0,nan\n");
  message = InputErrorOf([&] { vr::ReadCenterlines(nan); });
  EXPECT_MESSAGE_HAS(message, "line 2, column 4 (z)");
  EXPECT_MESSAGE_HAS(message, "not a finite number");

  const std::string shortRow = folder.File("short.csv");
  vr::test::WriteTextFile(shortRow, "branch,x,y,z,radius\n1,0,0,0,1\n1,0,0,0\n");
  EXPECT_MESSAGE_HAS(InputErrorOf([&] { vr::ReadCenterlines(shortRow); }), "line 3: 4 values, but the header names 5");

  const std::string headerOnly = folder.File("header.csv");
  vr::test::WriteTextFile(headerOnly, "branch,x,y,z\n");
  EXPECT_MESSAGE_HAS(InputErrorOf([&] { vr::ReadCenterlines(headerOnly); }), "no data rows");

  const std::string badBranch = folder.File("branch.csv");
  vr::test::WriteTextFile(badBranch, "branch,x,y,z\n0,1,2,3\n");
  EXPECT_MESSAGE_HAS(InputErrorOf([&] { vr::ReadCenterlines(badBranch); }), "line 2, column 1 (branch)");
}

TEST(BadCenterlineInput, VTKFilesWithoutLinesOrWithABadRadiusArray)
{
  vr::test::ScopedTemporaryFolder folder;
  const std::string               vertices = folder.File("vertices.vtk");
  vr::test::WriteTextFile(vertices,
                          "# vtk DataFile Version 4.2\nvtk output\nASCII\nDATASET POLYDATA\n"
                          "POINTS 2 double\n1 2 3\n4 5 6\nVERTICES 2 4\n1 0\n1 1\n");
  std::string message = InputErrorOf([&] { vr::ReadCenterlines(vertices); });
  EXPECT_MESSAGE_HAS(message, vertices);
  EXPECT_MESSAGE_HAS(message, "VERTICES are not part of a centerline file"); // refused by the legacy reader

  // XML with a Radius array one value short of the point count.
  const std::string shortRadius = folder.File("short-radius.vtp");
  vr::test::WriteTextFile(shortRadius, R"(<?xml version="1.0"?>
<VTKFile type="PolyData" version="0.1" byte_order="LittleEndian">
  <PolyData>
    <Piece NumberOfPoints="3" NumberOfVerts="0" NumberOfLines="1" NumberOfStrips="0" NumberOfPolys="0">
      <PointData>
        <DataArray type="Float64" Name="Radius" format="ascii">1 2</DataArray>
      </PointData>
      <Points>
        <DataArray type="Float64" NumberOfComponents="3" format="ascii">0 0 0 1 0 0 2 0 0</DataArray>
      </Points>
      <Lines>
        <DataArray type="Int64" Name="connectivity" format="ascii">0 1 2</DataArray>
        <DataArray type="Int64" Name="offsets" format="ascii">3</DataArray>
      </Lines>
    </Piece>
  </PolyData>
</VTKFile>
)");
  std::string printed;
  message = InputErrorAndPrintedTextOf([&] { vr::ReadCenterlines(shortRadius); }, printed);
  EXPECT_EQ(printed, "");
  EXPECT_MESSAGE_HAS(message, shortRadius);
  EXPECT_MESSAGE_HAS(message, "Radius");

  // The same checks on the polydata path, where nothing stops a node from holding such arrays.
  auto polyData = MakePolyData({ { P(0, 0, 0), P(1, 0, 0), P(2, 0, 0) } });
  polyData->GetPointData()->GetArray("Radius")->SetNumberOfTuples(2);
  message = InputErrorOf([&] { vr::CenterlineTreeFromPolyData(polyData, CoordinateSpace::RAS, "node \"CL\""); });
  EXPECT_MESSAGE_HAS(message, "node \"CL\": point array \"Radius\" (radius) has 2 values but the polydata has 3");

  auto withNaN = MakePolyData({ { P(0, 0, 0), P(1, std::nan(""), 0) } });
  message = InputErrorOf([&] { vr::CenterlineTreeFromPolyData(withNaN, CoordinateSpace::RAS, "node \"CL\""); });
  EXPECT_MESSAGE_HAS(message, "point 1 (polyline 0, vertex 1) has a non-finite coordinate");

  auto negative = MakePolyData({ { P(0, 0, 0), P(1, 0, 0) } }, -2.0);
  EXPECT_MESSAGE_HAS(InputErrorOf([&] { vr::CenterlineTreeFromPolyData(negative); }), "has radius -2");

  EXPECT_MESSAGE_HAS(InputErrorOf([&] { vr::CenterlineTreeFromPolyData(vtkSmartPointer<vtkPolyData>::New()); }),
                     "holds no polyline");
}

TEST(BadCenterlineInput, NotATubeFile)
{
  vr::test::ScopedTemporaryFolder folder;
  const std::string               path = folder.File("garbage.tre");
  vr::test::WriteTextFile(path, "this is not MetaIO\n");
  // MetaIO prints its complaints on stdout and stderr: they belong in the message, not on the terminal.
  std::string       printed;
  const std::string message = InputErrorAndPrintedTextOf([&] { vr::ReadCenterlines(path); }, printed);
  EXPECT_EQ(printed, "");
  EXPECT_MESSAGE_HAS(message, path);
  EXPECT_MESSAGE_HAS(message, "not a MetaIO .tre file");
}

TEST(BadCenterlineOutput, NothingWrittenAndAnExistingFileKept)
{
  vr::test::ScopedTemporaryFolder folder;
  const std::string               path = folder.File("result.csv");
  vr::test::WriteTextFile(path, "previous result\n");

  itk::CenterlineTree invalid = MakeYTree();
  invalid.GetBranches()[1].Points[1][2] = std::nan("");
  const std::string message = InputErrorOf([&] { vr::WriteCenterlines(invalid, path); });
  EXPECT_MESSAGE_HAS(message, path);
  EXPECT_MESSAGE_HAS(message, "non-finite");
  EXPECT_EQ(vr::test::ReadTextFile(path), "previous result\n");
  EXPECT_EQ(folder.Entries(), std::vector<std::string>{ "result.csv" });

  EXPECT_MESSAGE_HAS(InputErrorOf([&] { vr::WriteCenterlines(MakeYTree(), folder.File("nowhere/tree.vtp")); }),
                     "does not exist");
  EXPECT_MESSAGE_HAS(InputErrorOf([&] { vr::WriteCenterlines(MakeYTree(), folder.File("tree.stl")); }),
                     "unknown centerline format");
  EXPECT_EQ(folder.Entries(), std::vector<std::string>{ "result.csv" });
}
} // namespace
