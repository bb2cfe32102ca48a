// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrDICOMTestSeries_h
#define vrDICOMTestSeries_h

#include "vrImageTypes.h"

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

/** DICOM files written byte by byte, independently of GDCM and ITK (which the reader under test uses), so that a test
 * controls every attribute, the encoding and what the file claims about it: a CT series with full geometry from a
 * volume, and copies of it with one fault or another (vrDICOMFaults.h). */
namespace vr::test
{
/** A data element: its tag, its VR and its value as bytes (binary values little-endian; the writer swaps them for a
 * big-endian file). */
struct DICOMTestElement
{
  std::uint16_t Group{ 0 };
  std::uint16_t Element{ 0 };
  std::string   VR;
  std::string   Value;
};

/** The elements of a data set, written in tag order. */
class DICOMTestDataSet
{
public:
  /** A text value (padded to an even length as DICOM pads it: a NUL for UI, a space otherwise). */
  void
  SetText(std::uint16_t group, std::uint16_t element, const std::string & vr, const std::string & value);
  /** An unsigned short (VR US). */
  void
  SetUS(std::uint16_t group, std::uint16_t element, std::uint16_t value);
  /** A value as it is, bytes and VR. */
  void
  SetBytes(std::uint16_t group, std::uint16_t element, const std::string & vr, const std::string & bytes);
  void
  Remove(std::uint16_t group, std::uint16_t element);
  /** \return the element, or null. */
  const DICOMTestElement *
  Find(std::uint16_t group, std::uint16_t element) const;
  /** \return a text value without its padding ("" when absent). */
  std::string
  Text(std::uint16_t group, std::uint16_t element) const;

  std::map<std::uint32_t, DICOMTestElement> Elements;
};

/** How a file is encoded, and what its file meta information says about it. */
struct DICOMTestEncoding
{
  bool ExplicitVR{ true };
  bool BigEndian{ false };
  /** The Transfer Syntax UID written in the meta information; empty: the one the encoding is. */
  std::string ClaimedTransferSyntax;
};

/** One entry of a test folder: a DICOM image file made from its values, or a file of other bytes, or a folder. */
struct DICOMTestFile
{
  std::string Name;
  /** Every attribute but Pixel Data, which is made from Values at writing. */
  DICOMTestDataSet Data;
  /** Columns x Rows values, row by row, as the image holds them after its rescale. */
  std::vector<double> Values;
  /** The rescale the stored pixels are made with (stored = (value - Intercept) / Slope, exact for the tests' values);
   * the Rescale attributes are written from Data, which MakeCTSeries fills from these. */
  double Slope{ 1.0 };
  double Intercept{ 0.0 };
  /** The format the stored pixels are written in (16 bits allocated), whatever the attributes claim. */
  bool              SignedPixels{ false };
  unsigned int      StoredBits{ 16 };
  DICOMTestEncoding Encoding;
  /** Bytes added to (> 0) or cut from (< 0) the Pixel Data value, its length following. */
  long PixelDataChange{ 0 };
  bool OmitPixelData{ false };
  /** Written as it is instead of a DICOM file (a note, an empty file). */
  std::optional<std::string> Raw;
  /** A sub-folder (holding one note), not a file. */
  bool Folder{ false };
  /** Not one of the series' own files: a copy, a stray file, another series' (made by a fault). */
  bool Added{ false };
  /** The file cut to this many bytes after encoding. */
  std::optional<std::size_t> TruncateTo;
};

/** \return \a file encoded: preamble, "DICM", meta information (explicit VR little-endian, as DICOM asks), data set.
 * Throws std::logic_error when a value cannot be stored in the file's pixel format (a test's mistake). */
std::string
EncodeDICOMFile(const DICOMTestFile & file);

/** Writes the entries into \a folder (made when missing). */
void
WriteDICOMTestFolder(const std::string & folder, const std::vector<DICOMTestFile> & files);

/** How MakeCTSeries writes the series. */
struct CTSeriesOptions
{
  std::string SeriesInstanceUID{ "1.2.826.0.1.3680043.9.7731.37.2" };
  std::string StudyInstanceUID{ "1.2.826.0.1.3680043.9.7731.37.1" };
  std::string FrameOfReferenceUID{ "1.2.826.0.1.3680043.9.7731.37.3" };
  std::string SeriesDescription{ "CTA 1.5 mm" };
  std::string SeriesNumber{ "3" };
  /** Feet first: the orientation a feet-first supine scan writes (-1\0\0\0\1\0, its slices ordered from the feet),
   * instance 1 the lowest slice; head first (the default): 1\0\0\0\1\0, instance 1 the highest. */
  bool FeetFirst{ false };
  /** Signed 16-bit stored values with intercept 0; else (the default) unsigned, 12 bits stored, intercept -1024. */
  bool Signed{ false };
  /** Each file's slope and intercept (by its slice index along the volume's third axis), replacing the above. The
   * stored values must come out whole and in range. */
  std::function<std::pair<double, double>(unsigned int slice)> Rescale;
  DICOMTestEncoding                                            Encoding;
  /** The files' names: IM0001.dcm, ... by instance number. */
  std::string Prefix{ "IM" };
};

/** The files of a CT series holding \a volume: one file a slice along its third axis, whole-number values (HU), the
 * volume's geometry in Image Position/Orientation (Patient) and Pixel Spacing (its direction must be the identity).
 * Slice Thickness is written as the spacing, as scanners write it. */
std::vector<DICOMTestFile>
MakeCTSeries(const VolumeImageType * volume, const CTSeriesOptions & options = CTSeriesOptions());

/** \a volume with every value rounded to a whole number within [-1024, 3071] (what a 12-bit CT series holds): the
 * reference the DICOM files are made from, and the one NRRD and NIfTI copies are written from. */
VolumeImageType::Pointer
QuantizedCT(const VolumeImageType * volume);
} // namespace vr::test

#endif
