// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The module logic with a segmentation node instead of a centerline node (issue 15): extraction then reformation,
// extraction rerun only when the segmentation, its labels or the extraction parameters change, one of the two
// centerline sources, segmentations on another grid than the volume, labels, cancelling, bad parameters.

#include "itkImageRegionIteratorWithIndex.h"
#include "vrCenterlineExtraction.h"
#include "vrCoordinateFrames.h"
#include "vrInputError.h"
#include "vrNodeConversion.h"
#include "vrParameterName.h"
#include "vrTestImages.h"
#include "vrTestSegmentations.h"
#include "vrVesselReformationLogic.h"

#include <gtest/gtest.h>

#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace
{
using vr::test::LabelMap;
using vr::test::P;
using vr::test::PointType;

constexpr float         Lumen = 1000.0f;
constexpr float         Background = 100.0f;
constexpr unsigned char TrunkLabel = 3;
constexpr unsigned char BranchLabel = 5;

itk::Vector<double, 3>
V(double x, double y, double z)
{
  itk::Vector<double, 3> v;
  v[0] = x;
  v[1] = y;
  v[2] = z;
  return v;
}

/** A trunk along z and a branch leaving it part-way (LPS mm): three sections once split at the junction. */
itk::CenterlineTree
Vessels()
{
  itk::CenterlineTree tree;
  tree.AddBranch(vr::test::TubeBranch(1, vr::test::SegmentPoints(P(24.3, 23.8, 4.0), P(24.3, 23.8, 52.0), 0.5), 4.0));
  tree.AddBranch(vr::test::TubeBranch(2, vr::test::SegmentPoints(P(24.3, 23.8, 24.0), P(40.2, 30.1, 53.0), 0.5), 3.0));
  return tree;
}

/** The vessels' label map (trunk 3, branch 5) on a grid rotated and flipped like a real scan's. */
LabelMap::Pointer
VesselLabels(const itk::Vector<double, 3> & spacing, const PointType & origin, const itk::Size<3> & size)
{
  itk::Matrix<double, 3, 3> direction;
  direction.SetIdentity();
  direction(0, 0) = -1.0; // x runs right to left, as in aorta.mha
  direction(1, 1) = -1.0;
  auto                image = vr::test::MakeLabelMap(size, spacing, origin, direction);
  itk::CenterlineTree trunk;
  trunk.AddBranch(Vessels().GetBranches()[0]);
  itk::CenterlineTree branch;
  branch.AddBranch(Vessels().GetBranches()[1]);
  vr::test::DrawTubes(image, branch, BranchLabel);
  vr::test::DrawTubes(image, trunk, TrunkLabel);
  return image;
}

LabelMap::Pointer
SameGridLabels()
{
  return VesselLabels(V(1, 1, 1), P(48, 48, 0), { { 48, 48, 60 } });
}

/** The volume: lumen where the vessels are, background elsewhere, on the labels' grid. */
vtkSmartPointer<vr::VolumeNode>
VolumeNode()
{
  const auto labels = SameGridLabels();
  auto       volume = vr::VolumeImageType::New();
  volume->CopyInformation(labels);
  volume->SetRegions(labels->GetLargestPossibleRegion());
  volume->Allocate();
  for (std::size_t k = 0; k < labels->GetBufferedRegion().GetNumberOfPixels(); ++k)
  {
    volume->GetBufferPointer()[k] = labels->GetBufferPointer()[k] != 0 ? Lumen : Background;
  }
  return vr::ConvertItkImageToVolumeNode(volume.GetPointer(), "volume");
}

vr::ReformationParameters
QuickParameters()
{
  vr::ReformationParameters parameters;
  parameters.Iterations = 30;
  parameters.Backend = vr::RelaxBackend::CPU;
  return parameters;
}

class LogicWithSegmentation : public ::testing::Test
{
protected:
  void
  SetUp() override
  {
    m_Volume = VolumeNode();
    m_Segmentation = vr::ConvertItkImageToVolumeNode(SameGridLabels().GetPointer(), "vessels");
    m_Logic.SetVolumeNode(m_Volume);
    m_Logic.SetSegmentationNode(m_Segmentation);
    m_Logic.SetParameters(QuickParameters());
    m_Logic.SetWarningCallback([this](const std::string & message, const std::string &)
                               { m_Warnings.push_back(message); });
  }

  vtkSmartPointer<vr::VolumeNode> m_Volume;
  vtkSmartPointer<vr::VolumeNode> m_Segmentation;
  vr::VesselReformationLogic      m_Logic;
  std::vector<std::string>        m_Warnings;
};

TEST_F(LogicWithSegmentation, ExtractsTheCenterlinesThenReformsAlongThem)
{
  const vr::ReformationOutputs & outputs = m_Logic.Update();
  ASSERT_NE(outputs.ExtractedCenterlines, nullptr);
  const itk::CenterlineTree tree = vr::ConvertCenterlineNodeToTree(outputs.ExtractedCenterlines);
  EXPECT_EQ(tree.GetNumberOfBranches(), 3u);
  EXPECT_EQ(m_Logic.GetDepthFilter()->GetCenterlineTree(), tree);
  // The extracted centerlines lie on the drawn axes (LPS, through the node's RAS and back): every point inside the
  // lumen, most within half a voxel (the bifurcation, where the tubes overlap, has no single axis).
  std::vector<double> distances;
  for (const auto & branch : tree.GetBranches())
  {
    for (const auto & point : branch.Points)
    {
      const auto nearest = vr::test::NearestPointOnTree(point, Vessels()).Nearest;
      EXPECT_LT(nearest.Distance, nearest.Radius) << point;
      distances.push_back(nearest.Distance);
    }
  }
  EXPECT_LT(vr::test::Median(distances), 0.5);
  EXPECT_EQ(m_Logic.GetStageCounts().Extraction, 1u);
  EXPECT_GT(outputs.Times.Extraction, 0.0);
  EXPECT_TRUE(m_Warnings.empty()) << m_Warnings.front();
  // The fixed pixels (centerline and lumen) show lumen.
  const auto          cpr = vr::ConvertVolumeNodeToDepthImage(outputs.CPR);
  const auto          mask = vr::ConvertVolumeNodeToMaskImage(outputs.FixedMask);
  std::vector<double> fixed;
  for (std::size_t k = 0; k < cpr->GetBufferedRegion().GetNumberOfPixels(); ++k)
  {
    if (mask->GetBufferPointer()[k])
    {
      fixed.push_back(cpr->GetBufferPointer()[k]);
    }
  }
  ASSERT_GT(fixed.size(), 50u);
  EXPECT_GT(vr::test::Median(fixed), 0.9 * Lumen);
}

TEST_F(LogicWithSegmentation, ExtractsAgainOnlyWhenTheSegmentationOrItsParametersChange)
{
  m_Logic.Update();
  auto counts = m_Logic.GetStageCounts();
  ASSERT_EQ(counts.Extraction, 1u);
  ASSERT_EQ(counts.Depth, 1u);
  const unsigned conversions = counts.Conversion;

  // Nothing changed: nothing runs.
  m_Logic.Update();
  counts = m_Logic.GetStageCounts();
  EXPECT_EQ(counts.Extraction, 1u);
  EXPECT_EQ(counts.Depth, 1u);
  EXPECT_EQ(counts.Conversion, conversions);

  // A new angle: the reformation, not the extraction.
  vr::ReformationParameters parameters = QuickParameters();
  parameters.AngleInDegrees = 40.0;
  m_Logic.SetParameters(parameters);
  m_Logic.Update();
  counts = m_Logic.GetStageCounts();
  EXPECT_EQ(counts.Extraction, 1u);
  EXPECT_EQ(counts.Depth, 2u);

  // A minimum branch length below every branch: the extraction reruns, gives the same tree, and nothing after it
  // reruns.
  vr::CenterlineExtractionParameters extraction;
  extraction.MinimumBranchLength = 2.0;
  m_Logic.SetCenterlineExtractionParameters(extraction);
  m_Logic.Update();
  counts = m_Logic.GetStageCounts();
  EXPECT_EQ(counts.Extraction, 2u);
  EXPECT_EQ(counts.Depth, 2u);

  // A root point at the branch's far end (RAS): another tree, so everything after reruns.
  extraction.RootPointsRAS = { vr::LPSToRAS(P(40.2, 30.1, 53.0)) };
  m_Logic.SetCenterlineExtractionParameters(extraction);
  const itk::CenterlineTree rooted = vr::ConvertCenterlineNodeToTree(m_Logic.Update().ExtractedCenterlines);
  counts = m_Logic.GetStageCounts();
  EXPECT_EQ(counts.Extraction, 3u);
  EXPECT_EQ(counts.Depth, 3u);
  EXPECT_LT(rooted.GetBranches().front().Points.front().EuclideanDistanceTo(P(40.2, 30.1, 53.0)), 3.0);

  // The segmentation node modified: converted and extracted again.
  m_Segmentation->Modified();
  m_Logic.Update();
  counts = m_Logic.GetStageCounts();
  EXPECT_EQ(counts.Extraction, 4u);
  EXPECT_EQ(counts.Conversion, conversions + 1);
  EXPECT_EQ(counts.Depth, 3u) << "the same tree again reruns nothing after the extraction";

  // Relaxation only: no extraction.
  parameters.Relaxation = 0.5;
  m_Logic.SetParameters(parameters);
  m_Logic.Update();
  EXPECT_EQ(m_Logic.GetStageCounts().Extraction, 4u);
}

TEST_F(LogicWithSegmentation, LabelsChooseTheVesselsAndAreAConversionChange)
{
  vr::CenterlineExtractionParameters extraction;
  extraction.Labels = { TrunkLabel };
  m_Logic.SetCenterlineExtractionParameters(extraction);
  const itk::CenterlineTree trunk = vr::ConvertCenterlineNodeToTree(m_Logic.Update().ExtractedCenterlines);
  EXPECT_EQ(trunk.GetNumberOfBranches(), 1u);
  const unsigned conversions = m_Logic.GetStageCounts().Conversion;
  extraction.Labels = { TrunkLabel, BranchLabel };
  m_Logic.SetCenterlineExtractionParameters(extraction);
  EXPECT_EQ(vr::ConvertCenterlineNodeToTree(m_Logic.Update().ExtractedCenterlines).GetNumberOfBranches(), 3u);
  EXPECT_EQ(m_Logic.GetStageCounts().Conversion, conversions + 1);

  // Labels that no voxel has: the error names them and the parameter.
  extraction.Labels = { 9 };
  m_Logic.SetCenterlineExtractionParameters(extraction);
  try
  {
    m_Logic.Update();
    ADD_FAILURE() << "no error";
  }
  catch (const vr::InputError & error)
  {
    std::cout << "  " << error.what() << std::endl;
    EXPECT_NE(std::string(error.what()).find("segmentation \"vessels\""), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("no voxel with label 9; its values are 0 3 5"), std::string::npos)
      << error.what();
    EXPECT_EQ(error.Parameter(), vr::ParameterName::VesselLabels);
  }
}

TEST_F(LogicWithSegmentation, TakesOneOfTheTwoCenterlineSourcesAndSwitchesBetweenThem)
{
  const itk::CenterlineTree extracted = vr::ConvertCenterlineNodeToTree(m_Logic.Update().ExtractedCenterlines);
  // A centerline node as well: ambiguous.
  auto centerlines = vr::ConvertTreeToCenterlineNode(Vessels(), "drawn axes");
  m_Logic.SetCenterlineNode(centerlines);
  EXPECT_THROW(m_Logic.Update(), vr::InputError);
  // The centerline node alone: its tree, no extracted centerlines.
  m_Logic.SetSegmentationNode(nullptr);
  const vr::ReformationOutputs & fromNode = m_Logic.Update();
  EXPECT_EQ(fromNode.ExtractedCenterlines, nullptr);
  EXPECT_EQ(m_Logic.GetDepthFilter()->GetCenterlineTree(), vr::ConvertCenterlineNodeToTree(centerlines));
  // Back to the segmentation: its tree again, without extracting again.
  m_Logic.SetCenterlineNode(nullptr);
  m_Logic.SetSegmentationNode(m_Segmentation);
  const vr::ReformationOutputs & fromSegmentation = m_Logic.Update();
  ASSERT_NE(fromSegmentation.ExtractedCenterlines, nullptr);
  EXPECT_EQ(m_Logic.GetDepthFilter()->GetCenterlineTree(), extracted);
  EXPECT_EQ(m_Logic.GetStageCounts().Extraction, 1u);
  // Neither.
  m_Logic.SetSegmentationNode(nullptr);
  try
  {
    m_Logic.Update();
    ADD_FAILURE() << "no error";
  }
  catch (const vr::InputError & error)
  {
    EXPECT_NE(std::string(error.what()).find("no centerline node and no segmentation node"), std::string::npos);
  }
}

TEST_F(LogicWithSegmentation, SegmentationOnAnotherGridIsUsedWithAWarningAndOneAwayIsAnError)
{
  const itk::CenterlineTree sameGrid = vr::ConvertCenterlineNodeToTree(m_Logic.Update().ExtractedCenterlines);
  // Finer voxels, shifted origin: the same vessels in physical space.
  m_Segmentation = vr::ConvertItkImageToVolumeNode(
    VesselLabels(V(0.7, 0.7, 0.8), P(49.1, 48.6, -0.4), { { 72, 72, 76 } }).GetPointer(), "vessels, fine");
  m_Logic.SetSegmentationNode(m_Segmentation);
  const itk::CenterlineTree fineGrid = vr::ConvertCenterlineNodeToTree(m_Logic.Update().ExtractedCenterlines);
  ASSERT_EQ(m_Warnings.size(), 1u);
  EXPECT_NE(m_Warnings[0].find("segmentation \"vessels, fine\" lies on another grid"), std::string::npos)
    << m_Warnings[0];
  EXPECT_NE(m_Warnings[0].find("The reformation continues"), std::string::npos);
  EXPECT_EQ(fineGrid.GetNumberOfBranches(), sameGrid.GetNumberOfBranches());
  std::vector<double> distances;
  for (const auto & branch : fineGrid.GetBranches())
  {
    for (const auto & point : branch.Points)
    {
      distances.push_back(vr::test::NearestPointOnTree(point, sameGrid).Nearest.Distance);
    }
  }
  EXPECT_LT(vr::test::Median(distances), 0.5);

  // Half a metre away: not this scan's segmentation.
  auto elsewhere = SameGridLabels();
  elsewhere->SetOrigin(P(48, 48, 500));
  m_Logic.SetSegmentationNode(vr::ConvertItkImageToVolumeNode(elsewhere.GetPointer(), "elsewhere"));
  try
  {
    m_Logic.Update();
    ADD_FAILURE() << "no error";
  }
  catch (const vr::InputError & error)
  {
    std::cout << "  " << error.what() << std::endl;
    EXPECT_NE(std::string(error.what()).find("segmentation \"elsewhere\""), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("does not overlap the volume \"volume\""), std::string::npos);
  }
}

TEST_F(LogicWithSegmentation, AbortDuringTheExtractionCancelsAndTheNextUpdateRecovers)
{
  m_Logic.SetProgressCallback(
    [this](double, const std::string & stage)
    {
      if (stage == "centerlines")
      {
        m_Logic.AbortUpdate();
      }
    });
  EXPECT_THROW(m_Logic.Update(), vr::Cancelled);
  EXPECT_EQ(m_Logic.GetStageCounts().Depth, 0u);
  m_Logic.SetProgressCallback({});
  const vr::ReformationOutputs & outputs = m_Logic.Update();
  ASSERT_NE(outputs.ExtractedCenterlines, nullptr);
  EXPECT_EQ(vr::ConvertCenterlineNodeToTree(outputs.ExtractedCenterlines).GetNumberOfBranches(), 3u);
}

TEST_F(LogicWithSegmentation, BadExtractionParametersAreNamedByMeaning)
{
  const auto expectParameter = [this](const vr::CenterlineExtractionParameters & extraction, const char * meaning)
  {
    m_Logic.SetCenterlineExtractionParameters(extraction);
    try
    {
      m_Logic.Update();
      ADD_FAILURE() << "no error for " << meaning;
    }
    catch (const vr::InputError & error)
    {
      std::cout << "  " << error.what() << std::endl;
      EXPECT_EQ(error.Parameter(), meaning) << error.what();
    }
  };
  vr::CenterlineExtractionParameters extraction;
  extraction.MinimumBranchLength = -1.0;
  expectParameter(extraction, vr::ParameterName::MinimumBranchLength);
  extraction = {};
  extraction.Labels = { 2.5 };
  expectParameter(extraction, vr::ParameterName::VesselLabels);
  extraction = {};
  extraction.RootPointsRAS = { P(300, 300, 300) };
  expectParameter(extraction, vr::ParameterName::RootPoint);
}
} // namespace

