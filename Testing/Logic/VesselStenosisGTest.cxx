// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Reference diameter, MLD, MLA, % stenosis and the CAD-RADS class (docs/lumen-measurement.md) on profiles written by
// hand, against values worked out by hand; and on the lumen measured on a tube of known cross-section (the issue's
// 50 % concentric stenosis, from the mask and from the radii). A profile without a layout is one segment whose ends
// are vessel ends: no MLD within max(2 mm, the radius there) of either end.
#include "vrInputError.h"
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

TEST(VesselStenosis, InterpolatedReferenceBetweenTheEndsOfTheCandidates)
{
  auto       profile = Profile(0.0, 100.0, 1.0, TaperWithDip);
  const auto summary = vr::AnalyseVesselStenosis(profile);
  // Margins: radius 3 mm at the start (d = 6.0), 4 mm at the end (d = 8.0); sections 0-3 and 96-100 are excluded,
  // so the reference points are the first and the last candidate, 4 and 95 mm: 6.08 and 7.9 mm; at 50 mm
  // 6.08 + 46/91 * 1.82 = 7.0 mm.
  ASSERT_EQ(summary.ReferenceArcLengths.size(), 2u);
  EXPECT_DOUBLE_EQ(summary.ReferenceArcLengths[0], 4.0);
  EXPECT_DOUBLE_EQ(summary.ReferenceArcLengths[1], 95.0);
  EXPECT_NEAR(summary.ReferenceDiameter, 7.0, 1e-12);
  EXPECT_DOUBLE_EQ(summary.MinimalLumenDiameter, 3.5);
  EXPECT_DOUBLE_EQ(summary.MinimalLumenDiameterArcLength, 50.0);
  EXPECT_NEAR(summary.DiameterStenosisPercent, 50.0, 1e-10);
  // Areas from the diameters (radius source), their reference interpolated between the areas at 4 and 95 mm:
  // pi/4 (6.08^2 + 46/91 (7.9^2 - 6.08^2)) at 50 mm.
  const double referenceArea = M_PI / 4.0 * (6.08 * 6.08 + 46.0 / 91.0 * (7.9 * 7.9 - 6.08 * 6.08));
  EXPECT_NEAR(summary.ReferenceArea, referenceArea, 1e-10);
  EXPECT_NEAR(summary.AreaStenosisPercent, 100.0 * (1.0 - M_PI / 4.0 * 12.25 / referenceArea), 1e-10);
  // An unnamed vessel of 7 mm is graded as a peripheral artery: 50 % is "50-99 %", and no CAD-RADS class.
  EXPECT_EQ(summary.Scale, vr::StenosisScale::Peripheral);
  EXPECT_EQ(summary.CADRADS, -1);
  EXPECT_EQ(summary.Grade, "50–99 % (peripheral)");
  EXPECT_DOUBLE_EQ(summary.PathLength, 100.0);
  EXPECT_EQ(summary.MeasuredSections, 101u);
  EXPECT_EQ(summary.ExcludedSections, 9u);
  EXPECT_EQ(summary.Sections[3].ExcludedBecause, "path start");
  EXPECT_TRUE(summary.Sections[4].Candidate);
  EXPECT_EQ(summary.Sections[96].ExcludedBecause, "path end");
  // Constant beyond the reference points, linear between them.
  EXPECT_NEAR(profile.Sections[0].ReferenceDiameter, 6.08, 1e-12);
  EXPECT_NEAR(profile.Sections[2].ReferenceDiameter, 6.08, 1e-12);
  EXPECT_NEAR(profile.Sections[20].ReferenceDiameter, 6.08 + 16.0 / 91.0 * 1.82, 1e-12);
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
  // The MLD among the candidates: the path start's margin is 2 mm (radius 0.5 mm there), so 10-12 mm are excluded
  // and the narrowest candidate is 13 mm, 1.69 mm, its reference 1.565 + 0.5 / 7.5 * 2.435 mm.
  EXPECT_TRUE(summary.UserReferencePoints);
  EXPECT_DOUBLE_EQ(summary.MinimalLumenDiameterArcLength, 13.0);
  EXPECT_NEAR(summary.MinimalLumenDiameter, 1.69, 1e-12);
  const double reference = 1.565 + 0.5 / 7.5 * (4.0 - 1.565);
  EXPECT_NEAR(summary.ReferenceDiameter, reference, 1e-12);
  EXPECT_NEAR(summary.DiameterStenosisPercent, 100.0 * (1.0 - 1.69 / reference), 1e-10);
  // Areas (pi/4 d^2, the radius source) interpolated the same way: at 12.5 mm pi/4 (1.44^2 + 1.69^2) / 2, at 20 mm
  // pi/4 16.
  const double area12 = (1.44 * 1.44 + 1.69 * 1.69) / 2.0;
  EXPECT_NEAR(summary.MinimalLumenArea, M_PI / 4.0 * 1.69 * 1.69, 1e-12);
  EXPECT_NEAR(summary.ReferenceArea, M_PI / 4.0 * (area12 + 0.5 / 7.5 * (16.0 - area12)), 1e-12);
}

