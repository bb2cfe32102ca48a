// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Structure-aware fuzz harness: NRRD files read through vr::ReadVolume, as the modules read a volume (the data file
// checks, ITK's NRRD reader, our checks of size and geometry, then the voxels). Its custom mutator edits the header
// as "key: value" lines: a value replaced by one that has broken readers (per key: sizes, spacings, space
// directions, type, encoding, endian, data file, ...; or a number such as nan, -1, 1e309), a known key added, a line
// dropped, duplicated or moved. A fifth of the mutations are libFuzzer's byte-level ones. The bytes after the
// header's blank line are also written as input.raw beside the file, so that a detached header ("data file:
// input.raw") finds data. Any input must end in a volume or a vr::InputError.
#include "vrFuzzFieldMutation.h"
#include "vrFuzzSupport.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace
{
struct Key
{
  const char *              name;
  std::vector<const char *> values; // besides numbers from InterestingNumberText()
};

const std::vector<Key> &
Keys()
{
  static const std::vector<Key> keys = {
    { "type",
      { "float",
        "double",
        "short",
        "unsigned char",
        "int8",
        "uint16",
        "int64",
        "uint64",
        "block",
        "int",
        "unsigned long long int",
        "float32",
        "" } },
    { "dimension", { "1", "2", "3", "4", "16", "17" } },
    { "sizes",
      { "2 2 2", "1 1 1", "0 2 2", "2 2", "2 2 2 2", "65536 65536 65536", "4294967296 1 1", "-2 2 2", "2 2 nan" } },
    { "spacings", { "1 1 1", "0 1 1", "-1 1 1", "nan 1 1", "inf 1 1", "1e-320 1 1", "1 1", "NaN NaN NaN" } },
    { "space directions",
      { "(1,0,0) (0,1,0) (0,0,1)",
        "none (1,0,0) (0,1,0) (0,0,1)",
        "(0,0,0) (0,1,0) (0,0,1)",
        "(nan,0,0) (0,1,0) (0,0,1)",
        "(1,0,0) (1,0,0) (0,0,1)",
        "(1,0) (0,1) (0,0)",
        "(1e308,1e308,0) (0,1,0) (0,0,1)",
        "(1,0,0) (0,1,0)",
        "none none none" } },
    { "space origin", { "(0,0,0)", "(nan,0,0)", "(inf,-inf,0)", "(0,0)", "(0,0,0,0)", "none" } },
    { "space",
      { "left-posterior-superior", "right-anterior-superior", "scanner-xyz", "3D-right-handed-time", "unknown" } },
    { "space dimension", { "3", "2", "4", "0" } },
    { "encoding", { "raw", "gzip", "gz", "bzip2", "ascii", "text", "hex", "unknown" } },
    { "endian", { "little", "big", "middle" } },
    { "data file",
      { "input.raw",
        "missing.raw",
        "input.raw.gz",
        "LIST",
        "input.%d 0 2 1",
        "input.%d 0 -1 1",
        "/dev/null",
        ".",
        "" } },
    { "byte skip", { "-1", "0", "1", "4096", "2147483648" } },
    { "line skip", { "-1", "0", "1", "1000000" } },
    { "kinds",
      { "domain domain domain",
        "space space space",
        "RGB-color domain domain domain",
        "list domain",
        "3-vector domain domain domain" } },
    { "centers", { "cell cell cell", "node node node", "??? ??? ???" } },
    { "thicknesses", { "1 1 1", "nan nan nan" } },
    { "axis mins", { "0 0 0", "nan 0 0" } },
    { "axis maxs", { "1 1 1", "inf 1 1" } },
    { "measurement frame", { "(1,0,0) (0,1,0) (0,0,1)", "(nan,0,0) (0,1,0) (0,0,1)", "(1,0) (0,1)" } },
    { "space units", { "\"mm\" \"mm\" \"mm\"", "\"\" \"\"" } },
    { "content", { "fuzz", "" } },
    { "min", { "0", "nan" } },
    { "max", { "1", "inf" } },
    { "old min", { "0" } },
    { "old max", { "1" } },
    { "block size", { "0", "-1", "4" } },
    { "labels", { "\"x\" \"y\" \"z\"" } },
  };
  return keys;
}

/** A value for \a key: one of its own, or a number in one of its positions. */
std::string
ValueFor(const std::string & key, vr::fuzz::Random & random)
{
  for (const Key & known : Keys())
  {
    if (key == known.name && !known.values.empty() && random.Below(3) != 0)
    {
      return known.values[random.Below(known.values.size())];
    }
  }
  std::string value = vr::fuzz::InterestingNumberText(random);
  for (std::size_t k = random.Below(3); k > 0; --k)
  {
    value += " " + vr::fuzz::InterestingNumberText(random);
  }
  return value;
}

/** The header's lines (without their newlines) and where the data starts (after the blank line); false when the
 * input has no header line at all. */
bool
SplitHeader(const std::uint8_t * data, std::size_t size, std::vector<std::string> & lines, std::size_t & dataStart)
{
  std::size_t start = 0;
  dataStart = size;
  while (start < size)
  {
    const auto *      end = static_cast<const std::uint8_t *>(std::memchr(data + start, '\n', size - start));
    const std::size_t stop = end == nullptr ? size : static_cast<std::size_t>(end - data);
    std::string       line(reinterpret_cast<const char *>(data + start), stop - start);
    start = stop + 1;
    if (line.empty() || line == "\r")
    {
      dataStart = std::min(start, size);
      break;
    }
    lines.push_back(line);
  }
  return !lines.empty();
}
} // namespace

