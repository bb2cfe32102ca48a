// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The module logic with the whole view on an OpenCL device (docs/opencl.md "The whole view on the device"): with
// backend opencl the depth map, the relaxation and both CPR images come from the device and agree with backend cpu
// (depth map: bits; relaxed depth: 1e-4 mm; images: 1e-3 of the window) on both phantoms and the VMTK aorta; the
// volume is uploaded once while the view turns; a stage without a kernel runs on the CPU and says so; auto keeps its
// rule (OpenCL only on a GPU or accelerator). Skipped, with the reason, without an OpenCL device.
#include "itkOpenCLCPRResampleImageFilter.h"
#include "vrOpenCLSession.h"
#include "vrOpenCLTestSupport.h"
#include "vrReformationInputs.h"
#include "vrVesselReformationLogic.h"

#include <gtest/gtest.h>

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

namespace
{
using vr::ReformationParameters;
using vr::VesselReformationLogic;

/** The pixels of a one-slice output node, whatever its scalar type. */
std::vector<double>
PixelsOf(const vr::VolumeNode * node)
{
  vtkDataArray *      scalars = node->GetImageData()->GetPointData()->GetScalars();
  std::vector<double> values(static_cast<std::size_t>(scalars->GetNumberOfTuples()));
  for (vtkIdType k = 0; k < scalars->GetNumberOfTuples(); ++k)
  {
    values[static_cast<std::size_t>(k)] = scalars->GetComponent(k, 0);
  }
  return values;
}

double
MaxAbsoluteDifference(const vr::VolumeNode * a, const vr::VolumeNode * b)
{
  const auto va = PixelsOf(a);
  const auto vb = PixelsOf(b);
  EXPECT_EQ(va.size(), vb.size());
  double largest = 0.0;
  for (std::size_t k = 0; k < std::min(va.size(), vb.size()); ++k)
  {
    const double difference = std::fabs(va[k] - vb[k]);
    largest = std::isnan(difference) ? INFINITY : std::max(largest, difference);
  }
  return largest;
}

struct Case
{
  std::string           Name;
  vr::ReformationInputs Inputs;
  double                Angle;
  bool                  AutomaticUp;
  double                Window;
};

Case
PhantomCase(const std::string & name, double angle)
{
  return { name, vr::MakePhantomInputs(name, 2.0), angle, false, 900.0 };
}

Case
AortaCase(double angle)
{
  const std::filesystem::path folder = std::filesystem::path(VR_SHARED_DATA_DIR) / "vmtk-aorta-mra";
  return { "VMTK aorta",
           vr::MakeInputs(vr::ReadVolumeNode((folder / "aorta.mha").string()),
                          vr::ReadCenterlineNode((folder / "aorta-centerline.vtp").string())),
           angle,
           true,
           1800.0 };
}

ReformationParameters
Parameters(const Case & c, vr::RelaxBackend backend)
{
  ReformationParameters parameters;
  parameters.AutomaticUp = c.AutomaticUp;
  parameters.AngleInDegrees = c.Angle;
  parameters.ImageSize[0] = 256;
  parameters.ImageSize[1] = 512;
  parameters.Iterations = 300;
  parameters.Backend = backend;
  return parameters;
}

void
Prepare(VesselReformationLogic & logic, const Case & c, vr::RelaxBackend backend)
{
  logic.SetVolumeNode(c.Inputs.Volume);
  logic.SetCenterlineNode(c.Inputs.Centerlines);
  logic.SetSurfaceEnabled(false);
  logic.SetParameters(Parameters(c, backend));
}

/** Runs the case on the CPU and on the device and compares every output. */
void
ExpectTheDeviceMatchesTheCPU(const Case & c)
{
  VesselReformationLogic cpu;
  VesselReformationLogic opencl;
  Prepare(cpu, c, vr::RelaxBackend::CPU);
  Prepare(opencl, c, vr::RelaxBackend::OpenCL);
  const vr::ReformationOutputs & onCPU = cpu.Update();
  const vr::ReformationOutputs & onDevice = opencl.Update();
  EXPECT_EQ(onDevice.RelaxBackendUsed, "opencl") << c.Name;
  EXPECT_EQ(onDevice.DepthBackendUsed, "opencl") << c.Name << ": " << onDevice.DepthBackendReason;
  EXPECT_EQ(onDevice.ResampleBackendUsed, "opencl") << c.Name << ": " << onDevice.ResampleBackendReason;
  EXPECT_EQ(onCPU.DepthBackendUsed, "cpu");
  EXPECT_EQ(onCPU.ResampleBackendUsed, "cpu");
  EXPECT_EQ(PixelsOf(onDevice.Depth), PixelsOf(onCPU.Depth)) << c.Name;
  EXPECT_EQ(PixelsOf(onDevice.FixedMask), PixelsOf(onCPU.FixedMask)) << c.Name;
  const double relaxed = MaxAbsoluteDifference(onDevice.RelaxedDepth, onCPU.RelaxedDepth);
  const double image = MaxAbsoluteDifference(onDevice.CPR, onCPU.CPR);
  const double unfiltered = MaxAbsoluteDifference(onDevice.UnfilteredCPR, onCPU.UnfilteredCPR);
  std::cout << c.Name << " at " << c.Angle << " degrees: relaxed depth within " << relaxed << " mm, CPR within "
            << image << ", unfiltered CPR within " << unfiltered << std::endl;
  EXPECT_LE(relaxed, 1e-4) << c.Name;
  EXPECT_LE(image, 1e-3 * c.Window) << c.Name;
  EXPECT_LE(unfiltered, 1e-3 * c.Window) << c.Name;
  // Not vacuous: the relaxation moved the depth map.
  EXPECT_GT(MaxAbsoluteDifference(onCPU.RelaxedDepth, onCPU.Depth), 0.5) << c.Name;
}
} // namespace

