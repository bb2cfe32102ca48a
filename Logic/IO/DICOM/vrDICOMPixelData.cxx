// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrDICOMPixelData.h"

#include <gdcmImageReader.h>
#include <gdcmReader.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>

namespace vr::detail
{
namespace
{
const gdcm::Tag PixelDataTag(0x7fe0, 0x0010);
/** No rescaled value may be larger than this in size (the same bound as the rescale's attributes'). */
constexpr double LargestRescaledValue = 1e9;

/** Whether plain pixel data of \a length bytes lie whole in \a file: GDCM's parser accepts a file cut short inside
 * them (its reading stops at the file's end, the rest of the value left as it was), so the element is looked for in
 * the file's bytes: its tag, then an explicit VR OB/OW header or an implicit one with that length. */
bool
PixelDataWhole(const std::string & file, std::uint64_t length, bool bigEndian)
{
  std::ifstream stream(file, std::ios::binary | std::ios::ate);
  std::string   bytes(static_cast<std::size_t>(std::max<std::streamoff>(stream.tellg(), 0)), '\0');
  stream.seekg(0);
  stream.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  bytes.resize(static_cast<std::size_t>(std::max<std::streamsize>(stream.gcount(), 0)));
  const std::string tag = bigEndian ? std::string("\x7F\xE0\x00\x10", 4) : std::string("\xE0\x7F\x10\x00", 4);
  auto              number = [&](std::size_t at)
  {
    std::uint64_t value = 0;
    for (std::size_t k = 0; k < 4; ++k)
    {
      const auto byte = static_cast<unsigned char>(bytes[at + (bigEndian ? 3 - k : k)]);
      value |= std::uint64_t{ byte } << (8 * k);
    }
    return value;
  };
  // From the front: the element's header comes before its value (the value's bytes are never searched through).
  for (std::size_t at = bytes.find(tag); at != std::string::npos; at = bytes.find(tag, at + 1))
  {
    const bool explicitVR = at + 12 <= bytes.size() &&
                            (bytes.compare(at + 4, 2, "OW") == 0 || bytes.compare(at + 4, 2, "OB") == 0) &&
                            bytes[at + 6] == 0 && bytes[at + 7] == 0;
    if (explicitVR && number(at + 8) == length)
    {
      return at + 12 + length <= bytes.size();
    }
    if (at + 8 <= bytes.size() && number(at + 4) == length)
    {
      return at + 8 + length <= bytes.size();
    }
  }
  return false;
}

/** What is wrong with the Pixel Data element of \a elements for a file of \a layout; empty when nothing. */
std::string
PixelDataProblem(const std::string & file, const gdcm::DataSet & elements, const DICOMImageLayout & layout)
{
  if (!elements.FindDataElement(PixelDataTag))
  {
    return "the DICOM file " + file + " has no Pixel Data (7FE0,0010): an image without its pixels";
  }
  const gdcm::DataElement & pixels = elements.GetDataElement(PixelDataTag);
  const bool                compressed = pixels.GetSequenceOfFragments() != nullptr;
  const gdcm::ByteValue *   plain = pixels.GetByteValue();
  const std::string         syntax = "its Transfer Syntax UID (0002,0010) (" + layout.TransferSyntaxFamily + ")";
  if (IsEncapsulatedFamily(layout.TransferSyntaxFamily) && !compressed)
  {
    return "the DICOM file " + file + ": " + syntax +
           " says its Pixel Data are compressed, but they are stored plain: the file's claim does not match its data";
  }
  if (!IsEncapsulatedFamily(layout.TransferSyntaxFamily) && compressed)
  {
    return "the DICOM file " + file + ": its Pixel Data are compressed fragments, but " + syntax +
           " says they are stored plain: the file's claim does not match its data";
  }
  if (!compressed && plain == nullptr)
  {
    return "the DICOM file " + file + ": its Pixel Data (7FE0,0010) hold no value";
  }
  // (A deflated data set's bytes are not the elements': its inflation fails on a file cut short.)
  if (plain != nullptr && layout.TransferSyntaxFamily != "deflated" &&
      !PixelDataWhole(file, plain->GetLength(), layout.TransferSyntaxFamily == "native big-endian"))
  {
    return "the DICOM file " + file +
           " ends inside its Pixel Data (7FE0,0010): the file is cut short (truncated in a " + "transfer?)";
  }
  if (plain != nullptr)
  {
    const std::uint64_t expected = std::uint64_t{ layout.Rows } * layout.Columns * (layout.BitsAllocated / 8);
    const std::uint64_t length = plain->GetLength();
    if (length != expected && length != expected + 1) // + 1: the padding to an even length
    {
      std::ostringstream text;
      text << "the DICOM file " << file << ": its Pixel Data (7FE0,0010) hold " << length
           << " bytes, where Rows x Columns x Bits Allocated (" << layout.Rows << " x " << layout.Columns << " x "
           << layout.BitsAllocated << " bits) ask for " << expected << (length < expected ? " (truncated?)" : "");
      return text.str();
    }
  }
  return std::string();
}

/** Why a value of \a stored rescaled is too large; empty when it is not. */
template<typename TStored>
std::string
RescaledProblem(const std::string & file, TStored stored, double slope, double intercept, double & value)
{
  value = slope * static_cast<double>(stored) + intercept;
  if (std::abs(value) <= LargestRescaledValue)
  {
    return std::string();
  }
  std::ostringstream text;
  text << "the DICOM file " << file << ": its Rescale Slope (0028,1053) " << slope << " and Rescale Intercept "
       << "(0028,1052) " << intercept << " make its stored value " << +stored << " into " << value
       << ", larger than 1e9 in size: not an image's values";
  return text.str();
}

/** Checks the rescaled values of \a count stored values, which stay as they are. */
template<typename TStored>
std::string
CheckRescaled(const std::string & file, const void * slice, std::size_t count, double slope, double intercept)
{
  const auto * stored = static_cast<const TStored *>(slice);
  // Linear: the extremes of the stored values make the extremes of the rescaled ones.
  const auto [low, high] = std::minmax_element(stored, stored + count);
  double value = 0.0;
  for (const TStored extreme : { *low, *high })
  {
    if (std::string problem = RescaledProblem(file, extreme, slope, intercept, value); !problem.empty())
    {
      return problem;
    }
  }
  return std::string();
}

template<typename TStored>
std::string
Rescale(const std::string & file, const char * buffer, std::size_t count, double slope, double intercept, float * slice)
{
  for (std::size_t k = 0; k < count; ++k)
  {
    TStored stored;
    std::memcpy(&stored, buffer + k * sizeof(TStored), sizeof(TStored));
    double value = 0.0;
    if (std::string problem = RescaledProblem(file, stored, slope, intercept, value); !problem.empty())
    {
      return problem;
    }
    slice[k] = static_cast<float>(value);
  }
  return std::string();
}
itk::IOComponentEnum
ComponentOf(gdcm::PixelFormat::ScalarType type)
{
  switch (type)
  {
    case gdcm::PixelFormat::UINT8:
      return itk::IOComponentEnum::UCHAR;
    case gdcm::PixelFormat::INT8:
      return itk::IOComponentEnum::CHAR;
    case gdcm::PixelFormat::UINT16:
      return itk::IOComponentEnum::USHORT;
    case gdcm::PixelFormat::INT16:
      return itk::IOComponentEnum::SHORT;
    case gdcm::PixelFormat::UINT32:
      return itk::IOComponentEnum::UINT;
    case gdcm::PixelFormat::INT32:
      return itk::IOComponentEnum::INT;
    default:
      return itk::IOComponentEnum::UNKNOWNCOMPONENTTYPE;
  }
}
} // namespace

itk::IOComponentEnum
DICOMStoredPixelType(const DICOMImageLayout & layout)
{
  const bool isSigned = layout.PixelRepresentation == 1;
  switch (layout.BitsAllocated)
  {
    case 8:
      return isSigned ? itk::IOComponentEnum::CHAR : itk::IOComponentEnum::UCHAR;
    case 16:
      return isSigned ? itk::IOComponentEnum::SHORT : itk::IOComponentEnum::USHORT;
    case 32:
      return isSigned ? itk::IOComponentEnum::INT : itk::IOComponentEnum::UINT;
    default:
      return itk::IOComponentEnum::UNKNOWNCOMPONENTTYPE;
  }
}

std::string
ReadDICOMPixels(const std::string &      file,
                const DICOMImageLayout & layout,
                double                   slope,
                double                   intercept,
                float *                  slice)
{
  itk::IOComponentEnum decoded = itk::IOComponentEnum::UNKNOWNCOMPONENTTYPE;
  return ReadDICOMPixels(file, layout, slope, intercept, itk::IOComponentEnum::FLOAT, slice, decoded);
}

std::string
ReadDICOMPixels(const std::string &      file,
                const DICOMImageLayout & layout,
                double                   slope,
                double                   intercept,
                itk::IOComponentEnum     pixelType,
                void *                   slice,
                itk::IOComponentEnum &   decoded)
{
  decoded = itk::IOComponentEnum::UNKNOWNCOMPONENTTYPE;
  gdcm::ImageReader reader;
  reader.SetFileName(file.c_str());
  if (!reader.Read())
  {
    // Why: the file does not parse, or it parses and its pixel data are wrong, or GDCM's image reader refuses them.
    gdcm::Reader plain;
    plain.SetFileName(file.c_str());
    if (!plain.Read())
    {
      return "the DICOM file " + file +
             " cannot be read: GDCM's parser stops in it (truncated or corrupt?); remove or replace it";
    }
    if (std::string problem = PixelDataProblem(file, plain.GetFile().GetDataSet(), layout); !problem.empty())
    {
      return problem;
    }
    return "the DICOM file " + file + ": GDCM cannot read it as an image (transfer syntax " +
           layout.TransferSyntaxFamily + ")";
  }
  if (std::string problem = PixelDataProblem(file, reader.GetFile().GetDataSet(), layout); !problem.empty())
  {
    return problem;
  }
  const gdcm::Image &       image = reader.GetImage();
  const gdcm::PixelFormat & format = image.GetPixelFormat();
  const std::size_t         count = std::size_t{ layout.Rows } * layout.Columns;
  const bool                oneFrame =
    image.GetNumberOfDimensions() == 2 || (image.GetNumberOfDimensions() == 3 && image.GetDimension(2) == 1);
  if (image.GetDimension(0) != layout.Columns || image.GetDimension(1) != layout.Rows || !oneFrame ||
      format.GetSamplesPerPixel() != 1 ||
      image.GetBufferLength() != count * static_cast<std::size_t>(format.GetPixelSize()))
  {
    std::ostringstream text;
    text << "the DICOM file " << file << ": GDCM decodes its pixels as " << image.GetDimension(0) << " x "
         << image.GetDimension(1) << " pixels of " << format.GetScalarTypeAsString() << ", not as its attributes say ("
         << layout.Columns << " x " << layout.Rows << ", " << layout.BitsAllocated << " bits allocated)";
    return text.str();
  }
  const itk::IOComponentEnum type = ComponentOf(format.GetScalarType());
  if (type == itk::IOComponentEnum::UNKNOWNCOMPONENTTYPE)
  {
    return "the DICOM file " + file + ": GDCM decodes its pixels as " + format.GetScalarTypeAsString() +
           ", which the reader does not take";
  }
  decoded = type;
  if (pixelType != itk::IOComponentEnum::FLOAT && pixelType != type)
  {
    return std::string(); // the caller reads the series another way
  }
  // The stored values straight into the slice; for float, through a buffer of them.
  std::vector<char> buffer(pixelType == itk::IOComponentEnum::FLOAT ? image.GetBufferLength() : 0);
  char *            target = pixelType == itk::IOComponentEnum::FLOAT ? buffer.data() : static_cast<char *>(slice);
  if (!image.GetBuffer(target))
  {
    return "the DICOM file " + file + ": GDCM cannot decode its pixel data (transfer syntax " +
           layout.TransferSyntaxFamily + ")";
  }
  auto * floats = static_cast<float *>(slice);
  switch (pixelType == itk::IOComponentEnum::FLOAT ? type : itk::IOComponentEnum::UNKNOWNCOMPONENTTYPE)
  {
    case itk::IOComponentEnum::UCHAR:
      return Rescale<std::uint8_t>(file, target, count, slope, intercept, floats);
    case itk::IOComponentEnum::CHAR:
      return Rescale<std::int8_t>(file, target, count, slope, intercept, floats);
    case itk::IOComponentEnum::USHORT:
      return Rescale<std::uint16_t>(file, target, count, slope, intercept, floats);
    case itk::IOComponentEnum::SHORT:
      return Rescale<std::int16_t>(file, target, count, slope, intercept, floats);
    case itk::IOComponentEnum::UINT:
      return Rescale<std::uint32_t>(file, target, count, slope, intercept, floats);
    case itk::IOComponentEnum::INT:
      return Rescale<std::int32_t>(file, target, count, slope, intercept, floats);
    default:
      break;
  }
  switch (type)
  {
    case itk::IOComponentEnum::UCHAR:
      return CheckRescaled<std::uint8_t>(file, slice, count, slope, intercept);
    case itk::IOComponentEnum::CHAR:
      return CheckRescaled<std::int8_t>(file, slice, count, slope, intercept);
    case itk::IOComponentEnum::USHORT:
      return CheckRescaled<std::uint16_t>(file, slice, count, slope, intercept);
    case itk::IOComponentEnum::SHORT:
      return CheckRescaled<std::int16_t>(file, slice, count, slope, intercept);
    case itk::IOComponentEnum::UINT:
      return CheckRescaled<std::uint32_t>(file, slice, count, slope, intercept);
    default:
      return CheckRescaled<std::int32_t>(file, slice, count, slope, intercept);
  }
}
} // namespace vr::detail
