// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// BilateralDepthRelaxFilter against answers worked out by hand from docs/design.md "Relaxation" (Eq. 1):
//   D'_p = ((1-w)|Omega| D_p + w sum R(D_p - D_q) D_q) / ((1-w)|Omega| + w sum R(D_p - D_q)), R(x) = exp(-a x^2).

#include "itkBilateralDepthRelaxFilter.h"
#include "itkMetaDataObject.h"
#include "itkPoolMultiThreader.h"
#include "vrTestImages.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>
#include <utility>
#include <vector>

namespace
{
using vr::test::DepthImage;
using vr::test::MakeDepthImage;
using vr::test::MakeMaskImage;
using vr::test::MaskImage;
using vr::test::PixelsOf;
using FilterType = itk::BilateralDepthRelaxFilter<DepthImage>;

constexpr double Tolerance = 1e-6;

std::vector<float>
Relax(const DepthImage * depth, const MaskImage * mask, double w, double a, unsigned int iterations)
{
  auto filter = FilterType::New();
  filter->SetInput(depth);
  if (mask)
  {
    filter->SetFixedMask(mask);
  }
  filter->SetRelaxation(w);
  filter->SetAnisotropy(a);
  filter->SetNumberOfIterations(iterations);
  filter->Update();
  return PixelsOf(filter->GetOutput());
}

void
ExpectImageNear(const std::vector<float> & actual, const std::vector<double> & expected)
{
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t k = 0; k < actual.size(); ++k)
  {
    EXPECT_NEAR(actual[k], expected[k], Tolerance) << "pixel " << k;
  }
}

// 3 x 3, a single raised centre:  0 0 0 / 0 1 0 / 0 0 0.
DepthImage::Pointer
CentrePeak()
{
  return MakeDepthImage(3, 3, { 0, 0, 0, 0, 1, 0, 0, 0, 0 });
}

// Expands corner / edge / centre values of a symmetric 3 x 3 image.
std::vector<double>
Symmetric3x3(double corner, double edge, double centre)
{
  return { corner, edge, corner, edge, centre, edge, corner, edge, corner };
}

// 4 x 4, a vertical seam: columns 0, 1 at depth 0 and columns 2, 3 at depth 1.
DepthImage::Pointer
VerticalSeam4x4()
{
  return MakeDepthImage(4, 4, { 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1, 1 });
}

// Expands per-column values (top/bottom row value, middle rows value) of the 4 x 4 seam image.
std::vector<double>
Seam4x4(const std::array<double, 4> & borderRow, const std::array<double, 4> & middleRow)
{
  std::vector<double> values;
  for (int row = 0; row < 4; ++row)
  {
    const auto & source = (row == 0 || row == 3) ? borderRow : middleRow;
    values.insert(values.end(), source.begin(), source.end());
  }
  return values;
}
} // namespace

// (w, a) = (1, 0): plain averaging of the 2, 3 or 4 neighbours.
TEST(BilateralDepthRelaxFilter, CentrePeakLinearOneIteration)
{
  // Corners see two zeros; edges see 0, 0 and the peak: 1/3; the centre sees four zeros.
  ExpectImageNear(Relax(CentrePeak(), nullptr, 1.0, 0.0, 1), Symmetric3x3(0.0, 1.0 / 3.0, 0.0));
}

TEST(BilateralDepthRelaxFilter, CentrePeakLinearTwoIterations)
{
  // Corners: (1/3 + 1/3) / 2; edges: (0 + 0 + 0) / 3; centre: 4 (1/3) / 4.
  ExpectImageNear(Relax(CentrePeak(), nullptr, 1.0, 0.0, 2), Symmetric3x3(1.0 / 3.0, 0.0, 1.0 / 3.0));
}

TEST(BilateralDepthRelaxFilter, CentrePeakLinearWithFixedCentre)
{
  const auto mask = MakeMaskImage(3, 3, { 0, 0, 0, 0, 1, 0, 0, 0, 0 });
  // Iteration 1: edges (0 + 0 + 1) / 3, centre fixed at 1. Iteration 2: corners (1/3 + 1/3) / 2,
  // edges (0 + 0 + 1) / 3, centre still 1.
  ExpectImageNear(Relax(CentrePeak(), mask, 1.0, 0.0, 1), Symmetric3x3(0.0, 1.0 / 3.0, 1.0));
  ExpectImageNear(Relax(CentrePeak(), mask, 1.0, 0.0, 2), Symmetric3x3(1.0 / 3.0, 1.0 / 3.0, 1.0));
}

