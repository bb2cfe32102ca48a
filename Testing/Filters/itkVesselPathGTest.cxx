// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// VesselPath and RotationMinimizingFrame (docs/vessel-path.md "Path" and "Frame"): topology from geometry on a
// hand-made tree, the run-off phantom and VMTK's aorta; the frame against the rotation-minimising condition, a helix's
// analytic frame, and a Frenet frame (computed here only) that flips at an inflection where ours does not.

#include "itkRotationMinimizingFrame.h"
#include "itkRunoffPhantomImageSource.h"
#include "itkVesselPath.h"

#include "vrCenterlineIO.h"
#include "vrTestFiles.h"
#include "vrTestImages.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

namespace
{
using PointType = itk::Point<double, 3>;
using VectorType = itk::Vector<double, 3>;
using vr::test::P;

VectorType
V(double x, double y, double z)
{
  VectorType v;
  v[0] = x;
  v[1] = y;
  v[2] = z;
  return v;
}

VectorType
Cross(const VectorType & a, const VectorType & b)
{
  return V(a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]);
}

/** A straight branch from \a from to \a to with points every \a step mm (and the end), radius \a radius. */
itk::CenterlineBranch
Line(int id, const PointType & from, const PointType & to, double step = 1.0, double radius = -1.0)
{
  itk::CenterlineBranch branch;
  branch.Id = id;
  const double length = from.EuclideanDistanceTo(to);
  const auto   count = static_cast<int>(std::ceil(length / step));
  for (int k = 0; k <= count; ++k)
  {
    branch.Points.push_back(from + (to - from) * (static_cast<double>(k) / count));
    if (radius >= 0.0)
    {
      branch.Radii.push_back(radius);
    }
  }
  return branch;
}

/** A branch through curve(t), t in [0, 1], at \a count + 1 points. */
itk::CenterlineBranch
Curve(int id, const std::function<PointType(double)> & curve, int count)
{
  itk::CenterlineBranch branch;
  branch.Id = id;
  for (int k = 0; k <= count; ++k)
  {
    branch.Points.push_back(curve(static_cast<double>(k) / count));
  }
  return branch;
}

itk::CenterlineTree
Tree(std::vector<itk::CenterlineBranch> branches)
{
  itk::CenterlineTree tree;
  for (auto & branch : branches)
  {
    tree.AddBranch(std::move(branch));
  }
  return tree;
}

/** A trunk down from z = 100 to 0; a side branch leaving its middle (its start 0.5 mm off the trunk); a
 * continuation from the trunk's end down to z = -80, and a grandchild leaving that 0.3 mm off its z = -40 point.
 * Listed children first, with ids in no particular order. */
itk::CenterlineTree
HandTree()
{
  return Tree({ Line(7, P(0.3, 0, -40), P(100.3, 0, -40)),
                Line(3, P(0.5, 0, 50), P(60.5, 0, 50)),
                Line(5, P(0, 0, 0), P(0, 0, -80)),
                Line(2, P(0, 0, 100), P(0, 0, 0)) });
}

template<typename F>
std::string
MessageOf(F && f)
{
  try
  {
    f();
  }
  catch (const itk::ExceptionObject & error)
  {
    return error.GetDescription();
  }
  return "(nothing thrown)";
}

/** Where the path's consecutive points are farther apart than the tree's own points, the gap is a junction's. */
void
ExpectContinuous(const itk::VesselPath & path, double largestGap)
{
  const auto & points = path.GetPoints();
  for (std::size_t k = 1; k < points.size(); ++k)
  {
    EXPECT_LE(points[k - 1].EuclideanDistanceTo(points[k]), largestGap)
      << "between path points " << k - 1 << " and " << k;
  }
}

double
LargestSpacing(const itk::CenterlineTree & tree)
{
  double largest = 0.0;
  for (const auto & branch : tree.GetBranches())
  {
    for (std::size_t k = 1; k < branch.Points.size(); ++k)
    {
      largest = std::max(largest, branch.Points[k - 1].EuclideanDistanceTo(branch.Points[k]));
    }
  }
  return largest;
}

/** The signed angle about \a tangent from the minimal rotation of \a lateral (taking tangent \a from onto \a to) to
 * \a next: the twist a rotation-minimising frame does not have. */
double
Twist(const VectorType & from, const VectorType & to, const VectorType & lateral, const VectorType & next)
{
  VectorType   axis = Cross(from, to);
  const double sine = axis.GetNorm();
  const double cosine = from * to;
  VectorType   moved = lateral;
  if (sine > 0.0)
  {
    axis /= sine;
    // Rodrigues' rotation by the angle between the tangents about their common normal.
    moved = lateral * cosine + Cross(axis, lateral) * sine + axis * ((axis * lateral) * (1.0 - cosine));
  }
  return std::atan2(Cross(moved, next) * to, moved * next);
}
} // namespace

