// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Fuzz harness: a DICOM folder read through vr::ReadVolume, as the modules read one: the series is scanned and read
// in the child process vrReadDICOMSeries (vrDICOMSeriesProcess), which GDCM may abort or crash without taking the
// caller with it. The input is a folder of up to four files, each as a 4-byte little-endian length and its bytes
// (written as IM0001.dcm, ...). Its custom mutator works on DICOM elements: it walks one file's little-endian
// elements (after the preamble; explicit VR where a VR is there, implicit else) and changes one: a value (numbers and
// strings that break readers), a length, a VR, the tag; or drops or duplicates it; or drops, duplicates or truncates a
// file. A fifth of the mutations are libFuzzer's byte-level ones within one file.
//
// A finding is this process crashing (the protection failed), or a failure whose message names no file of the folder
// where a file is at fault (a read that died or failed must say which file). What GDCM does inside the child (its
// assertions, and its memory errors under the sanitizers) is contained by design and is no finding. Each input
// starts a process: expect a few executions per second.
#include "vrFuzzFieldMutation.h"
#include "vrFuzzSupport.h"
#include "vrInputError.h"
#include "vrVolumeIO.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace
{
constexpr std::size_t MaximumFiles = 4;

using Bytes = std::vector<std::uint8_t>;

std::vector<Bytes>
Unpack(const std::uint8_t * data, std::size_t size)
{
  std::vector<Bytes> files;
  std::size_t        at = 0;
  while (at + 4 <= size && files.size() < MaximumFiles)
  {
    const std::size_t length = std::min<std::size_t>(
      data[at] | (data[at + 1] << 8) | (data[at + 2] << 16) | (std::size_t{ data[at + 3] } << 24), size - at - 4);
    files.emplace_back(data + at + 4, data + at + 4 + length);
    at += 4 + length;
  }
  return files;
}

std::size_t
Pack(const std::vector<Bytes> & files, std::uint8_t * data, std::size_t maxSize)
{
  std::size_t at = 0;
  for (const Bytes & file : files)
  {
    if (at + 4 + file.size() > maxSize)
    {
      break;
    }
    const std::size_t length = file.size();
    for (int k = 0; k < 4; ++k)
    {
      data[at + k] = static_cast<std::uint8_t>(length >> (8 * k));
    }
    std::copy(file.begin(), file.end(), data + at + 4);
    at += 4 + length;
  }
  return at;
}

/** One element of an explicit-VR little-endian data set: where it starts, where its length field is and how wide,
 * where its value starts and how long it is (0 for an undefined length, whose content is walked as elements). */
struct Element
{
  std::size_t start;
  std::size_t lengthAt;
  std::size_t lengthBytes;
  std::size_t valueAt;
  std::size_t valueLength;
  bool        hasVR;
};

bool
IsVR(const std::uint8_t * vr)
{
  static const char * const vrs[] = { "AE", "AS", "AT", "CS", "DA", "DS", "DT", "FD", "FL", "IS", "LO", "LT",
                                      "OB", "OD", "OF", "OL", "OV", "OW", "PN", "SH", "SL", "SQ", "SS", "ST",
                                      "SV", "TM", "UC", "UI", "UL", "UN", "UR", "US", "UT", "UV" };
  return std::any_of(
    std::begin(vrs), std::end(vrs), [&](const char * name) { return vr[0] == name[0] && vr[1] == name[1]; });
}

bool
HasLongLength(const std::uint8_t * vr)
{
  static const char * const longVRs[] = {
    "OB", "OW", "OF", "OD", "OL", "OV", "SQ", "UT", "UN", "UC", "UR", "SV", "UV"
  };
  return std::any_of(
    std::begin(longVRs), std::end(longVRs), [&](const char * name) { return vr[0] == name[0] && vr[1] == name[1]; });
}

std::vector<Element>
Walk(const Bytes & file)
{
  std::vector<Element> elements;
  std::size_t          at = file.size() >= 132 && std::memcmp(file.data() + 128, "DICM", 4) == 0 ? 132 : 0;
  while (at + 8 <= file.size() && elements.size() < 4096)
  {
    const std::uint8_t * p = file.data() + at;
    const unsigned       group = p[0] | (p[1] << 8);
    Element              element{ at, 0, 0, 0, 0, false };
    if (group == 0xFFFE) // item and delimiters: tag and a 4-byte length, no VR
    {
      element.lengthAt = at + 4;
      element.lengthBytes = 4;
      element.valueAt = at + 8;
    }
    else if (IsVR(p + 4))
    {
      element.hasVR = true;
      if (HasLongLength(p + 4))
      {
        if (at + 12 > file.size())
        {
          break;
        }
        element.lengthAt = at + 8;
        element.lengthBytes = 4;
        element.valueAt = at + 12;
      }
      else
      {
        element.lengthAt = at + 6;
        element.lengthBytes = 2;
        element.valueAt = at + 8;
      }
    }
    else // implicit VR (the data set of ITK's files): tag and a 4-byte length
    {
      element.lengthAt = at + 4;
      element.lengthBytes = 4;
      element.valueAt = at + 8;
    }
    std::size_t length = 0;
    for (std::size_t k = 0; k < element.lengthBytes; ++k)
    {
      length |= std::size_t{ file[element.lengthAt + k] } << (8 * k);
    }
    const bool undefined = element.lengthBytes == 4 && length == 0xFFFFFFFFu;
    // Items and sequences of undefined length are walked into.
    element.valueLength = undefined || group == 0xFFFE ? 0 : std::min(length, file.size() - element.valueAt);
    elements.push_back(element);
    at = element.valueAt + element.valueLength;
  }
  return elements;
}

void
SetLength(Bytes & file, const Element & element, std::size_t length)
{
  for (std::size_t k = 0; k < element.lengthBytes; ++k)
  {
    file[element.lengthAt + k] = static_cast<std::uint8_t>(length >> (8 * k));
  }
}

/** A new value for an element: a number as text (even length, space-padded as DICOM pads), binary numbers that
 * break readers, or random bytes. */
Bytes
NewValue(const Bytes & file, const Element & element, vr::fuzz::Random & random)
{
  // Implicit VR: the image pixel module's unsigned shorts are known by their tags (rows, columns, bits, ...).
  const std::uint8_t * tag = file.data() + element.start;
  const bool           imagePixelUS =
    tag[0] == 0x28 && tag[1] == 0x00 &&
    ((tag[3] == 0x00 && (tag[2] == 0x02 || tag[2] == 0x10 || tag[2] == 0x11)) || (tag[3] == 0x01 && tag[2] <= 0x03));
  static const std::uint8_t us[] = { 'U', 'S' };
  const std::uint8_t *      vr = element.hasVR ? file.data() + element.start + 4 : imagePixelUS ? us : tag;
  const bool                binary = (element.hasVR || imagePixelUS) &&
                      (std::memcmp(vr, "US", 2) == 0 || std::memcmp(vr, "UL", 2) == 0 ||
                       std::memcmp(vr, "SS", 2) == 0 || std::memcmp(vr, "SL", 2) == 0 ||
                       std::memcmp(vr, "FL", 2) == 0 || std::memcmp(vr, "FD", 2) == 0 || std::memcmp(vr, "AT", 2) == 0);
  Bytes value(file.begin() + static_cast<std::ptrdiff_t>(element.valueAt),
              file.begin() + static_cast<std::ptrdiff_t>(element.valueAt + element.valueLength));
  if (binary && !value.empty() && random.Below(4) != 0)
  {
    static const vr::fuzz::Field fields[] = { { 0, vr::fuzz::FieldType::Int16, 1 } };
    static const vr::fuzz::Field wide[] = { { 0, vr::fuzz::FieldType::Int32, 1 } };
    static const vr::fuzz::Field floats[] = { { 0, vr::fuzz::FieldType::Float32, 1 } };
    static const vr::fuzz::Field doubles[] = { { 0, vr::fuzz::FieldType::Float64, 1 } };
    value.resize(std::max<std::size_t>(value.size(), 8)); // room for the widest; cut back below
    const std::size_t       width = std::memcmp(vr, "FD", 2) == 0 ? 8 : (vr[1] == 'S' && vr[0] != 'F') ? 2 : 4;
    const vr::fuzz::Field * field = std::memcmp(vr, "FL", 2) == 0   ? floats
                                    : std::memcmp(vr, "FD", 2) == 0 ? doubles
                                    : width == 2                    ? fields
                                                                    : wide;
    vr::fuzz::MutateField(value.data(), field, 1, false, random);
    value.resize(std::max<std::size_t>(width, element.valueLength));
    return value;
  }
  if (random.Below(4) == 0)
  {
    for (std::size_t k = random.Below(3) + 1; k > 0 && !value.empty(); --k)
    {
      value[random.Below(value.size())] = static_cast<std::uint8_t>(random.Next());
    }
    return value;
  }
  std::string text = vr::fuzz::InterestingNumberText(random);
  for (std::size_t k = random.Below(3); k > 0; --k)
  {
    text += "\\" + vr::fuzz::InterestingNumberText(random); // a multi-valued string
  }
  if (text.size() % 2 != 0)
  {
    text += ' ';
  }
  return Bytes(text.begin(), text.end());
}

void
MutateElement(Bytes & file, vr::fuzz::Random & random)
{
  const std::vector<Element> elements = Walk(file);
  if (elements.empty())
  {
    return;
  }
  const Element & element = elements[random.Below(elements.size())];
  const auto      begin = file.begin() + static_cast<std::ptrdiff_t>(element.start);
  const auto      valueEnd = file.begin() + static_cast<std::ptrdiff_t>(element.valueAt + element.valueLength);
  switch (random.Below(7))
  {
    case 0: // a value
    case 1:
    {
      const Bytes value = NewValue(file, element, random);
      if (element.lengthBytes == 2 && value.size() > 0xFFFF)
      {
        return;
      }
      file.erase(file.begin() + static_cast<std::ptrdiff_t>(element.valueAt), valueEnd);
      file.insert(file.begin() + static_cast<std::ptrdiff_t>(element.valueAt), value.begin(), value.end());
      SetLength(file, element, value.size());
      return;
    }
    case 2: // a length
    {
      static const std::size_t lengths[] = { 0,    1,      2,       3,          4,          6,         8,
                                             0xFF, 0xFFFF, 0x10000, 0x7FFFFFFF, 0xFFFFFFFE, 0xFFFFFFFF };
      std::size_t              length =
        random.Below(3) == 0 ? element.valueLength + random.Below(9) - 4 : lengths[random.Below(std::size(lengths))];
      SetLength(file, element, length);
      return;
    }
    case 3: // a VR
      if (element.hasVR)
      {
        static const char * const vrs[] = { "US", "SS", "UL", "SL", "FL", "FD", "DS", "IS", "CS", "UI", "OB", "OW",
                                            "SQ", "UN", "UT", "LO", "SH", "AT", "DA", "TM", "PN", "ST", "XX" };
        std::memcpy(file.data() + element.start + 4, vrs[random.Below(std::size(vrs))], 2);
      }
      return;
    case 4: // the tag: another element of the same group, or one GDCM and ITK act on
    {
      static const std::uint16_t tags[][2] = { { 0x0002, 0x0010 }, { 0x0002, 0x0000 }, { 0x0008, 0x0016 },
                                               { 0x0020, 0x000E }, { 0x0020, 0x0013 }, { 0x0020, 0x0032 },
                                               { 0x0020, 0x0037 }, { 0x0028, 0x0002 }, { 0x0028, 0x0004 },
                                               { 0x0028, 0x0008 }, { 0x0028, 0x0010 }, { 0x0028, 0x0011 },
                                               { 0x0028, 0x0030 }, { 0x0028, 0x0100 }, { 0x0028, 0x0101 },
                                               { 0x0028, 0x0102 }, { 0x0028, 0x0103 }, { 0x0028, 0x1052 },
                                               { 0x0028, 0x1053 }, { 0x7FE0, 0x0010 }, { 0xFFFE, 0xE000 } };
      const auto &               tag = tags[random.Below(std::size(tags))];
      const std::size_t          at = element.start;
      file[at] = static_cast<std::uint8_t>(tag[0]);
      file[at + 1] = static_cast<std::uint8_t>(tag[0] >> 8);
      file[at + 2] = static_cast<std::uint8_t>(tag[1]);
      file[at + 3] = static_cast<std::uint8_t>(tag[1] >> 8);
      return;
    }
    case 5: // dropped
      file.erase(begin, valueEnd);
      return;
    default: // duplicated
    {
      const Bytes copy(begin, valueEnd);
      file.insert(valueEnd, copy.begin(), copy.end());
      return;
    }
  }
}
} // namespace

