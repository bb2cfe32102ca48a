// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The hover readout names the vessel under the mouse: on both built-in phantoms, every fixed pixel of the CPR reads
// the name the phantom gives the vessel that runs there, on the right side of the patient. The reference is the
// phantom's own tree (its ids and its id -> name table), which never went through a centerline node, and the
// readout's RAS position: an id renumbered on the way to the owner labels would name a different vessel.
#include "vrWidgetsTestSupport.h"

#include "itkCTAPhantom.h"
#include "itkMetaDataObject.h"
#include "vrCenterlineIO.h"
#include "vrNodeConversion.h"
#include "vrTestFiles.h"
#include "vrTestSegmentations.h"
#include "vrVolumeIO.h"
#include "vrCoordinateFrames.h"
#include "vrPixelReadout.h"

#include <QEvent>
#include <QVTKOpenGLNativeWidget.h>

#include <vtkImageData.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <set>

namespace
{
using namespace vr;
using namespace vr::test;

/** Distance (mm) from \a point to the polyline of \a branch. */
double
DistanceToBranch(const itk::CenterlineBranch::PointType & point, const itk::CenterlineBranch & branch)
{
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k + 1 < branch.Points.size(); ++k)
  {
    const auto   a = branch.Points[k];
    const auto   segment = branch.Points[k + 1] - a;
    const double length2 = segment * segment;
    const double t = length2 > 0.0 ? std::clamp(((point - a) * segment) / length2, 0.0, 1.0) : 0.0;
    best = std::min(best, point.EuclideanDistanceTo(a + segment * t));
  }
  return best;
}

/** The checks for one phantom shown in \a window: returns the original ids whose name was read at least once. */
std::set<int>
ExpectEveryFixedPixelNamesItsVessel(ViewerWindow & window, const itk::CTAPhantom & phantom, double minimumRight = 1.0)
{
  const auto result = window.GetCPRView()->GetResult();
  EXPECT_TRUE(result);
  if (!result)
  {
    return {};
  }
  vtkImageData * mask = result->Outputs.FixedMask->GetImageData();
  int            dimensions[3];
  mask->GetDimensions(dimensions);
  std::set<int> named;
  int           checked = 0;
  int           right = 0;
  int           hovered = 0;
  for (int j = 0; j < dimensions[1]; ++j)
  {
    for (int i = 0; i < dimensions[0]; ++i)
    {
      if (mask->GetScalarComponentAsDouble(i, j, 0, 0) == 0.0)
      {
        continue;
      }
      const PixelReadout readout = ReadPixel(*result, false, i, j);
      EXPECT_TRUE(readout.Inside);
      EXPECT_GT(readout.Branch, 0) << "a fixed pixel belongs to a branch";
      // The vessel there, from the phantom's own tree: the nearest one, unless another is nearly as near (near a
      // junction, or where two vessels overlap in depth, either name is right).
      const itk::CenterlineBranch::PointType lps = RASToLPS(
        itk::CenterlineBranch::PointType(std::array<double, 3>{ readout.RAS[0], readout.RAS[1], readout.RAS[2] }));
      std::multimap<double, int> byDistance;
      for (const auto & branch : phantom.Tree.GetBranches())
      {
        byDistance.emplace(DistanceToBranch(lps, branch), branch.Id);
      }
      const auto nearest = byDistance.begin();
      auto       other = std::next(nearest);
      while (other != byDistance.end() && phantom.BranchName(other->second) == phantom.BranchName(nearest->second))
      {
        ++other;
      }
      if (other != byDistance.end() && other->first < nearest->first + 3.0)
      {
        continue;
      }
      const std::string expected = phantom.BranchName(nearest->second);
      if (minimumRight >= 1.0)
      {
        EXPECT_EQ(readout.BranchName, expected) << "pixel (" << i << ", " << j << ") at RAS (" << readout.RAS[0] << ", "
                                                << readout.RAS[1] << ", " << readout.RAS[2] << ")";
      }
      right += readout.BranchName == expected ? 1 : 0;
      // The patient's left is RAS -x: a vessel named left must lie there.
      if (expected.rfind("left ", 0) == 0)
      {
        EXPECT_LT(readout.RAS[0], 0.0) << expected << " at pixel (" << i << ", " << j << ")";
      }
      if (expected.rfind("right ", 0) == 0)
      {
        EXPECT_GT(readout.RAS[0], 0.0) << expected << " at pixel (" << i << ", " << j << ")";
      }
      ++checked;
      // Once per vessel, the same through the mouse: the hover readout is this readout.
      if (named.insert(nearest->second).second)
      {
        const QPointF position = window.GetCPRView()->WidgetPositionOfPixel(i, j, false);
        SendMouse(window.GetCPRView()->GetRenderWidget(),
                  QEvent::MouseMove,
                  QPointF(std::floor(position.x()), std::floor(position.y())),
                  Qt::NoButton,
                  Qt::NoButton);
        const PixelReadout & shown = window.GetCPRView()->GetReadout();
        EXPECT_EQ(shown.Column, i);
        EXPECT_EQ(shown.Row, j);
        EXPECT_EQ(shown.BranchName, readout.BranchName);
        EXPECT_TRUE(shown.ToText().contains(QString::fromStdString(readout.BranchName)))
          << shown.ToText().toStdString();
        ++hovered;
      }
    }
  }
  std::cout << right << " of " << checked << " fixed pixels away from junctions named as the phantom names them, "
            << named.size() << " vessels read\n";
  EXPECT_GT(checked, 100);
  EXPECT_GE(right, minimumRight * checked) << right << " of " << checked << " pixels named right";
  EXPECT_EQ(hovered, static_cast<int>(named.size()));
  return named;
}

