// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The legacy .vtk polyline reader: our own grammar, the only code that reads users' .vtk centerline files.
#include "vrLegacyVTKReader.h"
#include "vrInputError.h"
#include "vrText.h"

#include <vtkByteSwap.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <limits>
#include <set>
#include <type_traits>
#include <vector>

namespace vr::detail
{
namespace
{
/** Values of one array, components of one tuple, and the file size this reader accepts: a centerline file holds
 * thousands of points, so these only stop hostile counts before anything is allocated. */
constexpr long long      MaximumCount = 1LL << 30;
constexpr long long      MaximumComponents = 1024;
constexpr std::uintmax_t MaximumFileBytes = 1ULL << 28;
constexpr std::size_t    MaximumWordLength = 255; // VTK reads keywords, names and types into 256 bytes

/** A legacy data type: the VTK array it becomes and its size in a binary file. */
struct DataType
{
  int         VTKType{ 0 };
  std::size_t FileBytes{ 0 };
  bool        String{ false };
};

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

/** A cursor over the whole file: keyword lines, and the data blocks between them. */
class LegacyParser
{
public:
  LegacyParser(std::string text, std::string where)
    : m_Text(std::move(text))
    , m_Where(std::move(where))
  {
  }

  /** Throws the InputError for \a problem at the current position (on a line just read: that line). */
  [[noreturn]] void
  Fail(const std::string & problem) const
  {
    std::size_t end = std::min(m_At, m_Text.size());
    end -= end > 0 && m_Text[end - 1] == '\n' ? 1 : 0;
    const auto line = 1 + std::count(m_Text.begin(), m_Text.begin() + static_cast<std::ptrdiff_t>(end), '\n');
    throw InputError(m_Where + ": " + problem + " (legacy VTK, line " + std::to_string(line) + ")");
  }

  bool Binary{ false };

  /** Whether only white space remains. */
  bool
  AtEnd()
  {
    while (m_At < m_Text.size() && IsSpace(m_Text[m_At]))
    {
      ++m_At;
    }
    return m_At >= m_Text.size();
  }

  /** The next line without its end (and without a '\r' before it); fails at the end of the file. */
  std::string
  Line()
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

  /** The words of the next line that is not blank; fails at the end of the file. */
  std::vector<std::string>
  Words()
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

  /** A count from a section line: a whole number from \a low to MaximumCount. */
  long long
  Count(const std::string & text, const std::string & what, long long low = 0) const
  {
    long long value = 0;
    if (!ParseWholeInteger(text, value) || value < low || value > MaximumCount)
    {
      Fail(what + " \"" + text.substr(0, 20) + "\" is not a whole number from " + std::to_string(low) + " to " +
           std::to_string(MaximumCount));
    }
    return value;
  }

  /** \a tuples x \a components values of the type named \a typeName, then the METADATA block VTK may write after
   * them. \a what names the array in messages. */
  vtkSmartPointer<vtkAbstractArray>
  Array(const std::string & typeName, long long tuples, long long components, const std::string & what)
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

private:
  std::size_t
  Remaining() const
  {
    return m_At < m_Text.size() ? m_Text.size() - m_At : 0;
  }

  void
  CheckRemaining(double bytes, long long count, const std::string & what) const
  {
    if (count > 0 && bytes > static_cast<double>(Remaining()))
    {
      Fail(what + ": " + std::to_string(count) + " values declared, more than the " + std::to_string(Remaining()) +
           " bytes left in the file can hold");
    }
  }

  /** Big-endian values, right after the section line (VTK writes a newline after them). */
  void
  ReadBinary(vtkDataArray & array, const DataType & type, long long count)
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

  /** Whitespace-separated numbers, across lines; the rest of the last line must be blank. */
  template<typename T>
  void
  ReadAscii(T * out, long long count, const std::string & what)
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

  /** \a count strings: one a line, %XX-encoded (ASCII), or each after a length header whose top two bits say its
   * size (binary: 11 one byte, 10 two, 01 four, 00 eight; the rest of the header is the length, big-endian). */
  void
  ReadStrings(vtkStringArray & array, long long count, const std::string & what)
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
        Fail(what + ": string " + std::to_string(k) + " declares " + std::to_string(length) +
             " bytes, more than remain");
      }
      array.InsertNextValue(m_Text.substr(m_At, static_cast<std::size_t>(length)));
      m_At += static_cast<std::size_t>(length);
    }
    SkipNewline();
  }

  /** VTK's %XX escapes (vtkDataWriter encodes spaces and unprintable characters so). */
  std::string
  Decode(const std::string & text, const std::string & what) const
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

