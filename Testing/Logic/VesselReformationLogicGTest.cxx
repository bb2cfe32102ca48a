// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The module logic: nodes to ITK (RAS <-> LPS), the recompute rules of docs/design.md 3.7, warnings, parameter checks.

#include "itkCPRVectorHelpers.h"
#include "vrCoordinateFrames.h"
#include "vrCutSurface.h"
#include "vrInputError.h"
#include "vrNodeConversion.h"
#include "vrVesselReformationLogic.h"
#include "vrCenterlineVolumeFit.h"

#include "PlainBilateralDepthRelax.h"
#include "vrTestImages.h"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <array>
#include <functional>
#include <cmath>
#include <string>
#include <vector>

namespace
{
using vr::ReformationParameters;
using vr::VesselReformationLogic;

constexpr float  Lumen = 1000.0f;
constexpr float  Background = 100.0f;
constexpr double LumenRadius = 3.0;

/** A polyline given in LPS, stored in RAS as a platform would hand it over. */
struct Polyline
{
  std::vector<std::array<double, 3>> PointsLPS;
};

/** Distance from \a p to the segment a-b. */
double
DistanceToSegment(const std::array<double, 3> & p, const std::array<double, 3> & a, const std::array<double, 3> & b)
{
  double ab[3];
  double ap[3];
  double lengthSquared = 0.0;
  double dot = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    ab[k] = b[k] - a[k];
    ap[k] = p[k] - a[k];
    lengthSquared += ab[k] * ab[k];
    dot += ab[k] * ap[k];
  }
  const double t = lengthSquared > 0.0 ? std::clamp(dot / lengthSquared, 0.0, 1.0) : 0.0;
  double       distanceSquared = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const double d = ap[k] - t * ab[k];
    distanceSquared += d * d;
  }
  return std::sqrt(distanceSquared);
}

/** Two vessels, a straight trunk along z and a branch leaving it, in LPS mm. */
std::vector<Polyline>
TwoVessels()
{
  Polyline trunk;
  for (int z = 5; z <= 45; z += 2)
  {
    trunk.PointsLPS.push_back({ 15.0, 20.0, static_cast<double>(z) });
  }
  Polyline branch;
  for (int step = 0; step <= 10; ++step)
  {
    branch.PointsLPS.push_back({ 15.0 + 1.3 * step, 20.0 + 0.6 * step, 25.0 + 2.0 * step });
  }
  return { trunk, branch };
}

/** A 40 x 40 x 50 volume with 1 mm voxels whose IJK->RAS is diag(-1, -1, 1): voxel (i, j, k) lies at LPS
 * (i, j, k). Lumen intensity within LumenRadius of the vessels, background elsewhere. */
vtkSmartPointer<vr::VolumeNode>
MakeVolumeNode(const std::vector<Polyline> & vessels)
{
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetExtent(0, 39, 0, 39, 0, 49);
  data->AllocateScalars(VTK_SHORT, 1);
  auto * voxels = static_cast<short *>(data->GetScalarPointer());
  for (int k = 0; k < 50; ++k)
  {
    for (int j = 0; j < 40; ++j)
    {
      for (int i = 0; i < 40; ++i)
      {
        double distance = 1e9;
        for (const auto & vessel : vessels)
        {
          for (std::size_t s = 0; s + 1 < vessel.PointsLPS.size(); ++s)
          {
            distance = std::min(
              distance,
              DistanceToSegment({ double(i), double(j), double(k) }, vessel.PointsLPS[s], vessel.PointsLPS[s + 1]));
          }
        }
        voxels[(k * 40 + j) * 40 + i] = static_cast<short>(distance <= LumenRadius ? Lumen : Background);
      }
    }
  }
  auto matrix = vtkSmartPointer<vtkMatrix4x4>::New();
  matrix->SetElement(0, 0, -1.0);
  matrix->SetElement(1, 1, -1.0);
  auto node = vtkSmartPointer<vr::VolumeNode>::New();
  node->SetName("two-vessels");
  node->SetImageData(data);
  node->SetIJKToRASMatrix(matrix);
  return node;
}

/** The vessels as a centerline node: polylines in RAS with a "Radius" array. With \a forgetRAS the LPS
 * coordinates are stored as they are, the classic mistake. */
vtkSmartPointer<vr::CenterlineNode>
MakeCenterlineNode(const std::vector<Polyline> & vessels, bool forgetRAS = false)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  auto radii = vtkSmartPointer<vtkDoubleArray>::New();
  radii->SetName("Radius");
  for (const auto & vessel : vessels)
  {
    lines->InsertNextCell(static_cast<vtkIdType>(vessel.PointsLPS.size()));
    for (const auto & p : vessel.PointsLPS)
    {
      const double sign = forgetRAS ? 1.0 : -1.0;
      lines->InsertCellPoint(points->InsertNextPoint(sign * p[0], sign * p[1], p[2]));
      radii->InsertNextValue(LumenRadius);
    }
  }
  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetLines(lines);
  polyData->GetPointData()->AddArray(radii);
  auto node = vtkSmartPointer<vr::CenterlineNode>::New();
  node->SetName("two-vessels-centerlines");
  node->SetPolyData(polyData);
  return node;
}

itk::Point<double, 3>
MakePoint(double x, double y, double z)
{
  itk::Point<double, 3> point;
  point[0] = x;
  point[1] = y;
  point[2] = z;
  return point;
}

ReformationParameters
QuickParameters()
{
  ReformationParameters parameters;
  parameters.Iterations = 30;
  parameters.Backend = vr::RelaxBackend::CPU;
  return parameters;
}

class VesselReformationLogicTest : public ::testing::Test
{
protected:
  void
  SetUp() override
  {
    m_Vessels = TwoVessels();
    m_Volume = MakeVolumeNode(m_Vessels);
    m_Centerlines = MakeCenterlineNode(m_Vessels);
    m_Logic.SetVolumeNode(m_Volume);
    m_Logic.SetCenterlineNode(m_Centerlines);
    m_Logic.SetParameters(QuickParameters());
  }

  std::vector<Polyline>               m_Vessels;
  vtkSmartPointer<vr::VolumeNode>     m_Volume;
  vtkSmartPointer<vr::CenterlineNode> m_Centerlines;
  VesselReformationLogic              m_Logic;
};

void
ExpectCounts(const vr::StageCounts & counts,
             unsigned                depth,
             unsigned                relax,
             unsigned                resample,
             unsigned                unfiltered,
             unsigned                relaxed)
{
  EXPECT_EQ(counts.Depth, depth);
  EXPECT_EQ(counts.Relax, relax);
  EXPECT_EQ(counts.Resample, resample);
  EXPECT_EQ(counts.UnfilteredSamplings, unfiltered);
  EXPECT_EQ(counts.RelaxedSamplings, relaxed);
}

