// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrOpenCLSession.h"

#include "vrOpenCLSessionState.h"

#include "itkMacro.h"

#include <vector>

namespace vr
{
std::shared_ptr<OpenCLSession>
OpenCLSession::Create(const std::string & request, const std::string & origin)
{
  return Create(FindOpenCLDevice(request, origin));
}

std::shared_ptr<OpenCLSession>
OpenCLSession::Create(const OpenCLDeviceInfo & device)
{
  auto internals = std::make_unique<OpenCLSessionState>();
  internals->Info = device;
  try
  {
    internals->Device = GetOpenCLDevice(device.PlatformIndex, device.DeviceIndex);
    internals->Context = cl::Context(internals->Device);
    internals->Queue = cl::CommandQueue(internals->Context, internals->Device);
    const std::string extensions = internals->Device.getInfo<CL_DEVICE_EXTENSIONS>();
    internals->DoublePrecision = extensions.find("cl_khr_fp64") != std::string::npos;
    internals->LocalMemoryBytes = internals->Device.getInfo<CL_DEVICE_LOCAL_MEM_SIZE>();
    internals->MaximumAllocationBytes = internals->Device.getInfo<CL_DEVICE_MAX_MEM_ALLOC_SIZE>();
  }
  catch (const cl::Error & error)
  {
    itkGenericExceptionMacro(<< "opening OpenCL device " << device.Label() << ": " << DescribeOpenCLError(error));
  }
  return std::shared_ptr<OpenCLSession>(new OpenCLSession(std::move(internals)));
}

OpenCLSession::OpenCLSession(std::unique_ptr<OpenCLSessionState> internals)
  : m_Internals(std::move(internals))
{
}

OpenCLSession::~OpenCLSession()
{
  try
  {
    m_Internals->Queue.finish(); // nothing may still read or write host memory the buffers alias
  }
  catch (const cl::Error &)
  {
  }
}

const OpenCLDeviceInfo &
OpenCLSession::GetDeviceInfo() const
{
  return m_Internals->Info;
}

bool
OpenCLSession::HasDoublePrecision() const
{
  return m_Internals->DoublePrecision;
}

std::size_t
OpenCLSession::GetVolumeBytes() const
{
  return m_Internals->VolumeBytes();
}

std::size_t
OpenCLSession::GetVolumeUploads() const
{
  return m_Internals->VolumeUploads;
}

std::size_t
OpenCLSession::GetDeviceHandOffs() const
{
  return m_Internals->HandOffs;
}

void
OpenCLSession::ReleaseVolume()
{
  m_Internals->ReleaseVolume();
}

OpenCLSessionState &
OpenCLSession::GetInternals()
{
  return *m_Internals;
}

} // namespace vr