// (w, a) = (0.5, 0.5): the pixel keeps weight (1-w)|Omega| = 0.5 |Omega|; a unit jump weighs e^-1/2.
TEST(BilateralDepthRelaxFilter, CentrePeakHalfRelaxationOneAndTwoIterations)
{
  const double e = std::exp(-0.5);
  // Edge: (0.5*3*0 + 0.5 e) / (1.5 + 0.5 (2 + e)) = e / (5 + e).
  // Centre: (0.5*4*1 + 0) / (2 + 0.5*4e) = 1 / (1 + e). Corner: all zeros stay 0.
  const double edge1 = e / (5.0 + e);
  const double centre1 = 1.0 / (1.0 + e);
  ExpectImageNear(Relax(CentrePeak(), nullptr, 0.5, 0.5, 1), Symmetric3x3(0.0, edge1, centre1));

  // Iteration 2, from (corner 0, edge e1, centre c1):
  auto R = [](double x) { return std::exp(-0.5 * x * x); };
  // Corner: Dp = 0, two edge neighbours: (0 + 0.5*2 R(e1) e1) / (1 + 0.5*2 R(e1)).
  const double corner2 = R(edge1) * edge1 / (1.0 + R(edge1));
  // Edge: Dp = e1, two corners (0) and the centre (c1), |Omega| = 3.
  const double rCorner = R(edge1);
  const double rCentre = R(edge1 - centre1);
  const double edge2 =
    (1.5 * edge1 + 0.5 * (2 * rCorner * 0.0 + rCentre * centre1)) / (1.5 + 0.5 * (2 * rCorner + rCentre));
  // Centre: Dp = c1, four edges (e1).
  const double rEdge = R(centre1 - edge1);
  const double centre2 = (2.0 * centre1 + 0.5 * 4 * rEdge * edge1) / (2.0 + 0.5 * 4 * rEdge);
  ExpectImageNear(Relax(CentrePeak(), nullptr, 0.5, 0.5, 2), Symmetric3x3(corner2, edge2, centre2));
}

TEST(BilateralDepthRelaxFilter, CentrePeakHalfRelaxationWithFixedCorners)
{
  const auto   mask = MakeMaskImage(3, 3, { 1, 0, 1, 0, 0, 0, 1, 0, 1 });
  const double e = std::exp(-0.5);
  // Fixed corners stay 0; edges and centre move as without the mask in iteration 1 (the corners were 0).
  ExpectImageNear(Relax(CentrePeak(), mask, 0.5, 0.5, 1), Symmetric3x3(0.0, e / (5.0 + e), 1.0 / (1.0 + e)));
}

// (w, a) = (1, 2): a unit jump weighs e^-2, and the pixel itself has no weight.
TEST(BilateralDepthRelaxFilter, CentrePeakStrongAnisotropy)
{
  const double e = std::exp(-2.0);
  // Edge: (e * 1) / (2 + e). Centre: all four neighbours at 0 with weight e each: (4e * 0) / 4e = 0.
  ExpectImageNear(Relax(CentrePeak(), nullptr, 1.0, 2.0, 1), Symmetric3x3(0.0, e / (2.0 + e), 0.0));
  // With the centre fixed, the edges are the same and the centre stays.
  const auto mask = MakeMaskImage(3, 3, { 0, 0, 0, 0, 1, 0, 0, 0, 0 });
  ExpectImageNear(Relax(CentrePeak(), mask, 1.0, 2.0, 1), Symmetric3x3(0.0, e / (2.0 + e), 1.0));
}

// 4 x 4: |Omega| = 2 at corners, 3 on borders, 4 inside, all in one image.
TEST(BilateralDepthRelaxFilter, SeamLinearOneIteration)
{
  // Column 1 (value 0) sees 0, 1 and one or two 0 above/below: 1/3 on the top/bottom rows, 1/4 inside.
  // Column 2 mirrors it: 2/3 and 3/4. Columns 0 and 3 see only their own values.
  ExpectImageNear(Relax(VerticalSeam4x4(), nullptr, 1.0, 0.0, 1),
                  Seam4x4({ 0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0 }, { 0.0, 0.25, 0.75, 1.0 }));
}