TEST(VesselPath, TopologyComesFromGeometryNotOrderOrIds)
{
  const auto             tree = HandTree();
  const std::vector<int> parents = itk::VesselPath::FindParents(tree);
  // Indices: 0 = id 7, 1 = id 3, 2 = id 5, 3 = id 2 (the trunk, the root).
  EXPECT_EQ(parents, (std::vector<int>{ 2, 3, 3, -1 }));
}

TEST(VesselPath, DefaultIsTheLongestRootToLeafPathAndContinuous)
{
  const auto path = itk::VesselPath::FromTree(HandTree());
  EXPECT_EQ(path.GetBranchChain(), (std::vector<int>{ 2, 5, 7 }));
  // 100 mm of trunk, 40 mm of the continuation to the grandchild's junction, the 0.3 mm gap, 100 mm of it.
  EXPECT_NEAR(path.GetLength(), 240.3, 1e-9);
  ExpectContinuous(path, 1.0 + 1e-9);
  EXPECT_EQ(path.GetPoints().front(), P(0, 0, 100));
  EXPECT_EQ(path.GetPoints().back(), P(100.3, 0, -40));
  EXPECT_EQ(path.BranchIdAt(50.0), 2);
  EXPECT_EQ(path.BranchIdAt(120.0), 5);
  EXPECT_EQ(path.BranchIdAt(200.0), 7);
  EXPECT_TRUE(std::isnan(path.RadiusAt(10.0))) << "the tree has no radii";
}

TEST(VesselPath, PathToABranchLeavingItsParentsMiddle)
{
  const auto path = itk::VesselPath::FromTree(HandTree(), 3);
  EXPECT_EQ(path.GetBranchChain(), (std::vector<int>{ 2, 3 }));
  EXPECT_NEAR(path.GetLength(), 50.0 + 0.5 + 60.0, 1e-9);
  ExpectContinuous(path, 1.0 + 1e-9);
  EXPECT_NEAR(path.PointAt(25.0).EuclideanDistanceTo(P(0, 0, 75)), 0.0, 1e-12);
  EXPECT_NEAR(path.PointAt(80.5).EuclideanDistanceTo(P(30.5, 0, 50)), 0.0, 1e-12);
  const VectorType tangent = path.TangentAt(80.5);
  EXPECT_NEAR(tangent[0], 1.0, 1e-12);
  EXPECT_NEAR(path.ProjectPoint(P(30.5, 4, 52)), 80.5, 1e-12);
}

TEST(VesselPath, RadiusIsInterpolatedAlongThePath)
{
  auto tree = Tree({ Line(1, P(0, 0, 0), P(0, 0, -10), 5.0), Line(2, P(0, 0, -10), P(0, 0, -20), 10.0) });
  tree.GetBranches()[0].Radii = { 4.0, 3.0, 2.0 };
  tree.GetBranches()[1].Radii = { 2.0, 6.0 };
  const auto path = itk::VesselPath::FromTree(tree, 2);
  ASSERT_TRUE(path.HasRadii());
  EXPECT_NEAR(path.RadiusAt(0.0), 4.0, 1e-12);
  EXPECT_NEAR(path.RadiusAt(2.5), 3.5, 1e-12);
  EXPECT_NEAR(path.RadiusAt(15.0), 4.0, 1e-12);
  EXPECT_NEAR(path.RadiusAt(20.0), 6.0, 1e-12);
}

TEST(VesselPath, CutKeepsThePartBetweenTwoArcLengths)
{
  const auto path = itk::VesselPath::FromTree(HandTree());
  const auto cut = path.Cut(90.5, 150.25);
  EXPECT_NEAR(cut.GetLength(), 59.75, 1e-9);
  EXPECT_NEAR(cut.GetArcLengthOffset(), 90.5, 0.0);
  EXPECT_NEAR(cut.PointAt(0.0).EuclideanDistanceTo(path.PointAt(90.5)), 0.0, 1e-12);
  EXPECT_NEAR(cut.PointAt(30.0).EuclideanDistanceTo(path.PointAt(120.5)), 0.0, 1e-12);
  EXPECT_EQ(cut.GetBranchChain(), (std::vector<int>{ 2, 5, 7 }));
}