public:
  /** A name from a section line, %XX escapes decoded. */
  std::string
  Name(const std::string & text, const std::string & what) const
  {
    return Decode(text, what);
  }

private:
  void
  SkipNewline()
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

  /** The block VTK writes after an array with component names or information keys: "METADATA", then
   * "COMPONENT_NAMES" with one line per component and "INFORMATION n" with its key lines, up to a blank line. Its
   * content only decorates the array, so it is skipped; anything else there is refused. */
  void
  SkipMetaData(long long components)
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

  std::string m_Text;
  std::string m_Where;
  std::size_t m_At{ 0 };
};

/** The cells of a LINES section before version 5: per cell its size, then its point ids. */
vtkSmartPointer<vtkCellArray>
CellsFromLegacyLayout(const vtkIdType * values,
                      vtkIdType         size,
                      vtkIdType         cells,
                      vtkIdType         points,
                      LegacyParser &    parser)
{
  if (cells > size)
  {
    parser.Fail("LINES: " + std::to_string(cells) + " cells cannot fit in " + std::to_string(size) +
                " values (each takes its point count)");
  }
  auto offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  offsets->SetNumberOfValues(cells + 1);
  connectivity->SetNumberOfValues(size); // at most; trimmed to the ids found
  vtkIdType at = 0;
  vtkIdType used = 0;
  offsets->SetValue(0, 0);
  for (vtkIdType c = 0; c < cells; ++c)
  {
    const vtkIdType count = values[at++];
    // The ids must leave a value for the point count of each cell still to come.
    if (count < 0 || count > size - at - (cells - c - 1))
    {
      parser.Fail("LINES: cell " + std::to_string(c) + " declares " + std::to_string(count) +
                  " points, more than the values left");
    }
    for (vtkIdType k = 0; k < count; ++k)
    {
      const vtkIdType id = values[at++];
      if (id < 0 || id >= points)
      {
        parser.Fail("LINES: cell " + std::to_string(c) + " uses point " + std::to_string(id) + " of " +
                    std::to_string(points));
      }
      connectivity->SetValue(used++, id);
    }
    offsets->SetValue(c + 1, used);
  }
  if (at != size)
  {
    parser.Fail("LINES: the cells use " + std::to_string(at) + " of the " + std::to_string(size) + " values declared");
  }
  connectivity->SetNumberOfValues(used);
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  lines->SetData(offsets, connectivity);
  return lines;
}

/** An integer array (OFFSETS, CONNECTIVITY, legacy cells) as vtkIdType values. */
vtkSmartPointer<vtkIdTypeArray>
IdsOf(vtkAbstractArray * array, LegacyParser & parser, const std::string & what)
{
  auto * numbers = vtkDataArray::SafeDownCast(array);
  if (numbers == nullptr || numbers->GetDataType() == VTK_FLOAT || numbers->GetDataType() == VTK_DOUBLE)
  {
    parser.Fail(what + ": not an integer array");
  }
  auto ids = vtkSmartPointer<vtkIdTypeArray>::New();
  ids->SetNumberOfValues(numbers->GetNumberOfValues());
  for (vtkIdType k = 0; k < numbers->GetNumberOfValues(); ++k)
  {
    const double value = numbers->GetComponent(k, 0);
    if (std::abs(value) > static_cast<double>(MaximumCount))
    {
      parser.Fail(what + ": value " + std::to_string(k) + " is out of range");
    }
    ids->SetValue(k, static_cast<vtkIdType>(value));
  }
  return ids;
}

/** The cells of a LINES section from version 5: OFFSETS (first 0, non-decreasing, last the CONNECTIVITY size) and
 * CONNECTIVITY (point ids). */
