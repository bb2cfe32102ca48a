// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The walk through a legacy .vtk polydata file that must succeed before VTK's vtkPolyDataReader may read it.
#include "vrCenterlineFormats.h"
#include "vrInputError.h"
#include "vrText.h"

#include <cctype>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <vector>

namespace vr::detail
{
namespace
{
constexpr long long MaximumCount = 100000000; // values of one array; a centerline file holds thousands

/** A cursor over the file: lines of keywords, and the data blocks between them. */
class LegacyScanner
{
public:
  LegacyScanner(std::string text, std::string path)
    : m_Text(std::move(text))
    , m_Where("centerline file " + std::move(path) + ": ")
  {
  }

  [[noreturn]] void
  Fail(const std::string & problem) const
  {
    throw InputError(m_Where + problem + " (legacy VTK, line " + std::to_string(m_Line) + ")");
  }

  bool
  AtEnd()
  {
    SkipSpace();
    return m_At >= m_Text.size();
  }

  /** The next line, without its end; fails at the end of the file. */
  std::string
  Line()
  {
    if (m_At >= m_Text.size())
    {
      Fail("the file ends early");
    }
    auto end = m_Text.find('\n', m_At);
    if (end == std::string::npos)
    {
      end = m_Text.size();
    }
    std::string line = m_Text.substr(m_At, end - m_At);
    m_At = end + 1;
    ++m_Line;
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    return line;
  }

  /** The next non-blank line, split into words. */
  std::vector<std::string>
  Words()
  {
    while (true)
    {
      const std::string line = Trim(Line());
      if (!line.empty())
      {
        std::istringstream       stream(line);
        std::vector<std::string> words;
        std::string              word;
        while (stream >> word)
        {
          words.push_back(word);
        }
        return words;
      }
    }
  }

  /** \a count whitespace-separated numbers (ASCII data); returns them when \a keep. */
  std::vector<double>
  AsciiNumbers(long long count, const std::string & what, bool keep)
  {
    std::vector<double> values;
    for (long long k = 0; k < count; ++k)
    {
      SkipSpace();
      const std::size_t start = m_At;
      while (m_At < m_Text.size() && !std::isspace(static_cast<unsigned char>(m_Text[m_At])))
      {
        ++m_At;
      }
      double value = 0.0;
      if (start == m_At)
      {
        Fail(what + ": " + std::to_string(count) + " values declared, the file ends after " + std::to_string(k));
      }
      if (!ParseWholeDouble(m_Text.substr(start, m_At - start), value))
      {
        Fail(what + ": value " + std::to_string(k) + " \"" +
             m_Text.substr(start, std::min<std::size_t>(20, m_At - start)) + "\" is not a finite number");
      }
      if (keep)
      {
        values.push_back(value);
      }
    }
    // The rest of the last data line.
    while (m_At < m_Text.size() && m_Text[m_At] != '\n')
    {
      if (!std::isspace(static_cast<unsigned char>(m_Text[m_At])))
      {
        Fail(what + ": more values than the " + std::to_string(count) + " declared");
      }
      ++m_At;
    }
    return values;
  }