TEST(VesselPath, BadRequestsThrowNamingTheValue)
{
  const auto tree = HandTree();
  EXPECT_NE(MessageOf([&] { itk::VesselPath::FromTree(tree, 99); }).find("no branch 99"), std::string::npos);
  const auto path = itk::VesselPath::FromTree(tree, 3);
  EXPECT_NE(MessageOf([&] { path.Cut(-1.0, 10.0); }).find("start -1 mm"), std::string::npos);
  EXPECT_NE(MessageOf([&] { path.Cut(20.0, 10.0); }).find("end 10 mm"), std::string::npos);
  EXPECT_NE(MessageOf([&] { path.Cut(0.0, 1000.0); }).find("end 1000 mm"), std::string::npos);
  EXPECT_NE(MessageOf([&] { path.Cut(std::nan(""), 10.0); }).find("start nan"), std::string::npos);
  const std::string shortPath = MessageOf([&] { path.Cut(0.0, 1.5).SampleArcLengths(2.0); });
  EXPECT_NE(shortPath.find("shorter than one section of 2 mm"), std::string::npos) << shortPath;
  EXPECT_NE(MessageOf([&] { path.SampleArcLengths(0.0); }).find("step 0 mm"), std::string::npos);
  EXPECT_NE(MessageOf([&] { path.SampleArcLengths(std::nan("")); }).find("step nan mm"), std::string::npos);
  const itk::CPRViewGeometry view;
  EXPECT_NE(MessageOf([&] { itk::RotationMinimizingFrame::Compute(path, 1.0, view, INFINITY); }).find("roll angle inf"),
            std::string::npos);
}

TEST(VesselPath, RunoffPhantomPathsAreContinuousAndTheDefaultIsTheLongest)
{
  auto       source = itk::RunoffPhantomImageSource::New();
  const auto tree = source->GetCenterlineTree();
  const auto longest = itk::VesselPath::FromTree(tree);
  std::cout << "run-off phantom: default path through branches";
  for (const int id : longest.GetBranchChain())
  {
    std::cout << " " << id;
  }
  std::cout << ", " << longest.GetLength() << " mm" << std::endl;
  EXPECT_GE(longest.GetBranchChain().size(), 2u);
  const double gap = LargestSpacing(tree) + itk::VesselPath::JunctionTolerance;
  for (const auto & branch : tree.GetBranches())
  {
    const auto path = itk::VesselPath::FromTree(tree, branch.Id);
    EXPECT_LE(path.GetLength(), longest.GetLength()) << "the path to branch " << branch.Id << " is longer";
    EXPECT_EQ(path.GetBranchChain().back(), branch.Id);
    EXPECT_EQ(path.GetPoints().back(), branch.Points.back()) << "the path to branch " << branch.Id;
    ExpectContinuous(path, gap);
  }
}

TEST(VesselPath, VMTKAortaPathRunsFromTheTrunkIntoTheLongerIliac)
{
  const std::string folder = vr::test::AortaDataFolder();
  ASSERT_FALSE(folder.empty())
    << "VMTK's aorta (vmtk-aorta-mra) is missing from VR_SHARED_DATA_DIR (Testing/Data by default)";
  const itk::CenterlineTree tree = vr::ReadCenterlines(folder + "/aorta-centerline.vtp");
  ASSERT_EQ(tree.GetNumberOfBranches(), 3u);
  const auto longest = itk::VesselPath::FromTree(tree);
  ASSERT_EQ(longest.GetBranchChain().size(), 2u) << "trunk and one iliac";
  ASSERT_TRUE(longest.HasRadii());
  const double gap = LargestSpacing(tree) + itk::VesselPath::JunctionTolerance;
  ExpectContinuous(longest, gap);
  for (const auto & branch : tree.GetBranches())
  {
    const auto path = itk::VesselPath::FromTree(tree, branch.Id);
    EXPECT_LE(path.GetLength(), longest.GetLength());
    ExpectContinuous(path, gap);
    const auto sections = itk::RotationMinimizingFrame::Compute(path, 0.5, itk::CPRViewGeometry());
    for (const auto & section : sections)
    {
      EXPECT_TRUE(std::isfinite(section.Radius) && section.Radius > 0.0) << "at s = " << section.ArcLength;
    }
    double largestCurvature = 0.0;
    for (const auto & k : itk::RotationMinimizingFrame::CurvatureVectors(sections))
    {
      largestCurvature = std::max(largestCurvature, k.GetNorm());
    }
    std::cout << "aorta: path to branch " << branch.Id << ", " << path.GetLength() << " mm, smallest radius of "
              << "curvature " << 1.0 / largestCurvature << " mm" << std::endl;
    // With the tangent's default 2 mm window the centerline's wiggle (radii of curvature of 1.5-2.3 mm at the
    // point spacing, 0.3 mm) no longer reads as a bend tighter than the aorta's own lumen.
    EXPECT_GT(1.0 / largestCurvature, 5.0);
  }
}