TEST_F(VesselReformationLogicTest, RecomputesOnlyWhatAChangeInvalidates)
{
  m_Logic.Update();
  ExpectCounts(m_Logic.GetStageExecutionCounts(), 1, 1, 1, 1, 1);
  EXPECT_EQ(m_Logic.GetStageExecutionCounts().Conversion, 1u);
  EXPECT_EQ(m_Logic.GetStageExecutionCounts().Surface, 1u);

  // Unchanged parameters: nothing reruns.
  m_Logic.SetParameters(m_Logic.GetParameters());
  m_Logic.Update();
  ExpectCounts(m_Logic.GetStageExecutionCounts(), 1, 1, 1, 1, 1);
  EXPECT_EQ(m_Logic.GetStageExecutionCounts().Surface, 1u);

  // A new w: relax and the relaxed CPR, not depth, not the unfiltered CPR.
  ReformationParameters parameters = m_Logic.GetParameters();
  parameters.Relaxation = 0.5;
  m_Logic.SetParameters(parameters);
  m_Logic.Update();
  ExpectCounts(m_Logic.GetStageExecutionCounts(), 1, 2, 2, 1, 2);
  EXPECT_EQ(m_Logic.GetStageExecutionCounts().Surface, 2u);

  // A new a, then a new N: the same.
  parameters.Anisotropy = 2.0;
  m_Logic.SetParameters(parameters);
  m_Logic.Update();
  parameters.Iterations = 10;
  m_Logic.SetParameters(parameters);
  m_Logic.Update();
  ExpectCounts(m_Logic.GetStageExecutionCounts(), 1, 4, 4, 1, 4);

  // A new angle: all three.
  parameters.AngleInDegrees = 30.0;
  m_Logic.SetParameters(parameters);
  m_Logic.Update();
  ExpectCounts(m_Logic.GetStageExecutionCounts(), 2, 5, 5, 2, 5);

  // A new window and level: nothing.
  parameters.Window = 400.0;
  parameters.Level = 500.0;
  m_Logic.SetParameters(parameters);
  m_Logic.Update();
  ExpectCounts(m_Logic.GetStageExecutionCounts(), 2, 5, 5, 2, 5);
  double window = 0.0;
  double level = 0.0;
  m_Logic.GetDisplayWindowLevel(window, level);
  EXPECT_EQ(window, 400.0);
  EXPECT_EQ(level, 500.0);

  // A new interpolation: both CPR images, no depth, no relax.
  parameters.Interpolation = itk::CPRInterpolationMode::Nearest;
  m_Logic.SetParameters(parameters);
  m_Logic.Update();
  ExpectCounts(m_Logic.GetStageExecutionCounts(), 2, 5, 6, 3, 6);

  // A new slab: the same.
  parameters.SlabThickness = 2.0;
  m_Logic.SetParameters(parameters);
  m_Logic.Update();
  ExpectCounts(m_Logic.GetStageExecutionCounts(), 2, 5, 7, 4, 7);

  // A new mode: everything.
  parameters.Mode = itk::CPRDepthMode::Nearest;
  m_Logic.SetParameters(parameters);
  m_Logic.Update();
  ExpectCounts(m_Logic.GetStageExecutionCounts(), 3, 6, 8, 5, 8);

  // Modified centerlines (the platform edited the polydata): conversion and everything.
  m_Centerlines->GetPolyData()->GetPoints()->SetPoint(0, -15.0, -20.0, 6.0);
  m_Centerlines->GetPolyData()->GetPoints()->Modified();
  m_Logic.Update();
  ExpectCounts(m_Logic.GetStageExecutionCounts(), 4, 7, 9, 6, 9);
  EXPECT_EQ(m_Logic.GetStageExecutionCounts().Conversion, 2u);

  // Another volume node of the same geometry (another phase of the scan): conversion and resampling only; the
  // depth map and its relaxation depend on the volume's geometry alone.
  m_Logic.SetVolumeNode(MakeVolumeNode(m_Vessels));
  m_Logic.Update();
  ExpectCounts(m_Logic.GetStageExecutionCounts(), 4, 7, 10, 7, 10);
  EXPECT_EQ(m_Logic.GetStageExecutionCounts().Conversion, 3u);

  // A volume of another spacing changes the view's default pixel spacing: everything.
  auto finer = MakeVolumeNode(m_Vessels);
  auto matrix = vtkSmartPointer<vtkMatrix4x4>::New();
  matrix->DeepCopy(finer->GetIJKToRASMatrix());
  matrix->SetElement(2, 2, 0.9);
  finer->SetIJKToRASMatrix(matrix);
  m_Logic.SetVolumeNode(finer);
  m_Logic.Update();
  ExpectCounts(m_Logic.GetStageExecutionCounts(), 5, 8, 11, 8, 11);
}

TEST_F(VesselReformationLogicTest, KeepsOneFilterOfEachKindAcrossParameterChanges)
{
  m_Logic.Update();
  // Held here, so a filter made anew could not reuse a freed one's address.
  const itk::ProcessObject::Pointer depth = m_Logic.GetDepthFilter();
  const itk::ProcessObject::Pointer relax = m_Logic.GetRelaxFilter();
  const itk::ProcessObject::Pointer unfiltered = m_Logic.GetUnfilteredResampleFilter();
  const itk::ProcessObject::Pointer resample = m_Logic.GetResampleFilter();
  ASSERT_TRUE(depth && relax && unfiltered && resample);

  ReformationParameters                    parameters = m_Logic.GetParameters();
  const std::vector<std::function<void()>> changes = {
    [&] { parameters.AngleInDegrees = 45.0; }, [&] { parameters.Relaxation = 0.7; },
    [&] { parameters.Iterations = 12; },       [&] { parameters.Mode = itk::CPRDepthMode::Nearest; },
    [&] { parameters.SlabThickness = 1.5; },
  };
  unsigned int updates = 1;
  for (const auto & change : changes)
  {
    change();
    m_Logic.SetParameters(parameters);
    m_Logic.Update();
    ++updates;
    EXPECT_EQ(m_Logic.GetDepthFilter(), depth.GetPointer());
    EXPECT_EQ(m_Logic.GetRelaxFilter(), relax.GetPointer());
    EXPECT_EQ(m_Logic.GetUnfilteredResampleFilter(), unfiltered.GetPointer());
    EXPECT_EQ(m_Logic.GetResampleFilter(), resample.GetPointer());
  }
  // Every change reran something, so the same filters did the work.
  EXPECT_EQ(m_Logic.GetStageExecutionCounts().RelaxedSamplings, updates);
}

