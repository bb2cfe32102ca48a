// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The vtkPolyData path of the logic's centerline node: paths split where they diverge, names, the space field,
// branch groups.
#include "vrCenterlineIOTestSupport.h"

namespace
{
using namespace vr::test::centerlineio;

// ---------------------------------------------------------------------------------------------------------------
// The vtkPolyData path the logic's centerline node uses.

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

} // namespace
