// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Reference diameter, MLD, MLA, % stenosis and the CAD-RADS class (docs/lumen-measurement.md) on profiles written by
// hand, against values worked out by hand; and on the lumen measured on a tube of known cross-section (the issue's
// 50 % concentric stenosis, from the mask and from the radii).
#include "vrTestLumenTubes.h"
#include "vrVesselStenosis.h"

#include "gtest/gtest.h"

#include <cmath>
#include <functional>
#include <iostream>

namespace
{
/** Sections every \a step mm from \a first to \a last with the diameters \a diameter(s) (NaN: not measured). */
itk::VesselLumenProfile
Profile(double first, double last, double step, const std::function<double(double)> & diameter)
{
  itk::VesselLumenProfile profile;
  profile.Source = itk::VesselLumenSource::CenterlineRadius;
  for (double s = first; s <= last + 1e-9; s += step)
  {
    itk::VesselLumenSection section;
    section.ArcLength = s;
    section.Center.Fill(s);
    section.Diameter = diameter(s);
    section.InscribedDiameter = section.Diameter;
    profile.Sections.push_back(section);
  }
  return profile;
}

/** A tapering vessel 6 + 0.02 s mm with a dip to 3.5 mm at s = 50 (one section). */
double
TaperWithDip(double s)
{
  return std::abs(s - 50.0) < 1e-9 ? 3.5 : 6.0 + 0.02 * s;
}

TEST(VesselStenosis, CADRADSClassesAtTheirBoundaries)
{
  EXPECT_EQ(vr::CADRADSClass(std::nan("")), -1);
  EXPECT_EQ(vr::CADRADSClass(-12.0), 0);
  EXPECT_EQ(vr::CADRADSClass(0.0), 0);
  EXPECT_EQ(vr::CADRADSClass(0.49), 0);
  EXPECT_EQ(vr::CADRADSClass(0.5), 1);
  EXPECT_EQ(vr::CADRADSClass(1.0), 1);
  EXPECT_EQ(vr::CADRADSClass(24.0), 1);
  EXPECT_EQ(vr::CADRADSClass(24.49), 1);
  EXPECT_EQ(vr::CADRADSClass(24.5), 2);
  EXPECT_EQ(vr::CADRADSClass(25.0), 2);
  EXPECT_EQ(vr::CADRADSClass(49.0), 2);
  EXPECT_EQ(vr::CADRADSClass(49.49), 2);
  EXPECT_EQ(vr::CADRADSClass(49.5), 3);
  EXPECT_EQ(vr::CADRADSClass(50.0), 3);
  EXPECT_EQ(vr::CADRADSClass(69.0), 3);
  EXPECT_EQ(vr::CADRADSClass(69.5), 4);
  EXPECT_EQ(vr::CADRADSClass(70.0), 4);
  EXPECT_EQ(vr::CADRADSClass(99.0), 4);
  EXPECT_EQ(vr::CADRADSClass(99.9), 4); // some lumen left: not an occlusion
  EXPECT_EQ(vr::CADRADSClass(100.0), 5);
}

TEST(VesselStenosis, InterpolatedReferenceAtTheDefaultPoints)
{
  auto       profile = Profile(0.0, 100.0, 1.0, TaperWithDip);
  const auto summary = vr::AnalyseVesselStenosis(profile);
  // Reference points at 5 and 95 mm: 6.1 and 7.9 mm; at 50 mm 6.1 + 45/90 * 1.8 = 7.0 mm.
  ASSERT_EQ(summary.ReferenceArcLengths.size(), 2u);
  EXPECT_DOUBLE_EQ(summary.ReferenceArcLengths[0], 5.0);
  EXPECT_DOUBLE_EQ(summary.ReferenceArcLengths[1], 95.0);
  EXPECT_NEAR(summary.ReferenceDiameter, 7.0, 1e-12);
  EXPECT_DOUBLE_EQ(summary.MinimalLumenDiameter, 3.5);
  EXPECT_DOUBLE_EQ(summary.MinimalLumenDiameterArcLength, 50.0);
  EXPECT_NEAR(summary.DiameterStenosisPercent, 50.0, 1e-10);
  // Areas from the diameters (radius source), their reference interpolated between the areas at 5 and 95 mm:
  // pi/4 (6.1^2 + (7.9^2 - 6.1^2) / 2) = pi/4 49.81 at 50 mm, so 1 - 3.5^2 / 49.81.
  EXPECT_NEAR(summary.ReferenceArea, M_PI / 4.0 * 49.81, 1e-10);
  EXPECT_NEAR(summary.AreaStenosisPercent, 100.0 * (1.0 - 12.25 / 49.81), 1e-10);
  EXPECT_EQ(summary.CADRADS, 3);
  EXPECT_DOUBLE_EQ(summary.PathLength, 100.0);
  EXPECT_EQ(summary.MeasuredSections, 101u);
  EXPECT_EQ(summary.MeasuredSectionsInSpan, 91u);
  // Constant beyond the reference points, linear between them.
  EXPECT_NEAR(profile.Sections[0].ReferenceDiameter, 6.1, 1e-12);
  EXPECT_NEAR(profile.Sections[2].ReferenceDiameter, 6.1, 1e-12);
  EXPECT_NEAR(profile.Sections[20].ReferenceDiameter, 6.1 + 15.0 / 90.0 * 1.8, 1e-12);
  EXPECT_NEAR(profile.Sections[100].ReferenceDiameter, 7.9, 1e-12);
}

TEST(VesselStenosis, InterpolatedReferenceAtGivenPointsBetweenSections)
{
  // Diameter s^2 / 100 at the sections: between sections the profile is linear, not the parabola.
  auto                      profile = Profile(10.0, 30.0, 1.0, [](double s) { return s * s / 100.0; });
  vr::VesselStenosisOptions options;
  options.ReferenceArcLengths = { 28.5, 12.5, 20.0 }; // any order
  const auto summary = vr::AnalyseVesselStenosis(profile, options);
  ASSERT_EQ(summary.ReferenceArcLengths, (std::vector<double>{ 12.5, 20.0, 28.5 }));
  // At 12.5 mm: (1.44 + 1.69) / 2 = 1.565; at 20 mm: 4.0; at 28.5 mm: (7.84 + 8.41) / 2 = 8.125.
  const auto at = [&](double s)
  {
    for (const auto & section : profile.Sections)
    {
      if (std::abs(section.ArcLength - s) < 1e-9)
      {
        return section.ReferenceDiameter;
      }
    }
    return std::nan("");
  };
  EXPECT_NEAR(at(10.0), 1.565, 1e-12);
  EXPECT_NEAR(at(16.0), 1.565 + (16.0 - 12.5) / 7.5 * (4.0 - 1.565), 1e-12);
  EXPECT_NEAR(at(20.0), 4.0, 1e-12);
  EXPECT_NEAR(at(25.0), 4.0 + 5.0 / 8.5 * (8.125 - 4.0), 1e-12);
  EXPECT_NEAR(at(30.0), 8.125, 1e-12);
  // MLD over the whole path: the section at 10 mm, 1 mm, its reference 1.565 mm (constant before 12.5 mm).
  EXPECT_DOUBLE_EQ(summary.MinimalLumenDiameterArcLength, 10.0);
  EXPECT_NEAR(summary.MinimalLumenDiameter, 1.0, 1e-12);
  EXPECT_NEAR(summary.ReferenceDiameter, 1.565, 1e-12);
  EXPECT_NEAR(summary.DiameterStenosisPercent, 100.0 * (1.0 - 1.0 / 1.565), 1e-10);
  // Areas (pi/4 d^2, the radius source) interpolated the same way: at 12.5 mm pi/4 (1.44^2 + 1.69^2) / 2.
  EXPECT_NEAR(summary.MinimalLumenArea, M_PI / 4.0, 1e-12);
  EXPECT_NEAR(summary.ReferenceArea, M_PI / 4.0 * (1.44 * 1.44 + 1.69 * 1.69) / 2.0, 1e-12);
  EXPECT_NEAR(summary.AreaStenosisPercent, 100.0 * (1.0 - 2.0 / (1.44 * 1.44 + 1.69 * 1.69)), 1e-10);
}

TEST(VesselStenosis, UnmeasuredSectionsAreSkippedByTheInterpolation)
{
  // Not measured at 4, 5 and 6 mm: the reference at 5 mm comes from 3 and 7 mm, (6.06 + 6.14) / 2 = 6.1.
  auto profile =
    Profile(0.0, 100.0, 1.0, [](double s) { return (s > 3.5 && s < 6.5) ? std::nan("") : TaperWithDip(s); });
  const auto summary = vr::AnalyseVesselStenosis(profile);
  EXPECT_NEAR(profile.Sections[0].ReferenceDiameter, 6.1, 1e-12);
  EXPECT_EQ(summary.MeasuredSections, 98u);
  EXPECT_NEAR(summary.DiameterStenosisPercent, 50.0, 1e-10);
}

TEST(VesselStenosis, RobustFitIgnoresTheDip)
{
  // A taper with a 20 mm long dip of depth 3 mm (20 % of the span) and a little alternating noise.
  auto                      profile = Profile(0.0,
                         100.0,
                         0.5,
                         [](double s)
                         {
                           const double noise = 0.05 * std::sin(7.0 * s);
                           return 6.0 + 0.02 * s + noise - ((s >= 40.0 && s <= 60.0) ? 3.0 : 0.0);
                         });
  vr::VesselStenosisOptions options;
  options.Method = vr::VesselReferenceMethod::RobustFit;
  const auto summary = vr::AnalyseVesselStenosis(profile, options);
  // The line is the taper: 6 + 0.02 s within the noise.
  for (const auto & section : profile.Sections)
  {
    EXPECT_NEAR(section.ReferenceDiameter, 6.0 + 0.02 * section.ArcLength, 0.03) << section.ArcLength;
  }
  EXPECT_NEAR(summary.ReferenceDiameter, 6.0 + 0.02 * summary.MinimalLumenDiameterArcLength, 0.03);
  // An ordinary least-squares line would be pulled down by 3 * 0.2 = 0.6 mm on average: the test can tell.
  EXPECT_GT(summary.MinimalLumenDiameterArcLength, 39.9);
  EXPECT_LT(summary.MinimalLumenDiameterArcLength, 60.1);
}

TEST(VesselStenosis, ReferencePointsOutsideThePathAreNamed)
{
  auto                      profile = Profile(0.0, 80.0, 1.0, TaperWithDip);
  vr::VesselStenosisOptions options;
  options.ReferenceArcLengths = { 10.0, 120.0, -3.5 };
  try
  {
    vr::AnalyseVesselStenosis(profile, options);
    ADD_FAILURE() << "no exception";
  }
  catch (const itk::ExceptionObject & exception)
  {
    const std::string message = exception.GetDescription();
    EXPECT_NE(message.find("120 mm"), std::string::npos) << message;
    EXPECT_NE(message.find("-3.5 mm"), std::string::npos) << message;
    EXPECT_EQ(message.find("10 mm"), std::string::npos) << message;
    EXPECT_NE(message.find("0 to 80 mm"), std::string::npos) << message;
  }
  options.ReferenceArcLengths = { std::nan("") };
  EXPECT_THROW(vr::AnalyseVesselStenosis(profile, options), itk::ExceptionObject);
  options.ReferenceArcLengths = { 30.0 };
  options.Method = vr::VesselReferenceMethod::RobustFit;
  EXPECT_THROW(vr::AnalyseVesselStenosis(profile, options), itk::ExceptionObject);
  // One point is enough for the interpolated method: a constant reference.
  options.Method = vr::VesselReferenceMethod::Interpolated;
  const auto summary = vr::AnalyseVesselStenosis(profile, options);
  EXPECT_NEAR(profile.Sections.back().ReferenceDiameter, 6.6, 1e-12);
  EXPECT_DOUBLE_EQ(summary.MinimalLumenDiameterArcLength, 50.0);
  EXPECT_NEAR(summary.DiameterStenosisPercent, 100.0 * (1.0 - 3.5 / 6.6), 1e-10);
}

TEST(VesselStenosis, TooShortOrUnmeasuredPathsThrow)
{
  auto one = Profile(0.0, 0.0, 1.0, TaperWithDip);
  EXPECT_THROW(vr::AnalyseVesselStenosis(one), itk::ExceptionObject);
  auto none = Profile(0.0, 50.0, 1.0, [](double) { return std::nan(""); });
  EXPECT_THROW(vr::AnalyseVesselStenosis(none), itk::ExceptionObject);
  auto backwards = Profile(0.0, 50.0, 1.0, TaperWithDip);
  std::swap(backwards.Sections[3].ArcLength, backwards.Sections[4].ArcLength);
  EXPECT_THROW(vr::AnalyseVesselStenosis(backwards), itk::ExceptionObject);
}

using vr::test::LumenTube;
using vr::test::MakeLumenTube;
using vr::test::StenosisRadius;

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

TEST(VesselLumenMeasurement, StenosisGradedFromTheMask)
{
  auto                      profile = itk::MeasureVesselLumen(StenosisScene().Mask, StenosisScene().Sections);
  auto                      robust = profile;
  const auto                summary = vr::AnalyseVesselStenosis(profile);
  vr::VesselStenosisOptions options;
  options.Method = vr::VesselReferenceMethod::RobustFit;
  const auto robustSummary = vr::AnalyseVesselStenosis(robust, options);
  for (const auto * s : { &summary, &robustSummary })
  {
    std::cout << vr::ToString(s->Method) << ": MLD " << s->MinimalLumenDiameter << " mm at "
              << s->MinimalLumenDiameterArcLength << " mm, RVD " << s->ReferenceDiameter << " mm, DS "
              << s->DiameterStenosisPercent << " %, MLA " << s->MinimalLumenArea << " mm2 at "
              << s->MinimalLumenAreaArcLength << " mm, AS " << s->AreaStenosisPercent << " %, CAD-RADS " << s->CADRADS
              << std::endl;
    EXPECT_NEAR(s->MinimalLumenDiameter, 4.0, 0.2);
    EXPECT_NEAR(s->MinimalLumenDiameterArcLength, 40.0, 1.0);
    EXPECT_NEAR(s->ReferenceDiameter, 8.0, 0.25);
    EXPECT_NEAR(s->DiameterStenosisPercent, 50.0, 3.0);
    // Area stenosis 1 - (2/4)^2 = 75 %; 3 points of diameter stenosis are 3 of area stenosis here.
    EXPECT_NEAR(s->MinimalLumenArea, M_PI * 4.0, M_PI * 4.0 * 0.1);
    EXPECT_NEAR(s->AreaStenosisPercent, 75.0, 3.0);
    EXPECT_EQ(s->CADRADS, vr::CADRADSClass(s->DiameterStenosisPercent));
    EXPECT_TRUE(s->CADRADS == 2 || s->CADRADS == 3);
    EXPECT_DOUBLE_EQ(s->PathLength, 80.0);
    EXPECT_EQ(s->Source, itk::VesselLumenSource::Segmentation);
  }
  // The robust line is flat on the healthy tube: the dip has no weight.
  EXPECT_NEAR(robust.Sections.front().ReferenceDiameter, 8.0, 0.1);
  EXPECT_NEAR(robust.Sections.back().ReferenceDiameter, 8.0, 0.1);
}

TEST(VesselLumenMeasurement, StenosisGradedFromTheRadiiAlone)
{
  auto profile = itk::VesselLumenFromRadii(StenosisScene().Sections);
  EXPECT_EQ(profile.Source, itk::VesselLumenSource::CenterlineRadius);
  EXPECT_EQ(profile.SectionsWithoutRadius, 0u);
  for (const auto & section : profile.Sections)
  {
    EXPECT_TRUE(std::isnan(section.Area));
    EXPECT_TRUE(std::isnan(section.EquivalentDiameter));
    EXPECT_TRUE(std::isnan(section.MinimumDiameter));
    EXPECT_DOUBLE_EQ(section.Diameter, 2.0 * StenosisRadius(section.ArcLength));
  }
  for (const auto method : { vr::VesselReferenceMethod::Interpolated, vr::VesselReferenceMethod::RobustFit })
  {
    auto                      copy = profile;
    vr::VesselStenosisOptions options;
    options.Method = method;
    const auto summary = vr::AnalyseVesselStenosis(copy, options);
    // Exact for the interpolated reference (8 mm at 4 and 76 mm); the robust line gives the dip's flanks, close to
    // 8 mm, a little weight.
    const double tolerance = method == vr::VesselReferenceMethod::Interpolated ? 1e-9 : 0.01;
    EXPECT_NEAR(summary.MinimalLumenDiameter, 4.0, 1e-9);
    EXPECT_NEAR(summary.MinimalLumenDiameterArcLength, 40.0, 1e-9);
    EXPECT_NEAR(summary.ReferenceDiameter, 8.0, tolerance);
    EXPECT_NEAR(summary.DiameterStenosisPercent, 50.0, 100.0 * tolerance);
    EXPECT_NEAR(summary.MinimalLumenArea, M_PI * 4.0, 1e-9);
    EXPECT_NEAR(summary.AreaStenosisPercent, 75.0, 100.0 * tolerance);
    EXPECT_EQ(summary.CADRADS, 3);
    EXPECT_EQ(summary.Source, itk::VesselLumenSource::CenterlineRadius);
  }
}
} // namespace
