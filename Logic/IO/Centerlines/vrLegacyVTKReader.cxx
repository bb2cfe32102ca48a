// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The legacy .vtk polyline reader: our own grammar, the only code that reads users' .vtk centerline files.
#include "vrLegacyVTKReader.h"
#include "vrInputError.h"
#include "vrLegacyVTKScanner.h"
#include "vrText.h"

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <set>
#include <vector>

namespace vr::detail
{
namespace
{
/** The file size this reader accepts: a centerline file holds thousands of points, so this only stops hostile
 * files before anything is read. */
constexpr std::uintmax_t MaximumFileBytes = 1ULL << 28;

/** The cells of a LINES section before version 5: per cell its size, then its point ids. */
vtkSmartPointer<vtkCellArray>
CellsFromLegacyLayout(const vtkIdType *  values,
                      vtkIdType          size,
                      vtkIdType          cells,
                      vtkIdType          points,
                      LegacyVTKScanner & parser)
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
IdsOf(vtkAbstractArray * array, LegacyVTKScanner & parser, const std::string & what)
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
    if (std::abs(value) > static_cast<double>(LegacyVTKScanner::MaximumCount))
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
CellsFromOffsets(long long offsetCount, long long connectivityCount, vtkIdType points, LegacyVTKScanner & parser)
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
         LegacyVTKScanner &      parser,
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
ReadField(LegacyVTKScanner &               parser,
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
ReadAttributes(LegacyVTKScanner &     parser,
               vtkDataSetAttributes * attributes,
               long long              tuples,
               const std::string &    section)
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
  LegacyVTKScanner parser(std::move(text), description);

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
