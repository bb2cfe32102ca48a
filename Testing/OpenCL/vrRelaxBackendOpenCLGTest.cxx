// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The relax backend seam with OpenCL built in (docs/design.md "Module logic"): auto uses OpenCL when a device works and
// falls back to the CPU with a notice saying why; an explicit opencl without a usable device is an error saying what
// exists.
#include "itkOpenCLBilateralDepthRelaxFilter.h"
#include "vrInputError.h"
#include "vrOpenCLDevices.h"
#include "vrRelaxBackend.h"
#include "vrOpenCLTestSupport.h"
#include "vrTestImages.h"

#include <gtest/gtest.h>

#include <optional>
#include <string>

namespace
{
using OpenCLFilter = itk::OpenCLBilateralDepthRelaxFilter;

bool
IsOpenCL(const vr::RelaxFilterType * filter)
{
  return dynamic_cast<const OpenCLFilter *>(filter) != nullptr;
}

// The filter the factory returns really relaxes: one iteration of linear smoothing on (0, 1, 3) gives (1, 1.5, 1).
void
ExpectItRelaxes(vr::RelaxFilterType * filter)
{
  filter->SetDepthInput(vr::test::MakeDepthImage(3, 1, { 0.0f, 1.0f, 3.0f }));
  filter->SetRelaxation(1.0);
  filter->SetAnisotropy(0.0);
  filter->SetNumberOfIterations(1);
  filter->Update();
  const auto relaxed = vr::test::PixelsOf(filter->GetOutput());
  EXPECT_NEAR(relaxed[0], 1.0, 1e-6);
  EXPECT_NEAR(relaxed[1], 1.5, 1e-6);
  EXPECT_NEAR(relaxed[2], 1.0, 1e-6);
}

TEST(RelaxBackendWithOpenCL, CPUIsAlwaysTheCPUFilterWithoutNotice)
{
  std::string      notice = "stale";
  vr::RelaxBackend chosen = vr::RelaxBackend::Auto;
  const auto       filter = vr::CreateRelaxFilter(vr::RelaxBackend::CPU, "", notice, &chosen);
  EXPECT_FALSE(IsOpenCL(filter));
  EXPECT_EQ(chosen, vr::RelaxBackend::CPU);
  EXPECT_TRUE(notice.empty()) << notice;
  ExpectItRelaxes(filter);
}

/** A device query that reports \a type for whatever is asked (the device-type stub of issue 13). */
vr::OpenCLDeviceQuery
DeviceOfType(const std::string & type)
{
  return [type](const std::string &)
  {
    vr::OpenCLDeviceKind kind;
    kind.Label = "0:0 stub device (stub platform, " + type + ")";
    kind.Type = type;
    return kind;
  };
}

TEST(RelaxBackendWithOpenCL, OpenCLGivesTheOpenCLFilterWhenADeviceWorks)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  std::string      notice;
  std::string      reason;
  vr::RelaxBackend chosen = vr::RelaxBackend::CPU;
  const auto       filter = vr::CreateRelaxFilter(vr::RelaxBackend::OpenCL, "", notice, &chosen, &reason);
  EXPECT_TRUE(IsOpenCL(filter));
  EXPECT_EQ(chosen, vr::RelaxBackend::OpenCL);
  EXPECT_EQ(reason, "opencl requested");
  EXPECT_TRUE(notice.empty()) << notice;
  ExpectItRelaxes(filter);
}

// Issue 13: auto takes OpenCL only on a GPU or an accelerator. With the device query stubbed to say GPU, auto builds
// the real OpenCL filter on the real device; stubbed to say CPU (PoCL), it takes the native CPU path without trying.
TEST(RelaxBackendWithOpenCL, AutoTakesOpenCLOnAGPUAndTheCPUPathOnACPUDevice)
{
  std::string      notice = "stale";
  std::string      reason;
  vr::RelaxBackend chosen = vr::RelaxBackend::OpenCL;
  auto filter = vr::CreateRelaxFilter(vr::RelaxBackend::Auto, "", notice, &chosen, &reason, DeviceOfType("CPU"));
  EXPECT_FALSE(IsOpenCL(filter));
  EXPECT_EQ(chosen, vr::RelaxBackend::CPU);
  EXPECT_TRUE(notice.empty()) << "a deliberate choice, not a failure: " << notice;
  EXPECT_NE(reason.find("is a CPU device"), std::string::npos) << reason;
  EXPECT_NE(reason.find("stub device"), std::string::npos) << reason;
  ExpectItRelaxes(filter);

  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  for (const std::string type : { "GPU", "accelerator" })
  {
    filter = vr::CreateRelaxFilter(vr::RelaxBackend::Auto, "", notice, &chosen, &reason, DeviceOfType(type));
    EXPECT_TRUE(IsOpenCL(filter)) << type;
    EXPECT_EQ(chosen, vr::RelaxBackend::OpenCL) << type;
    EXPECT_TRUE(notice.empty()) << notice;
    EXPECT_NE(reason.find("OpenCL on 0:0 stub device"), std::string::npos) << reason;
    ExpectItRelaxes(filter);
  }

  // With the installed drivers' answer: OpenCL exactly when the default device is not a CPU device.
  filter = vr::CreateRelaxFilter(vr::RelaxBackend::Auto, "", notice, &chosen, &reason);
  const auto device = vr::FindOpenCLDevice("", "test");
  EXPECT_EQ(IsOpenCL(filter), !device.IsCPU) << device.Label() << ": " << reason;
  EXPECT_NE(reason.find(device.Label()), std::string::npos) << reason;
}