/** Checks that every vessel of \a phantom was among those \a named. */
void
ExpectEveryVesselRead(const itk::CTAPhantom & phantom, const std::set<int> & named)
{
  std::set<std::string> names;
  for (const int id : named)
  {
    names.insert(phantom.BranchName(id));
  }
  for (const auto & branch : phantom.Tree.GetBranches())
  {
    EXPECT_EQ(names.count(phantom.BranchName(branch.Id)), 1u) << phantom.BranchName(branch.Id) << " never read";
  }
}

/** \a branch drawn as a tube of its radii into a label map on \a grid's geometry (1 = vessel). */
vr::test::LabelMap::Pointer
MaskOfBranch(const vr::VolumeImageType * grid, const itk::CenterlineBranch & branch)
{
  auto mask = vr::test::MakeLabelMap(
    grid->GetLargestPossibleRegion().GetSize(), grid->GetSpacing(), grid->GetOrigin(), grid->GetDirection());
  itk::CenterlineTree one;
  one.AddBranch(branch);
  vr::test::DrawTubes(mask, one);
  return mask;
}

TEST(BranchNameReadout, EveryFixedPixelOfTheRunoffPhantomNamesItsVesselOnTheRightSide)
{
  const auto window = MakeWindowOnSmallPhantom(30.0);
  ASSERT_TRUE(window->GetCPRView()->GetResult()) << window->GetLastError().toStdString();
  const itk::CTAPhantom phantom = itk::MakeCTAPhantom(itk::CTAPhantomKind::Runoff, 3.0);
  const std::set<int>   named = ExpectEveryFixedPixelNamesItsVessel(*window, phantom);
  // Every vessel of the tree is seen and named at 30 degrees, both legs.
  ExpectEveryVesselRead(phantom, named);
}