TEST(RotationMinimizingFrame, StartsLikeTheTreeViewAnteriorUp)
{
  // A vessel running down (inferior) in the default view: Lateral = screen-right u = LPS +x, Up = anterior (-y).
  const auto path = itk::VesselPath::FromTree(Tree({ Line(1, P(0, 0, 0), P(0, 5, -100)) }));
  const auto sections = itk::RotationMinimizingFrame::Compute(path, 1.0, itk::CPRViewGeometry());
  EXPECT_NEAR((sections[0].Lateral - V(1, 0, 0)).GetNorm(), 0.0, 1e-12);
  EXPECT_LT(sections[0].Up[1], -0.99);
  // Straight: every section has the same frame.
  for (const auto & section : sections)
  {
    EXPECT_NEAR((section.Lateral - sections[0].Lateral).GetNorm(), 0.0, 1e-12);
    EXPECT_NEAR((section.Up - sections[0].Up).GetNorm(), 0.0, 1e-12);
  }
  // A vessel along u itself: Up comes from the view direction (towards the viewer, anterior).
  const VectorType lateral = itk::RotationMinimizingFrame::InitialLateral(V(1, 0, 0), itk::CPRViewGeometry());
  const VectorType up = Cross(V(1, 0, 0), lateral);
  EXPECT_NEAR((up - V(0, -1, 0)).GetNorm(), 0.0, 1e-12);
  // A view turned by 90 degrees about superior: u turns with it.
  const itk::CPRViewGeometry turned(
    V(0, 0, 1), 90.0, P(0, 0, 0), itk::Size<2>{ { 8, 8 } }, itk::Vector<double, 2>(1.0));
  const auto   turnedSections = itk::RotationMinimizingFrame::Compute(path, 1.0, turned);
  const double along = turned.GetU() * sections[0].Tangent;
  EXPECT_NEAR(turnedSections[0].Lateral * turned.GetU(), std::sqrt(1.0 - along * along), 1e-12);
}

TEST(RotationMinimizingFrame, RollTurnsLateralTowardsUp)
{
  const auto path = itk::VesselPath::FromTree(Tree({ Line(1, P(0, 0, 0), P(0, 0, -100)) }));
  const auto plain = itk::RotationMinimizingFrame::Compute(path, 1.0, itk::CPRViewGeometry());
  const auto rolled = itk::RotationMinimizingFrame::Compute(path, 1.0, itk::CPRViewGeometry(), 90.0);
  EXPECT_NEAR((rolled[3].Lateral - plain[3].Up).GetNorm(), 0.0, 1e-12);
  EXPECT_NEAR((rolled[3].Up + plain[3].Lateral).GetNorm(), 0.0, 1e-12);
}

