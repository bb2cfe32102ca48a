// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// CenterlineExtractionFilter on real and phantom data (issue 15, items 2 and 3): VMTK's aorta level set against
// VMTK's own centerlines, and the run-off phantom's arteries against the phantom's exact tree. Each writes a picture
// (the segmentation's projection with the centerlines over it) into the build tree for a person to look at.

#include "itkCenterlineExtractionFilter.h"
#include "itkRunoffPhantomImageSource.h"

#include "vrCenterlineIO.h"
#include "vrCenterlinePicture.h"
#include "vrTestFiles.h"
#include "vrTestSegmentations.h"
#include "vrVolumeIO.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>

namespace
{
using vr::test::LabelMap;
using vr::test::PointType;
using FilterType = itk::CenterlineExtractionFilter<LabelMap>;

std::string
PictureFolder()
{
  const std::filesystem::path folder = std::filesystem::path(VR_TEST_OUTPUT_DIR) / "centerline-pictures";
  std::filesystem::create_directories(folder);
  return folder.string();
}

/** Distances (mm) from every point of \a from to the polylines of \a to, and the radius differences there. */
struct PointToTree
{
  std::vector<double> Distances;
  std::vector<double> RadiusDifferences;
};
PointToTree
Measure(const itk::CenterlineTree & from, const itk::CenterlineTree & to)
{
  PointToTree measured;
  for (const auto & branch : from.GetBranches())
  {
    for (std::size_t k = 0; k < branch.Points.size(); ++k)
    {
      const auto nearest = vr::test::NearestPointOnTree(branch.Points[k], to);
      measured.Distances.push_back(nearest.Nearest.Distance);
      measured.RadiusDifferences.push_back(std::abs(branch.Radii[k] - nearest.Nearest.Radius));
    }
  }
  return measured;
}

/** The fraction of a branch's points within \a distance mm of \a tree, leaving out 1.5 radii at each end (where a
 * skeleton stops short of a vessel's cap) and the points within 1.5 radii of another branch of \a branches (where
 * vessels overlap at a bifurcation, their union has no single axis). \a considered receives the number of points
 * that count. */
double
CoveredFraction(const itk::CenterlineBranch & branch,
                const itk::CenterlineTree &   tree,
                double                        distance,
                const itk::CenterlineTree &   branches,
                std::size_t &                 considered)
{
  const double length = vr::test::PolylineLength(branch.Points);
  double       arc = 0.0;
  std::size_t  covered = 0;
  considered = 0;
  for (std::size_t k = 0; k < branch.Points.size(); ++k)
  {
    arc += k == 0 ? 0.0 : branch.Points[k - 1].EuclideanDistanceTo(branch.Points[k]);
    if (arc < 1.5 * branch.Radii.front() || arc > length - 1.5 * branch.Radii.back())
    {
      continue;
    }
    const bool nearAnother =
      std::any_of(branches.GetBranches().begin(),
                  branches.GetBranches().end(),
                  [&](const itk::CenterlineBranch & other)
                  {
                    if (other.Id == branch.Id)
                    {
                      return false;
                    }
                    const auto nearest = vr::test::NearestPointOnPolyline(branch.Points[k], other.Points, other.Radii);
                    return nearest.Distance <= 1.5 * nearest.Radius;
                  });
    if (nearAnother)
    {
      continue;
    }
    ++considered;
    covered += vr::test::NearestPointOnTree(branch.Points[k], tree).Nearest.Distance <= distance ? 1 : 0;
  }
  return considered ? static_cast<double>(covered) / static_cast<double>(considered) : 0.0;
}

TEST(CenterlineExtractionFilterData, AortaLevelSetGivesVMTKsCenterlines)
{
  const std::string folder = vr::test::AortaDataFolder();
  ASSERT_FALSE(folder.empty())
    << "VMTK's aorta (vmtk-aorta-mra) is missing from VR_SHARED_DATA_DIR (Testing/Data by default)";
  // VMTK's level set: inside where < 0.
  const auto levelSet = vr::ReadVolume(folder + "/aorta-final-levelset.mha");
  auto       mask = LabelMap::New();
  mask->CopyInformation(levelSet);
  mask->SetRegions(levelSet->GetLargestPossibleRegion());
  mask->Allocate();
  for (std::size_t k = 0; k < levelSet->GetLargestPossibleRegion().GetNumberOfPixels(); ++k)
  {
    mask->GetBufferPointer()[k] = levelSet->GetBufferPointer()[k] < 0.0f ? 1 : 0;
  }
  // VMTK's centerlines, its two overlapping paths merged into trunk and iliacs.
  const itk::CenterlineTree vmtk = vr::ReadCenterlines(folder + "/aorta-centerline.vtp");
  ASSERT_EQ(vmtk.GetNumberOfBranches(), 3u);

  auto filter = FilterType::New();
  filter->SetInput(mask);
  filter->Update();
  const itk::CenterlineTree & tree = filter->GetCenterlineTree();
  vr::test::WriteCenterlinePicture(mask, tree, PictureFolder() + "/aorta-centerlines.png", &vmtk);

  const PointToTree ours = Measure(tree, vmtk);
  const double      medianDistance = vr::test::Quantile(ours.Distances, 0.5);
  const double      medianRadius = vr::test::Quantile(ours.RadiusDifferences, 0.5);
  std::cout << "aorta: " << tree.GetNumberOfBranches() << " branches, " << tree.GetNumberOfPoints()
            << " points; distance to VMTK's centerlines median " << medianDistance << " mm, 95 % "
            << vr::test::Quantile(ours.Distances, 0.95) << " mm, max " << vr::test::Quantile(ours.Distances, 1.0)
            << " mm; radius difference median " << medianRadius << " mm, 95 % "
            << vr::test::Quantile(ours.RadiusDifferences, 0.95) << " mm" << std::endl;
  for (const auto & branch : tree.GetBranches())
  {
    std::cout << "  branch " << branch.Id << ": " << branch.Points.size() << " points, "
              << vr::test::PolylineLength(branch.Points) << " mm, from " << branch.Points.front() << " to "
              << branch.Points.back() << std::endl;
  }
  EXPECT_LT(medianDistance, 1.5);
  EXPECT_LT(medianRadius, 1.0);
  // The trunk and both iliacs: each of VMTK's three branches is followed by ours within 3 mm (away from its ends,
  // where VMTK runs to the open boundary and a skeleton stops about a radius short, and from the bifurcation).
  for (const auto & branch : vmtk.GetBranches())
  {
    std::size_t  considered = 0;
    const double covered = CoveredFraction(branch, tree, 3.0, vmtk, considered);
    std::cout << "  VMTK branch " << branch.Id << " (" << vr::test::PolylineLength(branch.Points)
              << " mm): " << 100.0 * covered << " % of " << considered << " points within 3 mm of ours" << std::endl;
    EXPECT_GT(considered, 10u);
    EXPECT_GT(covered, 0.95) << "VMTK branch " << branch.Id;
  }
  EXPECT_EQ(tree.GetNumberOfBranches(), 3u);
  // Rooted at the aorta (the widest end).
  const auto & root = tree.GetBranches().front();
  EXPECT_GT(root.Radii.front(), 5.0);
}
} // namespace