  /** \a count binary values of \a size bytes, big-endian (the legacy format's order); returns integers when \a keep
   * (the cell arrays). */
  std::vector<double>
  BinaryValues(long long count, std::size_t size, const std::string & what, bool keep, bool floating)
  {
    const double bytes = static_cast<double>(count) * static_cast<double>(size);
    if (bytes > static_cast<double>(m_Text.size() - std::min(m_At, m_Text.size())))
    {
      Fail(what + ": " + std::to_string(count) + " values declared need " +
           std::to_string(static_cast<long long>(bytes)) + " bytes, but only " +
           std::to_string(m_Text.size() - std::min(m_At, m_Text.size())) + " remain");
    }
    std::vector<double> values;
    if (keep)
    {
      for (long long k = 0; k < count; ++k)
      {
        std::uint64_t bits = 0;
        for (std::size_t b = 0; b < size; ++b)
        {
          bits = (bits << 8) | static_cast<unsigned char>(m_Text[m_At + static_cast<std::size_t>(k) * size + b]);
        }
        double value = 0.0;
        if (floating)
        {
          value = std::numeric_limits<double>::quiet_NaN(); // never kept: cell arrays are integers
        }
        else if (size == 4)
        {
          value = static_cast<double>(static_cast<std::int32_t>(static_cast<std::uint32_t>(bits)));
        }
        else
        {
          value = static_cast<double>(static_cast<std::int64_t>(bits));
        }
        values.push_back(value);
      }
    }
    m_At += static_cast<std::size_t>(bytes);
    // VTK writes a newline after each binary block.
    if (m_At < m_Text.size() && m_Text[m_At] == '\n')
    {
      ++m_At;
      ++m_Line;
    }
    return values;
  }

  /** \a count strings: one per line (ASCII), or each after a length header whose top two bits say its size
   * (binary: 11 one byte, 10 two, 01 four, 00 eight; the rest of the header is the length, big-endian). */
  void
  Strings(long long count, const std::string & what)
  {
    if (!Binary)
    {
      for (long long k = 0; k < count; ++k)
      {
        Line();
      }
      return;
    }
    for (long long k = 0; k < count; ++k)
    {
      if (m_At >= m_Text.size())
      {
        Fail(what + ": " + std::to_string(count) + " strings declared, the file ends after " + std::to_string(k));
      }
      const auto        first = static_cast<unsigned char>(m_Text[m_At]);
      const std::size_t header = first >= 0xC0 ? 1 : first >= 0x80 ? 2 : first >= 0x40 ? 4 : 8;
      if (m_At + header > m_Text.size())
      {
        Fail(what + ": string " + std::to_string(k) + " is cut off");
      }
      std::uint64_t length = first & 0x3Fu;
      for (std::size_t b = 1; b < header; ++b)
      {
        length = (length << 8) | static_cast<unsigned char>(m_Text[m_At + b]);
      }
      m_At += header;
      if (length > m_Text.size() - m_At)
      {
        Fail(what + ": string " + std::to_string(k) + " declares " + std::to_string(length) +
             " bytes, more than remain");
      }
      m_At += static_cast<std::size_t>(length);
    }
    if (m_At < m_Text.size() && m_Text[m_At] == '\n')
    {
      ++m_At;
      ++m_Line;
    }
  }

  bool Binary{ false };

private:
  void
  SkipSpace()
  {
    while (m_At < m_Text.size() && std::isspace(static_cast<unsigned char>(m_Text[m_At])))
    {
      m_Line += m_Text[m_At] == '\n' ? 1 : 0;
      ++m_At;
    }
  }