TEST(VesselReformationLogicOpenCL, TheWholeViewOnTheDeviceMatchesTheCPUOnBothPhantomsAndTheVMTKAorta)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  ExpectTheDeviceMatchesTheCPU(PhantomCase("runoff", 30.0));
  ExpectTheDeviceMatchesTheCPU(PhantomCase("thorax", 20.0));
  ExpectTheDeviceMatchesTheCPU(AortaCase(0.0));
  ExpectTheDeviceMatchesTheCPU(AortaCase(90.0));
}

// Turning the view reruns depth, relaxation and both samplings on the device; the volume stays there.
TEST(VesselReformationLogicOpenCL, TurningTheViewUploadsTheVolumeOnce)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const Case             c = PhantomCase("runoff", 30.0);
  VesselReformationLogic logic;
  Prepare(logic, c, vr::RelaxBackend::OpenCL);
  for (int step = 0; step < 4; ++step)
  {
    ReformationParameters parameters = Parameters(c, vr::RelaxBackend::OpenCL);
    parameters.AngleInDegrees = 30.0 + step;
    logic.SetParameters(parameters);
    logic.Update();
  }
  const auto * resample =
    dynamic_cast<itk::OpenCLCPRResampleImageFilter<itk::ImageBase<3>> *>(logic.GetResampleFilter());
  ASSERT_NE(resample, nullptr);
  EXPECT_TRUE(resample->GetDepthWasOnDevice());
  EXPECT_EQ(resample->GetSession()->GetVolumeUploads(), 1u);
  EXPECT_EQ(logic.GetStageCounts().Depth, 4u);
}

// Cubic interpolation has no kernel: the depth map and the relaxation stay on the device, the sampling runs on the
// CPU, and the outputs say which and why.
TEST(VesselReformationLogicOpenCL, ASamplingWithoutAKernelRunsOnTheCPUAndSaysWhy)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const Case             c = PhantomCase("thorax", 20.0);
  VesselReformationLogic logic;
  Prepare(logic, c, vr::RelaxBackend::OpenCL);
  ReformationParameters parameters = Parameters(c, vr::RelaxBackend::OpenCL);
  parameters.Interpolation = itk::CPRInterpolationMode::Cubic;
  logic.SetParameters(parameters);
  const vr::ReformationOutputs & outputs = logic.Update();
  EXPECT_EQ(outputs.DepthBackendUsed, "opencl");
  EXPECT_EQ(outputs.ResampleBackendUsed, "cpu");
  EXPECT_NE(outputs.ResampleBackendReason.find("cubic interpolation has no OpenCL kernel"), std::string::npos)
    << outputs.ResampleBackendReason;
}

// Switching the backend back and forth gives each backend's own outputs, made anew from the filters in use.
TEST(VesselReformationLogicOpenCL, SwitchingTheBackendGivesTheOutputsOfTheFiltersInUse)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const Case             c = PhantomCase("runoff", 30.0);
  VesselReformationLogic logic;
  for (const auto backend : { vr::RelaxBackend::CPU, vr::RelaxBackend::OpenCL, vr::RelaxBackend::CPU })
  {
    Prepare(logic, c, backend);
    const vr::ReformationOutputs & outputs = logic.Update();
    const std::string              expected = backend == vr::RelaxBackend::CPU ? "cpu" : "opencl";
    EXPECT_EQ(outputs.DepthBackendUsed, expected);
    EXPECT_EQ(outputs.ResampleBackendUsed, expected);
    EXPECT_EQ(outputs.RelaxBackendUsed, expected);
    const float * depth = logic.GetDepthFilter()->GetDepthOutput()->GetBufferPointer();
    EXPECT_EQ(PixelsOf(outputs.Depth), std::vector<double>(depth, depth + 256 * 512));
  }
}

// docs/design.md's rule stays: auto takes OpenCL only on a GPU or an accelerator, so on a CPU device (PoCL) the whole
// view runs on the CPU.
TEST(VesselReformationLogicOpenCL, AutoOnACPUDeviceKeepsTheWholeViewOnTheCPU)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const Case             c = PhantomCase("runoff", 30.0);
  VesselReformationLogic logic;
  logic.SetOpenCLDeviceQuery(
    [](const std::string &)
    {
      vr::OpenCLDeviceKind kind;
      kind.Label = "0:0 stub device (stub platform, CPU)";
      kind.Type = "CPU";
      return kind;
    });
  Prepare(logic, c, vr::RelaxBackend::Auto);
  const vr::ReformationOutputs & outputs = logic.Update();
  EXPECT_EQ(outputs.RelaxBackendUsed, "cpu");
  EXPECT_EQ(outputs.DepthBackendUsed, "cpu");
  EXPECT_EQ(outputs.ResampleBackendUsed, "cpu");
}
