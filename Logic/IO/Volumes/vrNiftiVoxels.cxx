// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrNiftiVoxels.h"

#include "vrInputError.h"

#include "nifti1_io.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <system_error>

namespace vr::detail
{
namespace
{
struct NiftiImageDeleter
{
  void
  operator()(nifti_image * image) const
  {
    nifti_image_free(image);
  }
};
using NiftiImagePointer = std::unique_ptr<nifti_image, NiftiImageDeleter>;

NiftiImagePointer
ReadHeader(const std::string & path, const std::string & where)
{
  NiftiImagePointer image(nifti_image_read(path.c_str(), 0));
  if (!image)
  {
    throw InputError(where + ": the NIfTI header cannot be read");
  }
  return image;
}

itk::IOComponentEnum
StoredPixelTypeOf(int datatype)
{
  switch (datatype)
  {
    case NIFTI_TYPE_INT8:
      return itk::IOComponentEnum::CHAR;
    case NIFTI_TYPE_UINT8:
      return itk::IOComponentEnum::UCHAR;
    case NIFTI_TYPE_INT16:
      return itk::IOComponentEnum::SHORT;
    case NIFTI_TYPE_UINT16:
      return itk::IOComponentEnum::USHORT;
    case NIFTI_TYPE_FLOAT32:
      return itk::IOComponentEnum::FLOAT;
    case NIFTI_TYPE_FLOAT64:
      return itk::IOComponentEnum::DOUBLE;
    default:
      return itk::IOComponentEnum::UNKNOWNCOMPONENTTYPE;
  }
}

/** Reverses the bytes of each of the \a count values of \a size bytes at \a data. */
void
SwapBytes(unsigned char * data, std::size_t count, int size)
{
  for (std::size_t k = 0; k < count; ++k, data += size)
  {
    std::reverse(data, data + size);
  }
}

struct ZnzCloser
{
  void
  operator()(znzptr * file) const
  {
    znzFile copy = file;
    znzclose(copy);
  }
};
} // namespace

NiftiVoxelLayout
InspectNiftiVoxels(const std::string & path, const std::string & where)
{
  const NiftiImagePointer header = ReadHeader(path, where);
  NiftiVoxelLayout        layout;
  layout.PixelType = StoredPixelTypeOf(header->datatype);
  layout.Voxels = header->nvox;
  // NIfTI: "If the scl_slope field is nonzero, then each voxel value in the dataset should be scaled".
  const double slope = header->scl_slope;
  if (std::isfinite(slope) && slope != 0.0)
  {
    layout.Slope = slope;
    layout.Intercept = header->scl_inter;
  }
  return layout;
}

void
ReadNiftiVoxels(const std::string & path, void * buffer, std::size_t bytes, const std::string & where)
{
  const NiftiImagePointer header = ReadHeader(path, where);
  if (header->iname == nullptr || header->nbyper <= 0 ||
      static_cast<std::uint64_t>(header->nvox) * static_cast<std::uint64_t>(header->nbyper) != bytes)
  {
    throw InputError(where + ": the NIfTI header's voxel count and type do not match the volume it describes");
  }
  const bool                         compressed = nifti_is_gzfile(header->iname) != 0;
  std::unique_ptr<znzptr, ZnzCloser> file(znzopen(header->iname, "rb", compressed ? 1 : 0));
  if (!file)
  {
    throw InputError(where + ": the NIfTI data file " + std::string(header->iname) + " cannot be opened");
  }
  // As the NIfTI library places the data: at vox_offset, or for an Analyze header with a negative offset at the end.
  long long offset = header->iname_offset;
  if (offset < 0)
  {
    std::error_code   error;
    const std::size_t size = std::filesystem::file_size(header->iname, error);
    if (compressed || error)
    {
      throw InputError(where + ": the voxel data cannot be read (truncated?): no data offset");
    }
    offset = size > bytes ? static_cast<long long>(size - bytes) : 0;
  }
  if (znzseek(file.get(), static_cast<long>(offset), SEEK_SET) < 0)
  {
    throw InputError(where + ": the voxel data cannot be read (truncated?): the file ends before its data offset " +
                     std::to_string(offset));
  }
  // znzread reads .gz files in pieces of at most 1 GiB (gzread takes an unsigned int), straight into the buffer.
  const std::size_t read = znzread(buffer, 1, bytes, file.get());
  if (read != bytes)
  {
    throw InputError(where + ": the voxel data cannot be read (truncated?): " + std::to_string(read) + " of " +
                     std::to_string(bytes) + " bytes");
  }
  if (header->swapsize > 1 && header->byteorder != nifti_short_order())
  {
    SwapBytes(
      static_cast<unsigned char *>(buffer), bytes / static_cast<std::size_t>(header->swapsize), header->swapsize);
  }
}
} // namespace vr::detail