extern "C" std::size_t
LLVMFuzzerCustomMutator(std::uint8_t * data, std::size_t size, std::size_t maxSize, unsigned int seed)
{
  vr::fuzz::Random   random(seed);
  std::vector<Bytes> files = Unpack(data, size);
  if (files.empty())
  {
    return LLVMFuzzerMutate(data, size, maxSize);
  }
  Bytes &           file = files[random.Below(files.size())];
  const std::size_t choice = random.Below(20);
  if (choice < 4 && !file.empty()) // bytes within the file
  {
    const std::size_t room = maxSize > size ? maxSize - size : 0;
    file.resize(file.size() + room / 2 + 16);
    file.resize(LLVMFuzzerMutate(file.data(), file.size() - room / 2 - 16, file.size()));
  }
  else if (choice == 4) // a file dropped
  {
    if (files.size() > 1)
    {
      files.erase(files.begin() + static_cast<std::ptrdiff_t>(random.Below(files.size())));
    }
  }
  else if (choice == 5) // a file duplicated (two of the same instance in a series)
  {
    if (files.size() < MaximumFiles)
    {
      files.push_back(file);
    }
  }
  else if (choice == 6) // a file truncated
  {
    file.resize(random.Below(file.size() + 1));
  }
  else
  {
    MutateElement(file, random);
  }
  return Pack(files, data, maxSize);
}