namespace
{
/** Sections of a tree split at its junctions: a branch that starts inside another (not at its end) splits it. */
std::size_t
SectionCount(const itk::CenterlineTree & tree)
{
  std::size_t sections = tree.GetNumberOfBranches();
  for (const auto & branch : tree.GetBranches())
  {
    for (const auto & other : tree.GetBranches())
    {
      if (&other == &branch)
      {
        continue;
      }
      const auto & start = branch.Points.front();
      const bool   atEnd =
        start.EuclideanDistanceTo(other.Points.back()) < 1e-6 || start.EuclideanDistanceTo(other.Points.front()) < 1e-6;
      const bool onOther = vr::test::NearestPointOnPolyline(start, other.Points, other.Radii).Distance < 1e-6;
      sections += onOther && !atEnd ? 1 : 0;
    }
  }
  return sections;
}

TEST(CenterlineExtractionFilterData, RunoffPhantomArteriesGiveBackThePhantomsTree)
{
  // The phantom's arteries as it draws them (capsules between its centerline points, radius varying along each),
  // on a 1 mm grid over their bounding box.
  auto                      phantom = itk::RunoffPhantomImageSource::New();
  const itk::CenterlineTree truth = phantom->GetCenterlineTree();
  PointType                 low;
  PointType                 high;
  truth.GetBounds(low, high);
  itk::Size<3> size;
  PointType    origin;
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    origin[axis] = low[axis] - 15.0;
    size[axis] = static_cast<itk::SizeValueType>(high[axis] - low[axis] + 30.0);
  }
  itk::Vector<double, 3> spacing;
  spacing.Fill(1.0);
  itk::Matrix<double, 3, 3> identity;
  identity.SetIdentity();
  auto mask = vr::test::MakeLabelMap(size, spacing, origin, identity);
  vr::test::DrawTubes(mask, truth);

  auto filter = FilterType::New();
  filter->SetInput(mask);
  filter->Update();
  const itk::CenterlineTree & tree = filter->GetCenterlineTree();
  vr::test::WriteCenterlinePicture(mask, tree, PictureFolder() + "/runoff-phantom-centerlines.png", &truth);

  const PointToTree ours = Measure(tree, truth);
  const double      within = static_cast<double>(std::count_if(
                          ours.Distances.begin(), ours.Distances.end(), [](double d) { return d <= 1.0; })) /
                        static_cast<double>(ours.Distances.size());
  const std::size_t sections = SectionCount(truth);
  std::cout << "run-off phantom (" << size << " voxels of 1 mm): " << tree.GetNumberOfBranches()
            << " branches (the phantom's " << truth.GetNumberOfBranches() << " vessels make " << sections
            << " sections); " << 100.0 * within << " % of " << ours.Distances.size()
            << " points within 1 mm of the phantom's tree; distance median " << vr::test::Quantile(ours.Distances, 0.5)
            << " mm, 95 % " << vr::test::Quantile(ours.Distances, 0.95) << " mm, max "
            << vr::test::Quantile(ours.Distances, 1.0) << " mm; radius difference median "
            << vr::test::Quantile(ours.RadiusDifferences, 0.5) << " mm" << std::endl;
  EXPECT_EQ(tree.GetNumberOfBranches(), sections);
  EXPECT_GE(within, 0.95);
  // Every vessel of the phantom is found (away from its ends and from where it overlaps its parent).
  for (const auto & branch : truth.GetBranches())
  {
    std::size_t  considered = 0;
    const double covered = CoveredFraction(branch, tree, 1.0, truth, considered);
    EXPECT_GT(considered, 10u) << itk::RunoffPhantomImageSource::GetBranchName(branch.Id);
    EXPECT_GT(covered, 0.95) << itk::RunoffPhantomImageSource::GetBranchName(branch.Id);
  }
  // Rooted at the top of the aorta.
  EXPECT_GT(tree.GetBranches().front().Points.front()[2], -20.0);
}
} // namespace
