// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The module logic's relax backend choice and its reasons, the parameter checks, and the relaxation's parameters
// reaching the filter.
#include "vrLogicTestFixture.h"

namespace
{
using namespace vr::test::logic;

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

  EXPECT_EQ(m_Logic.GetStageCounts().Depth, 0u);
}

TEST_F(VesselReformationLogicTest, ViewThatDoesNotFitInMemoryIsRefusedBeforeAllocating)
{
  ReformationParameters parameters = QuickParameters();
  parameters.ImageSize[0] = 100000000;
  parameters.ImageSize[1] = 100000000;
  m_Logic.SetParameters(parameters);
  ExpectInputError(m_Logic, { "view size", "100000000,100000000", "memory" }, vr::ParameterName::ViewSize);
  EXPECT_EQ(m_Logic.GetStageCounts().Depth, 0u);

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

} // namespace