TEST(BilateralDepthRelaxFilter, SeamLinearTwoIterations)
{
  // From iteration 1: (0,0): (1/3 + 0)/2 = 1/6; (0,1): (1/4 + 0 + 0)/3 = 1/12;
  // (1,0): (0 + 2/3 + 1/4)/3 = 11/36; (1,1): (0 + 3/4 + 1/3 + 1/4)/4 = 1/3; columns 2, 3 by antisymmetry.
  ExpectImageNear(
    Relax(VerticalSeam4x4(), nullptr, 1.0, 0.0, 2),
    Seam4x4({ 1.0 / 6.0, 11.0 / 36.0, 25.0 / 36.0, 5.0 / 6.0 }, { 1.0 / 12.0, 1.0 / 3.0, 2.0 / 3.0, 11.0 / 12.0 }));
}

TEST(BilateralDepthRelaxFilter, SeamHalfRelaxation)
{
  const double e = std::exp(-0.5);
  // Column 1, border row: (0.5*3*0 + 0.5 e) / (1.5 + 0.5 (2 + e)) = e / (5 + e); middle rows: e / (7 + e).
  const double border = e / (5.0 + e);
  const double middle = e / (7.0 + e);
  ExpectImageNear(Relax(VerticalSeam4x4(), nullptr, 0.5, 0.5, 1),
                  Seam4x4({ 0.0, border, 1.0 - border, 1.0 }, { 0.0, middle, 1.0 - middle, 1.0 }));
}

TEST(BilateralDepthRelaxFilter, SeamStrongAnisotropyWithFixedColumn)
{
  const double e = std::exp(-2.0);
  // Column 1: e / (2 + e) on borders, e / (3 + e) inside; column 2 mirrors: 2/(2+e), 3/(3+e).
  ExpectImageNear(Relax(VerticalSeam4x4(), nullptr, 1.0, 2.0, 1),
                  Seam4x4({ 0.0, e / (2.0 + e), 2.0 / (2.0 + e), 1.0 }, { 0.0, e / (3.0 + e), 3.0 / (3.0 + e), 1.0 }));
  // Fixing column 2 keeps it at 1; column 1 is unchanged from the free case after one iteration.
  const auto mask = MakeMaskImage(4, 4, { 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0 });
  ExpectImageNear(Relax(VerticalSeam4x4(), mask, 1.0, 2.0, 1),
                  Seam4x4({ 0.0, e / (2.0 + e), 1.0, 1.0 }, { 0.0, e / (3.0 + e), 1.0, 1.0 }));
}

TEST(BilateralDepthRelaxFilter, ZeroRelaxationLeavesTheImageAsItWas)
{
  const auto depth = vr::test::MakeRandomDepthImage(37, 23, -50.0f, 50.0f, 7);
  const auto before = PixelsOf(depth.GetPointer());
  const auto after = Relax(depth, nullptr, 0.0, 0.5, 25);
  EXPECT_EQ(0, std::memcmp(before.data(), after.data(), before.size() * sizeof(float)));
}

TEST(BilateralDepthRelaxFilter, FixedPixelsNeverChange)
{
  const auto  depth = vr::test::MakeRandomDepthImage(41, 29, -20.0f, 20.0f, 11);
  const auto  mask = vr::test::MakeRandomMaskImage(41, 29, 0.3, 12);
  const auto  before = PixelsOf(depth.GetPointer());
  const auto  fixed = PixelsOf(mask.GetPointer());
  const auto  after = Relax(depth, mask, 1.0, 0.1, 40);
  std::size_t changedFree = 0;
  for (std::size_t k = 0; k < before.size(); ++k)
  {
    if (fixed[k])
    {
      EXPECT_EQ(before[k], after[k]) << "fixed pixel " << k;
    }
    else
    {
      changedFree += before[k] != after[k];
    }
  }
  EXPECT_GT(changedFree, before.size() / 2) << "free pixels should move";
}

