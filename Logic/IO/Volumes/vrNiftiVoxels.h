// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrNiftiVoxels_h
#define vrNiftiVoxels_h

#include "itkCommonEnums.h"

#include <cstddef>
#include <string>

/** NIfTI voxels read straight into the buffer a volume keeps. Not installed: an implementation detail of the IO
 * library. ITK's NIfTI reader has its NIfTI library read the voxels into a buffer of its own, copy them into the
 * image's and, where scl_slope asks for it, turn integers into float: two or three times the voxel bytes at the peak.
 * Here the voxels go once into the final buffer (decompressed there for .nii.gz) and scl_slope and scl_inter become
 * the volume's intensity rescale (docs/design.md "Volumes in their stored type"). */
namespace vr::detail
{
/** What a NIfTI file's header says of its voxels. */
struct NiftiVoxelLayout
{
  /** The stored pixel type (CHAR for NIfTI's INT8), or UNKNOWNCOMPONENTTYPE for a datatype read through ITK as float
   * (32- and 64-bit integers). */
  itk::IOComponentEnum PixelType{ itk::IOComponentEnum::UNKNOWNCOMPONENTTYPE };
  /** The number of voxels (all dimensions). */
  std::size_t Voxels{ 0 };
  /** scl_slope and scl_inter as NIfTI defines them: a slope of 0 (or not finite) means none. */
  double Slope{ 1.0 };
  double Intercept{ 0.0 };
};

/** Reads the header of the NIfTI file \a path (already checked by CheckNiftiHeader) as ITK's NIfTI library does.
 * Throws vr::InputError "<where>: ..." when the library cannot read it. */
NiftiVoxelLayout
InspectNiftiVoxels(const std::string & path, const std::string & where);

/** Reads the \a bytes of voxels of the NIfTI file \a path into \a buffer, in the machine's byte order: from the data
 * file the header names (x.img for x.hdr), at its vox_offset, decompressed when it ends in .gz. Throws vr::InputError
 * "<where>: the voxel data cannot be read (truncated?): ..." when the file holds fewer bytes. Non-finite float voxels
 * are left as they are, for the reader's check to name (the NIfTI library would make them 0 without a word). */
void
ReadNiftiVoxels(const std::string & path, void * buffer, std::size_t bytes, const std::string & where);
} // namespace vr::detail

#endif
