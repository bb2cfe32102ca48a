// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrNrrdRawVoxels_h
#define vrNrrdRawVoxels_h

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

/** The voxels of a raw NRRD read straight into the buffer a volume keeps. Not installed: an implementation detail of
 * the IO library. ITK's NRRD reader hands the image's buffer to teem, which zeroes it whole before reading into it
 * (its calloc semantics): a pass over the voxel bytes that on a 630 MB CT costs about as much as a third of the read
 * itself (docs/measurements/2026-11-29-full-size-module.md). A raw NRRD with its header attached and its voxels in
 * the machine's byte order, filling the rest of the file, is read here with one read into the buffer; every other
 * NRRD (compressed, detached, another byte order, skips, a file of another length) goes through ITK as before. */
namespace vr::detail
{
/** Where the voxels of the NRRD file \a path begin when they can be read here: its header attached (no "data file"),
 * "encoding: raw", no "line skip" or "byte skip", "endian" the machine's (or absent for voxels of \a pixelBytes 1),
 * and exactly \a voxelBytes bytes after the blank line that ends the header; nullopt otherwise (ITK reads it).
 * \a path's header has been read by ITK before (its sizes and type give \a voxelBytes). */
std::optional<std::uint64_t>
RawNrrdVoxelOffset(const std::string & path, std::uint64_t voxelBytes, std::size_t pixelBytes);

/** Reads \a bytes bytes at \a offset of \a path into \a buffer. Throws vr::InputError "<where>: the voxel data cannot
 * be read (truncated?): ..." when the file holds fewer bytes or a read fails. */
void
ReadRawVoxels(const std::string & path,
              std::uint64_t       offset,
              void *              buffer,
              std::uint64_t       bytes,
              const std::string & where);
} // namespace vr::detail

#endif
