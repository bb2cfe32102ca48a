// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Centerline readers and writers (issue 3, docs/design.md 3.3): real VMTK data, round trips through every format,
// hand-written files in each coordinate convention, and the bad inputs.
#include "vrCenterlineIO.h"
#include "vrCenterlinePolyData.h"
#include "vrInputError.h"
#include "vrTestFiles.h"
#include "vrVolumeIO.h"

#include "vrTestImages.h"

#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkPolyDataWriter.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>

namespace
{
using vr::CoordinateSpace;
using PointType = itk::CenterlineBranch::PointType;

using vr::test::P;

using vr::test::InputErrorOf;

/** InputErrorOf, capturing what \a action printed on stdout and stderr into \a printed: VTK and MetaIO report
 * trouble there, which belongs in the message instead. */
std::string
InputErrorAndPrintedTextOf(const std::function<void()> & action, std::string & printed)
{
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  std::string message;
  bool        thrown = false;
  try
  {
    action();
  }
  catch (const vr::InputError & error)
  {
    message = error.what();
    thrown = true;
  }
  catch (...)
  {
  }
  printed = testing::internal::GetCapturedStderr();
  printed += testing::internal::GetCapturedStdout();
  EXPECT_TRUE(thrown) << "expected vr::InputError";
  std::cout << "  vr::InputError: " << message << std::endl;
  return message;
}

#define EXPECT_MESSAGE_HAS(message, part)                                                                              \
  EXPECT_NE((message).find(part), std::string::npos) << "message: " << (message) << "\nmissing: " << (part)

/** Distance from \a point to the polyline \a line. */
double
DistanceToPolyline(const PointType & point, const std::vector<PointType> & line)
{
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k + 1 < line.size(); ++k)
  {
    const auto   segment = line[k + 1] - line[k];
    const double length2 = segment.GetSquaredNorm();
    double       t = length2 > 0.0 ? ((point - line[k]) * segment) / length2 : 0.0;
    t = std::min(1.0, std::max(0.0, t));
    best = std::min(best, point.EuclideanDistanceTo(line[k] + segment * t));
  }
  if (line.size() == 1)
  {
    best = point.EuclideanDistanceTo(line[0]);
  }
  return best;
}

/** The largest distance from a point of \a from to the nearest branch of \a to. */
double
OneSidedDistance(const itk::CenterlineTree & from, const itk::CenterlineTree & to)
{
  double worst = 0.0;
  for (const auto & branch : from.GetBranches())
  {
    for (const auto & point : branch.Points)
    {
      double nearest = std::numeric_limits<double>::infinity();
      for (const auto & other : to.GetBranches())
      {
        nearest = std::min(nearest, DistanceToPolyline(point, other.Points));
      }
      worst = std::max(worst, nearest);
    }
  }
  return worst;
}

/** A Y-shaped tree (trunk and two children starting at its end) with radii, ids 4, 7, 9. */
itk::CenterlineTree
MakeYTree()
{
  itk::CenterlineTree   tree;
  itk::CenterlineBranch trunk;
  trunk.Id = 4;
  trunk.Points = { P(10.25, -20.5, 30.125), P(10.5, -20.0, 25.0), P(11.0, -19.75, 20.0) };
  trunk.Radii = { 6.5, 6.25, 6.0 };
  itk::CenterlineBranch left;
  left.Id = 7;
  left.Points = { P(11.0, -19.75, 20.0), P(15.0, -19.0, 15.0), P(19.125, -18.5, 10.0) };
  left.Radii = { 4.0, 3.5, 3.0 };
  itk::CenterlineBranch right;
  right.Id = 9;
  right.Points = { P(11.0, -19.75, 20.0), P(7.0, -20.0, 15.5), P(3.0, -20.25, 11.0), P(-1.0, -20.5, 7.0) };
  right.Radii = { 4.0, 3.75, 3.25, 2.75 };
  tree.AddBranch(trunk);
  tree.AddBranch(left);
  tree.AddBranch(right);
  return tree;
}