extern "C" int
LLVMFuzzerInitialize(int *, char ***)
{
  // A child that hangs is stopped by the reader (a message naming the file, no finding): after 10 s, not the default
  // minute, so that a hang costs little fuzzing time; below libFuzzer's -timeout (scripts/fuzz.sh gives 60 s here).
  ::setenv("VR_DICOM_SERIES_TIMEOUT", "10", 0);
  return 0;
}

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t * data, std::size_t size)
{
  const std::vector<Bytes> files = Unpack(data, size);
  // A folder of this input's files only: WriteInput's folder, emptied of the previous input's.
  const std::filesystem::path folder = std::filesystem::path(vr::fuzz::InputFolder()) / "series";
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  std::vector<std::string> names;
  for (std::size_t k = 0; k < files.size(); ++k)
  {
    char name[24];
    std::snprintf(name, sizeof(name), "IM%04zu.dcm", k + 1);
    names.push_back((folder / name).string());
    std::ofstream(names.back(), std::ios::binary)
      .write(reinterpret_cast<const char *>(files[k].data()), static_cast<std::streamsize>(files[k].size()));
  }
  try
  {
    vr::ReadVolume(folder.string());
  }
  catch (const vr::InputError & error)
  {
    // A failure of the series as a whole may name the folder only; one that a file caused must name the file.
    const std::string message = error.what();
    const bool        namesAFile = std::any_of(
      names.begin(), names.end(), [&](const std::string & name) { return message.find(name) != std::string::npos; });
    const bool aFileIsAtFault = message.find("DICOM file") != std::string::npos ||
                                message.find("died") != std::string::npos ||
                                message.find("cannot be read") != std::string::npos;
    if (message.find(folder.string()) == std::string::npos || (aFileIsAtFault && !namesAFile))
    {
      std::fprintf(stderr, "finding: the message names no file at fault: %s\n", message.c_str());
      std::abort();
    }
  }
  return 0;
}
