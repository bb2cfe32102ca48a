// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// How the DICOM reader process hands a series' voxels to its caller (docs/dicom-series.md "Where it runs"): through
// one file the caller opens (a memfd, anonymous memory, where the system has it) and gives the child as a file
// descriptor. The child maps it, decodes the slices straight into it and writes the header last, ending with a
// marker; the caller checks the header, the marker and the file's size against each other before it maps the file
// as the volume's buffer, so that a child that died half-way is refused and never read. Internal (namespace
// vr::detail): the child writes with DICOMVolumeHandOverWriter; the caller reads with ReceiveDICOMVolume
// (vrDICOMMappedVolume.h).
#ifndef vrDICOMVolumeHandOver_h
#define vrDICOMVolumeHandOver_h

#include "itkCommonEnums.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace vr::detail
{
/** The file's first page: what the voxels are. The voxels begin at DICOMVolumeVoxelOffset (a page boundary, so
 * that the caller's mapping of the file serves them as they lie). */
struct DICOMVolumeHeader
{
  char          Magic[8]{};     // DICOMVolumeMagic
  std::uint32_t Version{ 0 };   // DICOMVolumeVersion
  std::uint32_t PixelType{ 0 }; // an itk::IOComponentEnum: UCHAR, CHAR, USHORT, SHORT or FLOAT
  std::uint64_t Size[3]{};      // columns, rows, slices
  std::uint64_t VoxelBytes{ 0 };
  double        Spacing[3]{};
  double        Origin[3]{};
  double        Direction[9]{}; // row-major, columns the volume's axes, in LPS
  double        Slope{ 1.0 };   // stored values to intensities (identity for float voxels)
  double        Intercept{ 0.0 };
  char          Complete[8]{}; // DICOMVolumeCompleteMarker, written after everything else
};

inline constexpr char          DICOMVolumeMagic[8] = { 'V', 'R', 'D', 'C', 'M', 'V', 'O', 'L' };
inline constexpr char          DICOMVolumeCompleteMarker[8] = { 'C', 'O', 'M', 'P', 'L', 'E', 'T', 'E' };
inline constexpr std::uint32_t DICOMVolumeVersion = 1;
inline constexpr std::size_t   DICOMVolumeVoxelOffset = 4096;
static_assert(sizeof(DICOMVolumeHeader) <= DICOMVolumeVoxelOffset, "the header fits its page");

/** The file descriptor the child receives the hand-over file on. */
inline constexpr int DICOMVolumeHandOverDescriptor = 3;

/** The bytes a voxel of \a pixelType takes in the hand-over: 1, 2 or 4; 0 for a type it does not carry. */
std::size_t
DICOMVolumePixelBytes(itk::IOComponentEnum pixelType);

/** The child's side: sizes the file for the voxels, maps it and finishes it with the header. */
class DICOMVolumeHandOverWriter
{
public:
  DICOMVolumeHandOverWriter() = default;
  ~DICOMVolumeHandOverWriter();
  DICOMVolumeHandOverWriter(const DICOMVolumeHandOverWriter &) = delete;
  DICOMVolumeHandOverWriter &
  operator=(const DICOMVolumeHandOverWriter &) = delete;

  /** Sizes the file \a descriptor for \a voxels values of \a pixelType (its memory reserved, so that a volume that
   * does not fit is said so here and not a crash later) and maps it. \return empty, or why not (naming the bytes). */
  std::string
  Open(int descriptor, itk::IOComponentEnum pixelType, std::uint64_t voxels);
  /** The voxels' room, Open()'s count of values of its pixel type; null before Open(). */
  void *
  Voxels() const
  {
    return m_Voxels;
  }
  /** Writes \a header (its pixel type and voxel bytes set here, the marker last) and unmaps the file. */
  void
  Finish(DICOMVolumeHeader header);
  /** Unmaps the file, leaving it without its header: the caller refuses it. */
  void
  Close();

private:
  void *               m_Mapping{ nullptr };
  std::size_t          m_Length{ 0 };
  void *               m_Voxels{ nullptr };
  itk::IOComponentEnum m_PixelType{ itk::IOComponentEnum::UNKNOWNCOMPONENTTYPE };
};
} // namespace vr::detail

#endif
