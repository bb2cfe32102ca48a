// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrOpenCLDevices_h
#define vrOpenCLDevices_h

#include <string>
#include <vector>

namespace vr
{
/** One OpenCL device as the installed drivers report it.
 * \ingroup VesselReformation
 */
struct OpenCLDeviceInfo
{
  /** Position of the platform in clGetPlatformIDs' list and of the device in its platform's list. */
  unsigned int PlatformIndex{ 0 };
  unsigned int DeviceIndex{ 0 };
  std::string  PlatformName;
  std::string  DeviceName;
  /** CL_DEVICE_VERSION, e.g. "OpenCL 3.0 CUDA". */
  std::string DeviceVersion;
  bool        IsGPU{ false };
  bool        IsCPU{ false };
  /** Empty when the filter can run on the device; otherwise why not (unavailable, no compiler, OpenCL < 1.2). */
  std::string Unusable;

  /** "GPU", "CPU" or "accelerator". */
  std::string
  TypeName() const;
  /** "P:D name (platform, type)", the way messages and listings name the device. */
  std::string
  Label() const;
};

/** Every OpenCL device of every platform, in platform then device order. Never throws: when there is none, the
 * list is empty and \a problem (if given) receives why, e.g. that no OpenCL platform is installed. */
std::vector<OpenCLDeviceInfo>
ListOpenCLDevices(std::string * problem = nullptr);

/** The environment variable that picks the OpenCL device when no request is given explicitly. */
constexpr const char * OpenCLDeviceEnvironmentVariable = "VR_OPENCL_DEVICE";

/** Picks the device for \a request among \a devices:
 * - ""     the first usable GPU, else the first usable CPU device, else the first usable device;
 * - "P:D"  device D of platform P (the indices ListOpenCLDevices() reports);
 * - other  the first device whose name or platform name contains \a request, ignoring case.
 * \a origin names where the request came from (a parameter, a flag, the environment variable) for messages, and
 * \a problem is what ListOpenCLDevices() said when it found nothing.
 * \return the chosen device, which is usable.
 * Throws vr::InputError naming the request and listing the devices that exist (or saying there are none) when
 * nothing matches or the match is unusable. */
OpenCLDeviceInfo
ChooseOpenCLDevice(const std::vector<OpenCLDeviceInfo> & devices,
                   const std::string &                   request,
                   const std::string &                   origin,
                   const std::string &                   problem = std::string());

/** The device for \a request, or for VR_OPENCL_DEVICE when \a request is empty, among the installed ones:
 * ChooseOpenCLDevice(ListOpenCLDevices(), ...). \a origin names the explicit request in messages.
 * Throws vr::InputError like ChooseOpenCLDevice. */
OpenCLDeviceInfo
FindOpenCLDevice(const std::string & request, const std::string & origin);
} // namespace vr

#endif
