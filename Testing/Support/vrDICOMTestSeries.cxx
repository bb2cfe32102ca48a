// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrDICOMTestSeries.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace vr::test
{
namespace
{
constexpr std::uint32_t
Key(std::uint16_t group, std::uint16_t element)
{
  return (std::uint32_t{ group } << 16) | element;
}

bool
HasLongLength(const std::string & vr)
{
  for (const char * name : { "OB", "OD", "OF", "OL", "OV", "OW", "SQ", "UC", "UR", "UT", "UN", "SV", "UV" })
  {
    if (vr == name)
    {
      return true;
    }
  }
  return false;
}

/** The size of the units a binary VR's value is made of (swapped in a big-endian file), 1 for text. */
std::size_t
UnitSize(const std::string & vr)
{
  if (vr == "US" || vr == "SS" || vr == "OW" || vr == "AT")
  {
    return 2;
  }
  if (vr == "UL" || vr == "SL" || vr == "FL" || vr == "OF")
  {
    return 4;
  }
  if (vr == "FD" || vr == "OD")
  {
    return 8;
  }
  return 1;
}

void
AppendNumber(std::string & out, std::uint32_t value, std::size_t bytes, bool bigEndian)
{
  for (std::size_t k = 0; k < bytes; ++k)
  {
    const std::size_t shift = 8 * (bigEndian ? bytes - 1 - k : k);
    out += static_cast<char>((value >> shift) & 0xFF);
  }
}

void
AppendElement(std::string & out, const DICOMTestElement & element, bool explicitVR, bool bigEndian)
{
  std::string       value = element.Value;
  const std::size_t unit = UnitSize(element.VR);
  if (bigEndian && unit > 1)
  {
    for (std::size_t at = 0; at + unit <= value.size(); at += unit)
    {
      std::reverse(value.begin() + static_cast<std::ptrdiff_t>(at),
                   value.begin() + static_cast<std::ptrdiff_t>(at + unit));
    }
  }
  AppendNumber(out, element.Group, 2, bigEndian);
  AppendNumber(out, element.Element, 2, bigEndian);
  if (explicitVR)
  {
    out += element.VR.substr(0, 2);
    if (HasLongLength(element.VR))
    {
      out += std::string(2, '\0');
      AppendNumber(out, static_cast<std::uint32_t>(value.size()), 4, bigEndian);
    }
    else
    {
      AppendNumber(out, static_cast<std::uint32_t>(value.size()), 2, bigEndian);
    }
  }
  else
  {
    AppendNumber(out, static_cast<std::uint32_t>(value.size()), 4, bigEndian);
  }
  out += value;
}

std::string
TrueTransferSyntax(const DICOMTestEncoding & encoding)
{
  if (encoding.BigEndian)
  {
    return "1.2.840.10008.1.2.2";
  }
  return encoding.ExplicitVR ? "1.2.840.10008.1.2.1" : "1.2.840.10008.1.2";
}

std::string
Decimal(double value)
{
  char text[32];
  std::snprintf(text, sizeof(text), "%.10g", value);
  return text;
}

/** The stored pixels of \a file: its values through its rescale, in its pixel format. */
std::string
PixelBytes(const DICOMTestFile & file, unsigned int bitsAllocated, unsigned int bitsStored, bool isSigned)
{
  std::string  bytes;
  const double low = isSigned ? -std::ldexp(1.0, static_cast<int>(bitsStored) - 1) : 0.0;
  const double high = isSigned ? std::ldexp(1.0, static_cast<int>(bitsStored) - 1) - 1.0
                               : std::ldexp(1.0, static_cast<int>(bitsStored)) - 1.0;
  for (const double value : file.Values)
  {
    const double stored = (value - file.Intercept) / file.Slope;
    const double whole = std::round(stored);
    if (std::abs(stored - whole) > 1e-6 || whole < low || whole > high)
    {
      throw std::logic_error("test series " + file.Name + ": the value " + std::to_string(value) +
                             " has no stored value in this pixel format and rescale");
    }
    const auto bits = static_cast<std::uint32_t>(static_cast<std::int64_t>(whole));
    AppendNumber(bytes, bits, bitsAllocated / 8, false);
  }
  return bytes;
}
} // namespace

void
DICOMTestDataSet::SetText(std::uint16_t group, std::uint16_t element, const std::string & vr, const std::string & value)
{
  std::string padded = value;
  if (padded.size() % 2 != 0)
  {
    padded += vr == "UI" ? '\0' : ' ';
  }
  Elements[Key(group, element)] = { group, element, vr, padded };
}

void
DICOMTestDataSet::SetUS(std::uint16_t group, std::uint16_t element, std::uint16_t value)
{
  std::string bytes;
  AppendNumber(bytes, value, 2, false);
  Elements[Key(group, element)] = { group, element, "US", bytes };
}

void
DICOMTestDataSet::SetBytes(std::uint16_t       group,
                           std::uint16_t       element,
                           const std::string & vr,
                           const std::string & bytes)
{
  Elements[Key(group, element)] = { group, element, vr, bytes };
}

void
DICOMTestDataSet::Remove(std::uint16_t group, std::uint16_t element)
{
  Elements.erase(Key(group, element));
}

const DICOMTestElement *
DICOMTestDataSet::Find(std::uint16_t group, std::uint16_t element) const
{
  const auto found = Elements.find(Key(group, element));
  return found == Elements.end() ? nullptr : &found->second;
}

std::string
DICOMTestDataSet::Text(std::uint16_t group, std::uint16_t element) const
{
  const DICOMTestElement * found = Find(group, element);
  if (found == nullptr)
  {
    return std::string();
  }
  std::string text = found->Value;
  while (!text.empty() && (text.back() == ' ' || text.back() == '\0'))
  {
    text.pop_back();
  }
  return text;
}

std::string
EncodeDICOMFile(const DICOMTestFile & file)
{
  DICOMTestDataSet data = file.Data;
  if (!file.OmitPixelData && !file.Values.empty())
  {
    // In the format the file was made in, whatever its attributes claim now (a fault may have changed them).
    std::string pixels = PixelBytes(file, 16, file.StoredBits, file.SignedPixels);
    if (file.PixelDataChange < 0)
    {
      pixels.resize(pixels.size() - std::min(pixels.size(), static_cast<std::size_t>(-file.PixelDataChange)));
    }
    else
    {
      pixels += std::string(static_cast<std::size_t>(file.PixelDataChange), '\x11');
    }
    data.SetBytes(0x7FE0, 0x0010, "OW", pixels);
  }

  // The file meta information: explicit VR little-endian always; values from the data set unless it gives its own.
  DICOMTestDataSet meta;
  meta.SetBytes(0x0002, 0x0001, "OB", std::string("\x00\x01", 2));
  meta.SetText(0x0002, 0x0002, "UI", data.Text(0x0008, 0x0016));
  meta.SetText(0x0002, 0x0003, "UI", data.Text(0x0008, 0x0018));
  meta.SetText(0x0002,
               0x0010,
               "UI",
               file.Encoding.ClaimedTransferSyntax.empty() ? TrueTransferSyntax(file.Encoding)
                                                           : file.Encoding.ClaimedTransferSyntax);
  meta.SetText(0x0002, 0x0012, "UI", "1.2.826.0.1.3680043.9.7731.1");
  meta.SetText(0x0002, 0x0013, "SH", "VR_TEST_37");
  for (auto entry = data.Elements.begin(); entry != data.Elements.end();)
  {
    if (entry->second.Group == 0x0002)
    {
      meta.Elements[entry->first] = entry->second;
      entry = data.Elements.erase(entry);
    }
    else
    {
      ++entry;
    }
  }
  std::string metaBytes;
  for (const auto & [key, element] : meta.Elements)
  {
    AppendElement(metaBytes, element, true, false);
  }
  std::string out(128, '\0');
  out += "DICM";
  std::string groupLength;
  AppendNumber(groupLength, static_cast<std::uint32_t>(metaBytes.size()), 4, false);
  AppendElement(out, { 0x0002, 0x0000, "UL", groupLength }, true, false);
  out += metaBytes;
  for (const auto & [key, element] : data.Elements)
  {
    AppendElement(out, element, file.Encoding.ExplicitVR || file.Encoding.BigEndian, file.Encoding.BigEndian);
  }
  if (file.TruncateTo && *file.TruncateTo < out.size())
  {
    out.resize(*file.TruncateTo);
  }
  return out;
}

void
WriteDICOMTestFolder(const std::string & folder, const std::vector<DICOMTestFile> & files)
{
  namespace fs = std::filesystem;
  fs::create_directories(folder);
  for (const DICOMTestFile & file : files)
  {
    const fs::path path = fs::path(folder) / file.Name;
    if (file.Folder)
    {
      fs::create_directories(path);
      std::ofstream(path / "readme.txt") << "a note in a sub-folder\n";
      continue;
    }
    const std::string bytes = file.Raw ? *file.Raw : EncodeDICOMFile(file);
    std::ofstream     out(path, std::ios::binary);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out)
    {
      throw std::runtime_error("cannot write " + path.string());
    }
  }
}