TEST_F(VesselReformationLogicTest, AbortUpdateStopsTheRelaxationAndTheNextUpdateRecovers)
{
  ReformationParameters parameters = m_Logic.GetParameters();
  parameters.Iterations = 100000; // far longer than the test waits
  m_Logic.SetParameters(parameters);
  unsigned int relaxReports = 0;
  m_Logic.SetProgressCallback(
    [&](double, const std::string & stage)
    {
      if (stage == "relax" && ++relaxReports == 3)
      {
        m_Logic.AbortUpdate();
      }
    });
  EXPECT_THROW(m_Logic.Update(), vr::Cancelled);
  EXPECT_LT(relaxReports, 10u) << "the relaxation went on after the abort";
  EXPECT_EQ(m_Logic.GetStageExecutionCounts().RelaxedSamplings, 0u);

  // Without an abort the same logic finishes, and gives what a fresh logic gives.
  m_Logic.SetProgressCallback({});
  parameters.Iterations = 40;
  m_Logic.SetParameters(parameters);
  const auto             kept = vr::ConvertVolumeNodeToDepthImage(m_Logic.Update().CPR);
  VesselReformationLogic fresh;
  fresh.SetVolumeNode(m_Volume);
  fresh.SetCenterlineNode(m_Centerlines);
  fresh.SetParameters(parameters);
  const auto reference = vr::ConvertVolumeNodeToDepthImage(fresh.Update().CPR);
  const auto count = reference->GetBufferedRegion().GetNumberOfPixels();
  ASSERT_EQ(kept->GetBufferedRegion().GetNumberOfPixels(), count);
  EXPECT_TRUE(
    std::equal(reference->GetBufferPointer(), reference->GetBufferPointer() + count, kept->GetBufferPointer()));

  // An abort asked for outside an update is forgotten.
  m_Logic.AbortUpdate();
  parameters.Iterations = 41;
  m_Logic.SetParameters(parameters);
  EXPECT_NO_THROW(m_Logic.Update());
}

// A backend choice that keeps the relax filter reruns nothing (cpu -> auto on a CPU device: the same CPU filter); one
// that changes it reruns relax and resample (-> opencl, where this machine has a usable OpenCL device).
TEST_F(VesselReformationLogicTest, NewBackendRerunsRelaxAndResample)
{
  m_Logic.Update();
  ReformationParameters parameters = m_Logic.GetParameters();
  parameters.Backend = vr::RelaxBackend::Auto;
  m_Logic.SetParameters(parameters);
  m_Logic.SetOpenCLDeviceQuery([](const std::string &) { return vr::OpenCLDeviceKind{ "", "0:0 stub", "CPU" }; });
  m_Logic.Update();
  EXPECT_EQ(m_Logic.GetOutputs().RelaxBackendUsed, "cpu");
  ExpectCounts(m_Logic.GetStageExecutionCounts(), 1, 1, 1, 1, 1);

  std::string whyNot;
  if (vr::TryCreateOpenCLRelaxFilter("", whyNot))
  {
    parameters.Backend = vr::RelaxBackend::OpenCL;
    m_Logic.SetParameters(parameters);
    m_Logic.Update();
    EXPECT_EQ(m_Logic.GetOutputs().RelaxBackendUsed, "opencl");
    ExpectCounts(m_Logic.GetStageExecutionCounts(), 1, 2, 2, 1, 2);
  }
}

TEST_F(VesselReformationLogicTest, SurfaceIsBuiltOnlyWhenEnabled)
{
  m_Logic.SetSurfaceEnabled(false);
  const auto & outputs = m_Logic.Update();
  EXPECT_EQ(outputs.Surface, nullptr);
  EXPECT_EQ(m_Logic.GetStageExecutionCounts().Surface, 0u);
  m_Logic.SetSurfaceEnabled(true);
  m_Logic.Update();
  ASSERT_NE(m_Logic.GetOutputs().Surface, nullptr);
  EXPECT_EQ(m_Logic.GetStageExecutionCounts().Surface, 1u);
  ExpectCounts(m_Logic.GetStageExecutionCounts(), 1, 1, 1, 1, 1);
}

TEST_F(VesselReformationLogicTest, CenterlinePixelsShowLumenAndFixedPixelsKeepTheirValue)
{
  ReformationParameters parameters = m_Logic.GetParameters();
  parameters.FixLumen = false; // the mask is then exactly the centerline pixels
  parameters.Iterations = 200;
  m_Logic.SetParameters(parameters);
  const auto & outputs = m_Logic.Update();
  auto         mask = vr::ConvertVolumeNodeToMaskImage(outputs.FixedMask);
  auto         depth = vr::ConvertVolumeNodeToDepthImage(outputs.Depth);
  auto         relaxed = vr::ConvertVolumeNodeToDepthImage(outputs.RelaxedDepth);
  auto         unfiltered = vr::ConvertVolumeNodeToDepthImage(outputs.UnfilteredCPR);
  auto         cpr = vr::ConvertVolumeNodeToDepthImage(outputs.CPR);
  const auto   count = mask->GetBufferedRegion().GetNumberOfPixels();
  std::size_t  fixed = 0;
  std::size_t  moved = 0;
  for (std::size_t k = 0; k < count; ++k)
  {
    if (mask->GetBufferPointer()[k])
    {
      ++fixed;
      EXPECT_EQ(relaxed->GetBufferPointer()[k], depth->GetBufferPointer()[k]) << "pixel " << k;
      EXPECT_EQ(cpr->GetBufferPointer()[k], unfiltered->GetBufferPointer()[k]) << "pixel " << k;
      EXPECT_GT(cpr->GetBufferPointer()[k], 0.5f * (Lumen + Background)) << "centerline pixel " << k;
    }
    else if (relaxed->GetBufferPointer()[k] != depth->GetBufferPointer()[k])
    {
      ++moved;
    }
  }
  EXPECT_GT(fixed, 30u);
  EXPECT_GT(moved, 0u) << "the relaxation changed nothing";
  EXPECT_EQ(outputs.RelaxBackendUsed, "cpu");
  EXPECT_GE(outputs.Times.Relax, 0.0);
}

TEST_F(VesselReformationLogicTest, ProgressRisesToOne)
{
  std::vector<double> fractions;
  m_Logic.SetProgressCallback([&](double fraction, const std::string &) { fractions.push_back(fraction); });
  m_Logic.Update();
  ASSERT_GE(fractions.size(), 4u);
  for (std::size_t k = 1; k < fractions.size(); ++k)
  {
    EXPECT_GE(fractions[k], fractions[k - 1] - 1e-12);
  }
  EXPECT_EQ(fractions.back(), 1.0);
  EXPECT_GE(fractions.front(), 0.0);
}

TEST_F(VesselReformationLogicTest, ASteadySolveStoppedByItsBoundIsAWarningThatSaysHowFarItGot)
{
  ReformationParameters parameters = QuickParameters();
  parameters.Solver = itk::BilateralDepthRelaxSolver::Steady;
  m_Logic.SetParameters(parameters);
  std::vector<std::pair<std::string, std::string>> warned;
  m_Logic.SetWarningCallback([&](const std::string & message, const std::string & parameter)
                             { warned.emplace_back(message, parameter); });
  m_Logic.Update();
  EXPECT_TRUE(warned.empty()) << warned.front().first;
  EXPECT_TRUE(m_Logic.GetWarnings().empty());

  // No outer iteration allowed: the update still shows the (unrelaxed) result, and says so.
  m_Logic.GetRelaxFilter()->SetSteadyMaximumOuterIterations(0);
  const auto outputs = m_Logic.Update();
  EXPECT_NE(outputs.CPR, nullptr);
  ASSERT_EQ(warned.size(), 1u);
  EXPECT_EQ(warned[0].second, vr::ParameterName::Solver);
  EXPECT_NE(warned[0].first.find("stopped after 0 outer iterations"), std::string::npos) << warned[0].first;
  EXPECT_NE(warned[0].first.find("residual"), std::string::npos) << warned[0].first;
  EXPECT_NE(warned[0].first.find("energy"), std::string::npos) << warned[0].first;
  ASSERT_EQ(m_Logic.GetWarnings().size(), 1u);
  EXPECT_EQ(m_Logic.GetWarnings()[0], warned[0].first);

  // The warning holds while the result does, and goes with the next solve that converges.
  m_Logic.Update();
  EXPECT_EQ(m_Logic.GetWarnings().size(), 1u);
  m_Logic.GetRelaxFilter()->SetSteadyMaximumOuterIterations(
    itk::BilateralDepthRelaxSteadySolver::DefaultMaximumOuterIterations);
  m_Logic.Update();
  EXPECT_TRUE(m_Logic.GetWarnings().empty());
  EXPECT_EQ(warned.size(), 1u);
}

