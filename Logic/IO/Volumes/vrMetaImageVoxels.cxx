// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrMetaImageVoxels.h"

#include "vrInputError.h"
#include "vrMetaImageHeaderCheck.h"

#include "itkMetaImageIO.h"

#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

namespace vr::detail
{
namespace
{
/** Ends zlib's stream with its scope. */
struct InflateStream
{
  z_stream Stream{};
  bool     Started{ false };
  ~InflateStream()
  {
    if (Started)
    {
      inflateEnd(&Stream);
    }
  }
};

} // namespace

std::optional<CompressedMetaImageVoxels>
FindCompressedMetaImageVoxels(itk::ImageIOBase & io, const std::string & path, const std::string & where)
{
  auto * metaIO = dynamic_cast<itk::MetaImageIO *>(&io);
  if (metaIO == nullptr)
  {
    return std::nullopt;
  }
  MetaImage * header = metaIO->GetMetaImagePointer();
  if (header == nullptr || !header->CompressedData() || header->ElementNumberOfChannels() != 1 ||
      header->HeaderSize() != 0 || header->ElementDataFileName() == nullptr)
  {
    return std::nullopt;
  }
  const std::string dataFile = header->ElementDataFileName();
  // A file list or a numbered pattern (several files) stays with MetaIO.
  if (dataFile.empty() || dataFile.rfind("LIST", 0) == 0 || dataFile.find('%') != std::string::npos ||
      dataFile.find(' ') != std::string::npos)
  {
    return std::nullopt;
  }
  CompressedMetaImageVoxels voxels;
  voxels.BigEndian = header->BinaryDataByteOrderMSB();
  if (dataFile == "LOCAL")
  {
    voxels.DataFile = path;
    voxels.Offset = CheckMetaImageHeader(path, where);
  }
  else
  {
    // As MetaIO finds it: a relative name beside the header.
    const std::filesystem::path named(dataFile);
    voxels.DataFile = named.is_absolute() ? dataFile : (std::filesystem::path(path).parent_path() / named).string();
  }
  return voxels;
}

void
InflateMetaImageVoxels(const CompressedMetaImageVoxels & voxels,
                       void *                            buffer,
                       std::uint64_t                     bytes,
                       const std::string &               where)
{
  std::ifstream file(voxels.DataFile, std::ios::binary);
  if (!file || !file.seekg(static_cast<std::streamoff>(voxels.Offset)))
  {
    throw InputError(where + ": the voxel data cannot be read: " + voxels.DataFile + ": " + std::strerror(errno));
  }
  InflateStream inflating;
  // 15 + 32: a zlib stream (what MetaIO writes) or a gzip one, as MetaIO's own inflation accepts.
  if (inflateInit2(&inflating.Stream, 15 + 32) != Z_OK)
  {
    throw InputError(where + ": zlib could not start inflating the voxel data");
  }
  inflating.Started = true;
  z_stream &        stream = inflating.Stream;
  std::vector<char> piece(std::size_t{ 1 } << 20);
  auto *            target = static_cast<unsigned char *>(buffer);
  std::uint64_t     done = 0;
  int               status = Z_OK;
  const auto        truncated = [&]()
  {
    return InputError(where + ": the voxel data cannot be read (truncated?): the compressed data of " +
                      voxels.DataFile + " ends after " + std::to_string(done) + " of " + std::to_string(bytes) +
                      " voxel bytes");
  };
  while (status != Z_STREAM_END)
  {
    if (stream.avail_in == 0)
    {
      file.read(piece.data(), static_cast<std::streamsize>(piece.size()));
      const std::streamsize count = file.gcount();
      if (count <= 0)
      {
        throw truncated();
      }
      stream.next_in = reinterpret_cast<Bytef *>(piece.data());
      stream.avail_in = static_cast<uInt>(count);
    }
    // Out to the rest of the buffer, at most 1 GiB at a time (avail_out is an unsigned int); one byte more once the
    // buffer is full, so that a stream holding more than the header says is caught instead of cut.
    unsigned char spare = 0;
    const bool    full = done == bytes;
    stream.next_out = full ? &spare : target + done;
    stream.avail_out = full ? 1u : static_cast<uInt>(std::min<std::uint64_t>(bytes - done, std::uint64_t{ 1 } << 30));
    const uInt before = stream.avail_out;
    status = inflate(&stream, Z_NO_FLUSH);
    const uInt produced = before - stream.avail_out;
    if (full && produced > 0)
    {
      throw InputError(where + ": the compressed voxel data holds more than the header's " + std::to_string(bytes) +
                       " voxel bytes (DimSize and ElementType)");
    }
    done += full ? 0 : produced;
    if (status == Z_NEED_DICT || status == Z_DATA_ERROR || status == Z_MEM_ERROR || status == Z_STREAM_ERROR)
    {
      throw InputError(where + ": the compressed voxel data is damaged: zlib: " +
                       (stream.msg != nullptr ? std::string(stream.msg) : std::to_string(status)) + " after " +
                       std::to_string(done) + " of " + std::to_string(bytes) + " voxel bytes");
    }
    if (status == Z_BUF_ERROR && stream.avail_in != 0)
    {
      // No progress with input and room left: zlib cannot go on with this stream.
      throw InputError(where + ": the compressed voxel data is damaged: zlib made no progress after " +
                       std::to_string(done) + " of " + std::to_string(bytes) + " voxel bytes");
    }
  }
  if (done != bytes)
  {
    throw truncated();
  }
}
} // namespace vr::detail
