// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The attributes of one DICOM file that the series reader decides with, as the text the file holds. Internal (namespace
// vr::detail): filled by the reader process from GDCM (vrDICOMFolderExamination.h), judged without GDCM
// (vrDICOMSeriesGroups.h), so that the judging is tested on attributes written by hand.
#ifndef vrDICOMFileAttributes_h
#define vrDICOMFileAttributes_h

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace vr::detail
{
/** An attribute by its tag and the name DICOM PS3.6 gives it; Binary for the image pixel module's unsigned shorts
 * (VR US), which are kept as their decimal value. */
struct DICOMAttributeTag
{
  std::uint16_t Group;
  std::uint16_t Element;
  const char *  Name;
  bool          Binary;

  std::uint32_t
  Key() const
  {
    return (std::uint32_t{ Group } << 16) | Element;
  }
  /** "Rows (0028,0010)" */
  std::string
  Label() const;
};

/** The attributes the reader reads (and no others: Slice Thickness is not among them, on purpose). */
namespace DICOMTag
{
constexpr DICOMAttributeTag TransferSyntaxUID{ 0x0002, 0x0010, "Transfer Syntax UID", false };
constexpr DICOMAttributeTag MediaStorageSOPClassUID{ 0x0002, 0x0002, "Media Storage SOP Class UID", false };
constexpr DICOMAttributeTag SOPClassUID{ 0x0008, 0x0016, "SOP Class UID", false };
constexpr DICOMAttributeTag SOPInstanceUID{ 0x0008, 0x0018, "SOP Instance UID", false };
constexpr DICOMAttributeTag Modality{ 0x0008, 0x0060, "Modality", false };
constexpr DICOMAttributeTag SeriesDescription{ 0x0008, 0x103E, "Series Description", false };
constexpr DICOMAttributeTag GantryDetectorTilt{ 0x0018, 0x1120, "Gantry/Detector Tilt", false };
constexpr DICOMAttributeTag ImagerPixelSpacing{ 0x0018, 0x1164, "Imager Pixel Spacing", false };
constexpr DICOMAttributeTag NominalScannedPixelSpacing{ 0x0018, 0x2010, "Nominal Scanned Pixel Spacing", false };
constexpr DICOMAttributeTag SeriesInstanceUID{ 0x0020, 0x000E, "Series Instance UID", false };
constexpr DICOMAttributeTag SeriesNumber{ 0x0020, 0x0011, "Series Number", false };
constexpr DICOMAttributeTag ImagePosition{ 0x0020, 0x0032, "Image Position (Patient)", false };
constexpr DICOMAttributeTag ImageOrientation{ 0x0020, 0x0037, "Image Orientation (Patient)", false };
constexpr DICOMAttributeTag FrameOfReferenceUID{ 0x0020, 0x0052, "Frame of Reference UID", false };
constexpr DICOMAttributeTag SamplesPerPixel{ 0x0028, 0x0002, "Samples per Pixel", true };
constexpr DICOMAttributeTag PhotometricInterpretation{ 0x0028, 0x0004, "Photometric Interpretation", false };
constexpr DICOMAttributeTag NumberOfFrames{ 0x0028, 0x0008, "Number of Frames", false };
constexpr DICOMAttributeTag Rows{ 0x0028, 0x0010, "Rows", true };
constexpr DICOMAttributeTag Columns{ 0x0028, 0x0011, "Columns", true };
constexpr DICOMAttributeTag PixelSpacing{ 0x0028, 0x0030, "Pixel Spacing", false };
constexpr DICOMAttributeTag BitsAllocated{ 0x0028, 0x0100, "Bits Allocated", true };
constexpr DICOMAttributeTag BitsStored{ 0x0028, 0x0101, "Bits Stored", true };
constexpr DICOMAttributeTag HighBit{ 0x0028, 0x0102, "High Bit", true };
constexpr DICOMAttributeTag PixelRepresentation{ 0x0028, 0x0103, "Pixel Representation", true };
constexpr DICOMAttributeTag RescaleIntercept{ 0x0028, 0x1052, "Rescale Intercept", false };
constexpr DICOMAttributeTag RescaleSlope{ 0x0028, 0x1053, "Rescale Slope", false };
/** Every attribute above but the file meta information's, in tag order. */
const std::vector<DICOMAttributeTag> &
DataSetAttributes();
} // namespace DICOMTag

/** One file of a folder that holds a DICOM image: its path and the attributes it has, each as the text it holds (a
 * string without its padding; a Binary one as its decimal value, or "not a 2-byte value" when its length is not 2). */
struct DICOMFileAttributes
{
  std::string                          File;
  std::map<std::uint32_t, std::string> Values;
  /** The patient and study (vr::DICOMAttribute keys), for the node the volume becomes. */
  std::map<std::string, std::string> Identity;
  /** The file's Transfer Syntax UID says explicit VR, but GDCM found its data set written with implicit VR and read
   * it so (a wrong file meta information that GDCM recovers from): said in a warning when the file is read. */
  bool ImplicitUnderExplicitClaim{ false };

  /** \return the attribute's text, or none when the file lacks it. */
  std::optional<std::string>
  Get(const DICOMAttributeTag & tag) const;
  /** \return the attribute's text, or "(none)" when the file lacks it: for messages and grouping. */
  std::string
  Shown(const DICOMAttributeTag & tag) const;
};

/** The transfer syntax family a file's claimed syntax belongs to: "native little-endian" (implicit or explicit VR),
 * "native big-endian", "deflated", "JPEG", "JPEG-LS", "JPEG 2000", "RLE", "none given", or "unknown <uid>". Files of
 * one family decode alike; files of two are not one series. */
std::string
TransferSyntaxFamily(const std::optional<std::string> & uid);

/** Whether the family's pixel data are encapsulated (compressed fragments) rather than stored plain. */
bool
IsEncapsulatedFamily(const std::string & family);
} // namespace vr::detail

#endif