  std::string m_Text;
  std::string m_Where;
  std::size_t m_At{ 0 };
  std::size_t m_Line{ 0 };
};

/** Bytes of a legacy data type in binary files; 0 for one this reader refuses (bit, string). */
std::size_t
TypeSize(const std::string & type, bool & floating)
{
  const std::string t = ToLower(type);
  floating = t == "float" || t == "double";
  if (t == "unsigned_char" || t == "char")
  {
    return 1;
  }
  if (t == "short" || t == "unsigned_short")
  {
    return 2;
  }
  if (t == "int" || t == "unsigned_int" || t == "float" || t == "vtkidtype")
  {
    return 4;
  }
  if (t == "long" || t == "unsigned_long" || t == "double" || t == "vtktypeint64" || t == "vtktypeuint64")
  {
    return 8;
  }
  return 0;
}

long long
Count(const LegacyScanner & scanner, const std::string & text, const std::string & what, long long low = 0)
{
  long long value = 0;
  if (!ParseWholeInteger(text, value) || value < low || value > MaximumCount)
  {
    scanner.Fail(what + " \"" + text.substr(0, 20) + "\" is not a whole number from " + std::to_string(low) + " to " +
                 std::to_string(MaximumCount));
  }
  return value;
}

/** Reads \a count values of \a type (ASCII or binary). */
std::vector<double>
Values(LegacyScanner & scanner, long long count, const std::string & type, const std::string & what, bool keep)
{
  bool              floating = false;
  const std::size_t size = TypeSize(type, floating);
  if (size == 0)
  {
    scanner.Fail(what + ": data type \"" + type.substr(0, 20) + "\" is not one this reader accepts");
  }
  return scanner.Binary ? scanner.BinaryValues(count, size, what, keep, floating)
                        : scanner.AsciiNumbers(count, what, keep);
}

/** Checks a cell array in the legacy layout (count, ids, count, ids, ...). \return the number of cells. */
long long
CheckLegacyCells(const std::vector<double> & values,
                 long long                   cells,
                 long long                   points,
                 const LegacyScanner &       scanner,
                 const std::string &         what)
{
  std::size_t at = 0;
  for (long long c = 0; c < cells; ++c)
  {
    if (at >= values.size())
    {
      scanner.Fail(what + ": " + std::to_string(cells) + " cells declared, the data holds " + std::to_string(c));
    }
    const double size = values[at++];
    if (!(size >= 0.0) || size > static_cast<double>(values.size() - at))
    {
      scanner.Fail(what + ": cell " + std::to_string(c) + " declares " + std::to_string(static_cast<long long>(size)) +
                   " points, more than the data holds");
    }
    for (long long k = 0; k < static_cast<long long>(size); ++k)
    {
      const double id = values[at++];
      if (!(id >= 0.0 && id < static_cast<double>(points)))
      {
        scanner.Fail(what + ": cell " + std::to_string(c) + " uses point " +
                     std::to_string(static_cast<long long>(id)) + " of " + std::to_string(points));
      }
    }
  }
  if (at != values.size())
  {
    scanner.Fail(what + ": the cells use " + std::to_string(at) + " of the " + std::to_string(values.size()) +
                 " values declared");
  }
  return cells;
}

/** Checks a cell array in the version 5 layout (OFFSETS, CONNECTIVITY). */
void
CheckOffsetCells(const std::vector<double> & offsets,
                 const std::vector<double> & connectivity,
                 long long                   points,
                 const LegacyScanner &       scanner,
                 const std::string &         what)
{
  if (offsets.empty() || offsets.front() != 0.0 || offsets.back() != static_cast<double>(connectivity.size()))
  {
    scanner.Fail(what + ": OFFSETS must start at 0 and end at the CONNECTIVITY size " +
                 std::to_string(connectivity.size()));
  }
  for (std::size_t k = 1; k < offsets.size(); ++k)
  {
    if (offsets[k] < offsets[k - 1])
    {
      scanner.Fail(what + ": OFFSETS decrease at entry " + std::to_string(k));
    }
  }
  for (std::size_t k = 0; k < connectivity.size(); ++k)
  {
    if (!(connectivity[k] >= 0.0 && connectivity[k] < static_cast<double>(points)))
    {
      scanner.Fail(what + ": CONNECTIVITY entry " + std::to_string(k) + " is point " +
                   std::to_string(static_cast<long long>(connectivity[k])) + " of " + std::to_string(points));
    }
  }
}
} // namespace

void
CheckLegacyVTKPolyData(const std::string & path)
{
  std::ifstream input(path, std::ios::binary);
  if (!input)
  {
    throw InputError("centerline file " + path + ": cannot be opened");
  }
  LegacyScanner scanner(std::string((std::istreambuf_iterator<char>(input)), std::istreambuf_iterator<char>()), path);
  const std::string version = scanner.Line();
  if (version.rfind("# vtk DataFile Version ", 0) != 0)
  {
    scanner.Fail("the first line is not \"# vtk DataFile Version x.y\"");
  }
  // The version VTK's legacy writers write: 1.0 to 5.1. VTK 9.1's reader crashes on a later major version
  // (fuzzing: "Version 51" made it read past its own stream).
  const std::string number = Trim(version.substr(23));
  const bool        wellFormed = number.size() >= 3 && number[0] >= '1' && number[0] <= '5' && number[1] == '.' &&
                          number.find_first_not_of("0123456789", 2) == std::string::npos;
  if (!wellFormed)
  {
    scanner.Fail("the file version \"" + number.substr(0, 20) + "\" is not one VTK writes (1.0 to 5.1)");
  }
  const bool fiveOrLater = number[0] == '5';
  if (scanner.Line().size() > 256)
  {
    scanner.Fail("the header line is longer than 256 characters");
  }
  const std::string encoding = ToUpper(Trim(scanner.Line()));
  if (encoding != "ASCII" && encoding != "BINARY")
  {
    scanner.Fail("the third line must be ASCII or BINARY");
  }
  scanner.Binary = encoding == "BINARY";
  auto words = scanner.Words();
  if (words.size() != 2 || ToUpper(words[0]) != "DATASET" || ToUpper(words[1]) != "POLYDATA")
  {
    scanner.Fail("not DATASET POLYDATA");
  }

  long long points = -1;
  long long cells = 0;
  long long attributeCount = -1; // tuples of the current POINT_DATA or CELL_DATA section
  while (!scanner.AtEnd())
  {
    words = scanner.Words();
    const std::string keyword = ToUpper(words[0]);
    const auto        need = [&](std::size_t count)
    {
      if (words.size() < count)
      {
        scanner.Fail(keyword + " needs " + std::to_string(count - 1) + " values on its line");
      }
    };
    if (keyword == "POINTS")
    {
      need(3);
      if (points >= 0)
      {
        scanner.Fail("a second POINTS section");
      }
      points = Count(scanner, words[1], "POINTS count");
      Values(scanner, 3 * points, words[2], "POINTS", false);
    }
    else if (keyword == "VERTICES" || keyword == "LINES" || keyword == "POLYGONS" || keyword == "TRIANGLE_STRIPS")
    {
      need(3);
      if (points < 0)
      {
        scanner.Fail(keyword + " before POINTS");
      }
      const long long first = Count(scanner, words[1], keyword + " count");
      const long long second = Count(scanner, words[2], keyword + " size");
      if (fiveOrLater)
      {
        auto offsets = scanner.Words();
        if (offsets.size() != 2 || ToUpper(offsets[0]) != "OFFSETS")
        {
          scanner.Fail(keyword + ": OFFSETS expected");
        }
        const auto offsetValues = Values(scanner, first, offsets[1], keyword + " OFFSETS", true);
        auto       connectivity = scanner.Words();
        if (connectivity.size() != 2 || ToUpper(connectivity[0]) != "CONNECTIVITY")
        {
          scanner.Fail(keyword + ": CONNECTIVITY expected");
        }
        const auto connectivityValues = Values(scanner, second, connectivity[1], keyword + " CONNECTIVITY", true);
        if (first > 0)
        {
          CheckOffsetCells(offsetValues, connectivityValues, points, scanner, keyword);
          cells += first - 1;
        }
      }
      else
      {
        const auto values = Values(scanner, second, "int", keyword, true);
        cells += CheckLegacyCells(values, first, points, scanner, keyword);
      }
    }
    else if (keyword == "POINT_DATA" || keyword == "CELL_DATA")
    {
      need(2);
      attributeCount = Count(scanner, words[1], keyword + " count");
      const long long expected = keyword == "POINT_DATA" ? points : cells;
      if (attributeCount != expected)
      {
        scanner.Fail(keyword + " " + std::to_string(attributeCount) + " but the file has " + std::to_string(expected) +
                     (keyword == "POINT_DATA" ? " points" : " cells"));
      }
    }
    else if (keyword == "SCALARS")
    {
      need(3);
      if (attributeCount < 0)
      {
        scanner.Fail("SCALARS outside POINT_DATA or CELL_DATA");
      }
      const long long components = words.size() > 3 ? Count(scanner, words[3], "SCALARS components", 1) : 1;
      if (components > 4)
      {
        scanner.Fail("SCALARS with more than 4 components");
      }
      // An optional LOOKUP_TABLE line follows (VTK reads one if present).
      auto table = scanner.Words();
      if (ToUpper(table[0]) != "LOOKUP_TABLE")
      {
        scanner.Fail("SCALARS " + words[1] + ": LOOKUP_TABLE expected");
      }
      Values(scanner, attributeCount * components, words[2], "SCALARS " + words[1], false);
    }
    else if (keyword == "VECTORS" || keyword == "NORMALS")
    {
      need(3);
      if (attributeCount < 0)
      {
        scanner.Fail(keyword + " outside POINT_DATA or CELL_DATA");
      }
      Values(scanner, 3 * attributeCount, words[2], keyword + " " + words[1], false);
    }
    else if (keyword == "TENSORS")
    {
      need(3);
      if (attributeCount < 0)
      {
        scanner.Fail("TENSORS outside POINT_DATA or CELL_DATA");
      }
      Values(scanner, 9 * attributeCount, words[2], "TENSORS " + words[1], false);
    }
    else if (keyword == "TEXTURE_COORDINATES")
    {
      need(4);
      const long long dimension = Count(scanner, words[2], "TEXTURE_COORDINATES dimension", 1);
      if (attributeCount < 0 || dimension > 3)
      {
        scanner.Fail("TEXTURE_COORDINATES outside POINT_DATA or CELL_DATA, or of more than 3 dimensions");
      }
      Values(scanner, dimension * attributeCount, words[3], "TEXTURE_COORDINATES " + words[1], false);
    }
    else if (keyword == "FIELD")
    {
      need(3);
      const long long arrays = Count(scanner, words[2], "FIELD array count");
      for (long long a = 0; a < arrays; ++a)
      {
        auto array = scanner.Words();
        if (array.size() == 1 && ToUpper(array[0]) == "NULL_ARRAY")
        {
          continue;
        }
        if (array.size() != 4)
        {
          scanner.Fail("FIELD " + words[1] + ": array " + std::to_string(a) + " needs name, components, tuples, type");
        }
        const long long components = Count(scanner, array[1], "FIELD array components", 1);
        const long long tuples = Count(scanner, array[2], "FIELD array tuples");
        if (components > 64 || static_cast<double>(components) * static_cast<double>(tuples) > MaximumCount)
        {
          scanner.Fail("FIELD array " + array[0] + ": " + std::to_string(components) + " x " + std::to_string(tuples) +
                       " values is more than this reader accepts");
        }
        if (attributeCount >= 0 && tuples != attributeCount)
        {
          scanner.Fail("FIELD array " + array[0] + ": " + std::to_string(tuples) + " tuples, but the section has " +
                       std::to_string(attributeCount));
        }
        const std::string type = ToLower(array[3]);
        if (type == "string" || type == "utf8_string")
        {
          scanner.Strings(components * tuples, "FIELD array " + array[0]);
        }
        else
        {
          Values(scanner, components * tuples, array[3], "FIELD array " + array[0], false);
        }
      }
    }
    else if (keyword == "METADATA")
    {
      // Information keys and component names, up to a blank line: text VTK reads line by line.
      while (!Trim(scanner.Line()).empty())
      {
      }
    }
    else
    {
      scanner.Fail("unknown or unsupported keyword \"" + words[0].substr(0, 30) + "\"");
    }
  }
  if (points < 0)
  {
    scanner.Fail("no POINTS section");
  }
}
} // namespace vr::detail
