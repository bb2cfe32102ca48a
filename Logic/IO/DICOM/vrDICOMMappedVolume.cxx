// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrDICOMMappedVolume.h"

#include "vrDICOMVolumeHandOver.h"
#include "vrInputError.h"
#include "vrSharedVoxelContainer.h"

#include "itkImage.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>

namespace vr::detail
{
namespace
{
/** A mapping of the hand-over file, unmapped with its last owner. */
class Mapping
{
public:
  Mapping(void * address, std::size_t length)
    : m_Address(address)
    , m_Length(length)
  {
  }
  ~Mapping() { ::munmap(m_Address, m_Length); }
  Mapping(const Mapping &) = delete;
  Mapping &
  operator=(const Mapping &) = delete;

  char *
  Bytes() const
  {
    return static_cast<char *>(m_Address);
  }

private:
  void *      m_Address;
  std::size_t m_Length;
};

template<typename TPixel>
itk::ImageBase<3>::Pointer
WrapMapping(const std::shared_ptr<Mapping> & mapping, const DICOMVolumeHeader & header)
{
  using ImageType = itk::Image<TPixel, 3>;
  auto                              image = ImageType::New();
  typename ImageType::RegionType    region;
  typename ImageType::SpacingType   spacing;
  typename ImageType::PointType     origin;
  typename ImageType::DirectionType direction;
  for (unsigned int d = 0; d < 3; ++d)
  {
    region.SetSize(d, header.Size[d]);
    spacing[d] = header.Spacing[d];
    origin[d] = header.Origin[d];
    for (unsigned int c = 0; c < 3; ++c)
    {
      direction(d, c) = header.Direction[3 * d + c];
    }
  }
  image->SetRegions(region);
  image->SetSpacing(spacing);
  image->SetOrigin(origin);
  image->SetDirection(direction);
  auto container = SharedVoxelContainer<TPixel>::New();
  container->Share(
    reinterpret_cast<TPixel *>(mapping->Bytes() + DICOMVolumeVoxelOffset), region.GetNumberOfPixels(), mapping);
  image->SetPixelContainer(container);
  return image.GetPointer();
}

bool
AllFinite(const double * values, std::size_t count)
{
  for (std::size_t k = 0; k < count; ++k)
  {
    if (!std::isfinite(values[k]))
    {
      return false;
    }
  }
  return true;
}

/** What is wrong with a finished header; empty when nothing. */
std::string
HeaderProblem(const DICOMVolumeHeader & header)
{
  const auto        pixelType = static_cast<itk::IOComponentEnum>(header.PixelType);
  const std::size_t pixelBytes = DICOMVolumePixelBytes(pixelType);
  if (pixelBytes == 0)
  {
    return "a pixel type it does not hand over (" + std::to_string(header.PixelType) + ")";
  }
  std::uint64_t voxels = 1;
  for (const std::uint64_t size : header.Size)
  {
    if (size == 0 || voxels > std::numeric_limits<std::uint64_t>::max() / 8 / size)
    {
      return "a volume of impossible dimensions";
    }
    voxels *= size;
  }
  if (voxels * pixelBytes != header.VoxelBytes)
  {
    return "a volume whose dimensions and voxel bytes disagree";
  }
  if (!AllFinite(header.Spacing, 3) || !(header.Spacing[0] > 0 && header.Spacing[1] > 0 && header.Spacing[2] > 0) ||
      !AllFinite(header.Origin, 3) || !AllFinite(header.Direction, 9))
  {
    return "a volume whose geometry is not finite";
  }
  const itk::CPRIntensityRescale rescale{ header.Slope, header.Intercept };
  if (!rescale.IsValid() || (pixelType == itk::IOComponentEnum::FLOAT && !rescale.IsIdentity()))
  {
    return "a volume whose rescale is not valid";
  }
  return std::string();
}
} // namespace

StoredVolume
ReceiveDICOMVolume(int descriptor, const std::string & where)
{
  const std::string what = where + ": the DICOM reader process handed over ";
  const std::string notRead = "; the series is not read";
  // From here the file cannot shrink (a process left holding it cannot make the mapping fault); a file that cannot be
  // sealed (not a memfd) is only the child's, and the child has ended.
  ::fcntl(descriptor, F_ADD_SEALS, F_SEAL_SHRINK | F_SEAL_GROW | F_SEAL_SEAL);
  struct stat status
  {
  };
  if (::fstat(descriptor, &status) != 0)
  {
    throw InputError(what + "a file that cannot be examined: " + std::strerror(errno) + notRead);
  }
  const auto        length = static_cast<std::uint64_t>(status.st_size);
  DICOMVolumeHeader header;
  if (length < DICOMVolumeVoxelOffset ||
      ::pread(descriptor, &header, sizeof(header), 0) != static_cast<ssize_t>(sizeof(header)))
  {
    throw InputError(what + "no volume (" + std::to_string(length) +
                     " bytes, not even its header: it stopped before writing it?)" + notRead);
  }
  if (std::memcmp(header.Magic, DICOMVolumeMagic, sizeof(header.Magic)) != 0 || header.Version != DICOMVolumeVersion ||
      std::memcmp(header.Complete, DICOMVolumeCompleteMarker, sizeof(header.Complete)) != 0)
  {
    throw InputError(what +
                     "a volume it did not finish (its header is not complete: the process stopped while "
                     "writing it?)" +
                     notRead);
  }
  if (const std::string problem = HeaderProblem(header); !problem.empty())
  {
    throw InputError(what + problem + notRead);
  }
  if (length != DICOMVolumeVoxelOffset + header.VoxelBytes)
  {
    throw InputError(what + std::to_string(length > DICOMVolumeVoxelOffset ? length - DICOMVolumeVoxelOffset : 0) +
                     " bytes of voxels where the volume (" + std::to_string(header.Size[0]) + " x " +
                     std::to_string(header.Size[1]) + " x " + std::to_string(header.Size[2]) + ") has " +
                     std::to_string(header.VoxelBytes) +
                     (length < DICOMVolumeVoxelOffset + header.VoxelBytes ? " (cut short)" : "") + notRead);
  }
  void * address = ::mmap(nullptr, length, PROT_READ | PROT_WRITE, MAP_SHARED, descriptor, 0);
  if (address == MAP_FAILED)
  {
    throw InputError(what + "a volume of " + std::to_string(length) +
                     " bytes that cannot be mapped: " + std::strerror(errno) + notRead);
  }
  const auto   mapping = std::make_shared<Mapping>(address, length);
  StoredVolume volume;
  volume.Rescale = itk::CPRIntensityRescale{ header.Slope, header.Intercept };
  switch (static_cast<itk::IOComponentEnum>(header.PixelType))
  {
    case itk::IOComponentEnum::UCHAR:
      volume.Image = WrapMapping<unsigned char>(mapping, header);
      break;
    case itk::IOComponentEnum::CHAR:
      volume.Image = WrapMapping<signed char>(mapping, header);
      break;
    case itk::IOComponentEnum::USHORT:
      volume.Image = WrapMapping<unsigned short>(mapping, header);
      break;
    case itk::IOComponentEnum::SHORT:
      volume.Image = WrapMapping<short>(mapping, header);
      break;
    default: // FLOAT: HeaderProblem() let no other type through
      volume.Image = WrapMapping<float>(mapping, header);
      break;
  }
  return volume;
}
} // namespace vr::detail
