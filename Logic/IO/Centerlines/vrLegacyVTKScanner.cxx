// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The legacy .vtk scanner: lines, words, counts and the data blocks of the format, read from the file's bytes.
#include "vrLegacyVTKScanner.h"
#include "vrInputError.h"
#include "vrText.h"

#include <vtkByteSwap.h>
#include <vtkDataArray.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>

namespace vr::detail
{
namespace
{
using DataType = LegacyVTKScanner::DataType;

/** The types vtkDataReader::ReadArray knows, less bit and variant. vtkIdType is written as a 4-byte int. */
bool
LookUpType(const std::string & name, DataType & type)
{
  const std::string t = ToLower(name);
  struct Entry
  {
    const char * Name;
    DataType     Type;
  };
  static const Entry entries[] = {
    { "char", { VTK_CHAR, 1 } },
    { "signed_char", { VTK_CHAR, 1 } },
    { "unsigned_char", { VTK_UNSIGNED_CHAR, 1 } },
    { "short", { VTK_SHORT, 2 } },
    { "unsigned_short", { VTK_UNSIGNED_SHORT, 2 } },
    { "int", { VTK_INT, 4 } },
    { "unsigned_int", { VTK_UNSIGNED_INT, 4 } },
    { "long", { VTK_LONG, sizeof(long) } },
    { "unsigned_long", { VTK_UNSIGNED_LONG, sizeof(unsigned long) } },
    { "vtktypeint64", { VTK_TYPE_INT64, 8 } },
    { "vtktypeuint64", { VTK_TYPE_UINT64, 8 } },
    { "vtkidtype", { VTK_ID_TYPE, 4 } },
    { "float", { VTK_FLOAT, 4 } },
    { "double", { VTK_DOUBLE, 8 } },
    { "string", { VTK_STRING, 0, true } },
    { "utf8_string", { VTK_STRING, 0, true } },
  };
  for (const auto & entry : entries)
  {
    if (t == entry.Name)
    {
      type = entry.Type;
      return true;
    }
  }
  return false;
}

/** One ASCII token as a value of type T: the whole token, in T's range (floating values finite). */
template<typename T>
bool
ParseToken(const char * first, const char * last, T & value)
{
  if (first < last && *first == '+')
  {
    ++first;
  }
  if constexpr (std::is_floating_point_v<T>)
  {
    const auto result = std::from_chars(first, last, value);
    return result.ec == std::errc() && result.ptr == last && std::isfinite(value);
  }
  else if constexpr (std::is_signed_v<T>)
  {
    long long  wide = 0;
    const auto result = std::from_chars(first, last, wide);
    if (result.ec != std::errc() || result.ptr != last ||
        wide < static_cast<long long>(std::numeric_limits<T>::min()) ||
        wide > static_cast<long long>(std::numeric_limits<T>::max()))
    {
      return false;
    }
    value = static_cast<T>(wide);
    return true;
  }
  else
  {
    unsigned long long wide = 0;
    const auto         result = std::from_chars(first, last, wide);
    if (result.ec != std::errc() || result.ptr != last ||
        wide > static_cast<unsigned long long>(std::numeric_limits<T>::max()))
    {
      return false;
    }
    value = static_cast<T>(wide);
    return true;
  }
}

bool
IsSpace(char c)
{
  return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f';
}
} // namespace

LegacyVTKScanner::LegacyVTKScanner(std::string text, std::string where)
  : m_Text(std::move(text))
  , m_Where(std::move(where))
{
}

[[noreturn]] void
LegacyVTKScanner::Fail(const std::string & problem) const
{
  std::size_t end = std::min(m_At, m_Text.size());
  end -= end > 0 && m_Text[end - 1] == '\n' ? 1 : 0;
  const auto line = 1 + std::count(m_Text.begin(), m_Text.begin() + static_cast<std::ptrdiff_t>(end), '\n');
  throw InputError(m_Where + ": " + problem + " (legacy VTK, line " + std::to_string(line) + ")");
}

bool
LegacyVTKScanner::AtEnd()
{
  while (m_At < m_Text.size() && IsSpace(m_Text[m_At]))
  {
    ++m_At;
  }
  return m_At >= m_Text.size();
}

std::string
LegacyVTKScanner::Line()
{
  if (m_At >= m_Text.size())
  {
    Fail("the file ends early");
  }
  auto end = m_Text.find('\n', m_At);
  end = end == std::string::npos ? m_Text.size() : end;
  std::string line = m_Text.substr(m_At, end - m_At);
  m_At = end + 1;
  if (!line.empty() && line.back() == '\r')
  {
    line.pop_back();
  }
  return line;
}

std::vector<std::string>
LegacyVTKScanner::Words()
{
  while (true)
  {
    const std::string        line = Line();
    std::vector<std::string> words;
    std::size_t              k = 0;
    while (k < line.size())
    {
      while (k < line.size() && IsSpace(line[k]))
      {
        ++k;
      }
      const std::size_t first = k;
      while (k < line.size() && !IsSpace(line[k]))
      {
        ++k;
      }
      if (k > first)
      {
        if (k - first > MaximumWordLength)
        {
          Fail("a word longer than " + std::to_string(MaximumWordLength) + " characters");
        }
        words.push_back(line.substr(first, k - first));
      }
    }
    if (!words.empty())
    {
      return words;
    }
  }
}

long long
LegacyVTKScanner::Count(const std::string & text, const std::string & what, long long low) const
{
  long long value = 0;
  if (!ParseWholeInteger(text, value) || value < low || value > MaximumCount)
  {
    Fail(what + " \"" + text.substr(0, 20) + "\" is not a whole number from " + std::to_string(low) + " to " +
         std::to_string(MaximumCount));
  }
  return value;
}

vtkSmartPointer<vtkAbstractArray>
LegacyVTKScanner::Array(const std::string & typeName, long long tuples, long long components, const std::string & what)
{
  DataType type;
  if (!LookUpType(typeName, type))
  {
    Fail(what + ": data type \"" + typeName.substr(0, 30) + "\" is not one this reader accepts");
  }
  if (components < 1 || components > MaximumComponents || tuples < 0 || tuples > MaximumCount ||
      tuples * components > MaximumCount)
  {
    Fail(what + ": " + std::to_string(tuples) + " tuples of " + std::to_string(components) +
         " components is more than this reader accepts");
  }
  const long long                   count = tuples * components;
  vtkSmartPointer<vtkAbstractArray> array;
  if (type.String)
  {
    auto strings = vtkSmartPointer<vtkStringArray>::New();
    strings->SetNumberOfComponents(static_cast<int>(components));
    ReadStrings(*strings, count, what);
    array = strings;
  }
  else
  {
    vtkSmartPointer<vtkDataArray> numbers = vtk::TakeSmartPointer(vtkDataArray::CreateDataArray(type.VTKType));
    numbers->SetNumberOfComponents(static_cast<int>(components));
    if (Binary)
    {
      CheckRemaining(static_cast<double>(count) * static_cast<double>(type.FileBytes), count, what);
      numbers->SetNumberOfTuples(tuples);
      ReadBinary(*numbers, type, count);
    }
    else
    {
      // Each ASCII value takes a character and a separator (but the last).
      CheckRemaining(2.0 * static_cast<double>(count) - 1.0, count, what);
      numbers->SetNumberOfTuples(tuples);
      switch (numbers->GetDataType())
      {
        vtkTemplateMacro(ReadAscii(static_cast<VTK_TT *>(numbers->GetVoidPointer(0)), count, what));
      }
    }
    array = numbers;
  }
  SkipMetaData(components);
  return array;
}

std::size_t
LegacyVTKScanner::Remaining() const
{
  return m_At < m_Text.size() ? m_Text.size() - m_At : 0;
}

void
LegacyVTKScanner::CheckRemaining(double bytes, long long count, const std::string & what) const
{
  if (count > 0 && bytes > static_cast<double>(Remaining()))
  {
    Fail(what + ": " + std::to_string(count) + " values declared, more than the " + std::to_string(Remaining()) +
         " bytes left in the file can hold");
  }
}

void
LegacyVTKScanner::ReadBinary(vtkDataArray & array, const DataType & type, long long count)
{
  const auto bytes = static_cast<std::size_t>(count) * type.FileBytes;
  if (type.VTKType == VTK_ID_TYPE && sizeof(vtkIdType) != type.FileBytes && count > 0)
  {
    std::vector<std::int32_t> values(static_cast<std::size_t>(count));
    std::memcpy(values.data(), m_Text.data() + m_At, bytes);
    vtkByteSwap::Swap4BERange(values.data(), values.size());
    auto * ids = static_cast<vtkIdType *>(array.GetVoidPointer(0));
    std::copy(values.begin(), values.end(), ids);
  }
  else if (count > 0)
  {
    void * out = array.GetVoidPointer(0);
    std::memcpy(out, m_Text.data() + m_At, bytes);
    switch (type.FileBytes)
    {
      case 2:
        vtkByteSwap::Swap2BERange(out, static_cast<std::size_t>(count));
        break;
      case 4:
        vtkByteSwap::Swap4BERange(out, static_cast<std::size_t>(count));
        break;
      case 8:
        vtkByteSwap::Swap8BERange(out, static_cast<std::size_t>(count));
        break;
      default:
        break;
    }
  }
  m_At += bytes;
  SkipNewline();
}

template<typename T>
void
LegacyVTKScanner::ReadAscii(T * out, long long count, const std::string & what)
{
  const char * text = m_Text.data();
  for (long long k = 0; k < count; ++k)
  {
    while (m_At < m_Text.size() && IsSpace(text[m_At]))
    {
      ++m_At;
    }
    const std::size_t start = m_At;
    while (m_At < m_Text.size() && !IsSpace(text[m_At]))
    {
      ++m_At;
    }
    if (start == m_At)
    {
      Fail(what + ": " + std::to_string(count) + " values declared, the file ends after " + std::to_string(k));
    }
    if (!ParseToken(text + start, text + m_At, out[k]))
    {
      const std::string token = m_Text.substr(start, std::min<std::size_t>(20, m_At - start));
      Fail(what + ": value " + std::to_string(k) + " \"" + token + "\" is not a finite number of the array's type");
    }
  }
  while (m_At < m_Text.size() && text[m_At] != '\n')
  {
    if (!IsSpace(text[m_At]))
    {
      Fail(what + ": more values than the " + std::to_string(count) + " declared");
    }
    ++m_At;
  }
}

void
LegacyVTKScanner::ReadStrings(vtkStringArray & array, long long count, const std::string & what)
{
  if (!Binary)
  {
    // Each string takes at least its line's end.
    CheckRemaining(static_cast<double>(count) - 1.0, count, what);
    // Grown as strings are read: each takes at least a line end of the file.
    for (long long k = 0; k < count; ++k)
    {
      array.InsertNextValue(Decode(Line(), what));
    }
    return;
  }
  CheckRemaining(static_cast<double>(count), count, what);
  for (long long k = 0; k < count; ++k)
  {
    if (m_At >= m_Text.size())
    {
      Fail(what + ": " + std::to_string(count) + " strings declared, the file ends after " + std::to_string(k));
    }
    const auto        first = static_cast<unsigned char>(m_Text[m_At]);
    const std::size_t header = first >= 0xC0 ? 1 : first >= 0x80 ? 2 : first >= 0x40 ? 4 : 8;
    if (header > Remaining())
    {
      Fail(what + ": string " + std::to_string(k) + " is cut off");
    }
    std::uint64_t length = header == 8 ? first : first & 0x3F;
    for (std::size_t b = 1; b < header; ++b)
    {
      length = (length << 8) | static_cast<unsigned char>(m_Text[m_At + b]);
    }
    m_At += header;
    if (length > Remaining())
    {
      Fail(what + ": string " + std::to_string(k) + " declares " + std::to_string(length) + " bytes, more than remain");
    }
    array.InsertNextValue(m_Text.substr(m_At, static_cast<std::size_t>(length)));
    m_At += static_cast<std::size_t>(length);
  }
  SkipNewline();
}

std::string
LegacyVTKScanner::Decode(const std::string & text, const std::string & what) const
{
  std::string decoded;
  decoded.reserve(text.size());
  for (std::size_t k = 0; k < text.size(); ++k)
  {
    if (text[k] != '%')
    {
      decoded.push_back(text[k]);
      continue;
    }
    unsigned int value = 0;
    const char * first = text.data() + k + 1;
    const char * last = text.data() + std::min(text.size(), k + 3);
    const auto   result = std::from_chars(first, last, value, 16);
    if (last - first != 2 || result.ec != std::errc() || result.ptr != last)
    {
      Fail(what + ": \"" + text.substr(k, 3) + "\" is not a %XX escape");
    }
    decoded.push_back(static_cast<char>(value));
    k += 2;
  }
  return decoded;
}

std::string
LegacyVTKScanner::Name(const std::string & text, const std::string & what) const
{
  return Decode(text, what);
}

void
LegacyVTKScanner::SkipNewline()
{
  if (m_At < m_Text.size() && m_Text[m_At] == '\r')
  {
    ++m_At;
  }
  if (m_At < m_Text.size() && m_Text[m_At] == '\n')
  {
    ++m_At;
  }
}

void
LegacyVTKScanner::SkipMetaData(long long components)
{
  const std::size_t before = m_At;
  if (AtEnd())
  {
    return;
  }
  if (Trim(ToUpper(Line())) != "METADATA")
  {
    m_At = before;
    return;
  }
  bool information = false;
  while (m_At < m_Text.size())
  {
    const std::string line = Line();
    if (line.empty())
    {
      return;
    }
    const std::string upper = ToUpper(Trim(line));
    if (upper == "COMPONENT_NAMES")
    {
      for (long long c = 0; c < components; ++c)
      {
        Line();
      }
      information = false;
    }
    else if (upper.rfind("INFORMATION ", 0) == 0)
    {
      information = true;
    }
    else if (!information)
    {
      Fail("METADATA: \"" + line.substr(0, 30) + "\" is neither COMPONENT_NAMES nor INFORMATION");
    }
  }
}
} // namespace vr::detail
