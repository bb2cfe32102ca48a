// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The grading by segment (docs/lumen-measurement.md, issue 39) on analytic trees read through vr::VesselPathLogic:
// a parent tube of 16 mm and a child of 6 mm joining it, lumen from the exact centerline radii, so that every
// expected value is worked out by hand. No stenosis is reported across the junction; a 50 % narrowing inside the child
// is 50 % on the child's own reference; a narrowing in the path's last millimetre or at the child's ostium is
// excluded and marked; CAD-RADS is given on a branch named as a coronary artery only; the aorta's headline is its
// maximum diameter. Also the scales' categories, what names say, the path's junctions and the lumen table's notes.
#include "vrLumenMeasurement.h"
#include "vrPathSegments.h"
#include "vrStenosisScale.h"
#include "vrTestFiles.h"
#include "vrNodeConversion.h"
#include "vrVesselPathLogic.h"
#include "vrVesselPathOutputWriter.h"

#include "gtest/gtest.h"

#include <cmath>
#include <functional>
#include <sstream>

namespace
{
constexpr double ParentRadius = 8.0;
constexpr double ChildRadius = 3.0;
/** The parent runs along LPS x from 0 to 100 mm; the child leaves it at x = 60, at 45 degrees in the x-y plane, for
 * 80 mm. A path to the child is 140 mm long, its junction at 60 mm. */
constexpr double JunctionX = 60.0;
constexpr double ChildLength = 80.0;

using RadiusOf = std::function<double(double)>;

/** A raised-cosine narrowing to \a fraction of \a radius, \a halfWidth mm either side of \a centre. */
RadiusOf
Narrowing(double radius, double centre, double halfWidth, double fraction)
{
  return [=](double t)
  {
    const double u = std::abs(t - centre) / halfWidth;
    return u >= 1.0 ? radius : radius * (1.0 - (1.0 - fraction) * 0.5 * (1.0 + std::cos(M_PI * u)));
  };
}

RadiusOf
Constant(double radius)
{
  return [radius](double) { return radius; };
}

/** The tree: parent (id 1) and child (id 2), points every 0.5 mm, radii from the functions of each branch's own
 * arc length. */
itk::CenterlineTree
TwoVessels(const RadiusOf &    parent,
           const RadiusOf &    child,
           const std::string & parentName = std::string(),
           const std::string & childName = std::string())
{
  itk::CenterlineTree   tree;
  itk::CenterlineBranch trunk;
  trunk.Id = 1;
  trunk.Name = parentName;
  for (double x = 0.0; x <= 100.0 + 1e-9; x += 0.5)
  {
    itk::CenterlineBranch::PointType point;
    point[0] = x;
    point[1] = 0.0;
    point[2] = 0.0;
    trunk.Points.push_back(point);
    trunk.Radii.push_back(parent(x));
  }
  itk::CenterlineBranch side;
  side.Id = 2;
  side.Name = childName;
  for (double t = 0.0; t <= ChildLength + 1e-9; t += 0.5)
  {
    itk::CenterlineBranch::PointType point;
    point[0] = JunctionX + t / std::sqrt(2.0);
    point[1] = t / std::sqrt(2.0);
    point[2] = 0.0;
    side.Points.push_back(point);
    side.Radii.push_back(child(t));
  }
  tree.AddBranch(trunk);
  tree.AddBranch(side);
  return tree;
}

/** A blank volume around the tree: the logic samples it for the images, the lumen comes from the radii. */
vr::VolumeImageType::Pointer
BlankVolume()
{
  auto                             volume = vr::VolumeImageType::New();
  vr::VolumeImageType::RegionType  region;
  vr::VolumeImageType::SizeType    size = { { 150, 100, 30 } };
  vr::VolumeImageType::PointType   origin;
  vr::VolumeImageType::SpacingType spacing;
  origin[0] = -15.0;
  origin[1] = -30.0;
  origin[2] = -15.0;
  spacing.Fill(1.0);
  region.SetSize(size);
  volume->SetRegions(region);
  volume->SetOrigin(origin);
  volume->SetSpacing(spacing);
  volume->Allocate(true);
  return volume;
}

struct Reading
{
  vr::VolumeImageType::Pointer Volume = BlankVolume();
  vr::VesselPathLogic          Logic;

