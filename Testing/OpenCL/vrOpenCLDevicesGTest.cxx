// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Choosing an OpenCL device: the rules of vr::ChooseOpenCLDevice on device lists made by hand (no hardware
// needed), and vr::ListOpenCLDevices on the machine.
#include "vrInputError.h"
#include "vrOpenCLDevices.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace
{
vr::OpenCLDeviceInfo
Device(unsigned int        platform,
       unsigned int        index,
       const std::string & platformName,
       const std::string & name,
       bool                gpu,
       const std::string & unusable = std::string())
{
  vr::OpenCLDeviceInfo device;
  device.PlatformIndex = platform;
  device.DeviceIndex = index;
  device.PlatformName = platformName;
  device.DeviceName = name;
  device.DeviceVersion = "OpenCL 3.0";
  device.IsGPU = gpu;
  device.IsCPU = !gpu;
  device.Unusable = unusable;
  return device;
}

// A CPU platform listed before a GPU platform, as on a workstation with PoCL and a vendor driver.
const std::vector<vr::OpenCLDeviceInfo> Workstation{
  Device(0, 0, "Portable Computing Language", "pthread-haswell-Intel Xeon", false),
  Device(1, 0, "NVIDIA CUDA", "NVIDIA GeForce RTX 3060", true),
  Device(1, 1, "NVIDIA CUDA", "NVIDIA GeForce GTX 760", true),
};

std::string
MessageOf(const std::vector<vr::OpenCLDeviceInfo> & devices,
          const std::string &                       request,
          const std::string &                       origin = "test",
          const std::string &                       problem = std::string())
{
  try
  {
    vr::ChooseOpenCLDevice(devices, request, origin, problem);
  }
  catch (const vr::InputError & error)
  {
    return error.what();
  }
  ADD_FAILURE() << "request \"" << request << "\" was accepted";
  return std::string();
}

TEST(OpenCLDevices, TheDefaultIsTheFirstGPUEvenOnALaterPlatform)
{
  const auto chosen = vr::ChooseOpenCLDevice(Workstation, "", "test");
  EXPECT_EQ(chosen.PlatformIndex, 1u);
  EXPECT_EQ(chosen.DeviceIndex, 0u);
}

TEST(OpenCLDevices, TheDefaultIsACPUDeviceWhenThereIsNoGPU)
{
  const std::vector<vr::OpenCLDeviceInfo> laptop{ Device(0, 0, "Portable Computing Language", "pthread-cpu", false) };
  EXPECT_EQ(vr::ChooseOpenCLDevice(laptop, "", "test").DeviceName, "pthread-cpu");
}

TEST(OpenCLDevices, TheDefaultSkipsUnusableDevices)
{
  const std::vector<vr::OpenCLDeviceInfo> devices{
    Device(0, 0, "Old", "old GPU", true, "it reports \"OpenCL 1.1\"; OpenCL 1.2 or newer is needed"),
    Device(1, 0, "Portable Computing Language", "pthread-cpu", false),
  };
  EXPECT_EQ(vr::ChooseOpenCLDevice(devices, "", "test").DeviceName, "pthread-cpu");
}

TEST(OpenCLDevices, PlatformAndDeviceIndicesPickThatDevice)
{
  EXPECT_EQ(vr::ChooseOpenCLDevice(Workstation, "1:1", "test").DeviceName, "NVIDIA GeForce GTX 760");
  EXPECT_EQ(vr::ChooseOpenCLDevice(Workstation, "0:0", "test").DeviceName, "pthread-haswell-Intel Xeon");
  EXPECT_EQ(vr::ChooseOpenCLDevice(Workstation, " 1 : 0 ", "test").DeviceName, "NVIDIA GeForce RTX 3060");
}

TEST(OpenCLDevices, ANameSubstringPicksTheFirstDeviceOrPlatformContainingItIgnoringCase)
{
  EXPECT_EQ(vr::ChooseOpenCLDevice(Workstation, "gtx 760", "test").DeviceName, "NVIDIA GeForce GTX 760");
  EXPECT_EQ(vr::ChooseOpenCLDevice(Workstation, "geforce", "test").DeviceName, "NVIDIA GeForce RTX 3060");
  EXPECT_EQ(vr::ChooseOpenCLDevice(Workstation, "portable", "test").DeviceName, "pthread-haswell-Intel Xeon");
}

TEST(OpenCLDevices, AMissingDeviceIsAnErrorListingTheDevicesThatExist)
{
  for (const std::string request : { "radeon", "2:0", "1:5" })
  {
    const std::string message = MessageOf(Workstation, request, "--opencl-device");
    EXPECT_NE(message.find("\"" + request + "\""), std::string::npos) << message;
    EXPECT_NE(message.find("--opencl-device"), std::string::npos) << message;
    EXPECT_NE(message.find("0:0 pthread-haswell-Intel Xeon (Portable Computing Language, CPU)"), std::string::npos)
      << message;
    EXPECT_NE(message.find("1:0 NVIDIA GeForce RTX 3060 (NVIDIA CUDA, GPU)"), std::string::npos) << message;
    EXPECT_NE(message.find("1:1 NVIDIA GeForce GTX 760 (NVIDIA CUDA, GPU)"), std::string::npos) << message;
  }
}

TEST(OpenCLDevices, NoDeviceAtAllIsAnErrorSayingWhy)
{
  const std::string byDefault = MessageOf({}, "", "test", "no OpenCL platform is installed");
  EXPECT_NE(byDefault.find("no OpenCL device was found"), std::string::npos) << byDefault;
  EXPECT_NE(byDefault.find("no OpenCL platform is installed"), std::string::npos) << byDefault;
  const std::string byName = MessageOf({}, "0:0");
  EXPECT_NE(byName.find("no OpenCL device was found"), std::string::npos) << byName;
}

TEST(OpenCLDevices, AnUnusableDeviceIsAnErrorSayingWhy)
{
  const std::vector<vr::OpenCLDeviceInfo> devices{ Device(
    0, 0, "Old", "old GPU", true, "the device is not available") };
  const std::string                       explicitly = MessageOf(devices, "old");
  EXPECT_NE(explicitly.find("the device is not available"), std::string::npos) << explicitly;
  const std::string byDefault = MessageOf(devices, "");
  EXPECT_NE(byDefault.find("no usable OpenCL device"), std::string::npos) << byDefault;
  EXPECT_NE(byDefault.find("0:0 old GPU (Old, GPU) [not usable: the device is not available]"), std::string::npos)
    << byDefault;
}

TEST(OpenCLDevices, ListingTheMachinesDevicesNeverThrowsAndExplainsAnEmptyList)
{
  std::string                       problem = "stale";
  std::vector<vr::OpenCLDeviceInfo> devices;
  ASSERT_NO_THROW(devices = vr::ListOpenCLDevices(&problem));
  if (devices.empty())
  {
    EXPECT_FALSE(problem.empty());
    GTEST_SKIP() << "no OpenCL device on this machine: " << problem;
  }
  EXPECT_TRUE(problem.empty());
  for (const auto & device : devices)
  {
    EXPECT_FALSE(device.DeviceName.empty());
    EXPECT_FALSE(device.PlatformName.empty());
    EXPECT_EQ(device.DeviceVersion.rfind("OpenCL ", 0), 0u) << device.DeviceVersion;
  }
}
} // namespace