TEST_F(VesselReformationLogicTest, CenterlinesWithNoPointInTheVolumeAreRefusedNamingBothNodes)
{
  EXPECT_TRUE(m_Logic.GetWarnings().empty());
  m_Logic.Update();
  EXPECT_TRUE(m_Logic.GetWarnings().empty()) << m_Logic.GetWarnings().front();

  std::vector<std::string> warned;
  m_Logic.SetWarningCallback([&](const std::string & message, const std::string &) { warned.push_back(message); });
  // Centerlines taken as LPS although they are RAS: every point lands outside the volume (counted below).
  m_Logic.SetCenterlineNode(MakeCenterlineNode(m_Vessels, /*forgetRAS=*/true));
  try
  {
    m_Logic.Update();
    ADD_FAILURE() << "centerlines wholly outside the volume were reformatted";
  }
  catch (const vr::InputError & error)
  {
    const std::string message = error.what();
    EXPECT_EQ(error.Parameter(), vr::ParameterName::CenterlineSpace);
    EXPECT_NE(message.find("none of the"), std::string::npos) << message;
    EXPECT_NE(message.find("two-vessels-centerlines"), std::string::npos) << message;
    EXPECT_NE(message.find("the volume \"" + m_Volume->GetName() + "\""), std::string::npos) << message;
    EXPECT_NE(message.find("other coordinate system"), std::string::npos) << message;
    EXPECT_EQ(message.find("--"), std::string::npos) << "the logic names no flag: " << message;
  }
  EXPECT_TRUE(warned.empty()) << warned.front();
  EXPECT_EQ(
    vr::VesselReformationLogic::FractionOfPointsOutside(vr::ConvertCenterlineNodeToTree(MakeCenterlineNode(m_Vessels)),
                                                        vr::ConvertVolumeNodeToItkImage(m_Volume)),
    0.0);
}

TEST(CenterlineVolumeFit, CountsByTheVoxelGridAndDecidesBetweenNothingAWarningAndAnError)
{
  // A 10 x 10 x 10 grid of 2 mm voxels from LPS (0, 0, 0): voxel centres 0 .. 18 mm, the grid reaches 19 mm.
  auto volume = vr::VolumeImageType::New();
  volume->SetRegions(vr::VolumeImageType::RegionType({ { 0, 0, 0 } }, { { 10, 10, 10 } }));
  vr::VolumeImageType::SpacingType spacing;
  spacing.Fill(2.0);
  volume->SetSpacing(spacing);
  volume->Allocate(true);
  itk::CenterlineTree   tree;
  itk::CenterlineBranch branch;
  // Along x at y = z = 5 mm: x = -1.5 (out), -0.5 (in), 10, 18.5 (in), 19.5, 30 (out): 3 of 6 outside.
  for (const double x : { -1.5, -0.5, 10.0, 18.5, 19.5, 30.0 })
  {
    branch.Points.push_back(vr::test::P(x, 5.0, 5.0));
  }
  tree.AddBranch(branch);
  const vr::CenterlineVolumeFit fit = vr::MeasureCenterlineVolumeFit(tree, volume);
  EXPECT_EQ(fit.Points, 6u);
  EXPECT_EQ(fit.Outside, 3u);
  // The node's grid, through its IJK->RAS matrix, counts the same.
  const auto                    node = vr::ConvertItkImageToVolumeNode(volume.GetPointer(), "grid");
  const vr::CenterlineVolumeFit nodeFit = vr::MeasureCenterlineVolumeFit(tree, node.GetPointer());
  EXPECT_EQ(nodeFit.Points, 6u);
  EXPECT_EQ(nodeFit.Outside, 3u);

  // Half outside: no warning; more: a warning in full; all: an error naming both.
  EXPECT_EQ(vr::CheckCenterlineVolumeFit(fit, "centerlines \"c.vtp\"", "the volume \"v.nrrd\"", false), "");
  const std::string warning =
    vr::CheckCenterlineVolumeFit({ 6, 4 }, "centerlines \"c.vtp\"", "the volume \"v.nrrd\"", false);
  EXPECT_EQ(warning,
            "centerlines \"c.vtp\": 67% of the 6 points lie outside the volume \"v.nrrd\"; they may be in the other "
            "coordinate system: check whether the centerlines are in RAS or LPS. The reformation continues.");
  try
  {
    vr::CheckCenterlineVolumeFit({ 6, 6 }, "centerlines \"c.vtp\"", "the volume \"v.nrrd\"", false);
    ADD_FAILURE() << "no error";
  }
  catch (const vr::InputError & error)
  {
    EXPECT_EQ(error.Parameter(), vr::ParameterName::CenterlineSpace);
    EXPECT_NE(std::string(error.what())
                .find("centerlines \"c.vtp\": none of the 6 points lies inside the volume "
                      "\"v.nrrd\""),
              std::string::npos)
      << error.what();
  }
}

TEST_F(VesselReformationLogicTest, AutoBackendNoticeIsAWarning)
{
  ReformationParameters parameters = m_Logic.GetParameters();
  parameters.Backend = vr::RelaxBackend::Auto;
  m_Logic.SetParameters(parameters);
  std::string expected;
  vr::CreateRelaxFilter(vr::RelaxBackend::Auto, "", expected);
  m_Logic.Update();
  const auto warnings = m_Logic.GetWarnings();
  if (expected.empty())
  {
    EXPECT_TRUE(warnings.empty());
  }
  else
  {
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_EQ(warnings[0], expected);
  }
}

/** A device query that reports \a type, or no device when \a type is empty (the device-type stub of issue 13). */
vr::OpenCLDeviceQuery
DeviceOfType(const std::string & type)
{
  return [type](const std::string &)
  {
    vr::OpenCLDeviceKind kind;
    if (type.empty())
    {
      kind.WhyNot = "no OpenCL platform is installed";
      return kind;
    }
    kind.Label = "0:0 stub device (stub platform, " + type + ")";
    kind.Type = type;
    return kind;
  };
}

