// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrOpenCLSessionState.h"

#include <iterator>
#include <vector>

namespace vr
{
cl::Program
OpenCLSessionState::Program(const std::string & fileName, const std::string & source, const std::string & options)
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
OpenCLSessionState::Publish(const void *              producer,
                            const void *              image,
                            const void *              hostBuffer,
                            const OpenCLDeviceImage & device)
{
  m_Published[image] = Published{ producer, hostBuffer, device };
}

void
OpenCLSessionState::WithdrawAll(const void * producer)
{
  for (auto entry = m_Published.begin(); entry != m_Published.end();)
  {
    entry = entry->second.Producer == producer ? m_Published.erase(entry) : std::next(entry);
  }
}

bool
OpenCLSessionState::Find(const void *        image,
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
OpenCLSessionState::Volume(const void *        volume,
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
OpenCLSessionState::ReleaseVolume()
{
  Queue.finish();
  m_Volume = OpenCLDeviceVolume();
  m_VolumeObject = nullptr;
  m_VolumeHost = nullptr;
  m_VolumeTime = 0;
}
} // namespace vr
