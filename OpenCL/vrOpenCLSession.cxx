// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrOpenCLSession.h"

#include "vrOpenCLSessionInternals.h"

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
  auto internals = std::make_unique<Internals>();
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

OpenCLSession::OpenCLSession(std::unique_ptr<Internals> internals)
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

OpenCLSession::Internals &
OpenCLSession::GetInternals()
{
  return *m_Internals;
}

cl::Program
OpenCLSession::Internals::Program(const std::string & fileName, const std::string & source, const std::string & options)
{
  const auto key = std::make_pair(source, options);
  const auto found = m_Programs.find(key);
  if (found != m_Programs.end())
  {
    return found->second;
  }
  cl::Program program(Context, source);
  try
  {
    program.build(std::vector<cl::Device>{ Device }, options.c_str());
  }
  catch (const cl::Error & error)
  {
    if (error.err() != CL_BUILD_PROGRAM_FAILURE)
    {
      throw;
    }
    throw OpenCLBuildFailure("the OpenCL program " + fileName + " failed to build for " + Info.Label() +
                               " (build options: " + options + ")",
                             program.getBuildInfo<CL_PROGRAM_BUILD_LOG>(Device));
  }
  m_Programs.emplace(key, program);
  return program;
}

void
OpenCLSession::Internals::Publish(const void * image, const void * hostBuffer, const OpenCLDeviceImage & device)
{
  m_Published[image] = Published{ hostBuffer, device };
}

void
OpenCLSession::Internals::Withdraw(const void * image)
{
  m_Published.erase(image);
}

bool
OpenCLSession::Internals::Find(const void *        image,
                               const void *        hostBuffer,
                               std::size_t         width,
                               std::size_t         height,
                               std::size_t         pixelBytes,
                               OpenCLDeviceImage & device)
{
  const auto found = m_Published.find(image);
  if (found == m_Published.end() || found->second.Host != hostBuffer || found->second.Device.Width != width ||
      found->second.Device.Height != height || found->second.Device.PixelBytes != pixelBytes)
  {
    return false;
  }
  device = found->second.Device;
  ++HandOffs;
  return true;
}

const OpenCLDeviceVolume &
OpenCLSession::Internals::Volume(const void *        volume,
                                 const void *        hostBuffer,
                                 unsigned long       modifiedTime,
                                 const std::string & voxelType,
                                 const std::size_t   size[3],
                                 std::size_t         bytes)
{
  if (m_Volume.Buffer() != nullptr && m_VolumeObject == volume && m_VolumeHost == hostBuffer &&
      m_VolumeTime == modifiedTime && m_Volume.VoxelType == voxelType && m_Volume.Bytes == bytes)
  {
    return m_Volume;
  }
  ReleaseVolume();
  OpenCLDeviceVolume uploaded;
  uploaded.VoxelType = voxelType;
  uploaded.Bytes = bytes;
  for (int axis = 0; axis < 3; ++axis)
  {
    uploaded.Size[axis] = size[axis];
  }
  // A CPU device reads the host's memory: no second copy of the volume. The host buffer outlives its use: a
  // volume is read only while its data object (and so its buffer) is the key above.
  if (Info.IsCPU)
  {
    uploaded.Buffer = cl::Buffer(
      Context, CL_MEM_READ_ONLY | CL_MEM_USE_HOST_PTR | CL_MEM_HOST_NO_ACCESS, bytes, const_cast<void *>(hostBuffer));
  }
  else
  {
    uploaded.Buffer = cl::Buffer(Context, CL_MEM_READ_ONLY | CL_MEM_HOST_WRITE_ONLY, bytes);
    Queue.enqueueWriteBuffer(uploaded.Buffer, CL_TRUE, 0, bytes, hostBuffer);
  }
  m_Volume = uploaded;
  m_VolumeObject = volume;
  m_VolumeHost = hostBuffer;
  m_VolumeTime = modifiedTime;
  ++VolumeUploads;
  return m_Volume;
}

void
OpenCLSession::Internals::ReleaseVolume()
{
  Queue.finish();
  m_Volume = OpenCLDeviceVolume();
  m_VolumeObject = nullptr;
  m_VolumeHost = nullptr;
  m_VolumeTime = 0;
}
} // namespace vr