TEST(BranchNameReadout, EveryFixedPixelOfTheThoracicPhantomNamesItsArteryOnTheRightSide)
{
  const auto window = MakeWindowOnSmallPhantom(0.0);
  ASSERT_TRUE(window->GetCPRView()->GetResult()) << window->GetLastError().toStdString();
  const auto runoff = window->GetController()->GetInputs();
  window->GetController()->LoadInputs([] { return MakePhantomInputs("thorax", 1.5); }, QStringLiteral("thorax"));
  ASSERT_TRUE(WaitUntil([&] { return window->GetController()->GetInputs() != runoff; }, 300.0));
  ASSERT_TRUE(WaitUntilSettled(*window, 300.0));
  const itk::CTAPhantom phantom = itk::MakeCTAPhantom(itk::CTAPhantomKind::Thorax, 1.5);
  const std::set<int>   named = ExpectEveryFixedPixelNamesItsVessel(*window, phantom);
  ExpectEveryVesselRead(phantom, named);
}
/** The thoracic phantom's volume and its exact tree written to files, the tree as \a centerlineFile. */
std::string
WriteThoraxVolume(const vr::test::ScopedTemporaryFolder & folder, const itk::CTAPhantom & phantom)
{
  const std::string volume = folder.File("thorax.nrrd");
  vr::WriteVolume(phantom.Source->GetOutput(), volume);
  return volume;
}

TEST(BranchNameReadout, CurveNamesOfAMarkupsFileAppearInTheReadout)
{
  // The thoracic tree as 3D Slicer curves, each named after its artery (the markups writer writes branch names).
  vr::test::ScopedTemporaryFolder folder;
  const itk::CTAPhantom           phantom = itk::MakeCTAPhantom(itk::CTAPhantomKind::Thorax, 1.5);
  phantom.Source->Update();
  const std::string volume = WriteThoraxVolume(folder, phantom);
  const std::string curves = folder.File("arteries.mrk.json");
  vr::WriteCenterlines(phantom.Tree, curves);
  ASSERT_NE(vr::test::ReadTextFile(curves).find("\"left subclavian artery\""), std::string::npos);

  const auto window = MakeWindowOnSmallPhantom(0.0);
  const auto before = window->GetController()->GetInputs();
  window->OpenFiles(QString::fromStdString(volume), QString::fromStdString(curves));
  ASSERT_TRUE(WaitUntil([&] { return window->GetController()->GetInputs() != before; }, 120.0));
  ASSERT_TRUE(WaitUntilSettled(*window, 300.0));
  const std::set<int> named = ExpectEveryFixedPixelNamesItsVessel(*window, phantom);
  EXPECT_EQ(named.size(), phantom.Tree.GetNumberOfBranches());
}