// Issue 13: auto takes OpenCL only on a GPU or an accelerator; a CPU device (PoCL) or none gives the CPU path.
TEST(RelaxBackendChoice, AutoTakesOpenCLOnlyOnAGPUOrAnAccelerator)
{
  const auto cpu = vr::DecideAutoRelaxBackend("", DeviceOfType("CPU"));
  EXPECT_EQ(cpu.Backend, vr::RelaxBackend::CPU);
  EXPECT_NE(cpu.Reason.find("stub device"), std::string::npos) << cpu.Reason;
  EXPECT_NE(cpu.Reason.find("CPU device"), std::string::npos) << cpu.Reason;
  EXPECT_TRUE(cpu.DeviceProblem.empty());
  for (const std::string type : { "GPU", "accelerator" })
  {
    const auto decision = vr::DecideAutoRelaxBackend("", DeviceOfType(type));
    EXPECT_EQ(decision.Backend, vr::RelaxBackend::OpenCL) << type;
    EXPECT_NE(decision.Reason.find(type), std::string::npos) << decision.Reason;
  }
  const auto none = vr::DecideAutoRelaxBackend("", DeviceOfType(""));
  EXPECT_EQ(none.Backend, vr::RelaxBackend::CPU);
  EXPECT_EQ(none.DeviceProblem, "no OpenCL platform is installed");
  // The request reaches the query.
  std::string asked;
  vr::DecideAutoRelaxBackend("1:2",
                             [&asked](const std::string & request)
                             {
                               asked = request;
                               return vr::OpenCLDeviceKind{ "", "x", "CPU" };
                             });
  EXPECT_EQ(asked, "1:2");
}

// The one backend decision (vr::ChooseRelaxFilter), with the OpenCL filter's maker replaced: every rule and every
// message, without a device.
TEST(RelaxBackendChoice, OneDecisionForEverySolverBackendAndDevice)
{
  const vr::RelaxFilterType::Pointer openCLFilter = vr::RelaxFilterType::New(); // stands for a device's filter
  int                                made = 0;
  auto                               makes = [&](const std::string &, std::string &) -> vr::RelaxFilterType::Pointer
  {
    ++made;
    return openCLFilter;
  };
  auto fails = [&](const std::string &, std::string & whyNot) -> vr::RelaxFilterType::Pointer
  {
    ++made;
    whyNot = "the kernel did not build";
    return nullptr;
  };
  using Solver = itk::BilateralDepthRelaxSolver;
  // cpu: the CPU, nothing asked of OpenCL.
  auto choice = vr::ChooseRelaxFilter(vr::RelaxBackend::CPU, Solver::Jacobi, "", makes, DeviceOfType("GPU"));
  EXPECT_EQ(choice.Backend, vr::RelaxBackend::CPU);
  EXPECT_FALSE(choice.Filter);
  EXPECT_EQ(choice.Reason, "cpu requested");
  EXPECT_TRUE(choice.Notice.empty());
  EXPECT_EQ(made, 0);
  // The steady solver has no OpenCL kernel: the CPU; asked for OpenCL by name, the user hears it.
  choice = vr::ChooseRelaxFilter(vr::RelaxBackend::OpenCL, Solver::Steady, "", makes, DeviceOfType("GPU"));
  EXPECT_EQ(choice.Backend, vr::RelaxBackend::CPU);
  EXPECT_EQ(choice.Reason, "opencl: the steady solver has no OpenCL kernel, so the CPU");
  EXPECT_EQ(choice.Notice, "relax backend opencl: the steady solver has no OpenCL kernel; relaxing on the CPU instead");
  choice = vr::ChooseRelaxFilter(vr::RelaxBackend::Auto, Solver::Steady, "", makes, DeviceOfType("GPU"));
  EXPECT_EQ(choice.Backend, vr::RelaxBackend::CPU);
  EXPECT_EQ(choice.Reason, "auto: the steady solver has no OpenCL kernel, so the CPU");
  EXPECT_TRUE(choice.Notice.empty());
  EXPECT_EQ(made, 0);
  // auto on a GPU: the filter made for it.
  choice = vr::ChooseRelaxFilter(vr::RelaxBackend::Auto, Solver::Jacobi, "", makes, DeviceOfType("GPU"));
  EXPECT_EQ(choice.Backend, vr::RelaxBackend::OpenCL);
  EXPECT_EQ(choice.Filter, openCLFilter);
  EXPECT_EQ(choice.Reason, "auto: OpenCL on 0:0 stub device (stub platform, GPU), a GPU");
  EXPECT_EQ(made, 1);
  // auto on a GPU whose kernel fails: the CPU, and the user hears why.
  choice = vr::ChooseRelaxFilter(vr::RelaxBackend::Auto, Solver::Jacobi, "", fails, DeviceOfType("GPU"));
  EXPECT_EQ(choice.Backend, vr::RelaxBackend::CPU);
  EXPECT_FALSE(choice.Filter);
  EXPECT_EQ(choice.Notice,
            "relax backend auto: OpenCL is not usable, relaxing on the CPU instead. Reason: the kernel did not build");
  // auto without a device: the CPU with the same notice, nothing made.
  made = 0;
  choice = vr::ChooseRelaxFilter(vr::RelaxBackend::Auto, Solver::Jacobi, "", makes, DeviceOfType(""));
  EXPECT_EQ(choice.Backend, vr::RelaxBackend::CPU);
  EXPECT_EQ(
    choice.Notice,
    "relax backend auto: OpenCL is not usable, relaxing on the CPU instead. Reason: no OpenCL platform is installed");
  EXPECT_EQ(made, 0);
  // opencl: the filter, or an error naming why there is none.
  choice = vr::ChooseRelaxFilter(vr::RelaxBackend::OpenCL, Solver::Jacobi, "", makes, DeviceOfType("CPU"));
  EXPECT_EQ(choice.Backend, vr::RelaxBackend::OpenCL);
  EXPECT_EQ(choice.Reason, "opencl requested");
  try
  {
    vr::ChooseRelaxFilter(vr::RelaxBackend::OpenCL, Solver::Jacobi, "", fails, DeviceOfType("GPU"));
    ADD_FAILURE() << "opencl without a usable device must throw";
  }
  catch (const vr::InputError & error)
  {
    EXPECT_STREQ(error.what(), "relax backend opencl: no usable OpenCL device: the kernel did not build");
  }
}