vtkSmartPointer<vtkCellArray>
CellsFromOffsets(long long offsetCount, long long connectivityCount, vtkIdType points, LegacyParser & parser)
{
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  if (offsetCount == 0)
  {
    if (connectivityCount != 0)
    {
      parser.Fail("LINES: no OFFSETS for " + std::to_string(connectivityCount) + " CONNECTIVITY values");
    }
    return lines;
  }
  auto header = parser.Words();
  if (header.size() != 2 || ToUpper(header[0]) != "OFFSETS")
  {
    parser.Fail("LINES: \"OFFSETS type\" expected");
  }
  auto offsets = IdsOf(parser.Array(header[1], offsetCount, 1, "LINES OFFSETS"), parser, "LINES OFFSETS");
  header = parser.Words();
  if (header.size() != 2 || ToUpper(header[0]) != "CONNECTIVITY")
  {
    parser.Fail("LINES: \"CONNECTIVITY type\" expected");
  }
  auto connectivity =
    IdsOf(parser.Array(header[1], connectivityCount, 1, "LINES CONNECTIVITY"), parser, "LINES CONNECTIVITY");
  if (offsets->GetValue(0) != 0 || offsets->GetValue(offsetCount - 1) != connectivityCount)
  {
    parser.Fail("LINES: OFFSETS must start at 0 and end at the CONNECTIVITY size " + std::to_string(connectivityCount));
  }
  for (vtkIdType k = 1; k < offsetCount; ++k)
  {
    if (offsets->GetValue(k) < offsets->GetValue(k - 1))
    {
      parser.Fail("LINES: OFFSETS decrease at entry " + std::to_string(k));
    }
  }
  for (vtkIdType k = 0; k < connectivityCount; ++k)
  {
    if (connectivity->GetValue(k) < 0 || connectivity->GetValue(k) >= points)
    {
      parser.Fail("LINES: CONNECTIVITY entry " + std::to_string(k) + " is point " +
                  std::to_string(connectivity->GetValue(k)) + " of " + std::to_string(points));
    }
  }
  lines->SetData(offsets, connectivity);
  return lines;
}

/** Adds \a array to \a attributes; a second array of the same name is refused (VTK would drop the first). */
void
AddArray(vtkFieldData *          attributes,
         vtkAbstractArray *      array,
         std::set<std::string> & names,
         LegacyParser &          parser,
         const std::string &     section)
{
  if (!names.insert(array->GetName()).second)
  {
    parser.Fail(section + ": a second array named \"" + std::string(array->GetName()).substr(0, 40) + "\"");
  }
  attributes->AddArray(array);
}

/** The arrays of a FIELD section; \a tuples, when not negative, is the count each array must have. */
void
ReadField(LegacyParser &                   parser,
          const std::vector<std::string> & words,
          long long                        tuples,
          vtkFieldData *                   target,
          std::set<std::string> &          names,
          const std::string &              section)
{
  if (words.size() != 3)
  {
    parser.Fail("FIELD: \"FIELD name count\" expected");
  }
  const long long arrays = parser.Count(words[2], "FIELD array count");
  for (long long a = 0; a < arrays; ++a)
  {
    const auto array = parser.Words();
    if (array.size() == 1 && ToUpper(array[0]) == "NULL_ARRAY")
    {
      continue;
    }
    if (array.size() != 4)
    {
      parser.Fail("FIELD " + words[1] + ": array " + std::to_string(a) + ": \"name components tuples type\" expected");
    }
    const std::string name = parser.Name(array[0], "FIELD array name");
    const std::string what = "FIELD array " + name;
    const long long   components = parser.Count(array[1], what + " components", 1);
    const long long   count = parser.Count(array[2], what + " tuples");
    if (tuples >= 0 && count != tuples)
    {
      parser.Fail(what + ": " + std::to_string(count) + " tuples, but " + section + " has " + std::to_string(tuples));
    }
    auto values = parser.Array(array[3], count, components, what);
    values->SetName(name.c_str());
    AddArray(target, values, names, parser, section);
  }
}

/** The attribute sections of POINT_DATA or CELL_DATA, up to the next keyword that is not one. \return that
 * keyword's words, or none at the end of the file. */
