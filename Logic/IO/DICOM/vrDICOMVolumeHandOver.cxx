// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrDICOMVolumeHandOver.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace vr::detail
{
std::size_t
DICOMVolumePixelBytes(itk::IOComponentEnum pixelType)
{
  switch (pixelType)
  {
    case itk::IOComponentEnum::UCHAR:
    case itk::IOComponentEnum::CHAR:
      return 1;
    case itk::IOComponentEnum::USHORT:
    case itk::IOComponentEnum::SHORT:
      return 2;
    case itk::IOComponentEnum::FLOAT:
      return 4;
    default:
      return 0;
  }
}

DICOMVolumeHandOverWriter::~DICOMVolumeHandOverWriter()
{
  Close();
}

std::string
DICOMVolumeHandOverWriter::Open(int descriptor, itk::IOComponentEnum pixelType, std::uint64_t voxels)
{
  Close();
  const std::size_t   pixelBytes = DICOMVolumePixelBytes(pixelType);
  const std::uint64_t voxelBytes = voxels * pixelBytes;
  if (pixelBytes == 0 || voxels == 0)
  {
    return "the volume has no voxels or a pixel type the hand-over does not carry";
  }
  const std::uint64_t length = DICOMVolumeVoxelOffset + voxelBytes;
  if (::ftruncate(descriptor, static_cast<off_t>(length)) != 0)
  {
    return "the hand-over file cannot be sized to " + std::to_string(length) + " bytes: " + std::strerror(errno);
  }
  // Reserved now (a memfd's pages are memory): a volume that does not fit fails here with a reason, where writing into
  // a mapping that cannot be backed would end the process on SIGBUS. A file system without fallocate is left as it is.
  if (const int error = ::posix_fallocate(descriptor, 0, static_cast<off_t>(length));
      error != 0 && error != EOPNOTSUPP && error != EINVAL)
  {
    return "no room for the volume's " + std::to_string(voxelBytes) + " bytes: " + std::strerror(error);
  }
  void * mapping = ::mmap(nullptr, length, PROT_READ | PROT_WRITE, MAP_SHARED, descriptor, 0);
  if (mapping == MAP_FAILED)
  {
    return "the hand-over file of " + std::to_string(length) + " bytes cannot be mapped: " + std::strerror(errno);
  }
  m_Mapping = mapping;
  m_Length = length;
  m_Voxels = static_cast<char *>(mapping) + DICOMVolumeVoxelOffset;
  m_PixelType = pixelType;
  return std::string();
}

void
DICOMVolumeHandOverWriter::Finish(DICOMVolumeHeader header)
{
  if (m_Mapping == nullptr)
  {
    return;
  }
  std::memcpy(header.Magic, DICOMVolumeMagic, sizeof(header.Magic));
  header.Version = DICOMVolumeVersion;
  header.PixelType = static_cast<std::uint32_t>(m_PixelType);
  header.VoxelBytes = m_Length - DICOMVolumeVoxelOffset;
  std::memset(header.Complete, 0, sizeof(header.Complete));
  auto * target = static_cast<DICOMVolumeHeader *>(m_Mapping);
  std::memcpy(target, &header, sizeof(header));
  // The marker last: a header without it is one the child did not finish.
  std::memcpy(target->Complete, DICOMVolumeCompleteMarker, sizeof(header.Complete));
  Close();
}

void
DICOMVolumeHandOverWriter::Close()
{
  if (m_Mapping != nullptr)
  {
    ::munmap(m_Mapping, m_Length);
  }
  m_Mapping = nullptr;
  m_Voxels = nullptr;
  m_Length = 0;
}
} // namespace vr::detail