TEST(RelaxBackendWithOpenCL, AutoWithoutTheRequestedDeviceFallsBackToTheCPUAndSaysWhy)
{
  // A real path to "no usable device" on any machine: the environment names a device that does not exist.
  const vr::test::ScopedEnvironment environment(vr::OpenCLDeviceEnvironmentVariable, "no-such-opencl-device");
  std::string                       notice;
  vr::RelaxBackend                  chosen = vr::RelaxBackend::OpenCL;
  const auto                        filter = vr::CreateRelaxFilter(vr::RelaxBackend::Auto, "", notice, &chosen);
  EXPECT_FALSE(IsOpenCL(filter));
  EXPECT_EQ(chosen, vr::RelaxBackend::CPU);
  EXPECT_NE(notice.find("relaxing on the CPU"), std::string::npos) << notice;
  EXPECT_NE(notice.find("no-such-opencl-device"), std::string::npos) << notice;
  EXPECT_NE(notice.find("VR_OPENCL_DEVICE"), std::string::npos) << notice;
  ExpectItRelaxes(filter);
}

TEST(RelaxBackendWithOpenCL, OpenCLWithoutTheRequestedDeviceIsAnInputErrorListingTheDevicesFound)
{
  const auto devices = vr::ListOpenCLDevices();
  for (const bool fromEnvironment : { false, true })
  {
    std::optional<vr::test::ScopedEnvironment> environment;
    if (fromEnvironment)
    {
      environment.emplace(vr::OpenCLDeviceEnvironmentVariable, "no-such-opencl-device");
    }
    std::string notice;
    try
    {
      vr::CreateRelaxFilter(vr::RelaxBackend::OpenCL, fromEnvironment ? "" : "no-such-opencl-device", notice);
      FAIL() << "a missing device was accepted";
    }
    catch (const vr::InputError & error)
    {
      const std::string message = error.what();
      EXPECT_NE(message.find("backend opencl"), std::string::npos) << message;
      EXPECT_NE(message.find("no-such-opencl-device"), std::string::npos) << message;
      for (const auto & device : devices)
      {
        EXPECT_NE(message.find(device.Label()), std::string::npos) << message;
      }
      if (devices.empty())
      {
        EXPECT_NE(message.find("no OpenCL device was found"), std::string::npos) << message;
      }
    }
  }
}

// Run only by the CTest test RelaxBackendWithoutAnyOpenCLPlatform, with OCL_ICD_VENDORS naming an empty folder so
// that the OpenCL ICD loader finds no platform at all; the discovered tests of this suite leave it out.
TEST(RelaxBackendWithoutOpenCL, AutoFallsBackAndOpenCLFailsSayingSo)
{
  std::string problem;
  ASSERT_TRUE(vr::ListOpenCLDevices(&problem).empty()) << "run through CTest, which hides the OpenCL platforms";
  EXPECT_FALSE(problem.empty());

  std::string      notice;
  vr::RelaxBackend chosen = vr::RelaxBackend::OpenCL;
  const auto       filter = vr::CreateRelaxFilter(vr::RelaxBackend::Auto, "", notice, &chosen);
  EXPECT_FALSE(IsOpenCL(filter));
  EXPECT_EQ(chosen, vr::RelaxBackend::CPU);
  EXPECT_NE(notice.find("relaxing on the CPU"), std::string::npos) << notice;
  EXPECT_NE(notice.find(problem), std::string::npos) << notice;
  ExpectItRelaxes(filter);

  try
  {
    vr::CreateRelaxFilter(vr::RelaxBackend::OpenCL, "", notice);
    FAIL() << "backend opencl was accepted without any OpenCL platform";
  }
  catch (const vr::InputError & error)
  {
    EXPECT_NE(std::string(error.what()).find("no OpenCL device was found"), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find(problem), std::string::npos) << error.what();
  }
}

TEST(RelaxBackendWithOpenCL, AKernelThatDoesNotBuildMakesAutoFallBackAndOpenCLFail)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const vr::test::ScopedKernelSource broken(
    "__kernel void RelaxIteration(__global float * depth) { depth[0] = oops; }\n");

  std::string      notice;
  vr::RelaxBackend chosen = vr::RelaxBackend::OpenCL;
  // Auto tries OpenCL only on a GPU: the stub says it is one, the kernel build on the real device fails.
  const auto filter = vr::CreateRelaxFilter(vr::RelaxBackend::Auto, "", notice, &chosen, nullptr, DeviceOfType("GPU"));
  EXPECT_FALSE(IsOpenCL(filter));
  EXPECT_EQ(chosen, vr::RelaxBackend::CPU);
  EXPECT_NE(notice.find("failed to build"), std::string::npos) << notice;
  EXPECT_NE(notice.find("oops"), std::string::npos) << notice;

  try
  {
    vr::CreateRelaxFilter(vr::RelaxBackend::OpenCL, "", notice);
    FAIL() << "a kernel that does not build was accepted";
  }
  catch (const vr::InputError & error)
  {
    EXPECT_NE(std::string(error.what()).find("oops"), std::string::npos) << error.what();
  }
}
} // namespace