// The logic reports its choice and the reason in its outputs; a CPU device is a choice, not a warning.
TEST_F(VesselReformationLogicTest, AutoOnACPUDeviceRelaxesOnTheCPUAndSaysWhy)
{
  ReformationParameters parameters = m_Logic.GetParameters();
  parameters.Backend = vr::RelaxBackend::Auto;
  m_Logic.SetParameters(parameters);
  m_Logic.SetOpenCLDeviceQuery(DeviceOfType("CPU"));
  const auto & outputs = m_Logic.Update();
  EXPECT_EQ(outputs.RelaxBackendUsed, "cpu");
  EXPECT_NE(outputs.RelaxBackendReason.find("is a CPU device"), std::string::npos) << outputs.RelaxBackendReason;
  EXPECT_TRUE(m_Logic.GetWarnings().empty());

  m_Logic.SetOpenCLDeviceQuery(DeviceOfType(""));
  m_Logic.Update();
  EXPECT_EQ(m_Logic.GetOutputs().RelaxBackendUsed, "cpu");
  EXPECT_NE(m_Logic.GetOutputs().RelaxBackendReason.find("no usable OpenCL device"), std::string::npos);
  ASSERT_EQ(m_Logic.GetWarnings().size(), 1u) << "no device at all is worth a warning";
  EXPECT_NE(m_Logic.GetWarnings()[0].find("no OpenCL platform is installed"), std::string::npos);

  parameters.Backend = vr::RelaxBackend::CPU;
  m_Logic.SetParameters(parameters);
  m_Logic.Update();
  EXPECT_EQ(m_Logic.GetOutputs().RelaxBackendReason, "cpu requested");
}

/** Update() must throw vr::InputError whose message holds every one of \a names and no command-line flag, and
 * that names \a parameter (by meaning) as the one at fault. */
void
ExpectInputError(VesselReformationLogic &         logic,
                 const std::vector<std::string> & names,
                 const std::string &              parameter = "")
{
  try
  {
    logic.Update();
    FAIL() << "no error";
  }
  catch (const vr::InputError & error)
  {
    for (const auto & name : names)
    {
      EXPECT_NE(std::string(error.what()).find(name), std::string::npos) << error.what() << " lacks " << name;
    }
    EXPECT_EQ(std::string(error.what()).find("--"), std::string::npos) << "the logic names no flag: " << error.what();
    EXPECT_EQ(error.Parameter(), parameter) << error.what();
  }
}

TEST_F(VesselReformationLogicTest, BadParametersAreNamedWithTheirValue)
{
  ReformationParameters parameters = QuickParameters();
  parameters.Relaxation = 2.0;
  m_Logic.SetParameters(parameters);
  ExpectInputError(m_Logic, { "relaxation w", "2" }, vr::ParameterName::Relaxation);

  parameters = QuickParameters();
  parameters.Iterations = -5;
  m_Logic.SetParameters(parameters);
  ExpectInputError(m_Logic, { "iterations N", "-5" }, vr::ParameterName::Iterations);

  parameters = QuickParameters();
  parameters.ImageSize[0] = 0;
  parameters.ImageSize[1] = 10;
  m_Logic.SetParameters(parameters);
  ExpectInputError(m_Logic, { "view size", "0,10" }, vr::ParameterName::ViewSize);

  parameters = QuickParameters();
  parameters.Anisotropy = -1.0;
  m_Logic.SetParameters(parameters);
  ExpectInputError(m_Logic, { "anisotropy a", "-1" }, vr::ParameterName::Anisotropy);

  parameters = QuickParameters();
  parameters.Anisotropy.reset();
  parameters.JumpThreshold = 0.0;
  m_Logic.SetParameters(parameters);
  ExpectInputError(m_Logic, { "jump threshold J", "0" }, vr::ParameterName::JumpThreshold);

  // Two forms of one kernel: both set is refused, naming both by meaning.
  parameters = QuickParameters();
  parameters.JumpThreshold = 3.0;
  parameters.Anisotropy = 0.5;
  m_Logic.SetParameters(parameters);
  ExpectInputError(m_Logic, { "jump threshold", "anisotropy", "3", "0.5" }, vr::ParameterName::JumpThreshold);

  parameters = QuickParameters();
  parameters.SlabThickness = std::nan("");
  m_Logic.SetParameters(parameters);
  ExpectInputError(m_Logic, { "slab thickness", "nan" }, vr::ParameterName::SlabThickness);

  EXPECT_EQ(m_Logic.GetStageExecutionCounts().Depth, 0u);
}

TEST_F(VesselReformationLogicTest, ViewThatDoesNotFitInMemoryIsRefusedBeforeAllocating)
{
  ReformationParameters parameters = QuickParameters();
  parameters.ImageSize[0] = 100000000;
  parameters.ImageSize[1] = 100000000;
  m_Logic.SetParameters(parameters);
  ExpectInputError(m_Logic, { "view size", "100000000,100000000", "memory" }, vr::ParameterName::ViewSize);
  EXPECT_EQ(m_Logic.GetStageExecutionCounts().Depth, 0u);

  // The logic recovers: a sensible size runs.
  parameters.ImageSize[0] = 64;
  parameters.ImageSize[1] = 96;
  m_Logic.SetParameters(parameters);
  const auto & outputs = m_Logic.Update();
  int          dimensions[3];
  outputs.CPR->GetImageData()->GetDimensions(dimensions);
  EXPECT_EQ(dimensions[0], 64);
  EXPECT_EQ(dimensions[1], 96);
}

TEST_F(VesselReformationLogicTest, MissingNodesAreReported)
{
  VesselReformationLogic empty;
  ExpectInputError(empty, { "volume node" });
  empty.SetVolumeNode(m_Volume);
  ExpectInputError(empty, { "centerline node" });
}

TEST(VesselReformationLogicRelax, RelaxDepthImageFollowsEquationOne)
{
  // A 3 x 1 image [0, 10, 0], w = 1, a = 0, one iteration: each pixel becomes the mean of its neighbours.
  auto depth = vr::DepthImageType::New();
  depth->SetRegions(vr::DepthImageType::RegionType({ { 0, 0 } }, { { 3, 1 } }));
  depth->Allocate();
  depth->GetBufferPointer()[0] = 0.0f;
  depth->GetBufferPointer()[1] = 10.0f;
  depth->GetBufferPointer()[2] = 0.0f;
  ReformationParameters parameters;
  parameters.Relaxation = 1.0;
  parameters.Anisotropy = 0.0;
  parameters.Iterations = 1;
  parameters.Backend = vr::RelaxBackend::CPU;
  std::vector<std::string> warnings;
  auto                     relaxed = VesselReformationLogic::RelaxDepthImage(depth, nullptr, parameters, {}, warnings);
  EXPECT_FLOAT_EQ(relaxed->GetBufferPointer()[0], 10.0f);
  EXPECT_FLOAT_EQ(relaxed->GetBufferPointer()[1], 0.0f);
  EXPECT_FLOAT_EQ(relaxed->GetBufferPointer()[2], 10.0f);
  EXPECT_TRUE(warnings.empty());

  parameters.Relaxation = 1.5;
  EXPECT_THROW(VesselReformationLogic::RelaxDepthImage(depth, nullptr, parameters, {}, warnings), vr::InputError);
}

