// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The module logic in Visibility mode (issue 38): the hidden labels and the branches' hidden lengths as outputs, the
// least occluded angle from the occlusion profile (kept while only the angle changes), the warning about branches
// without radii, and the one writer's new outputs, all or nothing.

#include "itkCTAPhantom.h"
#include "itkCPROcclusionProfile.h"
#include "vrInputError.h"
#include "vrNodeConversion.h"
#include "vrOutputWriter.h"
#include "vrProgressiveRefinement.h"
#include "vrVesselReformationLogic.h"

#include "vrTestFiles.h"

#include <gtest/gtest.h>

#include <vtkImageData.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using vr::test::ScopedTemporaryFolder;

/** A logic on the run-off phantom at 3 mm, 96 x 192 pixels, 20 Jacobi passes. */
struct RunoffLogic
{
  vr::VesselReformationLogic Logic;
  itk::CenterlineTree        Tree;
  vr::ReformationParameters  Parameters;

  explicit RunoffLogic(bool withRadii = true)
  {
    auto phantom = itk::MakeCTAPhantom(itk::CTAPhantomKind::Runoff, 3.0);
    phantom.Source->Update();
    Tree = phantom.Tree;
    if (!withRadii)
    {
      // A centerline node carries radii for all its points or for none: centerlines without them.
      for (auto & branch : Tree.GetBranches())
      {
        branch.Radii.clear();
      }
    }
    Logic.SetVolumeNode(vr::ConvertItkImageToVolumeNode(phantom.Source->GetOutput(), "Runoff"));
    Logic.SetCenterlineNode(vr::ConvertTreeToCenterlineNode(Tree, "RunoffCenterlines"));
    Parameters.ImageSize[0] = 96;
    Parameters.ImageSize[1] = 192;
    Parameters.Iterations = 20;
    Parameters.Backend = vr::RelaxBackend::CPU;
    Parameters.Mode = itk::CPRDepthMode::Visibility;
    Parameters.AngleInDegrees = 124.0;
  }

  const vr::ReformationOutputs &
  Update()
  {
    Logic.SetParameters(Parameters);
    return Logic.Update();
  }
};

double
Sum(const std::vector<vr::BranchOcclusionRow> & rows, double vr::BranchOcclusionRow::*field)
{
  double sum = 0.0;
  for (const auto & row : rows)
  {
    sum += row.*field;
  }
  return sum;
}
} // namespace

TEST(VisibilityLogic, OutputsTheHiddenLabelsAndEachBranchsHiddenLengthWithItsName)
{
  RunoffLogic                    runoff;
  const vr::ReformationOutputs & outputs = runoff.Update();
  ASSERT_TRUE(outputs.HiddenLabels);
  // The tree as the logic reforms it (the centerline node's branches, split where a child leaves a trunk).
  const itk::CenterlineTree & tree = runoff.Logic.GetDepthFilter()->GetCenterlineTree();
  ASSERT_EQ(outputs.BranchOcclusions.size(), tree.GetNumberOfBranches());
  for (std::size_t b = 0; b < outputs.BranchOcclusions.size(); ++b)
  {
    EXPECT_EQ(outputs.BranchOcclusions[b].BranchId, tree.GetBranches()[b].Id);
    EXPECT_EQ(outputs.BranchOcclusions[b].Name, tree.GetBranches()[b].Name);
    EXPECT_FALSE(outputs.BranchOcclusions[b].Name.empty());
    EXPECT_LE(outputs.BranchOcclusions[b].HiddenLength, outputs.BranchOcclusions[b].Length);
  }
  // At 124 degrees the legs overlap: some vessel is hidden, and the labels name it where it is.
  EXPECT_GT(Sum(outputs.BranchOcclusions, &vr::BranchOcclusionRow::HiddenLength), 100.0);
  const auto  labels = vr::ConvertVolumeNodeToLabelImage(outputs.HiddenLabels);
  const auto  owners = vr::ConvertVolumeNodeToLabelImage(outputs.OwnerLabels);
  std::size_t hidden = 0;
  for (std::size_t k = 0; k < labels->GetLargestPossibleRegion().GetNumberOfPixels(); ++k)
  {
    hidden += labels->GetBufferPointer()[k] != 0 ? 1 : 0;
    EXPECT_TRUE(labels->GetBufferPointer()[k] == 0 || owners->GetBufferPointer()[k] != 0);
  }
  EXPECT_GT(hidden, 20u);
  EXPECT_FALSE(outputs.OcclusionProfile) << "not asked for";

  // The other modes have nothing hidden to say.
  runoff.Parameters.Mode = itk::CPRDepthMode::Scanline;
  const vr::ReformationOutputs & scanline = runoff.Update();
  EXPECT_FALSE(scanline.HiddenLabels);
  EXPECT_TRUE(scanline.BranchOcclusions.empty());
}

