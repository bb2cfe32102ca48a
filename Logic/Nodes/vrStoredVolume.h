// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrStoredVolume_h
#define vrStoredVolume_h

#include "itkCPRIntensityRescale.h"
#include "itkCommonEnums.h"
#include "itkImageBase.h"
#include "vrImageTypes.h"

#include <cstddef>
#include <string>

namespace vr
{
/** \struct StoredVolume
 * \brief A volume in the pixel type of its file (docs/design.md "Volumes in their stored type"): an itk::Image<T, 3>
 * in LPS of one of the stored pixel types (signed or unsigned 8- and 16-bit integers, float, double;
 * itk::CPRStoredPixelTypes) and the rescale of its stored values to intensities.
 *
 * What a reader returns (vr::ReadStoredVolume), what a volume node converts to without a copy
 * (vr::ConvertVolumeNodeToStoredVolume) and what the reformation filters sample (they take itk::ImageBase<3> and
 * apply the rescale to each value they read). A CT of 16-bit integers is held in 2 bytes a voxel from the file to the
 * filters, once.
 * \ingroup VesselReformation
 */
struct StoredVolume
{
  /** An itk::Image<T, 3> of a stored pixel type; null for no volume. */
  itk::ImageBase<3>::Pointer Image;
  /** Stored values to intensities. */
  itk::CPRIntensityRescale Rescale;

  /** \return the pixel type of Image (UNKNOWNCOMPONENTTYPE when it is null or of another type). */
  itk::IOComponentEnum
  GetPixelType() const;
  /** \return the bytes of Image's voxels (its buffered region), 0 without an image. */
  std::size_t
  GetVoxelBytes() const;
  /** \return the start of Image's voxels, null without an image. */
  const void *
  GetBufferPointer() const;
};

/** \return the bytes of one voxel of \a pixelType, 0 for a type that is not a stored pixel type. */
std::size_t
StoredPixelBytes(itk::IOComponentEnum pixelType);

/** \return how messages and tables name a stored pixel type: "int8", "uint8", "int16", "uint16", "float32",
 * "float64" ("unknown" otherwise). */
std::string
StoredPixelTypeName(itk::IOComponentEnum pixelType);

/** The volume as float intensities (the rescale applied): Image itself when it is a float image with the identity
 * rescale, else a new image (a copy, the size of the volume in float). For what needs float values of the whole
 * volume (a segmentation, tests); the reformation samples the stored volume. Throws vr::InputError when the volume is
 * null or of another pixel type. */
VolumeImageType::Pointer
ConvertStoredVolumeToFloat(const StoredVolume & volume);
} // namespace vr

#endif