extern "C" std::size_t
LLVMFuzzerCustomMutator(std::uint8_t * data, std::size_t size, std::size_t maxSize, unsigned int seed)
{
  vr::fuzz::Random         random(seed);
  std::vector<std::string> lines;
  std::size_t              dataStart = 0;
  if (random.Below(5) == 0 || !SplitHeader(data, size, lines, dataStart))
  {
    return LLVMFuzzerMutate(data, size, maxSize);
  }
  // Line 0 is the magic ("NRRD0004"): kept, but for the odd other version.
  const std::size_t line = 1 + random.Below(std::max<std::size_t>(lines.size(), 2) - 1);
  switch (random.Below(6))
  {
    case 0: // another value for a line's key
    case 1:
      if (line < lines.size())
      {
        const auto colon = lines[line].find(':');
        if (colon != std::string::npos)
        {
          const std::string key = lines[line].substr(0, colon);
          lines[line] = key + ": " + ValueFor(key, random);
          break;
        }
      }
      [[fallthrough]];
    case 2: // a known key added (a second one where the header has it)
    {
      const Key & key = Keys()[random.Below(Keys().size())];
      lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(std::min(line, lines.size())),
                   std::string(key.name) + ": " + ValueFor(key.name, random));
      break;
    }
    case 3: // a line dropped
      if (line < lines.size())
      {
        lines.erase(lines.begin() + static_cast<std::ptrdiff_t>(line));
      }
      break;
    case 4: // a line duplicated
      if (line < lines.size())
      {
        lines.insert(lines.begin() + static_cast<std::ptrdiff_t>(line), lines[line]);
      }
      break;
    default: // two lines swapped, or another magic
      if (lines.size() > 2 && random.Below(4) != 0)
      {
        std::swap(lines[line < lines.size() ? line : 1], lines[1 + random.Below(lines.size() - 1)]);
      }
      else
      {
        static const char * const magics[] = { "NRRD0001", "NRRD0004", "NRRD0005", "NRRD0006", "NRRD9999", "NRRD" };
        lines[0] = magics[random.Below(std::size(magics))];
      }
      break;
  }
  std::string text;
  for (const std::string & kept : lines)
  {
    text += kept + "\n";
  }
  text += "\n";
  const std::size_t dataSize = size - dataStart;
  if (text.size() + dataSize > maxSize)
  {
    return LLVMFuzzerMutate(data, size, maxSize);
  }
  std::memmove(data + text.size(), data + dataStart, dataSize);
  std::memcpy(data, text.data(), text.size());
  return text.size() + dataSize;
}

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t * data, std::size_t size)
{
  std::vector<std::string> lines;
  std::size_t              dataStart = size;
  SplitHeader(data, size, lines, dataStart);
  const std::string           path = vr::fuzz::WriteInput(data, size, ".nrrd");
  const std::filesystem::path raw = std::filesystem::path(path).parent_path() / "input.raw";
  std::ofstream(raw, std::ios::binary | std::ios::trunc)
    .write(reinterpret_cast<const char *>(data + dataStart), static_cast<std::streamsize>(size - dataStart));
  vr::fuzz::ReadVolumeOfBoundedSize(path);
  return 0;
}