TEST(VisibilityLogic, TheLeastOccludedAngleIsTheProfilesMinimumAndTheProfileIsKeptWhileOnlyTheAngleChanges)
{
  RunoffLogic runoff;
  runoff.Parameters.LeastOccludedAngle = true;
  runoff.Parameters.AngleInDegrees = 77.0; // ignored
  const vr::ReformationOutputs & outputs = runoff.Update();
  ASSERT_TRUE(outputs.OcclusionProfile);
  const itk::CPROcclusionProfile & profile = *outputs.OcclusionProfile;
  ASSERT_EQ(profile.HiddenLength.size(), 180u);
  EXPECT_TRUE(outputs.AngleChosen);
  EXPECT_EQ(outputs.View.GetAngleInDegrees(), static_cast<double>(profile.LeastOccludedAngle()));
  for (unsigned int angle = 0; angle < profile.LeastOccludedAngle(); ++angle)
  {
    EXPECT_GT(profile.HiddenLength[angle], profile.HiddenLength[profile.LeastOccludedAngle()]) << "ties go to 0";
  }
  EXPECT_GT(outputs.Times.OcclusionProfile, 0.0);
  // The view's hidden length is about the profile's there (pixels against millimetres, at 10 mm pixels).
  EXPECT_NEAR(Sum(outputs.BranchOcclusions, &vr::BranchOcclusionRow::HiddenLength),
              profile.HiddenLength[profile.LeastOccludedAngle()],
              0.05 * profile.TreeLength);

  // A given angle again, the profile asked for: the same profile object, not computed again.
  const auto kept = outputs.OcclusionProfile;
  runoff.Parameters.LeastOccludedAngle = false;
  runoff.Logic.SetOcclusionProfileEnabled(true);
  const vr::ReformationOutputs & turned = runoff.Update();
  EXPECT_EQ(turned.OcclusionProfile, kept);
  EXPECT_EQ(turned.Times.OcclusionProfile, 0.0);
  EXPECT_FALSE(turned.AngleChosen);
  EXPECT_EQ(turned.View.GetAngleInDegrees(), 77.0);
  // Another up axis is another profile.
  runoff.Parameters.Up[0] = 1.0;
  runoff.Parameters.Up[2] = 0.0;
  EXPECT_NE(runoff.Update().OcclusionProfile, kept);
}

TEST(VisibilityLogic, BranchesWithoutRadiiAreNamedInAWarningAndTheResultIsValid)
{
  RunoffLogic              runoff(false);
  std::vector<std::string> warnings;
  runoff.Logic.SetWarningCallback([&](const std::string & message, const std::string &)
                                  { warnings.push_back(message); });
  const vr::ReformationOutputs & outputs = runoff.Update();
  std::string                    all;
  for (const auto & warning : runoff.Logic.GetWarnings())
  {
    all += warning + "\n";
  }
  EXPECT_NE(all.find("visibility mode: "), std::string::npos) << all;
  EXPECT_NE(all.find(" branches have no lumen radius"), std::string::npos) << all;
  const std::size_t branches = runoff.Logic.GetDepthFilter()->GetCenterlineTree().GetNumberOfBranches();
  EXPECT_NE(all.find(std::to_string(branches) + " of " + std::to_string(branches) + " branches"), std::string::npos)
    << all;
  EXPECT_NE(all.find("\"aorta\" (branch 1)"), std::string::npos) << all;
  EXPECT_NE(all.find("only where the centerlines cross"), std::string::npos) << all;
  ASSERT_EQ(warnings.size(), 1u);
  runoff.Update();
  EXPECT_EQ(warnings.size(), 1u) << "said once for these centerlines and this mode";
  const auto depth = vr::ConvertVolumeNodeToDepthImage(outputs.RelaxedDepth);
  for (std::size_t k = 0; k < depth->GetLargestPossibleRegion().GetNumberOfPixels(); ++k)
  {
    ASSERT_TRUE(std::isfinite(depth->GetBufferPointer()[k]));
  }
  // Scanline mode has no such warning.
  runoff.Parameters.Mode = itk::CPRDepthMode::Scanline;
  runoff.Update();
  for (const auto & warning : runoff.Logic.GetWarnings())
  {
    EXPECT_EQ(warning.find("lumen radius"), std::string::npos) << warning;
  }
}

