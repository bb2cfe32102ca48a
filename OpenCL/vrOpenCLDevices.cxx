// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrOpenCLDevices.h"
#include "vrText.h"

#include "vrInputError.h"
#include "vrOpenCLRuntime.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <regex>
#include <sstream>

namespace vr
{
namespace
{
// Drivers pad some strings with trailing NULs or spaces.
std::string
Trimmed(std::string text)
{
  const auto end = text.find_last_not_of(std::string(" \t\n\r\0", 5));
  return end == std::string::npos ? std::string() : text.substr(0, end + 1);
}

// Why the filter cannot run on a device, or "" when it can: it needs an available device with a compiler that
// speaks OpenCL 1.2 (clEnqueueFillBuffer, the 1.2 built-ins).
std::string
WhyUnusable(const cl::Device & device, const std::string & version)
{
  if (!device.getInfo<CL_DEVICE_AVAILABLE>())
  {
    return "the device is not available";
  }
  if (!device.getInfo<CL_DEVICE_COMPILER_AVAILABLE>())
  {
    return "the driver has no OpenCL C compiler for it";
  }
  int major = 0;
  int minor = 0;
  if (std::sscanf(version.c_str(), "OpenCL %d.%d", &major, &minor) != 2 || major * 10 + minor < 12)
  {
    return "it reports \"" + version + "\"; OpenCL 1.2 or newer is needed";
  }
  return std::string();
}

std::string
ListForMessage(const std::vector<OpenCLDeviceInfo> & devices, const std::string & problem)
{
  if (devices.empty())
  {
    return "no OpenCL device was found" + (problem.empty() ? std::string() : " (" + problem + ")");
  }
  std::ostringstream text;
  text << "devices found:";
  for (const auto & device : devices)
  {
    text << "\n  " << device.Label();
    if (!device.Unusable.empty())
    {
      text << " [not usable: " << device.Unusable << "]";
    }
  }
  return text.str();
}

std::string
Quoted(const std::string & request, const std::string & origin)
{
  return "OpenCL device \"" + request + "\"" + (origin.empty() ? std::string() : " (" + origin + ")");
}
} // namespace

std::string
OpenCLDeviceInfo::TypeName() const
{
  return IsGPU ? "GPU" : IsCPU ? "CPU" : "accelerator";
}

std::string
OpenCLDeviceInfo::Label() const
{
  std::ostringstream text;
  text << PlatformIndex << ':' << DeviceIndex << ' ' << DeviceName << " (" << PlatformName << ", " << TypeName() << ')';
  return text.str();
}

std::vector<OpenCLDeviceInfo>
ListOpenCLDevices(std::string * problem)
{
  std::vector<OpenCLDeviceInfo> found;
  std::string                   why;
  try
  {
    std::vector<cl::Platform> platforms;
    cl::Platform::get(&platforms);
    for (unsigned int p = 0; p < platforms.size(); ++p)
    {
      const std::string       platformName = Trimmed(platforms[p].getInfo<CL_PLATFORM_NAME>());
      std::vector<cl::Device> devices;
      try
      {
        platforms[p].getDevices(CL_DEVICE_TYPE_ALL, &devices);
      }
      catch (const cl::Error & error)
      {
        why += (why.empty() ? "" : "; ") + ("platform " + platformName + ": " + DescribeOpenCLError(error));
        continue;
      }
      for (unsigned int d = 0; d < devices.size(); ++d)
      {
        OpenCLDeviceInfo info;
        info.PlatformIndex = p;
        info.DeviceIndex = d;
        info.PlatformName = platformName;
        info.DeviceName = Trimmed(devices[d].getInfo<CL_DEVICE_NAME>());
        info.DeviceVersion = Trimmed(devices[d].getInfo<CL_DEVICE_VERSION>());
        const cl_device_type type = devices[d].getInfo<CL_DEVICE_TYPE>();
        info.IsGPU = (type & CL_DEVICE_TYPE_GPU) != 0;
        info.IsCPU = !info.IsGPU && (type & CL_DEVICE_TYPE_CPU) != 0;
        info.Unusable = WhyUnusable(devices[d], info.DeviceVersion);
        found.push_back(info);
      }
    }
    if (platforms.empty())
    {
      why = "no OpenCL platform is installed";
    }
  }
  catch (const cl::Error & error)
  {
    why = error.err() == -1001 ? "no OpenCL platform is installed (the ICD loader found no driver)"
                               : DescribeOpenCLError(error);
  }
  catch (const std::exception & error)
  {
    why = error.what();
  }
  if (problem)
  {
    *problem = found.empty() ? why : std::string();
  }
  return found;
}

OpenCLDeviceInfo
ChooseOpenCLDevice(const std::vector<OpenCLDeviceInfo> & devices,
                   const std::string &                   request,
                   const std::string &                   origin,
                   const std::string &                   problem)
{
  if (request.empty())
  {
    for (const bool wantGPU : { true, false })
    {
      for (const auto & device : devices)
      {
        if (device.Unusable.empty() && device.IsGPU == wantGPU && (wantGPU || device.IsCPU))
        {
          return device;
        }
      }
    }
    for (const auto & device : devices)
    {
      if (device.Unusable.empty())
      {
        return device;
      }
    }
    throw InputError("no usable OpenCL device: " + ListForMessage(devices, problem));
  }

  const OpenCLDeviceInfo * match = nullptr;
  std::smatch              indices;
  if (std::regex_match(request, indices, std::regex(R"(\s*(\d+)\s*:\s*(\d+)\s*)")))
  {
    const unsigned long platform = std::stoul(indices[1]);
    const unsigned long device = std::stoul(indices[2]);
    for (const auto & candidate : devices)
    {
      if (candidate.PlatformIndex == platform && candidate.DeviceIndex == device)
      {
        match = &candidate;
        break;
      }
    }
  }
  else
  {
    const std::string wanted = ToLower(request);
    for (const auto & candidate : devices)
    {
      if (ToLower(candidate.DeviceName).find(wanted) != std::string::npos ||
          ToLower(candidate.PlatformName).find(wanted) != std::string::npos)
      {
        match = &candidate;
        break;
      }
    }
  }
  if (!match)
  {
    throw InputError(Quoted(request, origin) + " does not exist; " + ListForMessage(devices, problem));
  }
  if (!match->Unusable.empty())
  {
    throw InputError(Quoted(request, origin) + " is " + match->Label() +
                     ", which cannot run the filter: " + match->Unusable);
  }
  return *match;
}

OpenCLDeviceInfo
FindOpenCLDevice(const std::string & request, const std::string & origin)
{
  std::string effectiveRequest = request;
  std::string effectiveOrigin = origin;
  if (effectiveRequest.empty())
  {
    const char * fromEnvironment = std::getenv(OpenCLDeviceEnvironmentVariable);
    if (fromEnvironment && *fromEnvironment)
    {
      effectiveRequest = fromEnvironment;
      effectiveOrigin = std::string("environment variable ") + OpenCLDeviceEnvironmentVariable;
    }
  }
  std::string                         problem;
  const std::vector<OpenCLDeviceInfo> devices = ListOpenCLDevices(&problem);
  return ChooseOpenCLDevice(devices, effectiveRequest, effectiveOrigin, problem);
}
} // namespace vr
