// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The module logic: nodes to ITK (RAS <-> LPS), the recompute rules of docs/design.md "Module logic", warnings,
// parameter checks. This file: the recompute rules, abort, progress, the fit of the centerlines in the volume. The
// backend choice and the parameters are in VesselReformationLogicParametersGTest.cxx, node conversion and the cut
// surface in VesselReformationLogicConversionGTest.cxx; what they share, in vrLogicTestFixture.h.
#include "vrLogicTestFixture.h"

namespace
{
using namespace vr::test::logic;

TEST_F(VesselReformationLogicTest, RecomputesOnlyWhatAChangeInvalidates)
{
  m_Logic.Update();
  ExpectCounts(m_Logic.GetStageCounts(), 1, 1, 1, 1, 1);
  EXPECT_EQ(m_Logic.GetStageCounts().Conversion, 1u);
  EXPECT_EQ(m_Logic.GetStageCounts().Surface, 1u);

  // Unchanged parameters: nothing reruns.
  m_Logic.SetParameters(m_Logic.GetParameters());
  m_Logic.Update();
  ExpectCounts(m_Logic.GetStageCounts(), 1, 1, 1, 1, 1);
  EXPECT_EQ(m_Logic.GetStageCounts().Surface, 1u);

  // A new w: relax and the relaxed CPR, not depth, not the unfiltered CPR.
  ReformationParameters parameters = m_Logic.GetParameters();
  parameters.Relaxation = 0.5;
  m_Logic.SetParameters(parameters);
  m_Logic.Update();
  ExpectCounts(m_Logic.GetStageCounts(), 1, 2, 2, 1, 2);
  EXPECT_EQ(m_Logic.GetStageCounts().Surface, 2u);

  // A new a, then a new N: the same.
  parameters.Anisotropy = 2.0;
  m_Logic.SetParameters(parameters);
  m_Logic.Update();
  parameters.Iterations = 10;
  m_Logic.SetParameters(parameters);
  m_Logic.Update();
  ExpectCounts(m_Logic.GetStageCounts(), 1, 4, 4, 1, 4);

  // A new angle: all three.
  parameters.AngleInDegrees = 30.0;
  m_Logic.SetParameters(parameters);
  m_Logic.Update();
  ExpectCounts(m_Logic.GetStageCounts(), 2, 5, 5, 2, 5);

  // A new window and level: nothing.
  parameters.Window = 400.0;
  parameters.Level = 500.0;
  m_Logic.SetParameters(parameters);
  m_Logic.Update();
  ExpectCounts(m_Logic.GetStageCounts(), 2, 5, 5, 2, 5);
  double window = 0.0;
  double level = 0.0;
  m_Logic.GetDisplayWindowLevel(window, level);
  EXPECT_EQ(window, 400.0);
  EXPECT_EQ(level, 500.0);

  // A new interpolation: both CPR images, no depth, no relax.
  parameters.Interpolation = itk::CPRInterpolationMode::Nearest;
  m_Logic.SetParameters(parameters);
  m_Logic.Update();
  ExpectCounts(m_Logic.GetStageCounts(), 2, 5, 6, 3, 6);

  // A new slab: the same.
  parameters.SlabThickness = 2.0;
  m_Logic.SetParameters(parameters);
  m_Logic.Update();
  ExpectCounts(m_Logic.GetStageCounts(), 2, 5, 7, 4, 7);

  // A new mode: everything.
  parameters.Mode = itk::CPRDepthMode::Nearest;
  m_Logic.SetParameters(parameters);
  m_Logic.Update();
  ExpectCounts(m_Logic.GetStageCounts(), 3, 6, 8, 5, 8);

  // Modified centerlines (the platform edited the polydata): conversion and everything.
  m_Centerlines->GetPolyData()->GetPoints()->SetPoint(0, -15.0, -20.0, 6.0);
  m_Centerlines->GetPolyData()->GetPoints()->Modified();
  m_Logic.Update();
  ExpectCounts(m_Logic.GetStageCounts(), 4, 7, 9, 6, 9);
  EXPECT_EQ(m_Logic.GetStageCounts().Conversion, 2u);

  // Another volume node of the same geometry (another phase of the scan): conversion and resampling only; the
  // depth map and its relaxation depend on the volume's geometry alone.
  m_Logic.SetVolumeNode(MakeVolumeNode(m_Vessels));
  m_Logic.Update();
  ExpectCounts(m_Logic.GetStageCounts(), 4, 7, 10, 7, 10);
  EXPECT_EQ(m_Logic.GetStageCounts().Conversion, 3u);

  // A volume of another spacing changes the view's default pixel spacing: everything.
  auto finer = MakeVolumeNode(m_Vessels);
  auto matrix = vtkSmartPointer<vtkMatrix4x4>::New();
  matrix->DeepCopy(finer->GetIJKToRASMatrix());
  matrix->SetElement(2, 2, 0.9);
  finer->SetIJKToRASMatrix(matrix);
  m_Logic.SetVolumeNode(finer);
  m_Logic.Update();
  ExpectCounts(m_Logic.GetStageCounts(), 5, 8, 11, 8, 11);
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
  EXPECT_EQ(m_Logic.GetStageCounts().RelaxedSamplings, updates);
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
  EXPECT_EQ(m_Logic.GetStageCounts().RelaxedSamplings, 0u);

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
  ExpectCounts(m_Logic.GetStageCounts(), 1, 1, 1, 1, 1);

  std::string whyNot;
  if (vr::TryCreateOpenCLRelaxFilter("", whyNot))
  {
    // On an OpenCL device the depth map and both CPR images are computed there too (their own filters, in the
    // relaxation's session): the whole view runs again, on the device.
    parameters.Backend = vr::RelaxBackend::OpenCL;
    m_Logic.SetParameters(parameters);
    m_Logic.Update();
    EXPECT_EQ(m_Logic.GetOutputs().RelaxBackendUsed, "opencl");
    EXPECT_EQ(m_Logic.GetOutputs().DepthBackendUsed, "opencl");
    ExpectCounts(m_Logic.GetStageCounts(), 2, 2, 2, 2, 2);

    // Back to the CPU: its filters are still up to date, nothing reruns, and the outputs are theirs again.
    parameters.Backend = vr::RelaxBackend::CPU;
    m_Logic.SetParameters(parameters);
    m_Logic.Update();
    EXPECT_EQ(m_Logic.GetOutputs().DepthBackendUsed, "cpu");
    ExpectCounts(m_Logic.GetStageCounts(), 2, 2, 2, 2, 2);
  }
}

TEST_F(VesselReformationLogicTest, SurfaceIsBuiltOnlyWhenEnabled)
{
  m_Logic.SetSurfaceEnabled(false);
  const auto & outputs = m_Logic.Update();
  EXPECT_EQ(outputs.Surface, nullptr);
  EXPECT_EQ(m_Logic.GetStageCounts().Surface, 0u);
  m_Logic.SetSurfaceEnabled(true);
  m_Logic.Update();
  ASSERT_NE(m_Logic.GetOutputs().Surface, nullptr);
  EXPECT_EQ(m_Logic.GetStageCounts().Surface, 1u);
  ExpectCounts(m_Logic.GetStageCounts(), 1, 1, 1, 1, 1);
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

} // namespace