TEST(VesselStenosis, UnmeasuredSectionsAreSkippedByTheInterpolation)
{
  // Not measured at 4, 5 and 6 mm: the first candidate is 7 mm (6.14 mm), the last 95 mm (7.9 mm); at 50 mm
  // 6.14 + 43/88 * 1.76 = 7.0 mm.
  auto profile =
    Profile(0.0, 100.0, 1.0, [](double s) { return (s > 3.5 && s < 6.5) ? std::nan("") : TaperWithDip(s); });
  const auto summary = vr::AnalyseVesselStenosis(profile);
  EXPECT_NEAR(profile.Sections[0].ReferenceDiameter, 6.14, 1e-12);
  EXPECT_EQ(summary.MeasuredSections, 98u);
  EXPECT_EQ(summary.Sections[5].ExcludedBecause, "not measured");
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
  catch (const vr::InputError & exception)
  {
    EXPECT_EQ(exception.Parameter(), "reference points");
    const std::string message = exception.what();
    EXPECT_NE(message.find("120 mm"), std::string::npos) << message;
    EXPECT_NE(message.find("-3.5 mm"), std::string::npos) << message;
    EXPECT_EQ(message.find("10 mm"), std::string::npos) << message;
    EXPECT_NE(message.find("0 to 80 mm"), std::string::npos) << message;
  }
  options.ReferenceArcLengths = { std::nan("") };
  EXPECT_THROW(vr::AnalyseVesselStenosis(profile, options), vr::InputError);
  options.ReferenceArcLengths = { 30.0 };
  options.Method = vr::VesselReferenceMethod::RobustFit;
  EXPECT_THROW(vr::AnalyseVesselStenosis(profile, options), vr::InputError);
  // One point is enough for the interpolated method: a constant reference.
  options.Method = vr::VesselReferenceMethod::Interpolated;
  const auto summary = vr::AnalyseVesselStenosis(profile, options);
  EXPECT_NEAR(profile.Sections.back().ReferenceDiameter, 6.6, 1e-12);
  EXPECT_EQ(summary.ReferenceArcLengths, std::vector<double>{ 30.0 });
  EXPECT_DOUBLE_EQ(summary.MinimalLumenDiameterArcLength, 50.0);
  EXPECT_NEAR(summary.DiameterStenosisPercent, 100.0 * (1.0 - 3.5 / 6.6), 1e-10);
}

TEST(VesselStenosis, TooShortOrUnmeasuredPathsThrow)
{
  auto one = Profile(0.0, 0.0, 1.0, TaperWithDip);
  EXPECT_THROW(vr::AnalyseVesselStenosis(one), vr::InputError);
  auto none = Profile(0.0, 50.0, 1.0, [](double) { return std::nan(""); });
  EXPECT_THROW(vr::AnalyseVesselStenosis(none), vr::InputError);
  auto backwards = Profile(0.0, 50.0, 1.0, TaperWithDip);
  std::swap(backwards.Sections[3].ArcLength, backwards.Sections[4].ArcLength);
  EXPECT_THROW(vr::AnalyseVesselStenosis(backwards), vr::InputError);
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
  options.Scale = vr::StenosisScale::CADRADS; // as a user says when the tube is a coronary artery
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
    if (s == &robustSummary)
    {
      EXPECT_EQ(s->CADRADS, vr::CADRADSClass(s->DiameterStenosisPercent));
      EXPECT_TRUE(s->CADRADS == 2 || s->CADRADS == 3);
    }
    else
    {
      // An unnamed 8 mm tube is a peripheral artery: no CAD-RADS class, the peripheral category instead.
      EXPECT_EQ(s->CADRADS, -1);
      EXPECT_EQ(s->Scale, vr::StenosisScale::Peripheral);
      EXPECT_TRUE(s->Grade == "50–99 % (peripheral)" || s->Grade == "20–49 % (peripheral)") << s->Grade;
    }
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
    options.Scale = vr::StenosisScale::CADRADS;
    const auto summary = vr::AnalyseVesselStenosis(copy, options);
    // Exact for the interpolated reference (8 mm at the first and last candidate, 4 and 76 mm: the tube's 4 mm radius
    // is its end margin); the robust line gives the dip's flanks, close to
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