// Issue 13: the jump threshold reaches the filter (J = 2 mm and a = 0.25 mm^-2 give the same picture, J = 3 mm
// unset), and the steady solver finds the fixed point, on the hand-worked case of depths [0, 1, 3] with the ends
// fixed (vr::test::ThreePixelMiddleAfterOnePass, ThreePixelMiddleFixedPoint).
TEST(VesselReformationLogicRelax, JumpThresholdAndSteadySolverReachTheFilter)
{
  const auto depth = vr::test::MakeDepthImage(3, 1, { 0.0f, 1.0f, 3.0f });
  const auto mask = vr::test::MakeMaskImage(3, 1, { 1, 0, 1 });
  auto       middle = [&](const ReformationParameters & parameters, std::vector<std::string> & warnings)
  { return VesselReformationLogic::RelaxDepthImage(depth, mask, parameters, {}, warnings)->GetBufferPointer()[1]; };
  auto                  expected = [](double J) { return vr::test::ThreePixelMiddleAfterOnePass(1.0, J); };
  ReformationParameters parameters;
  parameters.Iterations = 1;
  parameters.Backend = vr::RelaxBackend::CPU;
  std::vector<std::string> warnings;
  EXPECT_NEAR(middle(parameters, warnings), expected(3.0), 1e-6) << "J unset: 3 mm";
  parameters.JumpThreshold = 2.0;
  EXPECT_NEAR(middle(parameters, warnings), expected(2.0), 1e-6);
  parameters.JumpThreshold.reset();
  parameters.Anisotropy = 0.25;
  EXPECT_NEAR(middle(parameters, warnings), expected(2.0), 1e-6);
  EXPECT_TRUE(warnings.empty());

  const auto fixedPoint = vr::test::ThreePixelMiddleFixedPoint;
  ASSERT_GT(std::abs(fixedPoint(2.0) - expected(2.0)), 0.1) << "one pass is not the fixed point here";
  parameters.Solver = itk::BilateralDepthRelaxSolver::Steady;
  EXPECT_NEAR(middle(parameters, warnings), fixedPoint(2.0), 1e-3);
  EXPECT_TRUE(warnings.empty());
  // Asked for OpenCL by name, the steady solver says that it relaxes on the CPU; auto relaxes there silently.
  parameters.Backend = vr::RelaxBackend::Auto;
  std::string backend;
  VesselReformationLogic::RelaxDepthImage(depth, mask, parameters, {}, warnings, &backend);
  EXPECT_EQ(backend, "cpu");
  EXPECT_TRUE(warnings.empty());
  parameters.Backend = vr::RelaxBackend::OpenCL;
  EXPECT_NEAR(middle(parameters, warnings), fixedPoint(2.0), 1e-3);
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("steady solver has no OpenCL kernel"), std::string::npos) << warnings[0];
}

// ---------------------------------------------------------------------------------------------------------------
// Node conversion against hand-computed cases.

TEST(NodeConversion, VolumeNodeGeometryBecomesLPS)
{
  // IJK->RAS with a rotation, anisotropic spacing and an offset:
  //   R = -2 j + 10,  A = 3 i + 20,  S = 4 k - 30.
  auto         matrix = vtkSmartPointer<vtkMatrix4x4>::New();
  const double elements[16] = { 0, -2, 0, 10, 3, 0, 0, 20, 0, 0, 4, -30, 0, 0, 0, 1 };
  matrix->DeepCopy(elements);
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetExtent(0, 2, 0, 3, 0, 4);
  data->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto * voxels = static_cast<unsigned char *>(data->GetScalarPointer());
  for (int k = 0; k < 3 * 4 * 5; ++k)
  {
    voxels[k] = static_cast<unsigned char>(k);
  }
  auto node = vtkSmartPointer<vr::VolumeNode>::New();
  node->SetImageData(data);
  node->SetIJKToRASMatrix(matrix);

  auto image = vr::ConvertVolumeNodeToItkImage(node);
  // By hand: IJK->LPS = [[0, 2, 0, -10], [-3, 0, 0, -20], [0, 0, 4, -30]].
  EXPECT_DOUBLE_EQ(image->GetSpacing()[0], 3.0);
  EXPECT_DOUBLE_EQ(image->GetSpacing()[1], 2.0);
  EXPECT_DOUBLE_EQ(image->GetSpacing()[2], 4.0);
  EXPECT_DOUBLE_EQ(image->GetOrigin()[0], -10.0);
  EXPECT_DOUBLE_EQ(image->GetOrigin()[1], -20.0);
  EXPECT_DOUBLE_EQ(image->GetOrigin()[2], -30.0);
  const double direction[3][3] = { { 0, 1, 0 }, { -1, 0, 0 }, { 0, 0, 1 } };
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_DOUBLE_EQ(image->GetDirection()[r][c], direction[r][c]) << r << "," << c;
    }
  }
  // Voxel (1, 2, 3): RAS (-2*2 + 10, 3*1 + 20, 4*3 - 30) = (6, 23, -18), so LPS (-6, -23, -18).
  vr::VolumeImageType::IndexType index = { { 1, 2, 3 } };
  itk::Point<double, 3>          point;
  image->TransformIndexToPhysicalPoint(index, point);
  EXPECT_NEAR(point[0], -6.0, 1e-12);
  EXPECT_NEAR(point[1], -23.0, 1e-12);
  EXPECT_NEAR(point[2], -18.0, 1e-12);
  EXPECT_EQ(image->GetPixel(index), static_cast<float>((3 * 4 + 2) * 3 + 1));

  // Back to a node: the same matrix and voxels.
  auto back = vr::ConvertItkImageToVolumeNode(image, "back");
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      EXPECT_NEAR(back->GetIJKToRASMatrix()->GetElement(r, c), elements[4 * r + c], 1e-12) << r << "," << c;
    }
  }
  EXPECT_EQ(static_cast<float *>(back->GetImageData()->GetScalarPointer())[59], 59.0f);
}

TEST(NodeConversion, BadVolumeNodesAreNamed)
{
  auto node = vtkSmartPointer<vr::VolumeNode>::New();
  node->SetName("broken");
  try
  {
    vr::ConvertVolumeNodeToItkImage(node);
    FAIL() << "no error";
  }
  catch (const vr::InputError & error)
  {
    EXPECT_NE(std::string(error.what()).find("\"broken\""), std::string::npos) << error.what();
  }
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetExtent(0, 1, 0, 1, 0, 1);
  data->AllocateScalars(VTK_FLOAT, 1);
  node->SetImageData(data);
  auto singular = vtkSmartPointer<vtkMatrix4x4>::New();
  singular->SetElement(2, 2, 0.0);
  node->SetIJKToRASMatrix(singular);
  EXPECT_THROW(vr::ConvertVolumeNodeToItkImage(node), vr::InputError);
  data->SetSpacing(2.0, 1.0, 1.0);
  node->SetIJKToRASMatrix(nullptr);
  EXPECT_THROW(vr::ConvertVolumeNodeToItkImage(node), vr::InputError);
}

