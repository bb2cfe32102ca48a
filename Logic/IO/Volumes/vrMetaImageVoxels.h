// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrMetaImageVoxels_h
#define vrMetaImageVoxels_h

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

namespace itk
{
class ImageIOBase;
}

/** The voxels of a compressed MetaImage inflated straight into the buffer a volume keeps. Not installed: an
 * implementation detail of the IO library. MetaIO reads a compressed file's bytes whole into a buffer of its own before
 * it inflates them into the image's: the compressed bytes on top of the voxel bytes at the peak. Here they are read
 * in pieces of 1 MiB and inflated as they come (docs/design.md "Volumes in their stored type"); every other MetaImage
 * (uncompressed, a file list or pattern, a HeaderSize to skip, several channels) goes through ITK as before. */
namespace vr::detail
{
/** Where a compressed MetaImage's voxels lie. */
struct CompressedMetaImageVoxels
{
  /** The file that holds the zlib (or gzip) stream: the header's own for LOCAL, else the data file it names. */
  std::string DataFile;
  /** Where the stream begins in DataFile. */
  std::uint64_t Offset{ 0 };
  /** Whether the voxels are stored most significant byte first (BinaryDataByteOrderMSB). */
  bool BigEndian{ false };
};

/** The compressed voxels of the MetaImage \a path, whose header ITK's reader \a io has read (and
 * CheckMetaImageHeader passed), when they can be read here: ITK's MetaImageIO, one channel, CompressedData true, no
 * HeaderSize, ElementDataFile LOCAL or one file. nullopt otherwise (ITK reads it). */
std::optional<CompressedMetaImageVoxels>
FindCompressedMetaImageVoxels(itk::ImageIOBase & io, const std::string & path, const std::string & where);

/** Inflates the stream of \a voxels into \a buffer of \a bytes, in the file's byte order (the caller, who knows the
 * pixel type, brings them into the machine's). Throws vr::InputError "<where>: the voxel data cannot be read
 * (truncated?): ..." when the stream ends before \a bytes, "<where>: the compressed voxel data is damaged: ..." when
 * zlib cannot inflate it, and "<where>: the compressed voxel data holds more than the header's ... bytes" when it holds
 * more. */
void
InflateMetaImageVoxels(const CompressedMetaImageVoxels & voxels,
                       void *                            buffer,
                       std::uint64_t                     bytes,
                       const std::string &               where);
} // namespace vr::detail

#endif
