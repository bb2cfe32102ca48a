// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The lumen measurement as the logic runs it (docs/lumen-measurement.md): the source it says it used, the errors
// that name what is wrong (a segmentation that misses the path, reference points outside it, no radius and no
// segmentation), and VMTK's aorta with its level set against VMTK's own inscribed-sphere radii.
#include "vrLumenMeasurement.h"
#include "vrTestFiles.h"
#include "vrTestLumenTubes.h"

#include "vrCenterlineIO.h"
#include "vrInputError.h"
#include "vrParameterName.h"
#include "vrSegmentationIO.h"

#include "gtest/gtest.h"

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

namespace
{
const vr::test::LumenTubeScene &
StenosisScene()
{
  static const vr::test::LumenTubeScene scene = []
  {
    vr::test::LumenTube tube;
    tube.Radius = vr::test::StenosisRadius;
    return vr::test::MakeLumenTube(tube);
  }();
  return scene;
}

TEST(LumenMeasurement, SaysWhichSourceItUsed)
{
  const auto & scene = StenosisScene();
  const auto   fromMask = vr::MeasureLumen(scene.Sections, scene.Mask, "segmentation tube.nrrd", {});
  EXPECT_EQ(fromMask.Profile.Source, itk::VesselLumenSource::Segmentation);
  EXPECT_EQ(fromMask.Summary.Source, itk::VesselLumenSource::Segmentation);
  EXPECT_NEAR(fromMask.Summary.DiameterStenosisPercent, 50.0, 3.0);
  const auto fromRadii = vr::MeasureLumen(scene.Sections, nullptr, "", {});
  EXPECT_EQ(fromRadii.Profile.Source, itk::VesselLumenSource::CenterlineRadius);
  EXPECT_NEAR(fromRadii.Summary.DiameterStenosisPercent, 50.0, 1e-7);
  EXPECT_STREQ(itk::ToString(fromRadii.Profile.Source), "centerline radius");
}

TEST(LumenMeasurement, SummaryAsReturnedValues)
{
  // The radius source on the analytic tube: MLD 4 mm at 40 mm, reference 8 mm, area 4 pi against 16 pi.
  const auto measured = vr::MeasureLumen(StenosisScene().Sections, nullptr, "", {});
  const auto values = vr::LumenSummaryValues(measured);
  const auto value = [&](const std::string & name)
  {
    for (const auto & entry : values)
    {
      if (entry.first == name)
      {
        return entry.second;
      }
    }
    ADD_FAILURE() << "no " << name;
    return std::string();
  };
  ASSERT_EQ(values.size(), 24u);
  EXPECT_EQ(values.front().first, "pathLength");
  EXPECT_EQ(value("pathLength"), "80");
  EXPECT_EQ(value("lumenSource"), "centerline radius");
  EXPECT_EQ(value("referenceMethod"), "interpolated");
  // The first and last candidate: the tube's 4 mm radius is the margin at both ends (sections every 0.2 mm, the
  // 21 of [0, 4] mm and the 21 of [76, 80] mm excluded).
  EXPECT_EQ(value("referencePoints"), "4.2,75.8");
  EXPECT_EQ(value("excludedSections"), "42");
  EXPECT_EQ(value("referenceScope"), "each segment");
  EXPECT_EQ(value("minimalLumenDiameter"), "4");
  EXPECT_EQ(value("minimalLumenDiameterArcLength"), "40");
  EXPECT_EQ(value("referenceDiameter"), "8");
  EXPECT_EQ(value("diameterStenosis"), "50");
  EXPECT_EQ(value("areaStenosis"), "75");
  // An unnamed 8 mm tube is a peripheral artery: its category, no CAD-RADS class.
  EXPECT_EQ(value("cadRads"), "");
  EXPECT_EQ(value("gradingScale"), "peripheral");
  EXPECT_EQ(value("grade"), "50–99 % (peripheral)");
  EXPECT_EQ(value("gradedSegment"), "1: 0.0–80.0 mm");
  EXPECT_EQ(value("notGradedBecause"), "");
  EXPECT_EQ(value("maximumDiameter"), ""); // no aorta
  EXPECT_EQ(value("sectionsOutsideSegmentation"), "0");
  EXPECT_NE(value("segments").find("segment 1 (0.0–80.0 mm), scale peripheral (unnamed, median diameter 8.0 mm"),
            std::string::npos)
    << value("segments");
  // As a coronary artery (the user's choice): CAD-RADS 3.
  vr::LumenMeasurementParameters coronary;
  coronary.Scale = vr::StenosisScale::CADRADS;
  for (const auto & [name, text] :
       vr::LumenSummaryValues(vr::MeasureLumen(StenosisScene().Sections, nullptr, "", coronary)))
  {
    if (name == "cadRads" || name == "grade")
    {
      EXPECT_EQ(text, name == "cadRads" ? "3" : "CAD-RADS 3 (50–69 %)");
    }
  }
  // The MLD's centre in RAS: the section at 40 mm, x and y negated.
  const auto &       center = StenosisScene().Sections[200].Center;
  std::ostringstream expected;
  expected.precision(10);
  expected << -center[0] << ',' << -center[1] << ',' << center[2];
  EXPECT_EQ(value("minimalLumenDiameterPoint"), expected.str());
}

TEST(LumenMeasurement, SegmentationThatMissesThePathIsNamed)
{
  auto sections = StenosisScene().Sections;
  for (auto & section : sections)
  {
    section.Center = section.Center + section.Lateral * 25.0;
  }
  const std::string message = vr::test::InputErrorOf(
    [&] { vr::MeasureLumen(sections, StenosisScene().Mask, "segmentation other-vessel.nii.gz", {}); });
  EXPECT_TRUE(vr::test::Contains(message, "segmentation other-vessel.nii.gz")) << message;
  EXPECT_TRUE(vr::test::Contains(message, "401 sections")) << message;
  // Part of the path outside is no error: counted.
  auto partly = StenosisScene().Sections;
  partly[3].Center = sections[3].Center;
  const auto measured = vr::MeasureLumen(partly, StenosisScene().Mask, "segmentation tube.nrrd", {});
  EXPECT_EQ(measured.Profile.SectionsOutsideSegmentation, 1u);
}

TEST(LumenMeasurement, ReferencePointsOutsideThePathAreNamed)
{
  vr::LumenMeasurementParameters parameters;
  parameters.ReferenceArcLengths = { 12.0, 95.5 };
  try
  {
    vr::MeasureLumen(StenosisScene().Sections, StenosisScene().Mask, "segmentation tube.nrrd", parameters);
    ADD_FAILURE() << "no error";
  }
  catch (const vr::InputError & error)
  {
    const std::string message = error.what();
    std::cout << message << std::endl;
    EXPECT_TRUE(vr::test::Contains(message, "reference point 95.5 mm lies outside the path (arc length 0 to 80 mm)"))
      << message;
    EXPECT_EQ(error.Parameter(), vr::ParameterName::ReferencePoints);
  }
  parameters.ReferenceArcLengths = { 12.0 };
  parameters.ReferenceMethod = vr::VesselReferenceMethod::RobustFit;
  EXPECT_TRUE(vr::test::Contains(
    vr::test::InputErrorOf([&] { vr::MeasureLumen(StenosisScene().Sections, nullptr, "", parameters); }),
    "two reference points"));
}

TEST(LumenMeasurement, NothingToMeasureFromIsAnError)
{
  auto sections = StenosisScene().Sections;
  for (auto & section : sections)
  {
    section.Radius = std::nan("");
  }
  EXPECT_TRUE(vr::test::Contains(vr::test::InputErrorOf([&] { vr::MeasureLumen(sections, nullptr, "", {}); }),
                                 "no segmentation was given and the centerlines carry no radius"));
  sections.resize(1);
  EXPECT_TRUE(vr::test::Contains(
    vr::test::InputErrorOf([&] { vr::MeasureLumen(sections, StenosisScene().Mask, "segmentation tube.nrrd", {}); }),
    "1 section(s)"));
  vr::LumenMeasurementParameters parameters;
  parameters.SamplingStep = -0.1;
  try
  {
    vr::MeasureLumen(StenosisScene().Sections, StenosisScene().Mask, "segmentation tube.nrrd", parameters);
    ADD_FAILURE() << "no error";
  }
  catch (const vr::InputError & error)
  {
    EXPECT_EQ(error.Parameter(), vr::ParameterName::LumenSampling);
  }
}

/** Sections at every point of \a branch: tangent by the difference of the neighbours two points away, any unit
 * vector perpendicular to it as Lateral (the area does not depend on the in-plane rotation). */
itk::VesselPathSectionList
BranchSections(const itk::CenterlineBranch & branch)
{
  itk::VesselPathSectionList sections;
  double                     arcLength = 0.0;
  const std::size_t          n = branch.Points.size();
  for (std::size_t k = 0; k < n; ++k)
  {
    if (k > 0)
    {
      arcLength += branch.Points[k].EuclideanDistanceTo(branch.Points[k - 1]);
    }
    const std::size_t      before = k >= 2 ? k - 2 : 0;
    const std::size_t      after = std::min(n - 1, k + 2);
    itk::Vector<double, 3> tangent = branch.Points[after] - branch.Points[before];
    tangent.Normalize();
    itk::Vector<double, 3> helper;
    helper.Fill(0.0);
    helper[std::abs(tangent[0]) < 0.6 ? 0 : 1] = 1.0;
    itk::Vector<double, 3> lateral = helper - tangent * (helper * tangent);
    lateral.Normalize();
    itk::VesselPathSection section;
    section.ArcLength = arcLength;
    section.Center = branch.Points[k];
    section.Tangent = tangent;
    section.Lateral = lateral;
    section.Up = itk::CrossProduct(tangent, lateral);
    section.Radius = branch.Radii[k];
    section.BranchId = branch.Id;
    sections.push_back(section);
  }
  return sections;
}

TEST(LumenMeasurement, AortaLevelSetAgainstVMTKsInscribedSpheres)
{
  const std::string folder = vr::test::AortaDataFolder();
  ASSERT_FALSE(folder.empty())
    << "VMTK's aorta (vmtk-aorta-mra) is missing from VR_SHARED_DATA_DIR (Testing/Data by default)";
  vr::SegmentationReadReport report;
  const auto                 mask = vr::ReadSegmentationMask(folder + "/aorta-final-levelset.mha", {}, &report);
  EXPECT_EQ(report.Kind, "level set (inside where < 0)");
  const itk::CenterlineTree tree = vr::ReadCenterlines(folder + "/aorta-centerline.vtp");
  ASSERT_TRUE(tree.HasRadii());
  const auto & spacing = mask->GetSpacing();
  // "One voxel": its smallest side, 0.88 mm, the stricter reading (the largest is 1.5 mm).
  const double voxel = std::min({ spacing[0], spacing[1], spacing[2] });

  std::vector<double> ratios;
  double              worstShortfall = -1e300;
  std::size_t         outside = 0;
  for (const auto & branch : tree.GetBranches())
  {
    const auto sections = BranchSections(branch);
    const auto measured = vr::MeasureLumen(sections, mask, "segmentation aorta-final-levelset.mha", {});
    outside += measured.Profile.SectionsOutsideSegmentation;
    std::vector<double> branchRatios;
    double              branchWorst = -1e300;
    for (const auto & section : measured.Profile.Sections)
    {
      if (!section.IsMeasured())
      {
        continue;
      }
      const double shortfall = section.InscribedDiameter - section.EquivalentDiameter;
      EXPECT_LE(shortfall, voxel) << "branch " << branch.Id << " at " << section.ArcLength << " mm: equivalent "
                                  << section.EquivalentDiameter << " mm, VMTK 2r " << section.InscribedDiameter;
      branchWorst = std::max(branchWorst, shortfall);
      branchRatios.push_back(section.EquivalentDiameter / section.InscribedDiameter);
    }
    worstShortfall = std::max(worstShortfall, branchWorst);
    ratios.insert(ratios.end(), branchRatios.begin(), branchRatios.end());
    std::sort(branchRatios.begin(), branchRatios.end());
    const auto & s = measured.Summary;
    std::cout << "branch " << branch.Id << ": " << sections.size() << " sections, " << s.PathLength
              << " mm; equivalent / 2r median " << branchRatios[branchRatios.size() / 2] << ", range "
              << branchRatios.front() << " to " << branchRatios.back() << "; largest 2r - equivalent " << branchWorst
              << " mm; MLD " << s.MinimalLumenDiameter << " mm at " << s.MinimalLumenDiameterArcLength << " mm, RVD "
              << s.ReferenceDiameter << " mm, DS " << s.DiameterStenosisPercent << " %, CAD-RADS " << s.CADRADS
              << "; outside " << measured.Profile.SectionsOutsideSegmentation << ", clipped "
              << measured.Profile.ClippedSections << std::endl;
  }
  std::sort(ratios.begin(), ratios.end());
  const double median = ratios[ratios.size() / 2];
  std::cout << "aorta: " << ratios.size() << " sections, median equivalent / 2r " << median
            << ", largest 2r - equivalent " << worstShortfall << " mm (one voxel: " << spacing[0] << " x " << spacing[1]
            << " x " << spacing[2] << " mm), sections outside " << outside << std::endl;
  EXPECT_GE(median, 1.0);
  EXPECT_LE(median, 1.3);
  EXPECT_EQ(outside, 0u);
}
} // namespace