std::vector<std::string>
ReadAttributes(LegacyParser & parser, vtkDataSetAttributes * attributes, long long tuples, const std::string & section)
{
  std::set<std::string> names;
  while (!parser.AtEnd())
  {
    auto              words = parser.Words();
    const std::string keyword = ToUpper(words[0]);
    long long         components = 0;
    std::size_t       typeWord = 2;
    int               attribute = -1;
    if (keyword == "FIELD")
    {
      ReadField(parser, words, tuples, attributes, names, section);
      continue;
    }
    if (keyword == "SCALARS")
    {
      if (words.size() != 3 && words.size() != 4)
      {
        parser.Fail("SCALARS: \"SCALARS name type [components]\" expected");
      }
      components = words.size() == 4 ? parser.Count(words[3], "SCALARS components", 1) : 1;
      const auto table = parser.Words();
      if (table.size() != 2 || ToUpper(table[0]) != "LOOKUP_TABLE")
      {
        parser.Fail("SCALARS " + words[1] + ": \"LOOKUP_TABLE name\" expected");
      }
      attribute = vtkDataSetAttributes::SCALARS;
    }
    else if (keyword == "VECTORS" || keyword == "NORMALS")
    {
      components = 3;
      attribute = keyword == "VECTORS" ? vtkDataSetAttributes::VECTORS : vtkDataSetAttributes::NORMALS;
    }
    else if (keyword == "TENSORS" || keyword == "TENSORS6")
    {
      components = keyword == "TENSORS" ? 9 : 6;
      attribute = vtkDataSetAttributes::TENSORS;
    }
    else if (keyword == "GLOBAL_IDS" || keyword == "PEDIGREE_IDS")
    {
      components = 1;
      attribute = keyword == "GLOBAL_IDS" ? vtkDataSetAttributes::GLOBALIDS : vtkDataSetAttributes::PEDIGREEIDS;
    }
    else if (keyword == "TEXTURE_COORDINATES")
    {
      if (words.size() != 4)
      {
        parser.Fail("TEXTURE_COORDINATES: \"TEXTURE_COORDINATES name dimension type\" expected");
      }
      components = parser.Count(words[2], "TEXTURE_COORDINATES dimension", 1);
      if (components > 3)
      {
        parser.Fail("TEXTURE_COORDINATES " + words[1] + ": " + std::to_string(components) + " dimensions; at most 3");
      }
      typeWord = 3;
      attribute = vtkDataSetAttributes::TCOORDS;
    }
    else
    {
      return words;
    }
    if (keyword != "SCALARS" && words.size() != typeWord + 1)
    {
      parser.Fail(keyword + ": \"" + keyword + " name " + (typeWord == 3 ? "dimension " : "") + "type\" expected");
    }
    const std::string name = parser.Name(words[1], keyword + " name");
    auto              array = parser.Array(words[typeWord], tuples, components, keyword + " " + name);
    array->SetName(name.c_str());
    if (attribute != vtkDataSetAttributes::PEDIGREEIDS && vtkDataArray::SafeDownCast(array) == nullptr)
    {
      parser.Fail(keyword + " " + name + ": not an array of numbers");
    }
    AddArray(attributes, array, names, parser, section);
    // The first array of each kind is the active one, as VTK's reader makes it.
    if (attributes->GetAbstractAttribute(attribute) == nullptr)
    {
      attributes->SetActiveAttribute(name.c_str(), attribute);
    }
  }
  return {};
}
} // namespace

