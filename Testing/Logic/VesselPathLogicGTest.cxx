// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The single-vessel reading in the module logic (issue 21, item 4): what each change reruns, counted on the
// stages; the pixel-to-patient mapping against the path; errors naming the parameter.

#include "vrInputError.h"
#include "vrNodeConversion.h"
#include "vrTestFiles.h"
#include "vrTestImages.h"
#include "vrTestSegmentations.h"
#include "vrVesselPathLogic.h"

#include "itkImageRegionIterator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace
{
using vr::test::P;
using PointType = itk::Point<double, 3>;
using DepthImagePointer = vr::DepthImageType::Pointer;

/** Two branches: a trunk along +z and a child leaving it at its middle along +x, radii known. */
itk::CenterlineTree
TwoBranchTree()
{
  itk::CenterlineTree tree;
  tree.AddBranch(vr::test::TubeBranch(1, vr::test::SegmentPoints(P(0, 0, -30), P(0, 0, 30), 0.5), 3.0));
  tree.AddBranch(vr::test::TubeBranch(2, vr::test::SegmentPoints(P(0, 0, 0), P(25, 0, 0), 0.5), 2.0));
  return tree;
}

struct Scene
{
  vr::test::LabelMap::Pointer  Mask;
  vr::VolumeImageType::Pointer Volume;
};

Scene
MakeScene()
{
  Scene scene;
  scene.Mask = vr::test::MakeLabelMap(itk::Size<3>{ { 70, 50, 80 } },
                                      itk::Vector<double, 3>(1.0),
                                      P(-20, -25, -40),
                                      vr::test::RotationMatrix(0, 0, 1, 0));
  vr::test::DrawTubes(scene.Mask, TwoBranchTree());
  scene.Volume = vr::VolumeImageType::New();
  scene.Volume->CopyInformation(scene.Mask);
  scene.Volume->SetRegions(scene.Mask->GetLargestPossibleRegion());
  scene.Volume->Allocate();
  itk::ImageRegionIterator<vr::VolumeImageType>     out(scene.Volume, scene.Volume->GetLargestPossibleRegion());
  itk::ImageRegionConstIterator<vr::test::LabelMap> in(scene.Mask, scene.Mask->GetLargestPossibleRegion());
  for (; !out.IsAtEnd(); ++out, ++in)
  {
    out.Set(in.Get() ? 300.0f : 0.0f);
  }
  return scene;
}

/** The scene's nodes, as a platform hands them to the logic (RAS; the logic converts them). */
vtkSmartPointer<vr::VolumeNode>
VolumeNodeOf(const Scene & scene)
{
  return vr::ConvertItkImageToVolumeNode(scene.Volume.GetPointer(), "tubes volume");
}

vtkSmartPointer<vr::CenterlineNode>
CenterlineNodeOf(const itk::CenterlineTree & tree)
{
  return vr::ConvertTreeToCenterlineNode(tree, "two branches");
}

/** Hands \a logic a centerline node of \a tree with the tree itself as its conversion (as the modules do): the
 * child leaves the trunk at its middle, which the node's polylines would cut into two branches. */
void
SetTree(vr::VesselPathLogic & logic, const itk::CenterlineTree & tree)
{
  const auto node = CenterlineNodeOf(tree);
  logic.GetInputCache()->SetCenterlines(node, tree);
  logic.SetCenterlineNode(node);
}

vr::VesselPathParameters
Defaults()
{
  vr::VesselPathParameters parameters;
  parameters.Width = 20.0;
  parameters.PixelSpacing = 0.5;
  return parameters;
}

void
ExpectCounts(const vr::VesselPathStageCounts & counts,
             unsigned                          path,
             unsigned                          frame,
             unsigned                          resampling,
             unsigned                          measurement)
{
  EXPECT_EQ(counts.Path, path);
  EXPECT_EQ(counts.Frame, frame);
  EXPECT_EQ(counts.Resampling, resampling);
  EXPECT_EQ(counts.Measurement, measurement);
}

TEST(VesselPathLogic, EachChangeRerunsOnlyWhatItInvalidates)
{
  const Scene         scene = MakeScene();
  vr::VesselPathLogic logic;
  logic.SetVolumeNode(VolumeNodeOf(scene));
  SetTree(logic, TwoBranchTree());
  vr::VesselPathParameters parameters = Defaults();
  logic.SetParameters(parameters);
  logic.Update();
  ExpectCounts(logic.GetStageCounts(), 1, 1, 1, 1);
  logic.Update();
  ExpectCounts(logic.GetStageCounts(), 1, 1, 1, 1);

  // The roll: the resampling alone.
  parameters.RollInDegrees = 30.0;
  logic.SetParameters(parameters);
  logic.Update();
  ExpectCounts(logic.GetStageCounts(), 1, 1, 2, 1);
  // The width and the interpolation: the resampling alone.
  parameters.Width = 16.0;
  parameters.Interpolation = itk::CPRInterpolationMode::Nearest;
  logic.SetParameters(parameters);
  logic.Update();
  ExpectCounts(logic.GetStageCounts(), 1, 1, 3, 1);
  // The path (another branch): frame, resampling and measurement with it.
  parameters.BranchId = 1;
  logic.SetParameters(parameters);
  logic.Update();
  ExpectCounts(logic.GetStageCounts(), 2, 2, 4, 2);
  // A range: the path again.
  parameters.HasRange = true;
  parameters.RangeStart = 5.0;
  parameters.RangeEnd = 40.0;
  logic.SetParameters(parameters);
  logic.Update();
  ExpectCounts(logic.GetStageCounts(), 3, 3, 5, 3);
  EXPECT_NEAR(logic.GetOutputs().Path.GetLength(), 35.0, 1e-6);
  // The segmentation and the reference points: the measurement alone.
  logic.SetSegmentationNode(vr::ConvertItkImageToVolumeNode(scene.Mask.GetPointer(), "tubes"));
  logic.Update();
  ExpectCounts(logic.GetStageCounts(), 3, 3, 5, 4);
  EXPECT_EQ(logic.GetOutputs().Lumen.Source, itk::VesselLumenSource::Segmentation);
  parameters.ReferencePoints = { 5.0, 30.0 };
  logic.SetParameters(parameters);
  logic.Update();
  ExpectCounts(logic.GetStageCounts(), 3, 3, 5, 5);
  // The reference method: the measurement alone.
  parameters.ReferenceMethod = vr::VesselReferenceMethod::RobustFit;
  logic.SetParameters(parameters);
  logic.Update();
  ExpectCounts(logic.GetStageCounts(), 3, 3, 5, 6);
  EXPECT_EQ(logic.GetOutputs().Stenosis.Method, vr::VesselReferenceMethod::RobustFit);
  // The section spacing: the frame, the resampling and the measurement.
  parameters.SectionSpacing = 1.0;
  logic.SetParameters(parameters);
  logic.Update();
  ExpectCounts(logic.GetStageCounts(), 3, 4, 6, 7);
}

// The nodes as the tree logic takes them (docs/module-logic.md): a node changed reruns what its conversion feeds, an
// unchanged one nothing; and the images an Update() handed out stay as they were when a stage reruns.
TEST(VesselPathLogic, EachNodeChangeRerunsOnlyWhatItInvalidates)
{
  const Scene         scene = MakeScene();
  const auto          volume = VolumeNodeOf(scene);
  const auto          centerlines = CenterlineNodeOf(TwoBranchTree());
  const auto          segmentation = vr::ConvertItkImageToVolumeNode(scene.Mask.GetPointer(), "tubes");
  vr::VesselPathLogic logic;
  logic.SetVolumeNode(volume);
  logic.SetCenterlineNode(centerlines);
  EXPECT_EQ(logic.GetVolumeNode(), volume.GetPointer());
  EXPECT_EQ(logic.GetCenterlineNode(), centerlines.GetPointer());
  vr::VesselPathParameters parameters = Defaults();
  logic.SetParameters(parameters);
  logic.Update();
  ExpectCounts(logic.GetStageCounts(), 1, 1, 1, 1);
  const DepthImagePointer  firstCPR = logic.GetOutputs().CPR;
  const std::vector<float> firstPixels(firstCPR->GetBufferPointer(),
                                       firstCPR->GetBufferPointer() +
                                         firstCPR->GetLargestPossibleRegion().GetNumberOfPixels());

  // The volume node modified: the resampling alone (the frame does not read the volume with a fixed up axis).
  volume->Modified();
  logic.Update();
  ExpectCounts(logic.GetStageCounts(), 1, 1, 2, 1);
  EXPECT_NE(logic.GetOutputs().CPR, firstCPR) << "a rerun stage makes a new image";
  EXPECT_TRUE(std::equal(firstPixels.begin(), firstPixels.end(), firstCPR->GetBufferPointer()))
    << "the image handed out before changed under its holder";
  // With the automatic up axis, the frame reads the volume: a modified volume reruns it too.
  parameters.AutomaticUp = true;
  logic.SetParameters(parameters);
  logic.Update();
  ExpectCounts(logic.GetStageCounts(), 1, 2, 3, 2);
  volume->Modified();
  logic.Update();
  ExpectCounts(logic.GetStageCounts(), 1, 3, 4, 3);
  // The centerline node modified but holding the same tree: nothing.
  centerlines->Modified();
  logic.Update();
  ExpectCounts(logic.GetStageCounts(), 1, 3, 4, 3);
  // Another centerline node, another tree: everything.
  itk::CenterlineTree longer;
  longer.AddBranch(vr::test::TubeBranch(1, vr::test::SegmentPoints(P(0, 0, -30), P(0, 0, 34), 0.5), 3.0));
  longer.AddBranch(vr::test::TubeBranch(2, vr::test::SegmentPoints(P(0, 0, 0), P(25, 0, 0), 0.5), 2.0));
  logic.SetCenterlineNode(CenterlineNodeOf(longer));
  logic.Update();
  ExpectCounts(logic.GetStageCounts(), 2, 4, 5, 4);
  // A segmentation node, and that node modified: the measurement alone, each time.
  logic.SetSegmentationNode(segmentation);
  EXPECT_EQ(logic.GetSegmentationNode(), segmentation.GetPointer());
  logic.Update();
  ExpectCounts(logic.GetStageCounts(), 2, 4, 5, 5);
  EXPECT_EQ(logic.GetOutputs().Lumen.Source, itk::VesselLumenSource::Segmentation);
  segmentation->Modified();
  logic.Update();
  ExpectCounts(logic.GetStageCounts(), 2, 4, 5, 6);
  // An abort asked for with no update running changes nothing: the next update runs (and here has nothing to do).
  logic.AbortUpdate();
  EXPECT_NO_THROW(logic.Update());
  ExpectCounts(logic.GetStageCounts(), 2, 4, 5, 6);
}

TEST(VesselPathLogic, WithoutNodesItSaysWhichIsMissing)
{
  const Scene         scene = MakeScene();
  vr::VesselPathLogic logic;
  logic.SetParameters(Defaults());
  try
  {
    logic.Update();
    ADD_FAILURE() << "no volume node, and no error";
  }
  catch (const vr::InputError & error)
  {
    EXPECT_NE(std::string(error.what()).find("no volume"), std::string::npos) << error.what();
  }
  logic.SetVolumeNode(VolumeNodeOf(scene));
  try
  {
    logic.Update();
    ADD_FAILURE() << "no centerline node, and no error";
  }
  catch (const vr::InputError & error)
  {
    EXPECT_NE(std::string(error.what()).find("no centerlines"), std::string::npos) << error.what();
  }
}

TEST(VesselPathLogic, ARefusedSegmentationLeavesNoStaleLumen)
{
  const Scene         scene = MakeScene();
  vr::VesselPathLogic logic;
  logic.SetVolumeNode(VolumeNodeOf(scene));
  SetTree(logic, TwoBranchTree());
  logic.SetParameters(Defaults());
  ASSERT_TRUE(logic.Update().HasLumen) << "the tree carries radii";
  const double fromRadii = logic.GetOutputs().Stenosis.MinimalLumenDiameter;
  // A segmentation without the path in it is refused...
  auto empty = vr::test::LabelMap::New();
  empty->CopyInformation(scene.Mask);
  empty->SetRegions(scene.Mask->GetLargestPossibleRegion());
  empty->Allocate(true);
  logic.SetSegmentationNode(vr::ConvertItkImageToVolumeNode(empty.GetPointer(), "empty"));
  EXPECT_THROW(logic.Update(), vr::InputError);
  // ...and going back to none measures from the radii again (the failed run had cleared the lumen).
  logic.SetSegmentationNode(nullptr);
  ASSERT_TRUE(logic.Update().HasLumen);
  EXPECT_EQ(logic.GetOutputs().Lumen.Source, itk::VesselLumenSource::CenterlineRadius);
  EXPECT_EQ(logic.GetOutputs().Stenosis.MinimalLumenDiameter, fromRadii);
}

TEST(VesselPathLogic, TheDefaultPathIsTheLongestAndPixelsMapBackToIt)
{
  const Scene         scene = MakeScene();
  vr::VesselPathLogic logic;
  logic.SetVolumeNode(VolumeNodeOf(scene));
  SetTree(logic, TwoBranchTree());
  logic.SetParameters(Defaults());
  const vr::VesselPathOutputs & results = logic.Update();
  // Root to the trunk's far end is 60 mm; root to the child's end 30 + 25 = 55 mm.
  EXPECT_NEAR(results.Path.GetLength(), 60.0, 1e-6);
  const auto   size = results.CPR->GetLargestPossibleRegion().GetSize();
  const double middle = 0.5 * static_cast<double>(size[0] - 1);
  for (const double s : { 0.0, 12.5, 33.0, 59.0 })
  {
    const PointType onPath = results.Path.PointAt(s);
    EXPECT_LT(logic.ComputePoint(middle, logic.RowOfArcLength(s)).EuclideanDistanceTo(onPath), 1e-6) << s;
    const itk::VesselPathSection section = logic.SectionAt(s);
    EXPECT_LT(section.Center.EuclideanDistanceTo(onPath), 1e-9);
    EXPECT_NEAR(section.Lateral * section.Tangent, 0.0, 1e-9);
    EXPECT_NEAR(section.Lateral.GetNorm(), 1.0, 1e-9);
  }
  // The child's path: the trunk from the root to the junction, then the child.
  vr::VesselPathParameters child = Defaults();
  child.BranchId = 2;
  logic.SetParameters(child);
  EXPECT_NEAR(logic.Update().Path.GetLength(), 55.0, 0.6);
  EXPECT_EQ(logic.GetOutputs().Path.GetBranchChain(), (std::vector<int>{ 1, 2 }));
}

TEST(VesselPathLogic, ErrorsNameTheParameter)
{
  const Scene         scene = MakeScene();
  vr::VesselPathLogic logic;
  const auto          parameterOf = [&logic](const vr::VesselPathParameters & parameters)
  {
    try
    {
      logic.SetParameters(parameters);
      logic.Update();
    }
    catch (const vr::InputError & error)
    {
      return error.Parameter();
    }
    return std::string("(no error)");
  };
  EXPECT_EQ(parameterOf(Defaults()), "") << "no volume and no tree: an error about no parameter";
  logic.SetVolumeNode(VolumeNodeOf(scene));
  SetTree(logic, TwoBranchTree());
  vr::VesselPathParameters parameters = Defaults();
  parameters.BranchId = 9;
  EXPECT_EQ(parameterOf(parameters), vr::ParameterName::Branch);
  parameters = Defaults();
  parameters.Width = std::nan("");
  EXPECT_EQ(parameterOf(parameters), vr::ParameterName::Width);
  parameters = Defaults();
  parameters.HasRange = true;
  parameters.RangeStart = 10.0;
  parameters.RangeEnd = 99.0;
  EXPECT_EQ(parameterOf(parameters), vr::ParameterName::PathRange);
  parameters = Defaults();
  parameters.ReferencePoints = { -3.0, 20.0 };
  EXPECT_EQ(parameterOf(parameters), vr::ParameterName::ReferencePoints);
  parameters = Defaults();
  EXPECT_EQ(parameterOf(parameters), "(no error)");
}
} // namespace

