// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Centerline readers and writers (issue 3, docs/design.md "Centerline tree"): real VMTK data, round trips through every
// format, hand-written files in each coordinate convention, and the bad inputs. This file: real data and round trips.
// Hand-written files and bad input are in vrCenterlineHandWrittenGTest.cxx, the logic's vtkPolyData path in
// vrCenterlinePolyDataGTest.cxx; what they share, in vrCenterlineIOTestSupport.h.
#include "vrCenterlineIOTestSupport.h"

namespace
{
using namespace vr::test::centerlineio;

// ---------------------------------------------------------------------------------------------------------------
// Real data: VMTK centerlines of the aorta and iliacs (Testing/Data/vmtk-aorta-mra, see its README).

class AortaCenterlines : public ::testing::Test
{
protected:
  void
  SetUp() override
  {
    m_Folder = vr::test::AortaDataFolder();
    if (m_Folder.empty())
    {
      GTEST_FAIL() << "VMTK's aorta (vmtk-aorta-mra) is missing from VR_SHARED_DATA_DIR (Testing/Data by default)";
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

} // namespace