TEST(RotationMinimizingFrame, HelixFrameDoesNotTwistAndMatchesTheAnalyticFrame)
{
  // (R cos t, R sin t, c t): curvature R / (R^2 + c^2), torsion c / (R^2 + c^2). The rotation-minimising normal
  // turns against the Frenet frame at the rate -torsion (d theta / ds = -tau).
  const double R = 20.0;
  const double c = 8.0;
  const double turns = 2.0;
  const double speed = std::sqrt(R * R + c * c);
  const auto   helix = [&](double u)
  {
    const double t = u * 2.0 * M_PI * turns;
    return P(R * std::cos(t), R * std::sin(t), c * t);
  };
  auto path = itk::VesselPath::FromTree(Tree({ Curve(1, helix, 20000) }));
  EXPECT_NEAR(path.GetLength(), 2.0 * M_PI * turns * speed, 1e-3);
  const double tau = c / (R * R + c * c);
  // Largest twist per step against the minimal rotation between tangents, and largest departure from the analytic
  // rotation-minimising frame.
  const auto measure = [&](const itk::VesselPath & measured, double & largestTwist, double & largestAnalytic)
  {
    const auto sections = itk::RotationMinimizingFrame::Compute(measured, 0.5, itk::CPRViewGeometry());
    largestTwist = 0.0;
    largestAnalytic = 0.0;
    double theta0 = 0.0;
    for (std::size_t k = 0; k < sections.size(); ++k)
    {
      const auto & section = sections[k];
      EXPECT_NEAR(section.Lateral.GetNorm(), 1.0, 1e-12);
      EXPECT_NEAR(section.Lateral * section.Tangent, 0.0, 1e-12);
      EXPECT_NEAR((Cross(section.Tangent, section.Lateral) - section.Up).GetNorm(), 0.0, 1e-12);
      if (k > 0)
      {
        largestTwist =
          std::max(largestTwist,
                   std::abs(Twist(sections[k - 1].Tangent, section.Tangent, sections[k - 1].Lateral, section.Lateral)));
      }
      // The analytic Frenet frame at t = s / speed: N points to the axis, B = T x N.
      const double     t = section.ArcLength / speed;
      const VectorType T = V(-R * std::sin(t), R * std::cos(t), c) / speed;
      const VectorType N = V(-std::cos(t), -std::sin(t), 0.0);
      const VectorType B = Cross(T, N);
      const double     theta = std::atan2(section.Lateral * B, section.Lateral * N);
      if (k == 0)
      {
        theta0 = theta;
      }
      largestAnalytic =
        std::max(largestAnalytic, std::abs(std::remainder(theta - (theta0 - tau * section.ArcLength), 2.0 * M_PI)));
    }
  };
  // With the tangent of the sampled helix itself (the chord over its own point spacing).
  path.SetTangentHalfWindow(path.GetLength() / 20000.0);
  double twist;
  double analytic;
  measure(path, twist, analytic);
  std::cout << "helix, own tangent: largest twist " << twist << " rad, largest deviation from the analytic frame "
            << analytic << " rad" << std::endl;
  EXPECT_LT(twist, 1e-6);
  EXPECT_LT(analytic, 1e-3);
  // With the default 2 mm chord, the tangent leans off the sampled helix by about 1e-3 rad; double reflection takes
  // positions and tangents as one curve's, so it departs from the per-step minimal rotation by about 1e-5 rad, and
  // still follows the analytic frame.
  path.SetTangentHalfWindow(itk::VesselPath::DefaultTangentHalfWindow);
  measure(path, twist, analytic);
  std::cout << "helix, 2 mm chord: largest twist " << twist << " rad, largest deviation from the analytic frame "
            << analytic << " rad" << std::endl;
  EXPECT_LT(twist, 1e-4);
  EXPECT_LT(analytic, 1e-3);
}

TEST(RotationMinimizingFrame, NoFlipAtAnInflectionWhereAFrenetFrameFlips)
{
  // x = 15 sin(2 pi z / 120) going down 120 mm: one inflection in the middle, at z = -60.
  const auto scurve = [](double u)
  {
    const double z = -120.0 * u;
    return P(15.0 * std::sin(2.0 * M_PI * z / 120.0), 0.0, z);
  };
  const auto path = itk::VesselPath::FromTree(Tree({ Curve(1, scurve, 12000) }));
  const auto sections = itk::RotationMinimizingFrame::Compute(path, 0.5, itk::CPRViewGeometry());
  const auto curvature = itk::RotationMinimizingFrame::CurvatureVectors(sections);
  double     smallestLateralTurn = 1.0;
  double     smallestFrenetTurn = 1.0;
  double     largestTwist = 0.0;
  for (std::size_t k = 1; k < sections.size(); ++k)
  {
    smallestLateralTurn = std::min(smallestLateralTurn, sections[k - 1].Lateral * sections[k].Lateral);
    largestTwist = std::max(
      largestTwist,
      std::abs(Twist(sections[k - 1].Tangent, sections[k].Tangent, sections[k - 1].Lateral, sections[k].Lateral)));
    // The Frenet normal, the curvature vector's direction (here only, for the comparison).
    if (curvature[k - 1].GetNorm() > 1e-6 && curvature[k].GetNorm() > 1e-6)
    {
      smallestFrenetTurn = std::min(
        smallestFrenetTurn, curvature[k - 1] * curvature[k] / (curvature[k - 1].GetNorm() * curvature[k].GetNorm()));
    }
  }
  std::cout << "S-curve: smallest cosine between consecutive Laterals " << smallestLateralTurn
            << ", between consecutive Frenet normals " << smallestFrenetTurn << std::endl;
  EXPECT_GT(smallestLateralTurn, 0.999) << "the frame turned suddenly";
  EXPECT_LT(smallestFrenetTurn, -0.9) << "a Frenet frame flips at the inflection";
  EXPECT_LT(largestTwist, 1e-6);
  // The curve lies in the frontal plane: Lateral stays in it and Up stays anterior.
  for (const auto & section : sections)
  {
    EXPECT_NEAR(section.Lateral[1], 0.0, 1e-9);
    EXPECT_NEAR(section.Up[1], -1.0, 1e-9);
  }
}
