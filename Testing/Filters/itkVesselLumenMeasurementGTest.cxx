// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The lumen along a path (docs/lumen-measurement.md) on tubes of known cross-section in a rotated, anisotropic mask
// (0.6 x 0.8 x 1.1 mm voxels, direction rotated 30 degrees, the tube oblique to every axis): areas and diameters
// against the analytic ones; sections outside the segmentation and clipped regions. Their grading is the one-vessel
// logic's (Testing/Logic/VesselStenosisGTest.cxx).
#include "vrTestLumenTubes.h"

#include "itkVesselLumenMeasurement.h"

#include "gtest/gtest.h"

#include <cmath>
#include <iostream>

namespace
{
using vr::test::LumenTube;
using vr::test::MakeLumenTube;
using vr::test::StenosisRadius;

/** Half the diagonal of a 0.6 x 0.8 x 1.1 mm voxel: how far the staircase of a binary mask moves a caliper. */
const double HalfVoxelDiagonal = 0.5 * std::sqrt(0.6 * 0.6 + 0.8 * 0.8 + 1.1 * 1.1);

const vr::test::LumenTubeScene &
StenosisScene()
{
  static const vr::test::LumenTubeScene scene = []
  {
    LumenTube tube;
    tube.Radius = StenosisRadius;
    return MakeLumenTube(tube);
  }();
  return scene;
}

TEST(VesselLumenMeasurement, StenosisDiameterWithinAQuarterMillimetreOfTheTruth)
{
  const auto & scene = StenosisScene();
  ASSERT_EQ(scene.Sections.size(), 401u);
  const itk::VesselLumenProfile profile = itk::MeasureVesselLumen(scene.Mask, scene.Sections);
  EXPECT_EQ(profile.Source, itk::VesselLumenSource::Segmentation);
  EXPECT_EQ(profile.SectionsOutsideSegmentation, 0u);
  EXPECT_EQ(profile.ClippedSections, 0u);
  EXPECT_DOUBLE_EQ(profile.SamplingStep, 0.15); // a quarter of 0.6 mm
  ASSERT_EQ(profile.Sections.size(), scene.Sections.size());
  double largestError = 0.0;
  for (std::size_t k = 0; k < profile.Sections.size(); ++k)
  {
    const auto & section = profile.Sections[k];
    EXPECT_EQ(section.ArcLength, scene.Sections[k].ArcLength);
    EXPECT_TRUE(section.CenterInSegmentation);
    const double truth = 2.0 * StenosisRadius(section.ArcLength);
    EXPECT_NEAR(section.EquivalentDiameter, truth, 0.25) << "at " << section.ArcLength << " mm";
    EXPECT_NEAR(section.Area, M_PI * truth * truth / 4.0, M_PI * truth * 0.25 / 2.0 + 1e-9);
    EXPECT_EQ(section.Diameter, section.EquivalentDiameter);
    EXPECT_DOUBLE_EQ(section.InscribedDiameter, truth);
    // A circle: both caliper diameters are its diameter, up to the mask's staircase: half a voxel's diagonal.
    EXPECT_NEAR(section.MinimumDiameter, truth, HalfVoxelDiagonal);
    EXPECT_NEAR(section.MaximumDiameter, truth, HalfVoxelDiagonal);
    EXPECT_LE(section.MinimumDiameter, section.MaximumDiameter);
    largestError = std::max(largestError, std::abs(section.EquivalentDiameter - truth));
  }
  std::cout << "largest error of the equivalent diameter: " << largestError << " mm" << std::endl;
}

TEST(VesselLumenMeasurement, EllipseCalipersAreItsAxes)
{
  LumenTube tube;
  tube.Radius = [](double) { return 3.0; };
  tube.LateralScale = 5.0 / 3.0; // semi-axes 5 and 3 mm
  tube.PathLength = 30.0;
  tube.SectionStep = 0.5;
  const auto scene = MakeLumenTube(tube);
  const auto profile = itk::MeasureVesselLumen(scene.Mask, scene.Sections);
  double     sumMinimum = 0.0;
  double     sumMaximum = 0.0;
  for (const auto & section : profile.Sections)
  {
    EXPECT_NEAR(section.EquivalentDiameter, 2.0 * std::sqrt(15.0), 0.25);
    EXPECT_NEAR(section.MinimumDiameter, 6.0, HalfVoxelDiagonal);
    EXPECT_NEAR(section.MaximumDiameter, 10.0, HalfVoxelDiagonal);
    sumMinimum += section.MinimumDiameter;
    sumMaximum += section.MaximumDiameter;
  }
  const double sections = static_cast<double>(profile.Sections.size());
  std::cout << "ellipse 10 x 6 mm: mean calipers " << sumMaximum / sections << " x " << sumMinimum / sections << " mm"
            << std::endl;
  // On average over the staircase's phases the calipers are the axes within the equivalent diameter's tolerance
  // (the convex hull bridges the staircase's notches, so they read a little wide).
  EXPECT_NEAR(sumMinimum / sections, 6.0, 0.25);
  EXPECT_NEAR(sumMaximum / sections, 10.0, 0.25);
}

TEST(VesselLumenMeasurement, InPlaneRotationChangesNoArea)
{
  const auto &               scene = StenosisScene();
  itk::VesselPathSectionList turned;
  for (std::size_t k = 0; k < scene.Sections.size(); k += 20)
  {
    auto         section = scene.Sections[k];
    const double angle = 0.3 * static_cast<double>(k);
    const auto   lateral = section.Lateral * std::cos(angle) + section.Up * std::sin(angle);
    section.Up = itk::CrossProduct(section.Tangent, lateral);
    section.Lateral = lateral;
    turned.push_back(section);
  }
  for (const auto & section : turned)
  {
    const auto measured = itk::MeasureVesselLumenSection(scene.Mask, section);
    EXPECT_NEAR(measured.EquivalentDiameter, 2.0 * StenosisRadius(section.ArcLength), 0.25);
  }
}

TEST(VesselLumenMeasurement, SectionsOutsideTheSegmentationAreCountedNotMeasured)
{
  auto sections = StenosisScene().Sections;
  // Half the path moved 20 mm sideways, out of the tube.
  for (std::size_t k = 0; k < sections.size() / 2; ++k)
  {
    sections[k].Center = sections[k].Center + sections[k].Lateral * 20.0;
  }
  const auto profile = itk::MeasureVesselLumen(StenosisScene().Mask, sections);
  EXPECT_EQ(profile.SectionsOutsideSegmentation, sections.size() / 2);
  for (std::size_t k = 0; k < sections.size(); ++k)
  {
    EXPECT_EQ(profile.Sections[k].CenterInSegmentation, k >= sections.size() / 2);
    EXPECT_EQ(profile.Sections[k].IsMeasured(), k >= sections.size() / 2);
  }
  // Far outside the mask's grid: background, nothing measured, no crash.
  for (auto & section : sections)
  {
    section.Center[0] += 1e6;
  }
  EXPECT_EQ(itk::MeasureVesselLumen(StenosisScene().Mask, sections).SectionsOutsideSegmentation, sections.size());
}

TEST(VesselLumenMeasurement, RegionWiderThanTheSquareIsClipped)
{
  itk::VesselLumenMeasurementOptions options;
  options.MaximumHalfWidth = 3.0; // the healthy tube's radius is 4 mm
  const auto profile = itk::MeasureVesselLumen(StenosisScene().Mask, StenosisScene().Sections, options);
  for (const auto & section : profile.Sections)
  {
    // The narrowest part fits, the healthy tube reaches the edge (between the two, the staircase decides).
    const double radius = StenosisRadius(section.ArcLength);
    if (radius < 2.5 || radius > 3.5)
    {
      EXPECT_EQ(section.RegionClipped, radius > 3.5) << section.ArcLength;
    }
  }
  EXPECT_GT(profile.ClippedSections, 300u);
}

TEST(VesselLumenMeasurement, BadOptionsAndSectionsThrow)
{
  const auto &                       scene = StenosisScene();
  itk::VesselLumenMeasurementOptions options;
  options.SamplingStep = -1.0;
  EXPECT_THROW(itk::MeasureVesselLumen(scene.Mask, scene.Sections, options), itk::ExceptionObject);
  options.SamplingStep = std::nan("");
  EXPECT_THROW(itk::MeasureVesselLumen(scene.Mask, scene.Sections, options), itk::ExceptionObject);
  options = {};
  options.MaximumHalfWidth = 0.0;
  EXPECT_THROW(itk::MeasureVesselLumen(scene.Mask, scene.Sections, options), itk::ExceptionObject);
  options = {};
  options.SamplingStep = 1e-4; // 30 mm at 0.1 um: far too many samples
  EXPECT_THROW(itk::MeasureVesselLumen(scene.Mask, scene.Sections, options), itk::ExceptionObject);
  EXPECT_THROW(itk::MeasureVesselLumen(nullptr, scene.Sections), itk::ExceptionObject);
  auto sections = scene.Sections;
  sections[7].Center[1] = std::nan("");
  EXPECT_THROW(itk::MeasureVesselLumen(scene.Mask, sections), itk::ExceptionObject);
}
} // namespace
