// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrVolumeIO_h
#define vrVolumeIO_h

#include "vrImageTypes.h"
#include "vrStoredVolume.h"

#include "itkImageIOBase.h"

#include <cstdint>
#include <string>
#include <vector>

namespace vr
{
/** The most voxels a volume may declare (2^32, 16 GiB as float): more means a corrupt or hostile header. */
constexpr std::uintmax_t MaximumVolumeVoxels = std::uintmax_t{ 1 } << 32;

/** How ReadVolume() reads what it is given.
 * \ingroup VesselReformation */
struct VolumeReadOptions
{
  /** Which series of a DICOM folder to read when it holds several (ParameterName::DICOMSeries): its number in the list
   * the reader gives (from 1) or its Series Instance UID. Empty: the folder must hold one. Not used for a file. */
  std::string DICOMSeries;
};

/** What reading a volume said beside the volume.
 * \ingroup VesselReformation */
struct VolumeReadReport
{
  /** What made the volume differ from the files that a user must know, each in full, naming the files: a DICOM
   * series' gap filled by interpolation, a duplicate file left out, another set of the series' files not read. */
  std::vector<std::string> Warnings;
  /** What was skipped and changes nothing: the entries of a DICOM folder that are no DICOM images. */
  std::vector<std::string> Notes;
};

/** Reads a scalar volume (LPS, origin/spacing/direction kept) in the pixel type of its file (docs/design.md "Volumes
 * in their stored type"): NRRD, NIfTI, MetaImage, or a DICOM series when \a path is a folder (docs/dicom-series.md:
 * one series, chosen by \a options when the folder holds several; every file checked against the others; geometry
 * from the files' positions; rescaled file by file). A URI name (vr::IsURIName, e.g. 3D Slicer's
 * "slicer:0x...#vtkMRMLScalarVolumeNode1") goes to ITK's reader untouched.
 *
 * Signed and unsigned 8- and 16-bit integers, float and double stay as stored and are read straight into the one
 * buffer the volume keeps (NRRD and MetaImage by ITK's reader of that pixel type, NIfTI by our own, .gz files
 * decompressed into it); NIfTI's scl_slope and scl_inter become the rescale. Other pixel types (32- and 64-bit
 * integers) are read as float, and a DICOM series as float intensities (its rescale applied per file).
 * \param report receives the warnings and notes, when given (a DICOM folder's; a file gives none).
 *
 * Throws vr::InputError naming the file and what is wrong: missing; a named pipe, device or socket (refused before
 * anything opens it, also as a detached header's data file); an unreadable header; not 3D (a 4D file says so);
 * not scalar; more than MaximumVolumeVoxels; voxels that need more memory than is available (refused before anything
 * is allocated, naming the bytes needed and available); a spacing, origin or direction that is not finite; voxel data
 * that is truncated (also where ITK's MetaImage reader would carry on with what it read); a NaN or infinite voxel
 * (named by its index); a DICOM folder without images, or a series refused (the file and the attribute named);
 * vr::DICOMSeriesChoiceRequired for a folder of several series without a choice of one. */
StoredVolume
ReadStoredVolume(const std::string &       path,
                 const VolumeReadOptions & options = VolumeReadOptions(),
                 VolumeReadReport *        report = nullptr);

/** ReadStoredVolume() as float intensities (vr::ConvertStoredVolumeToFloat: the image read for a float file without
 * rescale, else a float copy). For what needs float values; a reformation reads the stored volume. Throws as
 * ReadStoredVolume(). */
VolumeImageType::Pointer
ReadVolume(const std::string &       path,
           const VolumeReadOptions & options = VolumeReadOptions(),
           VolumeReadReport *        report = nullptr);

/** Opens a volume file and reads and checks its header as ReadVolume() does, without reading the voxels.
 * \return the ImageIO, ready to read. Throws vr::InputError as ReadVolume(). */
itk::ImageIOBase::Pointer
InspectVolumeFile(const std::string & path);

/** Writes a volume atomically, format from the extension. */
void
WriteVolume(const VolumeImageType * volume, const std::string & path);
} // namespace vr

#endif