TEST(BranchNameReadout, MaskFileNamesOfATotalSegmentatorFolderAppearInTheReadout)
{
  // One mask per artery, named as TotalSegmentator names its files ("left_subclavian_artery.nii.gz"), drawn from the
  // phantom's exact tubes; the viewer extracts the centerlines and names each branch after the file it runs in.
  vr::test::ScopedTemporaryFolder folder;
  const itk::CTAPhantom           phantom = itk::MakeCTAPhantom(itk::CTAPhantomKind::Thorax, 1.5);
  phantom.Source->Update();
  const std::string volume = WriteThoraxVolume(folder, phantom);
  const auto *      grid = phantom.Source->GetOutput();
  QStringList       masks;
  for (const auto & branch : phantom.Tree.GetBranches())
  {
    const auto  mask = MaskOfBranch(grid, branch);
    std::string file = phantom.BranchName(branch.Id);
    std::replace(file.begin(), file.end(), ' ', '_');
    const std::string path = folder.File(file + ".nii.gz");
    // As float voxels 0 and 1: a label map to the reader, written by the project's own volume writer.
    auto values = vr::VolumeImageType::New();
    values->CopyInformation(mask);
    values->SetRegions(mask->GetLargestPossibleRegion());
    values->Allocate();
    std::copy(mask->GetBufferPointer(),
              mask->GetBufferPointer() + mask->GetLargestPossibleRegion().GetNumberOfPixels(),
              values->GetBufferPointer());
    vr::WriteVolume(values, path);
    masks << QString::fromStdString(path);
  }
  const auto window = MakeWindowOnSmallPhantom(0.0);
  const auto before = window->GetController()->GetInputs();
  window->OpenFilesWithSegmentation(QString::fromStdString(volume), masks);
  ASSERT_TRUE(WaitUntil([&] { return window->GetController()->GetInputs() != before; }, 120.0));
  ASSERT_TRUE(WaitUntilSettled(*window, 300.0));
  ASSERT_TRUE(WaitUntil(
    [&]
    {
      return window->GetCPRView()->GetResult() &&
             window->GetCPRView()->GetResult()->Inputs->Tree.GetNumberOfBranches() > 0;
    },
    120.0));
  // Extracted branches end where the extraction splits them, near but not at the files' borders: most pixels away
  // from the junctions must read their file's vessel.
  const std::set<int> named = ExpectEveryFixedPixelNamesItsVessel(*window, phantom, 0.9);
  EXPECT_GE(named.size(), phantom.Tree.GetNumberOfBranches() - 1);
}
TEST(BranchNameReadout, SegmentNamesOfASlicerSegNrrdAppearInTheReadout)
{
  // The thoracic arteries as one label map, label k for the k-th artery, named in the header as 3D Slicer's
  // .seg.nrrd names its segments (SegmentN_Name, SegmentN_LabelValue, SegmentN_Layer).
  vr::test::ScopedTemporaryFolder folder;
  const itk::CTAPhantom           phantom = itk::MakeCTAPhantom(itk::CTAPhantomKind::Thorax, 1.5);
  phantom.Source->Update();
  const std::string volume = WriteThoraxVolume(folder, phantom);
  const auto *      grid = phantom.Source->GetOutput();
  auto              labels = vr::VolumeImageType::New();
  labels->CopyInformation(grid);
  labels->SetRegions(grid->GetLargestPossibleRegion());
  labels->Allocate(true);
  int segment = 0;
  for (const auto & branch : phantom.Tree.GetBranches())
  {
    const auto  mask = MaskOfBranch(grid, branch);
    const float label = static_cast<float>(segment + 1);
    for (std::size_t v = 0; v < mask->GetLargestPossibleRegion().GetNumberOfPixels(); ++v)
    {
      if (mask->GetBufferPointer()[v] != 0 && labels->GetBufferPointer()[v] == 0.0f)
      {
        labels->GetBufferPointer()[v] = label;
      }
    }
    const std::string prefix = "Segment" + std::to_string(segment) + "_";
    itk::EncapsulateMetaData<std::string>(
      labels->GetMetaDataDictionary(), prefix + "Name", phantom.BranchName(branch.Id));
    itk::EncapsulateMetaData<std::string>(
      labels->GetMetaDataDictionary(), prefix + "LabelValue", std::to_string(segment + 1));
    itk::EncapsulateMetaData<std::string>(labels->GetMetaDataDictionary(), prefix + "Layer", "0");
    ++segment;
  }
  const std::string path = folder.File("arteries.seg.nrrd");
  vr::WriteVolume(labels, path);
  ASSERT_NE(vr::test::ReadTextFile(path).find("Segment5_Name:="), std::string::npos) << "the names are in the header";

  const auto window = MakeWindowOnSmallPhantom(0.0);
  const auto before = window->GetController()->GetInputs();
  window->OpenFilesWithSegmentation(QString::fromStdString(volume), { QString::fromStdString(path) });
  ASSERT_TRUE(WaitUntil([&] { return window->GetController()->GetInputs() != before; }, 120.0));
  ASSERT_TRUE(WaitUntilSettled(*window, 300.0));
  const std::set<int> named = ExpectEveryFixedPixelNamesItsVessel(*window, phantom, 0.9);
  EXPECT_GE(named.size(), phantom.Tree.GetNumberOfBranches() - 1);
}
} // namespace
