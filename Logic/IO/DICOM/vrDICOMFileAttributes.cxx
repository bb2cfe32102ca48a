// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrDICOMFileAttributes.h"

#include <cstdio>

namespace vr::detail
{
std::string
DICOMAttributeTag::Label() const
{
  char tag[16];
  std::snprintf(tag, sizeof(tag), "(%04X,%04X)", Group, Element);
  return std::string(Name) + " " + tag;
}

namespace DICOMTag
{
const std::vector<DICOMAttributeTag> &
DataSetAttributes()
{
  static const std::vector<DICOMAttributeTag> attributes{ SOPClassUID,
                                                          SOPInstanceUID,
                                                          Modality,
                                                          SeriesDescription,
                                                          GantryDetectorTilt,
                                                          ImagerPixelSpacing,
                                                          NominalScannedPixelSpacing,
                                                          SeriesInstanceUID,
                                                          SeriesNumber,
                                                          ImagePosition,
                                                          ImageOrientation,
                                                          FrameOfReferenceUID,
                                                          SamplesPerPixel,
                                                          PhotometricInterpretation,
                                                          NumberOfFrames,
                                                          Rows,
                                                          Columns,
                                                          PixelSpacing,
                                                          BitsAllocated,
                                                          BitsStored,
                                                          HighBit,
                                                          PixelRepresentation,
                                                          RescaleIntercept,
                                                          RescaleSlope };
  return attributes;
}
} // namespace DICOMTag

std::optional<std::string>
DICOMFileAttributes::Get(const DICOMAttributeTag & tag) const
{
  const auto found = Values.find(tag.Key());
  if (found == Values.end())
  {
    return std::nullopt;
  }
  return found->second;
}

std::string
DICOMFileAttributes::Shown(const DICOMAttributeTag & tag) const
{
  const auto value = Get(tag);
  return value ? "\"" + *value + "\"" : std::string("(none)");
}

std::string
TransferSyntaxFamily(const std::optional<std::string> & uid)
{
  if (!uid)
  {
    return "none given";
  }
  const std::string & text = *uid;
  const std::string   jpeg = "1.2.840.10008.1.2.4.";
  if (text == "1.2.840.10008.1.2" || text == "1.2.840.10008.1.2.1")
  {
    return "native little-endian";
  }
  if (text == "1.2.840.10008.1.2.2")
  {
    return "native big-endian";
  }
  if (text == "1.2.840.10008.1.2.1.99")
  {
    return "deflated";
  }
  if (text == "1.2.840.10008.1.2.5")
  {
    return "RLE";
  }
  if (text.rfind(jpeg, 0) == 0)
  {
    const std::string rest = text.substr(jpeg.size());
    int               number = -1;
    if (!rest.empty() && rest.size() <= 3 && rest.find_first_not_of("0123456789") == std::string::npos)
    {
      number = std::stoi(rest);
    }
    if (number >= 50 && number <= 70)
    {
      return "JPEG";
    }
    if (number == 80 || number == 81)
    {
      return "JPEG-LS";
    }
    if (number >= 90 && number <= 93)
    {
      return "JPEG 2000";
    }
  }
  return "unknown " + text;
}

bool
IsEncapsulatedFamily(const std::string & family)
{
  return family == "JPEG" || family == "JPEG-LS" || family == "JPEG 2000" || family == "RLE";
}
} // namespace vr::detail