TEST(SegmentationRegionNames, FileNamesReadAsVesselNames)
{
  EXPECT_EQ(vr::VesselNameOfFile("/data/seg/aorta.nii.gz"), "aorta");
  EXPECT_EQ(vr::VesselNameOfFile("common_carotid_artery_left.nii.gz"), "common carotid artery left");
  EXPECT_EQ(vr::VesselNameOfFile("iliac_artery_right.nii"), "iliac artery right");
  EXPECT_EQ(vr::VesselNameOfFile("vessels.seg.nrrd"), "vessels");
  EXPECT_EQ(vr::VesselNameOfFile("a.b_c.mha"), "a.b c");
  EXPECT_EQ(vr::VesselNameOfFile("noextension"), "noextension");
}

TEST(SegmentationRegionNames, EachBranchTakesTheRegionMostOfItsPointsLieIn)
{
  // A 10 x 10 x 10 grid of 1 mm voxels: region 1 for x < 5, region 2 for x >= 5, region 3 nowhere named.
  auto regions = itk::Image<float, 3>::New();
  regions->SetRegions(itk::ImageRegion<3>({ { 0, 0, 0 } }, { { 10, 10, 10 } }));
  regions->Allocate();
  for (itk::ImageRegionIteratorWithIndex<itk::Image<float, 3>> it(regions, regions->GetBufferedRegion()); !it.IsAtEnd();
       ++it)
  {
    it.Set(it.GetIndex()[0] < 5 ? 1.0f : 2.0f);
  }
  itk::CenterlineTree   tree;
  itk::CenterlineBranch mostlyLeft; // x = 1, 2, 3, 6: three of four points in region 1
  mostlyLeft.Id = 1;
  mostlyLeft.Points = { vr::test::P(1, 5, 5), vr::test::P(2, 5, 5), vr::test::P(3, 5, 5), vr::test::P(6, 5, 5) };
  itk::CenterlineBranch right; // all in region 2
  right.Id = 2;
  right.Points = { vr::test::P(7, 1, 1), vr::test::P(8, 2, 2) };
  itk::CenterlineBranch outside; // outside the grid: keeps its name
  outside.Id = 3;
  outside.Name = "kept";
  outside.Points = { vr::test::P(50, 50, 50), vr::test::P(60, 50, 50) };
  tree.AddBranch(mostlyLeft);
  tree.AddBranch(right);
  tree.AddBranch(outside);
  vr::NameBranchesByRegion(tree, regions.GetPointer(), { { 1, "aorta" }, { 2, "iliac artery left" } });
  EXPECT_EQ(tree.GetBranches()[0].Name, "aorta");
  EXPECT_EQ(tree.GetBranches()[1].Name, "iliac artery left");
  EXPECT_EQ(tree.GetBranches()[2].Name, "kept");
}