TEST(NodeConversion, CenterlineNodePointsBecomeLPS)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->InsertNextPoint(10.0, 20.0, 30.0);
  points->InsertNextPoint(-1.5, 2.5, -3.5);
  points->InsertNextPoint(7.0, -8.0, 9.0);
  auto            lines = vtkSmartPointer<vtkCellArray>::New();
  const vtkIdType first[2] = { 0, 1 };
  const vtkIdType second[1] = { 2 };
  lines->InsertNextCell(2, first);
  lines->InsertNextCell(1, second);
  auto radii = vtkSmartPointer<vtkDoubleArray>::New();
  radii->SetName("MaximumInscribedSphereRadius");
  radii->InsertNextValue(2.0);
  radii->InsertNextValue(2.5);
  radii->InsertNextValue(3.0);
  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetLines(lines);
  polyData->GetPointData()->AddArray(radii);
  auto node = vtkSmartPointer<vr::CenterlineNode>::New();
  node->SetPolyData(polyData);

  const itk::CenterlineTree tree = vr::ConvertCenterlineNodeToTree(node);
  ASSERT_EQ(tree.GetNumberOfBranches(), 2u);
  const auto & trunk = tree.GetBranches()[0];
  EXPECT_EQ(trunk.Id, 1);
  ASSERT_EQ(trunk.Points.size(), 2u);
  EXPECT_DOUBLE_EQ(trunk.Points[0][0], -10.0);
  EXPECT_DOUBLE_EQ(trunk.Points[0][1], -20.0);
  EXPECT_DOUBLE_EQ(trunk.Points[0][2], 30.0);
  EXPECT_DOUBLE_EQ(trunk.Points[1][0], 1.5);
  EXPECT_DOUBLE_EQ(trunk.Points[1][1], -2.5);
  EXPECT_DOUBLE_EQ(trunk.Points[1][2], -3.5);
  EXPECT_DOUBLE_EQ(trunk.Radii[1], 2.5);
  EXPECT_EQ(tree.GetBranches()[1].Id, 2);
  EXPECT_DOUBLE_EQ(tree.GetBranches()[1].Points[0][1], 8.0);

  // Back to a node and again to a tree: ids and radii survive.
  auto   back = vr::ConvertTreeToCenterlineNode(tree, "back");
  double ras[3];
  back->GetPolyData()->GetPoint(0, ras);
  EXPECT_DOUBLE_EQ(ras[0], 10.0);
  EXPECT_DOUBLE_EQ(ras[1], 20.0);
  const itk::CenterlineTree again = vr::ConvertCenterlineNodeToTree(back);
  EXPECT_EQ(again.GetBranches()[1].Id, 2);
  EXPECT_DOUBLE_EQ(again.GetBranches()[0].Radii[0], 2.0);

  auto empty = vtkSmartPointer<vr::CenterlineNode>::New();
  empty->SetName("nothing");
  empty->SetPolyData(vtkSmartPointer<vtkPolyData>::New());
  EXPECT_THROW(vr::ConvertCenterlineNodeToTree(empty), vr::InputError);
}

TEST(NodeConversion, OutputImageNodeLiesOnTheViewPlane)
{
  // up S, angle 0: u = LPS (1, 0, 0), v = (0, 1, 0); C = (5, 6, 7), 4 x 3 pixels of 0.5 x 2 mm.
  const itk::CPRViewGeometry view(itk::detail::MakeVector3(0, 0, 1),
                                  0.0,
                                  MakePoint(5, 6, 7),
                                  itk::Size<2>{ { 4, 3 } },
                                  itk::detail::MakeVector2(0.5, 2.0));
  auto                       image = vr::DepthImageType::New();
  view.ConfigureImage(image.GetPointer());
  image->Allocate();
  for (int k = 0; k < 12; ++k)
  {
    image->GetBufferPointer()[k] = static_cast<float>(k) - 3.0f;
  }
  auto node = vr::ConvertItkImageToVolumeNode(image.GetPointer(), "Depth");
  // Pixel (i, j) at LPS B = C + (i - 1.5) 0.5 u - (j - 1) 2 up; pixel (3, 2): (5.75, 6, 5), RAS (-5.75, -6, 5).
  const double ijk[4] = { 3, 2, 0, 1 };
  double       ras[4];
  node->GetIJKToRASMatrix()->MultiplyPoint(ijk, ras);
  EXPECT_NEAR(ras[0], -5.75, 1e-12);
  EXPECT_NEAR(ras[1], -6.0, 1e-12);
  EXPECT_NEAR(ras[2], 5.0, 1e-12);
  // One slice step is one millimetre along v = LPS (0, 1, 0), RAS (0, -1, 0).
  EXPECT_NEAR(node->GetIJKToRASMatrix()->GetElement(1, 2), -1.0, 1e-12);
  EXPECT_STREQ(node->GetAttribute("CPR_Frame"), "LPS");

  auto back = vr::ConvertVolumeNodeToDepthImage(node);
  EXPECT_EQ(itk::CPRViewGeometry::ReadFromDictionary(back->GetMetaDataDictionary()), view);
  EXPECT_EQ(back->GetSpacing(), image->GetSpacing());
  EXPECT_EQ(back->GetOrigin(), image->GetOrigin());
  EXPECT_EQ(back->GetBufferPointer()[11], 8.0f);
}

// ---------------------------------------------------------------------------------------------------------------
// The cut surface.

TEST(CutSurface, PointsLieAtTheDepthAndJumpsStayOpen)
{
  // 3 x 2 pixels of 1 mm, C = 0, up S, angle 0. Depths: left column 0, the rest 0 except pixel (2, 1) = 10 mm.
  const itk::CPRViewGeometry view(itk::detail::MakeVector3(0, 0, 1),
                                  0.0,
                                  MakePoint(0, 0, 0),
                                  itk::Size<2>{ { 3, 2 } },
                                  itk::detail::MakeVector2(1.0, 1.0));
  auto                       depth = vr::DepthImageType::New();
  auto                       intensity = vr::DepthImageType::New();
  view.ConfigureImage(depth.GetPointer());
  view.ConfigureImage(intensity.GetPointer());
  depth->Allocate();
  intensity->Allocate();
  const float depths[6] = { 0, 0, 0, 0, 0, 10 };
  for (int k = 0; k < 6; ++k)
  {
    depth->GetBufferPointer()[k] = depths[k];
    intensity->GetBufferPointer()[k] = 100.0f + k;
  }
  auto surface = vr::BuildCutSurface(depth, intensity, view, 4.0);
  ASSERT_EQ(surface->GetNumberOfPoints(), 6);
  // Pixel (2, 1): B = (2 - 1) u - (1 - 0.5) up = LPS (1, 0, -0.5); X = B + 10 v = (1, 10, -0.5); RAS (-1, -10, -0.5).
  double x[3];
  surface->GetPoint(5, x);
  EXPECT_NEAR(x[0], -1.0, 1e-6);
  EXPECT_NEAR(x[1], -10.0, 1e-6);
  EXPECT_NEAR(x[2], -0.5, 1e-6);
  EXPECT_EQ(surface->GetPointData()->GetScalars()->GetComponent(5, 0), 105.0);
  // Two squares, four triangles; the two of the right square that touch pixel 5 cross the 10 mm jump.
  EXPECT_EQ(surface->GetNumberOfPolys(), 2);
  // With a threshold above the jump all four stay.
  EXPECT_EQ(vr::BuildCutSurface(depth, intensity, view, 10.0)->GetNumberOfPolys(), 4);
}
} // namespace