TEST(BilateralDepthRelaxFilter, UnderflowingWeightsKeepTheValue)
{
  // w = 1 and every neighbour 1000 mm away: exp(-a 10^6) underflows, so the sum of weights is 0. The pixel keeps
  // its value instead of computing 0/0. Neighbours are fixed so only the centre and its corner twin are free.
  const auto depth = MakeDepthImage(3, 3, { 1000, 0, 0, 0, 1000, 0, 0, 0, 0 });
  const auto mask = MakeMaskImage(3, 3, { 0, 1, 1, 1, 0, 1, 1, 1, 1 });
  const auto after = Relax(depth, mask, 1.0, 1.0, 3);
  for (const float value : after)
  {
    EXPECT_TRUE(std::isfinite(value));
  }
  EXPECT_EQ(after[0], 1000.0f) << "corner: both weights underflow";
  EXPECT_EQ(after[4], 1000.0f) << "centre: all four weights underflow";
}

TEST(BilateralDepthRelaxFilter, OneAndTwoThreadsGiveIdenticalBits)
{
  const auto depth = vr::test::MakeRandomDepthImage(512, 1024, -30.0f, 30.0f, 3);
  const auto mask = vr::test::MakeRandomMaskImage(512, 1024, 0.05, 4);
  auto       run = [&](unsigned int workUnits)
  {
    auto filter = FilterType::New();
    filter->SetInput(depth);
    filter->SetFixedMask(mask);
    filter->SetRelaxation(1.0);
    filter->SetAnisotropy(0.5);
    filter->SetNumberOfIterations(50);
    filter->SetNumberOfWorkUnits(workUnits);
    filter->Update();
    return PixelsOf(filter->GetOutput());
  };
  const auto one = run(1);
  const auto two = run(2);
  ASSERT_EQ(one.size(), two.size());
  EXPECT_EQ(0, std::memcmp(one.data(), two.data(), one.size() * sizeof(float)));
  EXPECT_NE(0, std::memcmp(one.data(), PixelsOf(depth.GetPointer()).data(), one.size() * sizeof(float)));
}

// ITK's pool threader gives a filter four work units per thread, and its maximum is the process's one pool, which
// only grows: after another threader asked for more threads than the cores, a filter left at ITK's defaults took
// min(4 x cores, pool) threads, and its teams shared cores. Its default team is one thread per ITK default thread;
// work units that are set are honoured up to the threader's maximum.
TEST(BilateralDepthRelaxFilter, DefaultTeamStaysOneThreadPerCoreAfterAnotherThreaderGrewITKsPool)
{
  const unsigned int cores = itk::MultiThreaderBase::GetGlobalDefaultNumberOfThreads();
  auto               grower = itk::PoolMultiThreader::New();
  grower->SetMaximumNumberOfThreads(4 * cores + 4);
  auto filter = FilterType::New();
  ASSERT_NE(dynamic_cast<itk::PoolMultiThreader *>(filter->GetMultiThreader()), nullptr)
    << "the premise: ITK's default threader is the pool one";
  ASSERT_GE(filter->GetMultiThreader()->GetMaximumNumberOfThreads(), 4 * cores + 4) << "the premise: the pool grew";
  EXPECT_EQ(filter->GetNumberOfHostThreads(), cores);

  filter->SetNumberOfWorkUnits(cores + 3);
  EXPECT_EQ(filter->GetNumberOfHostThreads(), cores + 3);
  filter->SetNumberOfWorkUnits(1);
  EXPECT_EQ(filter->GetNumberOfHostThreads(), 1u);
  // A team asked for may have as many threads as ITK's default work units (4 x cores with more than one core): the
  // thread-count tests' 8 threads on 2 cores.
  auto               asked = FilterType::New();
  const unsigned int itkDefault = asked->GetNumberOfWorkUnits();
  asked->SetNumberOfWorkUnits(itkDefault);
  EXPECT_EQ(asked->GetNumberOfHostThreads(), itkDefault);
  // Through the base class too (ITK's setter is virtual).
  auto                 viaBase = FilterType::New();
  itk::ProcessObject & base = *viaBase;
  base.SetNumberOfWorkUnits(cores + 2);
  EXPECT_EQ(viaBase->GetNumberOfHostThreads(), cores + 2);
}