  const vr::VesselPathOutputs &
  Read(const itk::CenterlineTree & tree, int branch, vr::StenosisScale scale = vr::StenosisScale::Automatic)
  {
    Logic.SetVolumeNode(vr::ConvertItkImageToVolumeNode(Volume.GetPointer(), "blank"));
    const auto centerlines = vr::ConvertTreeToCenterlineNode(tree, "tree");
    Logic.GetInputCache()->SetCenterlines(centerlines, tree); // the tree as built, junctions and all
    Logic.SetCenterlineNode(centerlines);
    vr::VesselPathParameters parameters;
    parameters.BranchId = branch;
    parameters.SectionSpacing = 0.5;
    parameters.Width = 10.0;
    parameters.GradingScale = scale;
    Logic.SetParameters(parameters);
    return Logic.Update();
  }
};

/** The grading of the section at arc length \a s. */
const vr::SectionGrading &
MarkAt(const vr::VesselPathOutputs & results, double s)
{
  const auto & sections = results.Lumen.Sections;
  for (std::size_t k = 0; k < sections.size(); ++k)
  {
    if (std::abs(sections[k].ArcLength - s) < 1e-6)
    {
      return results.Stenosis.Sections[k];
    }
  }
  throw std::runtime_error("no section at " + std::to_string(s) + " mm");
}

TEST(StenosisGrading, NoStenosisAcrossTheJunctionIntoASmallerChild)
{
  Reading      reading;
  const auto & results = reading.Read(TwoVessels(Constant(ParentRadius), Constant(ChildRadius)), 2);
  ASSERT_TRUE(results.HasLumen);
  EXPECT_NEAR(results.Path.GetLength(), JunctionX + ChildLength, 1e-6);
  // Two segments, cut at the junction; the child's own reference is its own 6 mm.
  const auto & stenosis = results.Stenosis;
  ASSERT_EQ(stenosis.Segments.size(), 2u);
  EXPECT_NEAR(stenosis.Segments[0].Segment.End, JunctionX, 1e-6);
  EXPECT_EQ(stenosis.Segments[1].Segment.BranchId, 2);
  EXPECT_NEAR(stenosis.Segments[0].ReferenceDiameter, 2.0 * ParentRadius, 1e-9);
  EXPECT_NEAR(stenosis.Segments[1].ReferenceDiameter, 2.0 * ChildRadius, 1e-9);
  for (const auto & segment : stenosis.Segments)
  {
    EXPECT_NEAR(segment.DiameterStenosisPercent, 0.0, 1e-9);
  }
  // The unnamed 16 mm parent is aorta-sized: its stenosis is computed, not graded; the child is a peripheral artery.
  EXPECT_EQ(stenosis.Segments[0].Scale, vr::StenosisScale::Aorta);
  EXPECT_FALSE(stenosis.Segments[0].IsGraded());
  EXPECT_EQ(stenosis.Segments[1].Category, 0);
  EXPECT_EQ(stenosis.Segments[1].Grade, "normal (peripheral)");
  EXPECT_EQ(stenosis.HeadlineSegment, 1);
  EXPECT_EQ(stenosis.Grade, "normal (peripheral)");
  EXPECT_NEAR(stenosis.DiameterStenosisPercent, 0.0, 1e-9);
  EXPECT_TRUE(stenosis.NotGradedBecause.empty());
  // The reference never runs across the junction: each section's reference is its own vessel's diameter.
  for (const auto & section : results.Lumen.Sections)
  {
    EXPECT_NEAR(section.ReferenceDiameter, section.ArcLength < JunctionX ? 16.0 : 6.0, 1e-9) << section.ArcLength;
  }
  // What the old single reference across the path would say (points at 5 % and 95 %, 7 and 133 mm): a false
  // stenosis of the child, as the issue saw on the aorta -> celiac trunk path.
  reading.Logic.SetParameters(
    [&]
    {
      auto parameters = reading.Logic.GetParameters();
      parameters.ReferencePoints = { 7.0, 133.0 };
      return parameters;
    }());
  const auto & across = reading.Logic.Update().Stenosis;
  EXPECT_TRUE(across.UserReferencePoints);
  EXPECT_GT(across.DiameterStenosisPercent, 40.0);
}

TEST(StenosisGrading, FiftyPercentInsideTheChildOnItsOwnReference)
{
  Reading      reading;
  const auto & results = reading.Read(TwoVessels(Constant(ParentRadius), Narrowing(ChildRadius, 40.0, 5.0, 0.5)), 2);
  const auto & stenosis = results.Stenosis;
  ASSERT_EQ(stenosis.HeadlineSegment, 1);
  EXPECT_NEAR(stenosis.MinimalLumenDiameter, 3.0, 1e-9);
  EXPECT_NEAR(stenosis.MinimalLumenDiameterArcLength, JunctionX + 40.0, 1e-6);
  EXPECT_NEAR(stenosis.ReferenceDiameter, 6.0, 1e-9);
  EXPECT_NEAR(stenosis.DiameterStenosisPercent, 50.0, 1e-9);
  EXPECT_NEAR(stenosis.AreaStenosisPercent, 75.0, 1e-9);
  EXPECT_EQ(stenosis.Scale, vr::StenosisScale::Peripheral);
  EXPECT_EQ(stenosis.Grade, "50–99 % (peripheral)");
  EXPECT_EQ(stenosis.CADRADS, -1);
  // The child's reference points: its first and last candidate, outside the junction's margin (the parent's radius,
  // 8 mm) and the end's (max(2 mm, 3 mm)).
  EXPECT_EQ(stenosis.ReferenceArcLengths, (std::vector<double>{ 68.5, 136.5 }));
  // The parent is not narrowed.
  EXPECT_NEAR(stenosis.Segments[0].DiameterStenosisPercent, 0.0, 1e-9);
}

TEST(StenosisGrading, NarrowingInTheLastMillimetreIsExcludedAndMarked)
{
  Reading reading;
  // The child narrows to half in its last millimetre (a centerline's end cap).
  const auto   lastMillimetre = [](double t) { return t > ChildLength - 1.0 ? 0.5 * ChildRadius : ChildRadius; };
  const auto & results = reading.Read(TwoVessels(Constant(ParentRadius), lastMillimetre), 2);
  const auto & stenosis = results.Stenosis;
  EXPECT_NEAR(stenosis.DiameterStenosisPercent, 0.0, 1e-9);
  EXPECT_LT(stenosis.MinimalLumenDiameterArcLength, 138.0);
  for (const double s : { 139.0, 139.5, 140.0 })
  {
    EXPECT_FALSE(MarkAt(results, s).Candidate) << s;
    EXPECT_EQ(MarkAt(results, s).ExcludedBecause, "path end") << s;
  }
  EXPECT_TRUE(MarkAt(results, 137.5).Candidate);
}

TEST(StenosisGrading, NarrowingAtTheOstiumIsExcludedAndMarked)
{
  Reading reading;
  // The child's first 3 mm are narrowed to half: inside the junction's margin of one parent radius.
  const auto   ostium = [](double t) { return t < 3.0 ? 0.5 * ChildRadius : ChildRadius; };
  const auto & results = reading.Read(TwoVessels(Constant(ParentRadius), ostium), 2);
  const auto & stenosis = results.Stenosis;
  EXPECT_NEAR(stenosis.DiameterStenosisPercent, 0.0, 1e-9);
  for (const double s : { 52.0, 60.0, 61.0, 62.5, 68.0 })
  {
    EXPECT_EQ(MarkAt(results, s).ExcludedBecause, "junction into branch 2") << s;
  }
  EXPECT_TRUE(MarkAt(results, 68.5).Candidate);
  EXPECT_TRUE(MarkAt(results, 51.5).Candidate);
  // The same narrowing beyond the margin is graded: 50 %.
  const auto   later = [](double t) { return t > 20.0 && t < 23.0 ? 0.5 * ChildRadius : ChildRadius; };
  const auto & graded = reading.Read(TwoVessels(Constant(ParentRadius), later), 2).Stenosis;
  EXPECT_NEAR(graded.DiameterStenosisPercent, 50.0, 1e-9);
}

TEST(StenosisGrading, CADRADSOnlyOnABranchNamedAsCoronary)
{
  const auto narrowed = Narrowing(ChildRadius, 40.0, 5.0, 0.5);
  struct Case
  {
    std::string       Name;
    vr::StenosisScale Scale;
    int               CADRADS;
    std::string       Grade;
  };
  const Case cases[] = {
    { "left anterior descending artery", vr::StenosisScale::CADRADS, 3, "CAD-RADS 3 (50–69 %)" },
    { "RCA", vr::StenosisScale::CADRADS, 3, "CAD-RADS 3 (50–69 %)" },
    { "celiac trunk", vr::StenosisScale::Peripheral, -1, "50–99 % (peripheral)" },
    { "right internal carotid artery", vr::StenosisScale::Carotid, -1, "50–69 % (NASCET)" },
    { "", vr::StenosisScale::Peripheral, -1, "50–99 % (peripheral)" },
  };
  for (const Case & c : cases)
  {
    Reading      reading;
    const auto & stenosis = reading.Read(TwoVessels(Constant(ParentRadius), narrowed, "aorta", c.Name), 2).Stenosis;
    EXPECT_EQ(stenosis.Scale, c.Scale) << c.Name;
    EXPECT_EQ(stenosis.CADRADS, c.CADRADS) << c.Name;
    EXPECT_EQ(stenosis.Grade, c.Grade) << c.Name;
    EXPECT_NEAR(stenosis.DiameterStenosisPercent, 50.0, 1e-9) << c.Name;
    // The aorta's segment is not graded, and says why.
    EXPECT_EQ(stenosis.Segments[0].Scale, vr::StenosisScale::Aorta);
    EXPECT_FALSE(stenosis.Segments[0].IsGraded());
    EXPECT_NE(stenosis.Segments[0].NotGradedBecause.find("aorta"), std::string::npos);
  }
  // Or when the user says so, whatever the name.
  Reading      reading;
  const auto & chosen =
    reading.Read(TwoVessels(Constant(ParentRadius), narrowed, "", "celiac trunk"), 2, vr::StenosisScale::CADRADS)
      .Stenosis;
  EXPECT_EQ(chosen.CADRADS, 3);
  EXPECT_EQ(chosen.Segments[1].ScaleReason, "chosen by the user");
}

TEST(StenosisGrading, TheAortasHeadlineIsItsMaximumDiameter)
{
  Reading reading;
  // A fusiform aneurysm of the aorta: radius 8 -> 12 mm at x = 30 (diameter 24 mm).
  const auto aneurysm = [](double x)
  {
    const double u = std::abs(x - 30.0) / 10.0;
    return u >= 1.0 ? ParentRadius : ParentRadius + 4.0 * 0.5 * (1.0 + std::cos(M_PI * u));
  };
  const auto & results = reading.Read(TwoVessels(aneurysm, Constant(ChildRadius), "abdominal aorta"), 1);
  const auto & stenosis = results.Stenosis;
  // The child leaves at 60 mm: a side branch's junction cuts the aorta in two segments, both aortic.
  ASSERT_EQ(stenosis.Segments.size(), 2u);
  EXPECT_FALSE(results.Layout.Junctions.front().OnPath);
  EXPECT_EQ(stenosis.HeadlineSegment, 0);
  EXPECT_EQ(stenosis.Scale, vr::StenosisScale::Aorta);
  EXPECT_NEAR(stenosis.MaximumDiameter, 24.0, 1e-9);
  EXPECT_NEAR(stenosis.MaximumDiameterArcLength, 30.0, 1e-6);
  EXPECT_TRUE(stenosis.Grade.empty());
  EXPECT_EQ(stenosis.CADRADS, -1);
  EXPECT_NE(stenosis.NotGradedBecause.find("maximum diameter"), std::string::npos) << stenosis.NotGradedBecause;
  // The % stenosis stays available, not graded.
  EXPECT_TRUE(std::isfinite(stenosis.DiameterStenosisPercent));
  // An unnamed vessel of aortic size is the aorta too, and says why.
  Reading      unnamed;
  const auto & bySize = unnamed.Read(TwoVessels(aneurysm, Constant(ChildRadius)), 1).Stenosis;
  EXPECT_EQ(bySize.Scale, vr::StenosisScale::Aorta);
  EXPECT_NE(bySize.Segments[0].ScaleReason.find("by its size"), std::string::npos);
}

TEST(StenosisGrading, ASegmentTooShortForTwoReferencePointsSaysSo)
{
  Reading reading;
  // The child is 12 mm long: its junction margin (8 mm) and end margin (3 mm) leave 1 mm, two sections.
  itk::CenterlineTree tree = TwoVessels(Constant(ParentRadius), Constant(ChildRadius));
  auto &              child = tree.GetBranches()[1];
  child.Points.resize(25);
  child.Radii.resize(25);
  const auto & stenosis = reading.Read(tree, 2).Stenosis;
  ASSERT_EQ(stenosis.Segments.size(), 2u);
  EXPECT_FALSE(stenosis.Segments[1].IsGraded());
  EXPECT_NE(stenosis.Segments[1].NotGradedBecause.find("too short for two reference points"), std::string::npos)
    << stenosis.Segments[1].NotGradedBecause;
  EXPECT_TRUE(std::isnan(stenosis.Segments[1].DiameterStenosisPercent));
  // The parent is graded: the headline.
  EXPECT_EQ(stenosis.HeadlineSegment, 0);
}

TEST(StenosisGrading, CategoriesAtTheirBoundaries)
{
  using vr::StenosisScale;
  const auto peripheral = [](double p) { return vr::StenosisCategory(StenosisScale::Peripheral, p); };
  EXPECT_EQ(peripheral(std::nan("")), -1);
  EXPECT_EQ(peripheral(-3.0), 0);
  EXPECT_EQ(peripheral(0.49), 0);
  EXPECT_EQ(peripheral(0.5), 1);
  EXPECT_EQ(peripheral(19.49), 1);
  EXPECT_EQ(peripheral(19.5), 2);
  EXPECT_EQ(peripheral(49.49), 2);
  EXPECT_EQ(peripheral(49.5), 3);
  EXPECT_EQ(peripheral(99.9), 3); // some lumen left
  EXPECT_EQ(peripheral(100.0), 4);
  const auto carotid = [](double p) { return vr::StenosisCategory(StenosisScale::Carotid, p); };
  EXPECT_EQ(carotid(0.0), 0);
  EXPECT_EQ(carotid(49.49), 0);
  EXPECT_EQ(carotid(49.5), 1);
  EXPECT_EQ(carotid(69.49), 1);
  EXPECT_EQ(carotid(69.5), 2);
  EXPECT_EQ(carotid(99.9), 2);
  EXPECT_EQ(carotid(100.0), 3);
  EXPECT_EQ(vr::StenosisCategory(StenosisScale::CADRADS, 60.0), vr::CADRADSClass(60.0));
  EXPECT_EQ(vr::StenosisCategory(StenosisScale::Aorta, 60.0), -1);
  EXPECT_EQ(vr::StenosisCategoryText(StenosisScale::Peripheral, 4), "occlusion (peripheral)");
  EXPECT_EQ(vr::StenosisCategoryText(StenosisScale::Carotid, 0), "< 50 % (NASCET)");
  EXPECT_EQ(vr::StenosisCategoryText(StenosisScale::CADRADS, 5), "CAD-RADS 5 (100 %, occlusion)");
}

TEST(StenosisGrading, WhatNamesSay)
{
  using vr::StenosisScale;
  EXPECT_EQ(vr::ScaleOfVesselName("aorta"), StenosisScale::Aorta);
  EXPECT_EQ(vr::ScaleOfVesselName("ascending aorta, arch and descending aorta"), StenosisScale::Aorta);
  EXPECT_EQ(vr::ScaleOfVesselName("Aortic arch"), StenosisScale::Aorta);
  EXPECT_EQ(vr::ScaleOfVesselName("left coronary artery"), StenosisScale::CADRADS);
  EXPECT_EQ(vr::ScaleOfVesselName("LAD_proximal"), StenosisScale::CADRADS);
  EXPECT_EQ(vr::ScaleOfVesselName("left circumflex"), StenosisScale::CADRADS);
  EXPECT_EQ(vr::ScaleOfVesselName("OM1"), StenosisScale::CADRADS);
  EXPECT_EQ(vr::ScaleOfVesselName("left common carotid artery"), StenosisScale::Carotid);
  EXPECT_EQ(vr::ScaleOfVesselName("celiac trunk"), StenosisScale::Automatic);
  EXPECT_EQ(vr::ScaleOfVesselName("iliac artery left"), StenosisScale::Automatic);
  EXPECT_EQ(vr::ScaleOfVesselName("palmar arch"), StenosisScale::Automatic); // "lm" only as a word of its own
  EXPECT_EQ(vr::ScaleOfVesselName(""), StenosisScale::Automatic);
  vr::StenosisScale scale = StenosisScale::Automatic;
  EXPECT_TRUE(vr::ParseStenosisScale("CAD-RADS", scale));
  EXPECT_EQ(scale, StenosisScale::CADRADS);
  EXPECT_TRUE(vr::ParseStenosisScale("carotid", scale));
  EXPECT_EQ(scale, StenosisScale::Carotid);
  EXPECT_FALSE(vr::ParseStenosisScale("coronary", scale));
}

TEST(StenosisGrading, PathNamesMergeRepeatsAndJunctionsAreFound)
{
  EXPECT_EQ(vr::JoinPathNames({ "aorta", "aorta", "aorta", "aorta", "celiac trunk" }), "aorta → celiac trunk");
  EXPECT_EQ(vr::JoinPathNames({ "a", "b", "a" }), "a → b → a");
  EXPECT_EQ(vr::JoinPathNames({}), "");
  const itk::CenterlineTree tree = TwoVessels(Constant(ParentRadius), Constant(ChildRadius), "aorta", "renal artery");
  const auto                intoChild = vr::FindPathLayout(tree, itk::VesselPath::FromTree(tree, 2), false, false);
  ASSERT_EQ(intoChild.Junctions.size(), 1u);
  EXPECT_TRUE(intoChild.Junctions[0].OnPath);
  EXPECT_NEAR(intoChild.Junctions[0].ArcLength, JunctionX, 1e-6);
  EXPECT_DOUBLE_EQ(intoChild.Junctions[0].ParentRadius, ParentRadius);
  ASSERT_EQ(intoChild.Segments.size(), 2u);
  EXPECT_EQ(intoChild.Segments[1].Name, "renal artery");
  const auto alongParent = vr::FindPathLayout(tree, itk::VesselPath::FromTree(tree, 1), false, false);
  ASSERT_EQ(alongParent.Junctions.size(), 1u);
  EXPECT_FALSE(alongParent.Junctions[0].OnPath);
  EXPECT_EQ(alongParent.Junctions[0].BranchId, 2);
  // A cut of the parent before the child leaves it has no junction, and its cut ends are no vessel ends.
  const auto cut = vr::FindPathLayout(tree, itk::VesselPath::FromTree(tree, 1).Cut(10.0, 50.0), true, true);
  EXPECT_TRUE(cut.Junctions.empty());
  EXPECT_EQ(cut.Segments.size(), 1u);
  EXPECT_FALSE(cut.StartIsVesselEnd);
  EXPECT_FALSE(cut.EndIsVesselEnd);
}

TEST(StenosisGrading, TheLumenTableStatesTheGradingAndMarksTheRows)
{
  Reading      reading;
  const auto & results = reading.Read(
    TwoVessels(Constant(ParentRadius), Narrowing(ChildRadius, 40.0, 5.0, 0.5), "aorta", "celiac trunk"), 2);
  EXPECT_EQ(results.PathName, "aorta → celiac trunk");
  vr::test::ScopedTemporaryFolder folder;
  const std::string               path = folder.File("lumen.csv");
  vr::VesselPathOutputWriter      writer;
  writer.Add(vr::VesselPathOutput::LumenTable, path, "--outputLumenTable");
  writer.Write(results);
  writer.CommitAll();
  std::istringstream       text(vr::test::ReadTextFile(path));
  std::vector<std::string> comments;
  std::string              line;
  while (std::getline(text, line) && line.rfind("# ", 0) == 0)
  {
    comments.push_back(line);
  }
  // The header row after the comments, with the renamed RAS columns and the marks.
  EXPECT_EQ(line.rfind("arc_length_mm,ras_r_mm,ras_a_mm,ras_s_mm,", 0), 0u) << line;
  EXPECT_NE(line.find(",segment,mld_candidate,excluded_because"), std::string::npos) << line;
  std::string all;
  for (const auto & comment : comments)
  {
    all += comment + "\n";
  }
  EXPECT_NE(all.find("path: 140.0 mm: aorta → celiac trunk"), std::string::npos) << all;
  EXPECT_NE(all.find("reference: interpolated within each segment"), std::string::npos) << all;
  EXPECT_NE(all.find("segment 1 (aorta, 0.0–60.0 mm), scale aorta (by its name)"), std::string::npos) << all;
  EXPECT_NE(all.find("; the aorta is sized, not graded: its headline is the maximum diameter"), std::string::npos)
    << all;
  EXPECT_NE(all.find("segment 2 (celiac trunk, 60.0–140.0 mm), scale peripheral"), std::string::npos) << all;
  EXPECT_NE(all.find("headline: 50 % diameter stenosis, 50–99 % (peripheral), in segment 2 (celiac trunk)"),
            std::string::npos)
    << all;
  // The row at the junction: segment 2, no candidate, why.
  std::getline(text, line);
  EXPECT_NE(line.find(",1,0,path start"), std::string::npos) << line;
  bool junction = false;
  while (std::getline(text, line))
  {
    junction = junction || line.find(",2,0,junction into branch 2") != std::string::npos;
  }
  EXPECT_TRUE(junction);
}
} // namespace