namespace
{
TEST(VesselPathLogic, ANarrowerWidthAfterAWiderOneIsResampledWhole)
{
  // The viewer's fold warning offers a narrower width: the filters must not keep the wider run's requested region
  // (it failed with "Requested region is (at least partially) outside the largest possible region").
  const Scene         scene = MakeScene();
  vr::VesselPathLogic logic;
  logic.SetVolumeNode(VolumeNodeOf(scene));
  SetTree(logic, TwoBranchTree());
  logic.SetCrossSectionsEnabled(true);
  vr::VesselPathParameters parameters = Defaults();
  parameters.Width = 40.0;
  logic.SetParameters(parameters);
  EXPECT_EQ(logic.Update().CPR->GetLargestPossibleRegion().GetSize()[0], 81u);
  for (const double width : { 17.2, 6.0, 30.0 })
  {
    parameters.Width = width;
    logic.SetParameters(parameters);
    const auto & results = logic.Update();
    const auto   columns = static_cast<unsigned long>(2 * std::lround(width / (2 * 0.5)) + 1);
    EXPECT_EQ(results.CPR->GetLargestPossibleRegion().GetSize()[0], columns) << width;
    EXPECT_EQ(results.CrossSections->GetLargestPossibleRegion().GetSize()[0],
              static_cast<unsigned long>(std::lround(width / 0.5)) | 1u)
      << width;
  }
}
} // namespace