namespace
{
// Runs the filter expecting an itk::ExceptionObject whose message contains every word of \a names.
void
ExpectRejected(FilterType * filter, const std::vector<std::string> & names)
{
  try
  {
    filter->Update();
    ADD_FAILURE() << "no exception";
  }
  catch (const itk::ExceptionObject & error)
  {
    for (const auto & name : names)
    {
      EXPECT_NE(std::string(error.GetDescription()).find(name), std::string::npos)
        << "message \"" << error.GetDescription() << "\" does not name " << name;
    }
  }
}

FilterType::Pointer
ValidFilter()
{
  auto filter = FilterType::New();
  filter->SetInput(vr::test::MakeRandomDepthImage(5, 4, 0.0f, 1.0f, 1));
  filter->SetNumberOfIterations(2);
  return filter;
}
} // namespace

TEST(BilateralDepthRelaxFilter, RejectsBadParameters)
{
  auto filter = ValidFilter();
  filter->SetRelaxation(-0.1);
  ExpectRejected(filter, { "Relaxation", "-0.1" });

  filter = ValidFilter();
  filter->SetRelaxation(1.1);
  ExpectRejected(filter, { "Relaxation", "1.1" });

  filter = ValidFilter();
  filter->SetAnisotropy(-1.0);
  ExpectRejected(filter, { "Anisotropy", "-1" });

  filter = ValidFilter();
  filter->SetRelaxation(std::numeric_limits<double>::quiet_NaN());
  ExpectRejected(filter, { "Relaxation", "nan" });

  filter = ValidFilter();
  filter->SetAnisotropy(std::numeric_limits<double>::infinity());
  ExpectRejected(filter, { "Anisotropy", "inf" });

  for (const double jump : { 0.0, -2.0, std::numeric_limits<double>::infinity(), std::nan("") })
  {
    filter = ValidFilter();
    filter->SetJumpThreshold(jump);
    std::ostringstream value;
    value << jump;
    ExpectRejected(filter, { "JumpThreshold", value.str(), "mm" });
  }

  filter = ValidFilter();
  filter->SetSolver(itk::BilateralDepthRelaxSolver::Steady);
  filter->SetSteadyTolerance(0.0);
  ExpectRejected(filter, { "SteadyTolerance", "0" });
}

// The range kernel by meaning: J in mm and the paper's a = 1/J^2 are two views of one parameter; either setter sets
// both, and the default is J = 3 mm.
TEST(BilateralDepthRelaxFilter, JumpThresholdAndAnisotropyAreOneParameter)
{
  auto filter = FilterType::New();
  EXPECT_EQ(filter->GetJumpThreshold(), 3.0);
  EXPECT_DOUBLE_EQ(filter->GetAnisotropy(), 1.0 / 9.0);
  filter->SetJumpThreshold(2.0);
  EXPECT_EQ(filter->GetAnisotropy(), 0.25);
  filter->SetAnisotropy(0.5);
  EXPECT_DOUBLE_EQ(filter->GetJumpThreshold(), std::sqrt(2.0));
  filter->SetAnisotropy(0.0);
  EXPECT_EQ(filter->GetJumpThreshold(), std::numeric_limits<double>::infinity());

  // The same relaxation either way: the row 0, 0, 2 of RangeWeightWorkedByHand with R(2) = 1/2, that is
  // J = 2 / sqrt(ln 2) mm or a = ln 2 / 4 mm^-2.
  const auto depth = MakeDepthImage(3, 1, { 0.0f, 0.0f, 2.0f });
  auto       byJump = FilterType::New();
  byJump->SetInput(depth);
  byJump->SetJumpThreshold(2.0 / std::sqrt(std::log(2.0)));
  byJump->SetNumberOfIterations(1);
  byJump->Update();
  EXPECT_NEAR(PixelsOf(byJump->GetOutput())[1], 2.0 / 3.0, Tolerance);
  EXPECT_EQ(PixelsOf(byJump->GetOutput()), Relax(depth, nullptr, 1.0, std::log(2.0) / 4.0, 1));

  // Setting a value equal to the current one changes nothing, by either parametrisation (nothing reruns).
  const auto time = byJump->GetMTime();
  byJump->SetJumpThreshold(2.0 / std::sqrt(std::log(2.0)));
  byJump->SetAnisotropy(byJump->GetAnisotropy());
  EXPECT_EQ(byJump->GetMTime(), time);
  byJump->SetJumpThreshold(2.0);
  EXPECT_GT(byJump->GetMTime(), time);
}