LegacyVTKPolyData
ReadLegacyVTKPolyData(const std::string & path, const std::string & description)
{
  std::ifstream input(path, std::ios::binary | std::ios::ate);
  if (!input)
  {
    throw InputError(description + ": cannot be opened");
  }
  const auto size = static_cast<std::uintmax_t>(input.tellg());
  if (size > MaximumFileBytes)
  {
    throw InputError(description + ": " + std::to_string(size) + " bytes, more than the " +
                     std::to_string(MaximumFileBytes) + " this reader accepts for a legacy VTK file");
  }
  std::string text(static_cast<std::size_t>(size), '\0');
  input.seekg(0);
  input.read(text.data(), static_cast<std::streamsize>(size));
  if (!input)
  {
    throw InputError(description + ": could not be read");
  }
  LegacyParser parser(std::move(text), description);

  const std::string version = parser.Line();
  if (version.rfind("# vtk DataFile Version ", 0) != 0)
  {
    parser.Fail("the first line is not \"# vtk DataFile Version x.y\"");
  }
  // The versions VTK's legacy writers write: 1.0 to 5.1.
  const std::string number = Trim(version.substr(23));
  const bool        wellFormed = number.size() == 3 && number[0] >= '1' && number[0] <= '5' && number[1] == '.' &&
                          std::isdigit(static_cast<unsigned char>(number[2])) && (number[0] != '5' || number[2] <= '1');
  if (!wellFormed)
  {
    parser.Fail("the file version \"" + number.substr(0, 20) + "\" is not one VTK writes (1.0 to 5.1)");
  }
  const bool        offsetsAndConnectivity = number[0] == '5';
  LegacyVTKPolyData result;
  result.Header = parser.Line();
  if (result.Header.size() > 255)
  {
    parser.Fail("the header line is longer than 255 characters");
  }
  const std::string encoding = ToUpper(Trim(parser.Line()));
  if (encoding != "ASCII" && encoding != "BINARY")
  {
    parser.Fail("the third line must be ASCII or BINARY");
  }
  parser.Binary = encoding == "BINARY";
  auto words = parser.Words();
  if (words.size() != 2 || ToUpper(words[0]) != "DATASET")
  {
    parser.Fail("\"DATASET POLYDATA\" expected");
  }
  if (ToUpper(words[1]) != "POLYDATA")
  {
    parser.Fail("DATASET " + words[1].substr(0, 30) + " is not POLYDATA, the only dataset of centerline files");
  }

  auto                  polyData = vtkSmartPointer<vtkPolyData>::New();
  std::set<std::string> seen;
  std::set<std::string> fieldNames;
  vtkIdType             points = -1;
  vtkIdType             cells = 0;
  bool                  attributes = false;
  words = parser.AtEnd() ? std::vector<std::string>() : parser.Words();
  while (!words.empty())
  {
    const std::string keyword = ToUpper(words[0]);
    if (!seen.insert(keyword).second)
    {
      parser.Fail("a second " + keyword + " section");
    }
    const auto need = [&](std::size_t count, const char * form)
    {
      if (words.size() != count)
      {
        parser.Fail(keyword + ": \"" + form + "\" expected");
      }
    };
    if ((keyword == "FIELD" || keyword == "POINTS" || keyword == "LINES") && attributes)
    {
      parser.Fail(keyword + " after POINT_DATA or CELL_DATA");
    }
    if (keyword == "FIELD")
    {
      ReadField(parser, words, -1, polyData->GetFieldData(), fieldNames, "FIELD");
    }
    else if (keyword == "POINTS")
    {
      need(3, "POINTS count type");
      points = parser.Count(words[1], "POINTS count");
      const auto array = parser.Array(words[2], points, 3, "POINTS");
      auto *     coordinates = vtkDataArray::SafeDownCast(array);
      if (coordinates == nullptr)
      {
        parser.Fail("POINTS: not an array of numbers");
      }
      auto pointSet = vtkSmartPointer<vtkPoints>::New();
      pointSet->SetData(coordinates);
      polyData->SetPoints(pointSet);
    }
    else if (keyword == "LINES")
    {
      need(3, "LINES count size");
      if (points < 0)
      {
        parser.Fail("LINES before POINTS");
      }
      const long long               first = parser.Count(words[1], "LINES count");
      const long long               second = parser.Count(words[2], "LINES size");
      vtkSmartPointer<vtkCellArray> lines;
      if (offsetsAndConnectivity)
      {
        lines = CellsFromOffsets(first, second, points, parser);
      }
      else
      {
        auto values = IdsOf(parser.Array("int", second, 1, "LINES"), parser, "LINES");
        lines = CellsFromLegacyLayout(values->GetPointer(0), second, first, points, parser);
      }
      cells = lines->GetNumberOfCells();
      polyData->SetLines(lines);
    }
    else if (keyword == "POINT_DATA" || keyword == "CELL_DATA")
    {
      need(2, keyword == "POINT_DATA" ? "POINT_DATA count" : "CELL_DATA count");
      const long long count = parser.Count(words[1], keyword + " count");
      const long long expected = keyword == "POINT_DATA" ? points : cells;
      if (count != expected)
      {
        parser.Fail(keyword + " " + std::to_string(count) + ", but the file has " +
                    std::to_string(std::max(0LL, expected)) + (keyword == "POINT_DATA" ? " points" : " cells"));
      }
      attributes = true;
      vtkDataSetAttributes * target = keyword == "POINT_DATA"
                                        ? static_cast<vtkDataSetAttributes *>(polyData->GetPointData())
                                        : static_cast<vtkDataSetAttributes *>(polyData->GetCellData());
      words = ReadAttributes(parser, target, count, keyword);
      continue;
    }
    else if (keyword == "VERTICES" || keyword == "POLYGONS" || keyword == "TRIANGLE_STRIPS")
    {
      parser.Fail(keyword + " are not part of a centerline file (POINTS and LINES only)");
    }
    else
    {
      parser.Fail("\"" + words[0].substr(0, 30) + "\" is not a section this reader accepts (FIELD, POINTS, LINES, " +
                  "POINT_DATA, CELL_DATA)");
    }
    words = parser.AtEnd() ? std::vector<std::string>() : parser.Words();
  }
  if (points < 0)
  {
    parser.Fail("no POINTS section");
  }
  if (seen.count("LINES") == 0)
  {
    parser.Fail("no LINES section: a centerline file holds polylines");
  }
  result.PolyData = polyData;
  return result;
}
} // namespace vr::detail