TEST(VisibilityLogic, TheOneWriterWritesWhatLiesHiddenAndRefusesItOutsideVisibilityMode)
{
  RunoffLogic runoff;
  runoff.Logic.SetOcclusionProfileEnabled(true);
  const vr::ReformationOutputs outputs = runoff.Update();
  ScopedTemporaryFolder        folder;
  vr::OutputSelection          selection{ false, false, false, false, false, false, false };
  selection.HiddenLabels = selection.HiddenLengths = selection.OcclusionProfile = true;
  vr::WriteOutputs(outputs, selection, folder.Path().string(), 900.0, 200.0);
  EXPECT_EQ(folder.Entries(),
            (std::vector<std::string>{ "hidden-labels.nrrd", "hidden-lengths.csv", "occlusion-profile.csv" }));
  // The table: a header, a row per branch, a row for the whole tree; lengths as the outputs have them.
  std::ifstream            table(folder.File("hidden-lengths.csv"));
  std::vector<std::string> lines;
  for (std::string line; std::getline(table, line);)
  {
    lines.push_back(line);
  }
  ASSERT_EQ(lines.size(), outputs.BranchOcclusions.size() + 2);
  EXPECT_EQ(lines[0], "branch_id,name,length_mm,hidden_length_mm,hidden_percent,angle_degrees");
  std::istringstream whole(lines.back());
  std::string        id, name, length, hiddenLength;
  std::getline(whole, id, ',');
  std::getline(whole, name, ',');
  std::getline(whole, length, ',');
  std::getline(whole, hiddenLength, ',');
  EXPECT_EQ(id, "0");
  EXPECT_EQ(name, "whole tree");
  EXPECT_NEAR(std::stod(hiddenLength), Sum(outputs.BranchOcclusions, &vr::BranchOcclusionRow::HiddenLength), 1e-6);
  EXPECT_NE(lines.back().find(",124"), std::string::npos) << lines.back();
  std::ifstream profile(folder.File("occlusion-profile.csv"));
  std::size_t   rows = 0;
  for (std::string line; std::getline(profile, line);)
  {
    ++rows;
  }
  EXPECT_EQ(rows, 181u);

  // In Scanline mode, asking for them writes nothing at all.
  runoff.Parameters.Mode = itk::CPRDepthMode::Scanline;
  const vr::ReformationOutputs scanline = runoff.Update();
  ScopedTemporaryFolder        empty;
  vr::OutputSelection          withCPR = selection;
  withCPR.CPR = true;
  try
  {
    vr::WriteOutputs(scanline, withCPR, empty.Path().string(), 900.0, 200.0);
    ADD_FAILURE() << "hidden labels outside visibility mode must be refused";
  }
  catch (const vr::InputError & error)
  {
    EXPECT_NE(std::string(error.what()).find("visibility depth mode"), std::string::npos) << error.what();
  }
  EXPECT_TRUE(empty.Entries().empty());
}

TEST(VisibilityLogic, TheDragPreviewRunsVisibilityModeOnItsOwnCoarserGrid)
{
  // Progressive refinement (docs/progressive-refinement.md): the preview keeps the depth mode; its footprints, hidden
  // labels and hidden lengths are those of its own grid, over the same millimetres.
  RunoffLogic                     runoff;
  const vr::ReformationOutputs    full = runoff.Update();
  const vr::ReformationParameters preview = vr::PreviewParameters(runoff.Parameters, full.View, 2);
  EXPECT_EQ(preview.Mode, itk::CPRDepthMode::Visibility);
  runoff.Logic.SetParameters(preview);
  const vr::ReformationOutputs & coarse = runoff.Logic.Update();
  ASSERT_TRUE(coarse.HiddenLabels);
  EXPECT_EQ(coarse.View.GetSize()[0], (full.View.GetSize()[0] + 1) / 2);
  EXPECT_EQ(coarse.View.GetSpacing()[0], 2.0 * full.View.GetSpacing()[0]);
  int dimensions[3];
  coarse.HiddenLabels->GetImageData()->GetDimensions(dimensions);
  EXPECT_EQ(static_cast<unsigned int>(dimensions[0]), coarse.View.GetSize()[0]);
  // The same vessels hidden, about as much (pixels twice as large decide the footprints' edges).
  const double fine = Sum(full.BranchOcclusions, &vr::BranchOcclusionRow::HiddenLength);
  const double rough = Sum(coarse.BranchOcclusions, &vr::BranchOcclusionRow::HiddenLength);
  EXPECT_GT(rough, 0.0);
  EXPECT_NEAR(rough, fine, 0.25 * fine);
}
