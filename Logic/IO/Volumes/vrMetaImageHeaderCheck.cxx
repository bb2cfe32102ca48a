// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrMetaImageHeaderCheck.h"

#include "vrInputError.h"
#include "vrMetaIOWords.h"
#include "vrText.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <set>
#include <vector>

namespace vr::detail
{
namespace
{
// A header longer than this is not one any writer makes; MetaIO would read on into the data.
constexpr std::size_t MaximumHeaderBytes = 64 * 1024;
// MetaIO reads a value with getline into 500 characters and fails its stream on a longer line.
constexpr std::size_t MaximumLineLength = 400;

/** How MetaIO 5.2 (metaObject.cxx, metaImage.cxx) stores each field it knows. */
enum class FieldKind
{
  Text,
  Integer,   // MET_INT: read as a double, stored as int
  Count,     // MET_ULONG_LONG (CompressedDataSize)
  Real,      // MET_FLOAT
  PerAxis,   // MET_FLOAT_ARRAY of NDims values
  AxisSizes, // MET_INT_ARRAY of NDims values
  Matrix,    // MET_FLOAT_MATRIX of NDims x NDims values
  Color      // MET_FLOAT_ARRAY of 4 values
};

/** Fields MetaIO does not know it keeps as text, as it keeps its own string fields. */
FieldKind
KindOf(const std::string & name)
{
  if (name == "NDims" || name == "ID" || name == "ParentID" || name == "HeaderSize" ||
      name == "ElementNumberOfChannels" || name == "ElementNBits")
  {
    return FieldKind::Integer;
  }
  if (name == "CompressedDataSize")
  {
    return FieldKind::Count;
  }
  if (name == "ElementMin" || name == "ElementMax" || name == "ElementToIntensityFunctionSlope" ||
      name == "ElementToIntensityFunctionOffset")
  {
    return FieldKind::Real;
  }
  if (name == "Position" || name == "Origin" || name == "Offset" || name == "CenterOfRotation" ||
      name == "ElementSpacing" || name == "ImagePosition" || name == "ElementSize")
  {
    return FieldKind::PerAxis;
  }
  if (name == "DimSize" || name == "SequenceID")
  {
    return FieldKind::AxisSizes;
  }
  if (name == "TransformMatrix" || name == "Rotation" || name == "Orientation")
  {
    return FieldKind::Matrix;
  }
  if (name == "Color")
  {
    return FieldKind::Color;
  }
  return FieldKind::Text;
}

/** A plain decimal number, read alike by strtod and by MetaIO's `stream >> double` (no hex, inf or nan). */
bool
IsPlainNumber(const std::string & token)
{
  std::size_t k = 0;
  const auto  digits = [&]()
  {
    const std::size_t start = k;
    while (k < token.size() && token[k] >= '0' && token[k] <= '9')
    {
      ++k;
    }
    return k - start;
  };
  if (k < token.size() && (token[k] == '+' || token[k] == '-'))
  {
    ++k;
  }
  std::size_t mantissa = digits();
  if (k < token.size() && token[k] == '.')
  {
    ++k;
    mantissa += digits();
  }
  if (mantissa == 0)
  {
    return false;
  }
  if (k < token.size() && (token[k] == 'e' || token[k] == 'E'))
  {
    ++k;
    if (k < token.size() && (token[k] == '+' || token[k] == '-'))
    {
      ++k;
    }
    if (digits() == 0)
    {
      return false;
    }
  }
  return k == token.size();
}

bool
IsMetaIOElementType(const std::string & type)
{
  static const std::set<std::string> names = { "MET_CHAR",
                                               "MET_UCHAR",
                                               "MET_SHORT",
                                               "MET_USHORT",
                                               "MET_INT",
                                               "MET_UINT",
                                               "MET_LONG",
                                               "MET_ULONG",
                                               "MET_LONG_LONG",
                                               "MET_ULONG_LONG",
                                               "MET_FLOAT",
                                               "MET_DOUBLE",
                                               "MET_CHAR_ARRAY",
                                               "MET_UCHAR_ARRAY",
                                               "MET_SHORT_ARRAY",
                                               "MET_USHORT_ARRAY",
                                               "MET_INT_ARRAY",
                                               "MET_UINT_ARRAY",
                                               "MET_LONG_ARRAY",
                                               "MET_ULONG_ARRAY",
                                               "MET_LONG_LONG_ARRAY",
                                               "MET_ULONG_LONG_ARRAY",
                                               "MET_FLOAT_ARRAY",
                                               "MET_DOUBLE_ARRAY" };
  return names.count(type) != 0;
}
} // namespace

std::size_t
CheckMetaImageHeaderBytes(const char * bytes, std::size_t count, const std::string & where)
{
  std::size_t           at = 0;
  std::size_t           lineNumber = 0;
  long long             dimensions = 0;
  std::set<std::string> seen;
  std::string           place;
  const auto            fail = [&](const std::string & problem)
  { throw InputError(where + ": MetaImage header " + place + problem); };
  while (at < count)
  {
    if (at >= MaximumHeaderBytes)
    {
      place.clear();
      fail("is longer than " + std::to_string(MaximumHeaderBytes / 1024) + " KiB before its ElementDataFile");
    }
    const char *      newline = static_cast<const char *>(std::memchr(bytes + at, '\n', count - at));
    const std::size_t end = newline != nullptr ? static_cast<std::size_t>(newline - bytes) : count;
    std::string       line(bytes + at, end - at);
    at = end + 1;
    ++lineNumber;
    place = "line " + std::to_string(lineNumber) + ": ";
    if (!line.empty() && line.back() == '\r')
    {
      line.pop_back();
    }
    if (line.size() > MaximumLineLength)
    {
      fail("over " + std::to_string(MaximumLineLength) + " characters; not a MetaImage header");
    }
    // Control bytes (a \r inside a line included) and bytes above ASCII end MetaIO's names where this walk would not.
    if (std::any_of(line.begin(), line.end(), [](char c) { return (c < 0x20 && c != '\t') || c > 0x7E; }))
    {
      fail("holds a character that is not printable ASCII; not a MetaImage header");
    }
    if (Trim(line).empty())
    {
      continue;
    }
    // MetaIO ends a name at the first "=" or ":"; a line with neither makes it take the next line's value.
    const std::size_t separator = line.find_first_of("=:");
    if (separator == std::string::npos || line[separator] != '=')
    {
      fail("\"" + Trim(line).substr(0, 40) + "\" is not \"Name = value\"");
    }
    const std::string name = Trim(line.substr(0, separator));
    place += name.substr(0, 40) + " ";
    if (name.empty())
    {
      fail("has no field name before its \"=\"");
    }
    // MetaIO skips every "=", ":" and blank after the name.
    const std::size_t valueStart = line.find_first_not_of("=: \t", separator);
    const std::string value = valueStart == std::string::npos ? std::string() : Trim(line.substr(valueStart));
    if (!seen.insert(name).second)
    {
      fail("appears a second time");
    }
    const FieldKind kind = KindOf(name);
    if (kind == FieldKind::Text)
    {
      if (name == "ElementType" && !IsMetaIOElementType(value))
      {
        fail("= " + value.substr(0, 40) + " is not a MetaIO element type (MET_SHORT, MET_FLOAT, ...)");
      }
      if (name == "ElementDataFile")
      {
        if (value.empty())
        {
          fail("names no data file (LOCAL when the voxels follow the header)");
        }
        if (dimensions == 0 || seen.count("DimSize") == 0 || seen.count("ElementType") == 0)
        {
          fail("comes before NDims, DimSize and ElementType");
        }
        // A file list ("LIST 2D") or a numbered pattern ("slice%03d.raw 1 40 1") MetaIO splits into words as it
        // splits a tube's PointDim, and goes wrong where the tube reader did.
        if ((value.rfind("LIST", 0) == 0 || value.find('%') != std::string::npos) && MetaIOWords(value).empty())
        {
          fail("= " + value.substr(0, 40) + ": a file list or pattern must be words separated by single spaces, " +
               "each of at most " + std::to_string(MaximumMetaIOWordLength) + " characters");
        }
        return at; // MetaIO's header ends here; the voxels (or a file list) follow.
      }
      continue;
    }
    // A numeric field: MetaIO reads as many numbers as it wants, across lines if this one has fewer.
    std::size_t wanted = 1;
    if (kind == FieldKind::PerAxis || kind == FieldKind::AxisSizes || kind == FieldKind::Matrix)
    {
      if (dimensions == 0)
      {
        fail("comes before NDims, which gives its number of values");
      }
      wanted = kind == FieldKind::Matrix ? static_cast<std::size_t>(dimensions * dimensions)
                                         : static_cast<std::size_t>(dimensions);
    }
    else if (kind == FieldKind::Color)
    {
      wanted = 4;
    }
    std::vector<std::string> tokens;
    for (std::size_t k = 0; k < value.size();)
    {
      const std::size_t start = value.find_first_not_of(" \t", k);
      if (start == std::string::npos)
      {
        break;
      }
      const std::size_t stop = std::min(value.find_first_of(" \t", start), value.size());
      tokens.push_back(value.substr(start, stop - start));
      k = stop;
    }
    const bool integers = kind == FieldKind::Integer || kind == FieldKind::Count || kind == FieldKind::AxisSizes;
    double     low = -2147483648.0;
    double     high = 2147483647.0;
    if (name == "NDims")
    {
      low = 1.0;
      high = 4.0;
    }
    else if (name == "DimSize" || name == "ElementNumberOfChannels")
    {
      low = 1.0;
    }
    else if (name == "HeaderSize")
    {
      low = -1.0;
    }
    else if (kind == FieldKind::Count)
    {
      low = 0.0;
      high = 9007199254740992.0; // 2^53: MetaIO holds it in a double
    }
    const std::string expectation =
      std::to_string(wanted) + (integers ? " whole number" : " finite number") + (wanted == 1 ? "" : "s") +
      (integers ? " from " + std::to_string(static_cast<long long>(low)) + " to " +
                    std::to_string(static_cast<long long>(high))
                : std::string()) +
      (kind == FieldKind::PerAxis || kind == FieldKind::AxisSizes || kind == FieldKind::Matrix
         ? " (NDims = " + std::to_string(dimensions) + ")"
         : std::string());
    if (tokens.size() != wanted)
    {
      fail("= " + value.substr(0, 40) + ": must be " + expectation);
    }
    for (const std::string & token : tokens)
    {
      const double number = IsPlainNumber(token) ? std::strtod(token.c_str(), nullptr) : std::nan("");
      if (!std::isfinite(number) || (integers && (number != std::floor(number) || number < low || number > high)))
      {
        fail("= " + value.substr(0, 40) + ": must be " + expectation);
      }
      if (name == "NDims")
      {
        dimensions = static_cast<long long>(number);
      }
    }
  }
  place.clear();
  fail("ends without ElementDataFile; not a whole MetaImage header");
}

std::size_t
CheckMetaImageHeader(const std::string & path, const std::string & where)
{
  std::ifstream input(path, std::ios::binary);
  if (!input)
  {
    throw InputError(where + ": cannot be opened");
  }
  std::vector<char> bytes(MaximumHeaderBytes + MaximumLineLength + 2);
  input.read(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return CheckMetaImageHeaderBytes(bytes.data(), static_cast<std::size_t>(input.gcount()), where);
}
} // namespace vr::detail