std::vector<DICOMTestFile>
MakeCTSeries(const VolumeImageType * volume, const CTSeriesOptions & options)
{
  const auto   size = volume->GetLargestPossibleRegion().GetSize();
  const auto & spacing = volume->GetSpacing();
  const auto & origin = volume->GetOrigin();
  if (!volume->GetDirection().GetVnlMatrix().is_identity())
  {
    throw std::logic_error("MakeCTSeries: the volume's direction must be the identity");
  }
  std::vector<DICOMTestFile> files;
  const auto                 slices = static_cast<unsigned int>(size[2]);
  for (unsigned int z = 0; z < slices; ++z)
  {
    DICOMTestFile      file;
    const unsigned int instance = options.FeetFirst ? z + 1 : slices - z;
    char               name[64];
    std::snprintf(name, sizeof(name), "%s%04u.dcm", options.Prefix.c_str(), instance);
    file.Name = name;
    file.Encoding = options.Encoding;
    // Feet first, the rows run from the patient's left to right (-x): column i holds the volume's x index nx-1-i.
    const double x = options.FeetFirst ? origin[0] + static_cast<double>(size[0] - 1) * spacing[0] : origin[0];
    for (unsigned int j = 0; j < size[1]; ++j)
    {
      for (unsigned int i = 0; i < size[0]; ++i)
      {
        const unsigned int xIndex = options.FeetFirst ? static_cast<unsigned int>(size[0]) - 1 - i : i;
        file.Values.push_back(volume->GetPixel({ { xIndex, j, z } }));
      }
    }
    file.Intercept = options.Signed ? 0.0 : -1024.0;
    file.Slope = 1.0;
    if (options.Rescale)
    {
      std::tie(file.Slope, file.Intercept) = options.Rescale(z);
    }
    const std::string  uidRoot = options.SeriesInstanceUID;
    DICOMTestDataSet & d = file.Data;
    d.SetText(0x0008, 0x0005, "CS", "ISO_IR 100");
    d.SetText(0x0008, 0x0008, "CS", "ORIGINAL\\PRIMARY\\AXIAL");
    d.SetText(0x0008, 0x0016, "UI", "1.2.840.10008.5.1.4.1.1.2");
    d.SetText(0x0008, 0x0018, "UI", uidRoot + "." + std::to_string(instance));
    d.SetText(0x0008, 0x0020, "DA", "20261128");
    d.SetText(0x0008, 0x0030, "TM", "101500");
    d.SetText(0x0008, 0x0050, "SH", "A37");
    d.SetText(0x0008, 0x0060, "CS", "CT");
    d.SetText(0x0008, 0x103E, "LO", options.SeriesDescription);
    d.SetText(0x0010, 0x0010, "PN", "Phantom^Thorax");
    d.SetText(0x0010, 0x0020, "LO", "VR-37");
    d.SetText(0x0010, 0x0030, "DA", "19600101");
    d.SetText(0x0010, 0x0040, "CS", "O");
    d.SetText(0x0018, 0x0050, "DS", Decimal(spacing[2]));
    d.SetText(0x0018, 0x5100, "CS", options.FeetFirst ? "FFS" : "HFS");
    d.SetText(0x0020, 0x000D, "UI", options.StudyInstanceUID);
    d.SetText(0x0020, 0x000E, "UI", options.SeriesInstanceUID);
    d.SetText(0x0020, 0x0010, "SH", "1");
    d.SetText(0x0020, 0x0011, "IS", options.SeriesNumber);
    d.SetText(0x0020, 0x0013, "IS", std::to_string(instance));
    d.SetText(0x0020,
              0x0032,
              "DS",
              Decimal(x) + "\\" + Decimal(origin[1]) + "\\" + Decimal(origin[2] + static_cast<double>(z) * spacing[2]));
    d.SetText(0x0020, 0x0037, "DS", options.FeetFirst ? "-1\\0\\0\\0\\1\\0" : "1\\0\\0\\0\\1\\0");
    d.SetText(0x0020, 0x0052, "UI", options.FrameOfReferenceUID);
    d.SetUS(0x0028, 0x0002, 1);
    d.SetText(0x0028, 0x0004, "CS", "MONOCHROME2");
    d.SetUS(0x0028, 0x0010, static_cast<std::uint16_t>(size[1]));
    d.SetUS(0x0028, 0x0011, static_cast<std::uint16_t>(size[0]));
    d.SetText(0x0028, 0x0030, "DS", Decimal(spacing[1]) + "\\" + Decimal(spacing[0]));
    const unsigned int storedBits = options.Signed || options.Rescale ? 16 : 12;
    d.SetUS(0x0028, 0x0100, 16);
    d.SetUS(0x0028, 0x0101, static_cast<std::uint16_t>(storedBits));
    d.SetUS(0x0028, 0x0102, static_cast<std::uint16_t>(storedBits - 1));
    d.SetUS(0x0028, 0x0103, options.Signed ? 1 : 0);
    d.SetText(0x0028, 0x1050, "DS", "40");
    d.SetText(0x0028, 0x1051, "DS", "400");
    d.SetText(0x0028, 0x1052, "DS", Decimal(file.Intercept));
    d.SetText(0x0028, 0x1053, "DS", Decimal(file.Slope));
    d.SetText(0x0028, 0x1054, "LO", "HU");
    file.SignedPixels = options.Signed;
    file.StoredBits = storedBits;
    files.push_back(std::move(file));
  }
  std::sort(files.begin(), files.end(), [](const auto & a, const auto & b) { return a.Name < b.Name; });
  return files;
}

VolumeImageType::Pointer
QuantizedCT(const VolumeImageType * volume)
{
  auto copy = VolumeImageType::New();
  copy->SetRegions(volume->GetLargestPossibleRegion());
  copy->CopyInformation(volume);
  copy->Allocate();
  const std::size_t count = volume->GetLargestPossibleRegion().GetNumberOfPixels();
  for (std::size_t k = 0; k < count; ++k)
  {
    const double value = std::round(static_cast<double>(volume->GetBufferPointer()[k]));
    copy->GetBufferPointer()[k] = static_cast<float>(std::clamp(value, -1024.0, 3071.0));
  }
  return copy;
}
} // namespace vr::test