// The steady solver through the filter: on the 3 x 3 cross worked by hand (IsotropicCentreIsTheMeanOfItsNeighbours
// of the solver's suite) the centre is the mean of its neighbours; w and N change nothing; fixed pixels keep their
// values; the filter reports what the solve did; a double image gives the same values.
TEST(BilateralDepthRelaxFilter, SteadySolverGivesTheFixedPointWhateverWAndN)
{
  const auto         depth = MakeDepthImage(3, 3, { 0, 4, 0, 0, 9, 0, 0, 0, 0 });
  const auto         mask = MakeMaskImage(3, 3, { 1, 1, 1, 1, 0, 1, 1, 1, 1 });
  std::vector<float> first;
  for (const auto & [w, n] : { std::pair<double, unsigned int>{ 1.0, 500 }, { 0.3, 1 }, { 0.0, 0 } })
  {
    auto filter = FilterType::New();
    filter->SetInput(depth);
    filter->SetFixedMask(mask);
    filter->SetAnisotropy(0.0);
    filter->SetRelaxation(w);
    filter->SetNumberOfIterations(n);
    filter->SetSolver(itk::BilateralDepthRelaxSolver::Steady);
    filter->Update();
    const auto relaxed = PixelsOf(filter->GetOutput());
    EXPECT_NEAR(relaxed[4], 1.0, 1e-4) << "w = " << w << ", N = " << n;
    EXPECT_EQ(relaxed[1], 4.0f);
    EXPECT_LE(filter->GetSteadyReport().Residual, filter->GetSteadyTolerance());
    first = first.empty() ? relaxed : first;
    EXPECT_EQ(relaxed, first);
  }

  using DoubleImage = itk::Image<double, 2>;
  auto doubleDepth = DoubleImage::New();
  doubleDepth->SetRegions(depth->GetLargestPossibleRegion());
  doubleDepth->Allocate();
  std::copy_n(depth->GetBufferPointer(), 9, doubleDepth->GetBufferPointer());
  auto generic = itk::BilateralDepthRelaxFilter<DoubleImage>::New();
  generic->SetInput(doubleDepth);
  generic->SetFixedMask(mask);
  generic->SetAnisotropy(0.0);
  generic->SetSolver(itk::BilateralDepthRelaxSolver::Steady);
  generic->Update();
  EXPECT_NEAR(generic->GetOutput()->GetBufferPointer()[4], 1.0, 1e-4);
  EXPECT_EQ(generic->GetOutput()->GetBufferPointer()[1], 4.0);
}

TEST(BilateralDepthRelaxFilter, RejectsANonFiniteDepth)
{
  auto filter = FilterType::New();
  filter->SetInput(MakeDepthImage(3, 2, { 0, 1, 2, 3, std::numeric_limits<float>::quiet_NaN(), 5 }));
  ExpectRejected(filter, { "Depth", "nan", "[1, 1]" });
}

TEST(BilateralDepthRelaxFilter, RejectsAMaskOfAnotherSize)
{
  auto filter = ValidFilter();
  filter->SetFixedMask(MakeMaskImage(4, 4, std::vector<unsigned char>(16, 0)));
  ExpectRejected(filter, { "FixedMask", "[4, 4]", "[5, 4]" });
}

TEST(BilateralDepthRelaxFilter, PassesTheViewMetadataOn)
{
  auto depth = CentrePeak();
  itk::EncapsulateMetaData<std::string>(depth->GetMetaDataDictionary(), "CPR_AngleDegrees", "30");
  auto filter = FilterType::New();
  filter->SetInput(depth);
  filter->SetNumberOfIterations(1);
  filter->Update();
  std::string angle;
  EXPECT_TRUE(
    itk::ExposeMetaData<std::string>(filter->GetOutput()->GetMetaDataDictionary(), "CPR_AngleDegrees", angle));
  EXPECT_EQ(angle, "30");
}