void
ExpectSameTree(const itk::CenterlineTree & expected,
               const itk::CenterlineTree & actual,
               double                      tolerance,
               bool                        sameIds = true)
{
  ASSERT_EQ(actual.GetNumberOfBranches(), expected.GetNumberOfBranches());
  for (std::size_t b = 0; b < expected.GetNumberOfBranches(); ++b)
  {
    const auto & want = expected.GetBranches()[b];
    const auto & got = actual.GetBranches()[b];
    if (sameIds)
    {
      EXPECT_EQ(got.Id, want.Id) << "branch " << b;
    }
    ASSERT_EQ(got.Points.size(), want.Points.size()) << "branch " << b;
    ASSERT_EQ(got.Radii.size(), want.Radii.size()) << "branch " << b;
    for (std::size_t k = 0; k < want.Points.size(); ++k)
    {
      EXPECT_LE(got.Points[k].EuclideanDistanceTo(want.Points[k]), tolerance) << "branch " << b << " point " << k;
      if (!want.Radii.empty())
      {
        EXPECT_NEAR(got.Radii[k], want.Radii[k], tolerance) << "branch " << b << " point " << k;
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Real data: VMTK centerlines of the aorta and iliacs (../shared/data/vmtk-aorta-mra, see its README).

class AortaCenterlines : public ::testing::Test
{
protected:
  void
  SetUp() override
  {
    m_Folder = vr::test::AortaDataFolder();
    if (m_Folder.empty())
    {
      GTEST_SKIP() << "the shared data folder vmtk-aorta-mra is not beside this checkout (VR_SHARED_DATA_DIR)";
    }
  }
  std::string
  Data(const std::string & name) const
  {
    return m_Folder + "/" + name;
  }
  std::string m_Folder;
};

TEST_F(AortaCenterlines, OverlappingPathsBecomeTrunkAndTwoIliacs)
{
  vr::CenterlineReadReport  report;
  const itk::CenterlineTree tree = vr::ReadCenterlines(Data("aorta-centerline.vtp"), CoordinateSpace::Auto, &report);

  // Two paths of 211 and 198 points whose first 62 points are identical: the trunk (62 points) once, then each
  // path's own part from the bifurcation, which starts on the trunk's last point.
  ASSERT_EQ(tree.GetNumberOfBranches(), 3U);
  const auto & trunk = tree.GetBranches()[0];
  const auto & first = tree.GetBranches()[1];
  const auto & second = tree.GetBranches()[2];
  EXPECT_EQ(trunk.Points.size(), 62U);
  EXPECT_EQ(first.Points.size(), 211U - 61U);
  EXPECT_EQ(second.Points.size(), 198U - 61U);
  EXPECT_EQ(first.Points.front(), trunk.Points.back());
  EXPECT_EQ(second.Points.front(), trunk.Points.back());
  EXPECT_EQ(report.InputPolylines, 2U);
  EXPECT_EQ(report.MergedPoints, 62U);
  EXPECT_EQ(report.RadiusArray, "MaximumInscribedSphereRadius");
  EXPECT_EQ(report.FileSpace, CoordinateSpace::RAS);
  EXPECT_FALSE(report.UsedBranchGroups);

  // The file's first point is RAS (222.096, 175.870, 21.673): LPS negates x and y.
  EXPECT_NEAR(trunk.Points.front()[0], -222.0963, 1e-3);
  EXPECT_NEAR(trunk.Points.front()[1], -175.8700, 1e-3);
  EXPECT_NEAR(trunk.Points.front()[2], 21.6731, 1e-3);

  // The trunk is held once: apart from the bifurcation point, no point of one branch recurs in another.
  for (std::size_t a = 0; a < 3; ++a)
  {
    for (std::size_t b = a + 1; b < 3; ++b)
    {
      std::size_t shared = 0;
      for (const auto & p : tree.GetBranches()[a].Points)
      {
        for (const auto & q : tree.GetBranches()[b].Points)
        {
          shared += p.EuclideanDistanceTo(q) < 1e-6 ? 1 : 0;
        }
      }
      EXPECT_EQ(shared, 1U) << "branches " << a << " and " << b;
    }
  }

  ASSERT_TRUE(tree.HasRadii());
  double smallest = std::numeric_limits<double>::infinity();
  double largest = 0.0;
  for (const auto & branch : tree.GetBranches())
  {
    for (const double radius : branch.Radii)
    {
      smallest = std::min(smallest, radius);
      largest = std::max(largest, radius);
    }
  }
  EXPECT_GE(smallest, 2.7);
  EXPECT_LE(largest, 7.6);
  EXPECT_LT(smallest, 2.8); // the README's range 2.78 - 7.58 mm, so the radii are the file's, not a default
  EXPECT_GT(largest, 7.5);
}

/** Fraction of the tree's points inside \a volume, and the median intensity at those inside (nearest voxel). */
std::pair<double, double>
InsideFractionAndMedian(const itk::CenterlineTree & tree, const vr::VolumeImageType * volume)
{
  std::size_t         total = 0;
  std::vector<double> intensities;
  for (const auto & branch : tree.GetBranches())
  {
    for (const auto & point : branch.Points)
    {
      ++total;
      itk::Index<3> index;
      if (volume->TransformPhysicalPointToIndex(point, index))
      {
        intensities.push_back(volume->GetPixel(index));
      }
    }
  }
  double median = 0.0;
  if (!intensities.empty())
  {
    std::nth_element(intensities.begin(), intensities.begin() + intensities.size() / 2, intensities.end());
    median = intensities[intensities.size() / 2];
  }
  return { static_cast<double>(intensities.size()) / static_cast<double>(total), median };
}

TEST_F(AortaCenterlines, PointsLieInTheLumenOnlyWhenRASIsHandled)
{
  const vr::VolumeImageType::Pointer volume = vr::ReadVolume(Data("aorta.mha"));

  const auto asRAS = InsideFractionAndMedian(vr::ReadCenterlines(Data("aorta-centerline.vtp")), volume);
  EXPECT_EQ(asRAS.first, 1.0) << "every centerline point must fall inside aorta.mha";
  // Lumen is about 1850, background about 230: the centerline runs through the lumen.
  EXPECT_GT(asRAS.second, 1000.0);

  const auto wronglyLPS =
    InsideFractionAndMedian(vr::ReadCenterlines(Data("aorta-centerline.vtp"), CoordinateSpace::LPS), volume);
  EXPECT_LT(wronglyLPS.first, 0.5) << "taking the RAS file as LPS must put most points outside the volume";
}

TEST_F(AortaCenterlines, BranchExtractorGroupsGiveTheSameVessels)
{
  vr::CenterlineReadReport  report;
  const itk::CenterlineTree paths = vr::ReadCenterlines(Data("aorta-centerline.vtp"));
  const itk::CenterlineTree groups =
    vr::ReadCenterlines(Data("aorta-centerline-branches.vtp"), CoordinateSpace::Auto, &report);

  EXPECT_TRUE(report.UsedBranchGroups);
  EXPECT_EQ(report.InputPolylines, 6U);
  // Groups 0 (trunk), 2 and 3 (iliacs); group 1, the blanked bifurcation, belongs to the iliacs.
  ASSERT_EQ(groups.GetNumberOfBranches(), 3U);
  EXPECT_EQ(groups.GetBranches()[1].Points.front(), groups.GetBranches()[0].Points.back());
  EXPECT_EQ(groups.GetBranches()[2].Points.front(), groups.GetBranches()[0].Points.back());

  // The same vessel geometry both ways. The trunk of the group file averages the two paths over their last
  // millimetres, where they are at most about 1.7 mm apart, so a point may sit up to half that off either path.
  const double fromGroups = OneSidedDistance(groups, paths);
  const double fromPaths = OneSidedDistance(paths, groups);
  EXPECT_LT(fromGroups, 1.0);
  EXPECT_LT(fromPaths, 1.0);
  std::cout << "aorta-centerline-branches.vtp vs aorta-centerline.vtp: " << fromGroups << " mm and " << fromPaths
            << " mm" << std::endl;

  const vr::VolumeImageType::Pointer volume = vr::ReadVolume(Data("aorta.mha"));
  EXPECT_EQ(InsideFractionAndMedian(groups, volume).first, 1.0);
}

TEST_F(AortaCenterlines, TruncatedVtpIsAnInputErrorNamingTheFileAndPrintsNothing)
{
  vr::test::ScopedTemporaryFolder folder;
  const std::string               whole = vr::test::ReadTextFile(Data("aorta-centerline.vtp"));
  const std::string               path = folder.File("truncated.vtp");
  vr::test::WriteTextFile(path, whole.substr(0, whole.size() / 2));

  std::string       printed;
  const std::string message = InputErrorAndPrintedTextOf([&] { vr::ReadCenterlines(path); }, printed);
  EXPECT_MESSAGE_HAS(message, path);
  EXPECT_MESSAGE_HAS(message, "VTK XML PolyData");
  EXPECT_MESSAGE_HAS(message, "line 19"); // where the XML parser gave up
  EXPECT_EQ(printed, "") << "VTK's own error text leaked to the terminal";
}

// ---------------------------------------------------------------------------------------------------------------
// Round trips: every writer's output read back.

class CenterlineRoundTrip : public ::testing::TestWithParam<std::string>
{
};

TEST_P(CenterlineRoundTrip, ReadsBackWhatTheWriterWrote)
{
  vr::test::ScopedTemporaryFolder folder;
  const itk::CenterlineTree       tree = MakeYTree();
  const std::string               path = folder.File("tree" + GetParam());
  vr::WriteCenterlines(tree, path);
  vr::CenterlineReadReport  report;
  const itk::CenterlineTree back = vr::ReadCenterlines(path, CoordinateSpace::Auto, &report);
  // .tre stores float32 positions; the others keep doubles exactly.
  ExpectSameTree(tree, back, GetParam() == ".tre" ? 1e-4 : 1e-12);
  EXPECT_EQ(folder.Entries(), std::vector<std::string>{ "tree" + GetParam() }) << "a temporary file was left";
}

INSTANTIATE_TEST_SUITE_P(EveryExactFormat,
                         CenterlineRoundTrip,
                         ::testing::Values(".vtp", ".vtk", ".tre", ".csv"),
                         [](const auto & info) { return info.param.substr(1); });

class CenterlineNameRoundTrip : public ::testing::TestWithParam<std::string>
{
};

TEST_P(CenterlineNameRoundTrip, EveryFormatThatHasNamesKeepsEachBranchsName)
{
  vr::test::ScopedTemporaryFolder folder;
  itk::CenterlineTree             tree = MakeYTree();
  const std::vector<std::string>  names = { "abdominal aorta", "left common iliac artery", "" };
  for (std::size_t b = 0; b < names.size(); ++b)
  {
    tree.GetBranches()[b].Name = names[b];
  }
  const std::string path = folder.File("named" + GetParam());
  vr::WriteCenterlines(tree, path);
  const itk::CenterlineTree back = vr::ReadCenterlines(path, CoordinateSpace::Auto);
  ASSERT_EQ(back.GetNumberOfBranches(), 3U);
  EXPECT_EQ(back.GetBranches()[0].Name, "abdominal aorta");
  EXPECT_EQ(back.GetBranches()[1].Name, "left common iliac artery");
  // A branch without a name: none invented by the binary formats; the markups writer names every curve.
  EXPECT_EQ(back.GetBranches()[2].Name, GetParam() == ".mrk.json" ? "Branch 9" : "");
}

INSTANTIATE_TEST_SUITE_P(FormatsWithNames,
                         CenterlineNameRoundTrip,
                         ::testing::Values(".vtp", ".vtk", ".tre", ".mrk.json"),
                         [](const auto & info)
                         { return info.param == ".mrk.json" ? std::string("mrk_json") : info.param.substr(1); });

TEST(CenterlineRoundTrip, CSVInEachHeaderForm)
{
  vr::test::ScopedTemporaryFolder folder;
  const itk::CenterlineTree       tree = MakeYTree();
  for (const CoordinateSpace space : { CoordinateSpace::LPS, CoordinateSpace::RAS })
  {
    const std::string path = folder.File(std::string("tree-") + vr::ToString(space) + ".csv");
    vr::WriteCenterlines(tree, path, space);
    const std::string text = vr::test::ReadTextFile(path);
    EXPECT_EQ(text.rfind(space == CoordinateSpace::RAS ? "branch,r,a,s,radius\n" : "branch,x,y,z,radius\n", 0), 0U)
      << text.substr(0, 40);
    ExpectSameTree(tree, vr::ReadCenterlines(path), 1e-12);
  }
}

TEST(CenterlineRoundTrip, VTKFilesInLPSCarryTheirSpace)
{
  vr::test::ScopedTemporaryFolder folder;
  const itk::CenterlineTree       tree = MakeYTree();
  for (const std::string name : { "lps.vtp", "lps.vtk" })
  {
    vr::WriteCenterlines(tree, folder.File(name), CoordinateSpace::LPS);
    vr::CenterlineReadReport report;
    ExpectSameTree(tree, vr::ReadCenterlines(folder.File(name), CoordinateSpace::Auto, &report), 1e-12);
    EXPECT_EQ(report.FileSpace, CoordinateSpace::LPS) << name;
  }
  EXPECT_NE(vr::test::ReadTextFile(folder.File("lps.vtk")).find("SPACE=LPS"), std::string::npos);
}

TEST(CenterlineRoundTrip, VTKFilesNameTheRadiusAsVMTKAndSlicerDo)
{
  vr::test::ScopedTemporaryFolder folder;
  const itk::CenterlineTree       tree = MakeYTree();
  const std::string               path = folder.File("tree.vtp");
  vr::WriteCenterlines(tree, path);
  auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPointData * points = reader->GetOutput()->GetPointData();
  vtkDataArray * vmtk = points->GetArray("MaximumInscribedSphereRadius");
  vtkDataArray * slicer = points->GetArray("Radius");
  ASSERT_NE(vmtk, nullptr);
  ASSERT_NE(slicer, nullptr);
  ASSERT_EQ(vmtk->GetNumberOfTuples(), static_cast<vtkIdType>(tree.GetNumberOfPoints()));
  std::size_t k = 0;
  for (const auto & branch : tree.GetBranches())
  {
    for (const double radius : branch.Radii)
    {
      EXPECT_EQ(vmtk->GetTuple1(static_cast<vtkIdType>(k)), radius);
      EXPECT_EQ(slicer->GetTuple1(static_cast<vtkIdType>(k)), radius);
      ++k;
    }
  }
}

TEST(CenterlineRoundTrip, MarkupsCurvesPassThroughEveryWrittenPoint)
{
  vr::test::ScopedTemporaryFolder folder;
  const itk::CenterlineTree       tree = MakeYTree();
  const std::string               path = folder.File("tree.mrk.json");
  vr::WriteCenterlines(tree, path);
  const itk::CenterlineTree back = vr::ReadCenterlines(path);
  ASSERT_EQ(back.GetNumberOfBranches(), tree.GetNumberOfBranches());
  for (std::size_t b = 0; b < tree.GetNumberOfBranches(); ++b)
  {
    // The written points become control points: each is a vertex of the read curve, in order, with its radius.
    const auto & written = tree.GetBranches()[b];
    const auto & read = back.GetBranches()[b];
    std::size_t  next = 0;
    for (std::size_t k = 0; k < read.Points.size() && next < written.Points.size(); ++k)
    {
      if (read.Points[k].EuclideanDistanceTo(written.Points[next]) < 1e-9)
      {
        EXPECT_NEAR(read.Radii[k], written.Radii[next], 1e-12);
        ++next;
      }
    }
    EXPECT_EQ(next, written.Points.size()) << "branch " << b << ": a control point is missing from the curve";
    for (std::size_t k = 0; k + 1 < read.Points.size(); ++k)
    {
      EXPECT_LE(read.Points[k].EuclideanDistanceTo(read.Points[k + 1]), 0.5 + 1e-9);
    }
  }
}

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
// The vtkPolyData path the logic's centerline node uses.

/** Polylines (RAS) from point lists, one cell each, with a Radius array of \a radius everywhere. */
vtkSmartPointer<vtkPolyData>
MakePolyData(const std::vector<std::vector<PointType>> & polylines, double radius = 1.0)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  auto radii = vtkSmartPointer<vtkDoubleArray>::New();
  radii->SetName("Radius");
  for (const auto & polyline : polylines)
  {
    lines->InsertNextCell(static_cast<vtkIdType>(polyline.size()));
    for (const auto & point : polyline)
    {
      lines->InsertCellPoint(points->InsertNextPoint(point.GetDataPointer()));
      radii->InsertNextValue(radius);
    }
  }
  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetLines(lines);
  polyData->GetPointData()->AddArray(radii);
  return polyData;
}

std::vector<PointType>
Line(const PointType & from, const PointType & to, int steps)
{
  std::vector<PointType> points;
  for (int k = 0; k <= steps; ++k)
  {
    points.push_back(from + (to - from) * (static_cast<double>(k) / steps));
  }
  return points;
}

std::vector<PointType>
Concatenate(std::vector<PointType> a, const std::vector<PointType> & b)
{
  a.insert(a.end(), b.begin() + 1, b.end());
  return a;
}

TEST(CenterlinePolyData, PathsFromOneRootSplitWhereTheyDiverge)
{
  // Three source-to-target paths as VMTK writes them: R..P..X..Y1, R..P..X..Y2 and R..P..Z.
  const PointType R = P(0, 0, 0), Pj = P(0, 0, -10), X = P(0, 0, -20), Y1 = P(8, 0, -30), Y2 = P(-8, 0, -30),
                  Z = P(0, 9, -16);
  const auto rp = Line(R, Pj, 10), px = Line(Pj, X, 10);
  const auto path1 = Concatenate(Concatenate(rp, px), Line(X, Y1, 12));
  const auto path2 = Concatenate(Concatenate(rp, px), Line(X, Y2, 12));
  const auto path3 = Concatenate(rp, Line(Pj, Z, 10));

  vr::CenterlineReadReport  report;
  const itk::CenterlineTree tree =
    vr::CenterlineTreeFromPolyData(MakePolyData({ path1, path2, path3 }), CoordinateSpace::LPS, "test", &report);

  // Five vessel sections, each once: R-P, P-X, X-Y1, X-Y2, P-Z.
  ASSERT_EQ(tree.GetNumberOfBranches(), 5U);
  std::vector<std::pair<PointType, PointType>> ends;
  for (const auto & branch : tree.GetBranches())
  {
    ends.emplace_back(branch.Points.front(), branch.Points.back());
  }
  const std::vector<std::pair<PointType, PointType>> expected = {
    { R, Pj }, { Pj, X }, { X, Y1 }, { X, Y2 }, { Pj, Z }
  };
  EXPECT_EQ(ends, expected);
  EXPECT_EQ(tree.GetBranches()[0].Points.size(), 11U);
  EXPECT_EQ(tree.GetBranches()[4].Points.size(), 11U);
  // Path 2 repeats R..X (21 points), path 3 repeats R..P (11 points).
  EXPECT_EQ(report.MergedPoints, 21U + 11U);
  EXPECT_EQ(report.InputPolylines, 3U);
}

TEST(CenterlinePolyData, NamesFollowTheirVesselsWhenATrunkIsCutAndTheIdsRenumbered)
{
  // A named trunk R..E and a named child leaving it at its 5th point M: as a node, the trunk is cut at M, so the
  // three branches that come back are numbered 1, 2, 3 and none has its old id (7, 12); each keeps its vessel's name.
  const PointType       R = P(0, 0, 0), M = P(0, 0, -50), E = P(0, 0, -100), C = P(30, 0, -80);
  itk::CenterlineTree   tree;
  itk::CenterlineBranch trunk;
  trunk.Id = 7;
  trunk.Name = "aorta";
  trunk.Points = Concatenate(Line(R, M, 5), Line(M, E, 5));
  itk::CenterlineBranch child;
  child.Id = 12;
  child.Name = "left renal artery";
  child.Points = Line(M, C, 6);
  tree.AddBranch(trunk);
  tree.AddBranch(child);

  const auto                polyData = vr::PolyDataFromCenterlineTree(tree, CoordinateSpace::LPS);
  const itk::CenterlineTree back = vr::CenterlineTreeFromPolyData(polyData, CoordinateSpace::LPS, "test");
  ASSERT_EQ(back.GetNumberOfBranches(), 3U);
  for (const auto & branch : back.GetBranches())
  {
    // Which vessel a branch is, from its geometry: the child's points all lie off the z axis but its first.
    const bool isChild = branch.Points.back()[0] > 1.0;
    EXPECT_EQ(branch.Name, isChild ? "left renal artery" : "aorta") << "branch " << branch.Id;
    EXPECT_NE(branch.Id, isChild ? 12 : 7) << "the ids were renumbered, so only the names can tell";
  }

  // A string cell array of another name, as other tools write it, names the branches too.
  auto other = vr::PolyDataFromCenterlineTree(tree, CoordinateSpace::LPS);
  auto renamed = vtkSmartPointer<vtkStringArray>::New();
  renamed->SetName("Name");
  renamed->InsertNextValue("trunk");
  renamed->InsertNextValue("side branch");
  other->GetCellData()->RemoveArray(vr::BranchNamesArrayName);
  other->GetCellData()->AddArray(renamed);
  const itk::CenterlineTree fromOther = vr::CenterlineTreeFromPolyData(other, CoordinateSpace::LPS, "test");
  ASSERT_EQ(fromOther.GetNumberOfBranches(), 3U);
  EXPECT_EQ(fromOther.GetBranches()[0].Name, "trunk");
  EXPECT_EQ(fromOther.GetBranches()[2].Name, "side branch");
}

TEST(CenterlinePolyData, ASlicerNodeIsRASUnlessItsSpaceFieldSaysLPS)
{
  auto polyData = MakePolyData({ { P(1, 2, 3), P(4, 5, 6) } });
  EXPECT_EQ(vr::CenterlineTreeFromPolyData(polyData).GetBranches()[0].Points[0], P(-1, -2, 3));
  auto space = vtkSmartPointer<vtkStringArray>::New();
  space->SetName("SPACE");
  space->InsertNextValue("LPS");
  polyData->GetFieldData()->AddArray(space);
  EXPECT_EQ(vr::CenterlineTreeFromPolyData(polyData, CoordinateSpace::Auto).GetBranches()[0].Points[0], P(1, 2, 3));
  EXPECT_EQ(vr::CenterlineTreeFromPolyData(polyData, CoordinateSpace::RAS).GetBranches()[0].Points[0], P(-1, -2, 3));
}

TEST(CenterlinePolyData, BranchGroupsAverageTractsAndGiveBifurcationsToChildren)
{
  // vmtkbranchextractor output of two paths: tract 0 (group 0) differs by 2 mm in x between the paths, tract 1 is
  // the blanked bifurcation (group 1), tract 2 the own branch of each path (groups 2 and 3).
  const auto trunkA = Line(P(-1, 0, 0), P(-1, 0, -10), 10);
  const auto trunkB = Line(P(1, 0, 0), P(1, 0, -10), 10);
  const auto blankA = Line(P(-1, 0, -10), P(-3, 0, -12), 2);
  const auto blankB = Line(P(1, 0, -10), P(3, 0, -12), 2);
  const auto ownA = Line(P(-3, 0, -12), P(-9, 0, -20), 8);
  const auto ownB = Line(P(3, 0, -12), P(9, 0, -20), 8);
  auto       polyData = MakePolyData({ trunkA, blankA, ownA, trunkB, blankB, ownB });
  const std::vector<std::pair<const char *, std::vector<int>>> arrays = {
    { "CenterlineIds", { 0, 0, 0, 1, 1, 1 } },
    { "TractIds", { 0, 1, 2, 0, 1, 2 } },
    { "GroupIds", { 0, 1, 2, 0, 1, 3 } },
    { "Blanking", { 0, 1, 0, 0, 1, 0 } },
  };
  for (const auto & array : arrays)
  {
    auto values = vtkSmartPointer<vtkIntArray>::New();
    values->SetName(array.first);
    for (const int value : array.second)
    {
      values->InsertNextValue(value);
    }
    polyData->GetCellData()->AddArray(values);
  }
  vr::CenterlineReadReport  report;
  const itk::CenterlineTree tree = vr::CenterlineTreeFromPolyData(polyData, CoordinateSpace::LPS, "test", &report);
  EXPECT_TRUE(report.UsedBranchGroups);
  ASSERT_EQ(tree.GetNumberOfBranches(), 3U);
  // Group 0: the two tracts averaged (equal radii, equal weights) lie on x = 0.
  const auto & trunk = tree.GetBranches()[0];
  ASSERT_EQ(trunk.Points.size(), 11U);
  for (std::size_t k = 0; k < trunk.Points.size(); ++k)
  {
    EXPECT_NEAR(trunk.Points[k].EuclideanDistanceTo(P(0, 0, -static_cast<double>(k))), 0.0, 1e-12);
  }
  // Groups 2 and 3: from the trunk's end, through their own bifurcation tract, to their end.
  const auto & left = tree.GetBranches()[1];
  EXPECT_EQ(left.Points.front(), P(0, 0, -10));
  EXPECT_EQ(left.Points[1], P(-1, 0, -10));
  EXPECT_EQ(left.Points.back(), P(-9, 0, -20));
  EXPECT_EQ(left.Points.size(), 1U + 3U + 8U);
  EXPECT_EQ(tree.GetBranches()[2].Points.back(), P(9, 0, -20));
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
