// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// OpenCLBilateralDepthRelaxFilter::GetWorkspaceBytes against the bytes an update keeps in host memory, counted by
// allocation (vrAllocationCounter replaces malloc in this executable): on a CPU device its buffers are the host's;
// a GPU's are not, and the report says 0.
#include "vrAllocationCounter.h"
#include "vrOpenCLTestSupport.h"
#include "vrTestImages.h"

#include "itkOpenCLBilateralDepthRelaxFilter.h"
#include "vrOpenCLDevices.h"

#include <gtest/gtest.h>

#include <iostream>
#include <string>

namespace
{
using Filter = itk::OpenCLBilateralDepthRelaxFilter;

/** "P:D" of the first usable device that is (\a cpu) or is not a CPU, "" when there is none. */
std::string
FirstDevice(bool cpu)
{
  for (const auto & device : vr::ListOpenCLDevices())
  {
    if (device.Unusable.empty() && device.IsCPU == cpu)
    {
      return std::to_string(device.PlatformIndex) + ":" + std::to_string(device.DeviceIndex);
    }
  }
  return "";
}
} // namespace

TEST(OpenCLBilateralDepthRelaxWorkspace, ReportedBytesMatchTheHostBytesAnUpdateKeeps)
{
  VR_SKIP_WITHOUT_OPENCL_DEVICE();
  const auto map = vr::test::MakePhantomDepthMap(512, 1024);
  const auto size = map.Depth->GetLargestPossibleRegion().GetSize();
  for (const bool cpu : { true, false })
  {
    const std::string device = FirstDevice(cpu);
    if (device.empty())
    {
      continue;
    }
    auto filter = Filter::New();
    filter->SetDeviceRequest(device);
    filter->SetInput(map.Depth);
    filter->SetFixedMask(map.Fixed);
    filter->SetNumberOfIterations(20);
    filter->PrepareDevice(); // the program and the device's own allocations, before the count
    const long long before = vr::test::AllocatedBytes();
    filter->Update();
    const long long output = static_cast<long long>(size[0] * size[1] * sizeof(float));
    const long long kept = vr::test::AllocatedBytes() - before - output;
    const double    reported = static_cast<double>(filter->GetWorkspaceBytes(size));
    const double    pixels = static_cast<double>(size[0]) * size[1];
    std::cout << filter->GetDeviceLabel() << ": kept " << kept / pixels << " bytes per pixel in host memory, reported "
              << reported / pixels << std::endl;
    if (cpu)
    {
      EXPECT_NEAR(static_cast<double>(kept), reported, 0.01 * reported);
    }
    else
    {
      EXPECT_EQ(reported, 0.0);
    }
  }
}
