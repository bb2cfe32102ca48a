// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrOpenCLSessionState_h
#define vrOpenCLSessionState_h

// Private to VesselReformationOpenCL: what the OpenCL filters share through a vr::OpenCLSession (which holds one).
#include "vrOpenCLDevices.h"
#include "vrOpenCLRuntime.h"

#include <cstddef>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

namespace vr
{
/** A program that did not build: what() names the file and the device, Log() is the compiler's log. */
class OpenCLBuildFailure : public std::runtime_error
{
public:
  OpenCLBuildFailure(const std::string & message, std::string log)
    : std::runtime_error(message)
    , m_Log(std::move(log))
  {
  }
  const std::string &
  Log() const
  {
    return m_Log;
  }

private:
  std::string m_Log;
};

/** A 2D image of W x H pixels in a device buffer: row y starts at Offset + y * RowPitch bytes. */
struct OpenCLDeviceImage
{
  cl::Buffer  Buffer;
  std::size_t Offset{ 0 };
  std::size_t RowPitch{ 0 };
  std::size_t Width{ 0 };
  std::size_t Height{ 0 };
  std::size_t PixelBytes{ 0 };
};

/** The volume a session keeps on its device: the voxels in their stored type, x fastest. */
struct OpenCLDeviceVolume
{
  cl::Buffer  Buffer;
  std::string VoxelType; // the OpenCL C type name: short, ushort, char, uchar, float, double
  std::size_t Size[3]{ 0, 0, 0 };
  std::size_t Bytes{ 0 };
};

/** A vr::OpenCLSession's device, context, queue, programs, published device images and volume. */
struct OpenCLSessionState
{
  OpenCLDeviceInfo Info;
  cl::Device       Device;
  cl::Context      Context;
  /** In order: a kernel sees what the commands before it wrote. */
  cl::CommandQueue Queue;
  bool             DoublePrecision{ false };
  std::size_t      LocalMemoryBytes{ 0 };
  std::size_t      MaximumAllocationBytes{ 0 };

  /** The program built from \a source with \a options, built on first use and kept. \a fileName names the source
   * in messages. Throws OpenCLBuildFailure (with the log) when it does not build, cl::Error for other failures. */
  cl::Program
  Program(const std::string & fileName, const std::string & source, const std::string & options);

  /** Records that the host image \a image, an output of the filter \a producer of this session whose pixels are at
   * \a hostBuffer, holds what \a device holds. A later Find() for it reads the device copy, until the producer
   * withdraws its images. */
  void
  Publish(const void * producer, const void * image, const void * hostBuffer, const OpenCLDeviceImage & device);
  /** Forgets the device copies of every image \a producer published: it is about to write its device buffers again
   * (its next update), or goes away. An output disconnected from the producer in between is forgotten too, so a
   * consumer never reads a device buffer that holds something newer than its host image. */
  void
  WithdrawAll(const void * producer);
  /** The device copy of \a image when a filter of this session published it and the image's pixels are still at
   * \a hostBuffer with \a width x \a height pixels of \a pixelBytes bytes; counts a hand-off. */
  bool
  Find(const void *        image,
       const void *        hostBuffer,
       std::size_t         width,
       std::size_t         height,
       std::size_t         pixelBytes,
       OpenCLDeviceImage & device);

  /** The device copy of the volume whose voxels (\a bytes bytes of \a voxelType, \a size voxels, x fastest) are at
   * \a hostBuffer in the data object \a volume last modified at \a modifiedTime: uploaded on the first call and
   * whenever another volume (or a modified one) comes, else the copy already there. On a CPU device the buffer
   * uses the host's memory (no second copy). Throws cl::Error (e.g. CL_MEM_OBJECT_ALLOCATION_FAILURE,
   * CL_INVALID_BUFFER_SIZE) when the device cannot hold it. */
  const OpenCLDeviceVolume &
  Volume(const void *        volume,
         const void *        hostBuffer,
         unsigned long       modifiedTime,
         const std::string & voxelType,
         const std::size_t   size[3],
         std::size_t         bytes);
  void
  ReleaseVolume();
  std::size_t
  VolumeBytes() const
  {
    return m_Volume.Bytes;
  }

  std::size_t VolumeUploads{ 0 };
  std::size_t HandOffs{ 0 };

private:
  struct Published
  {
    const void *      Producer{ nullptr };
    const void *      Host{ nullptr };
    OpenCLDeviceImage Device;
  };
  std::map<std::pair<std::string, std::string>, cl::Program> m_Programs; // by source and options
  std::map<const void *, Published>                          m_Published;

  OpenCLDeviceVolume m_Volume;
  const void *       m_VolumeObject{ nullptr };
  const void *       m_VolumeHost{ nullptr };
  unsigned long      m_VolumeTime{ 0 };
};
} // namespace vr

#endif
