// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCenterlineFormats.h"
#include "vrText.h"
#include "vrInputError.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <vector>

namespace vr::detail
{
namespace
{
/** A field without the white space and the double quotes around it. */
std::string
Unquoted(const std::string & text)
{
  std::string trimmed = Trim(text);
  if (trimmed.size() >= 2 && trimmed.front() == '"' && trimmed.back() == '"')
  {
    trimmed = trimmed.substr(1, trimmed.size() - 2);
  }
  return trimmed;
}

std::vector<std::string>
SplitFields(const std::string & line)
{
  std::vector<std::string> fields;
  std::stringstream        stream(line);
  std::string              field;
  while (std::getline(stream, field, ','))
  {
    fields.push_back(Unquoted(field));
  }
  if (!line.empty() && line.back() == ',')
  {
    fields.emplace_back();
  }
  return fields;
}

/** The columns a header names: their positions, or -1 when absent. */
struct Columns
{
  int                      Branch{ -1 };
  int                      Coordinate[3]{ -1, -1, -1 };
  int                      Radius{ -1 };
  CoordinateSpace          Space{ CoordinateSpace::Auto };
  std::size_t              Count{ 0 };
  std::vector<std::string> Names; // lower case, one per column
};

const char * const HeaderHelp = "; the header must be branch,x,y,z[,radius] (LPS) or branch,r,a,s[,radius] (RAS)";

Columns
ParseHeader(const std::string & line, const std::string & where)
{
  const std::vector<std::string> names = SplitFields(line);
  Columns                        columns;
  columns.Count = names.size();
  bool hasXYZ = false;
  bool hasRAS = false;
  for (std::size_t c = 0; c < names.size(); ++c)
  {
    const std::string name = ToLower(names[c]);
    int *             slot = nullptr;
    if (name == "branch")
    {
      slot = &columns.Branch;
    }
    else if (name == "radius")
    {
      slot = &columns.Radius;
    }
    else if (name.size() == 1 && std::string("xyzras").find(name[0]) != std::string::npos)
    {
      const auto position = std::string("xyzras").find(name[0]);
      slot = &columns.Coordinate[position % 3];
      (position < 3 ? hasXYZ : hasRAS) = true;
    }
    else
    {
      throw InputError(where + ", column " + std::to_string(c + 1) + ": \"" + names[c] +
                       "\" is not a column name this reader knows" + HeaderHelp);
    }
    if (*slot != -1)
    {
      throw InputError(where + ", column " + std::to_string(c + 1) + ": a second column for \"" + names[c] + "\"" +
                       HeaderHelp);
    }
    *slot = static_cast<int>(c);
    columns.Names.push_back(name);
  }
  if (hasXYZ && hasRAS)
  {
    throw InputError(where + ": mixes x,y,z (LPS) with r,a,s (RAS) columns" + HeaderHelp);
  }
  if (columns.Branch == -1)
  {
    throw InputError(where + ": no \"branch\" column" + HeaderHelp);
  }
  const char * axisNames = hasRAS ? "ras" : "xyz";
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    if (columns.Coordinate[axis] == -1)
    {
      throw InputError(where + ": no \"" + std::string(1, axisNames[axis]) + "\" column" + HeaderHelp);
    }
  }
  columns.Space = hasRAS ? CoordinateSpace::RAS : CoordinateSpace::LPS;
  return columns;
}

double
ParseNumber(const std::string & text, const std::string & where)
{
  if (text.empty())
  {
    throw InputError(where + ": the value is empty; it must be a number");
  }
  char * end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || errno == ERANGE)
  {
    throw InputError(where + ": \"" + text + "\" is not a number");
  }
  if (!std::isfinite(value))
  {
    throw InputError(where + ": \"" + text + "\" is not a finite number");
  }
  return value;
}
} // namespace

itk::CenterlineTree
ReadCenterlineCSV(const std::string & path, CoordinateSpace space, CenterlineReadReport & report)
{
  std::ifstream input(path);
  if (!input)
  {
    throw InputError("centerline file " + path + ": cannot be opened");
  }
  report.Format = "CSV";
  const std::string          file = "centerline file " + path;
  std::string                line;
  std::size_t                lineNumber = 0;
  Columns                    columns;
  bool                       haveHeader = false;
  std::map<int, std::size_t> branchIndex;
  itk::CenterlineTree        tree;
  std::size_t                rows = 0;
  while (std::getline(input, line))
  {
    ++lineNumber;
    if (lineNumber == 1 && line.rfind("\xEF\xBB\xBF", 0) == 0)
    {
      line = line.substr(3); // a UTF-8 byte order mark, as spreadsheet programs write
    }
    const std::string trimmed = Trim(line);
    if (trimmed.empty() || trimmed[0] == '#')
    {
      continue;
    }
    const std::string where = file + ", line " + std::to_string(lineNumber);
    if (!haveHeader)
    {
      columns = ParseHeader(trimmed, where + " (header)");
      haveHeader = true;
      continue;
    }
    const std::vector<std::string> fields = SplitFields(trimmed);
    if (fields.size() != columns.Count)
    {
      throw InputError(where + ": " + std::to_string(fields.size()) + " values, but the header names " +
                       std::to_string(columns.Count) + " columns");
    }
    auto cell = [&](int column)
    { return where + ", column " + std::to_string(column + 1) + " (" + columns.Names[column] + ")"; };
    const double branchValue = ParseNumber(fields[columns.Branch], cell(columns.Branch));
    if (branchValue < 1.0 || branchValue != std::floor(branchValue) || branchValue > std::numeric_limits<int>::max())
    {
      throw InputError(cell(columns.Branch) + ": \"" + fields[columns.Branch] +
                       "\" is not a whole number >= 1 (branch ids start at 1)");
    }
    itk::CenterlineBranch::PointType point;
    for (unsigned int axis = 0; axis < 3; ++axis)
    {
      point[axis] = ParseNumber(fields[columns.Coordinate[axis]], cell(columns.Coordinate[axis]));
    }
    const int id = static_cast<int>(branchValue);
    auto      found = branchIndex.find(id);
    if (found == branchIndex.end())
    {
      itk::CenterlineBranch branch;
      branch.Id = id;
      tree.AddBranch(branch);
      found = branchIndex.emplace(id, tree.GetNumberOfBranches() - 1).first;
    }
    itk::CenterlineBranch & branch = tree.GetBranches()[found->second];
    branch.Points.push_back(point);
    if (columns.Radius != -1)
    {
      const double radius = ParseNumber(fields[columns.Radius], cell(columns.Radius));
      if (radius < 0.0)
      {
        throw InputError(cell(columns.Radius) + ": radius " + fields[columns.Radius] + " mm is negative");
      }
      branch.Radii.push_back(radius);
    }
    ++rows;
  }
  if (!haveHeader)
  {
    throw InputError(file + ": no header line" + HeaderHelp);
  }
  if (rows == 0)
  {
    throw InputError(file + ": a header but no data rows; the file holds no centerline point");
  }
  const CoordinateSpace used = space == CoordinateSpace::Auto ? columns.Space : space;
  report.FileSpace = used;
  report.SpaceSource =
    space == CoordinateSpace::Auto
      ? std::string("the header's ") + (columns.Space == CoordinateSpace::RAS ? "r,a,s" : "x,y,z") + " columns"
      : std::string("override");
  report.RadiusArray = columns.Radius != -1 ? "radius" : "";
  report.InputPolylines = tree.GetNumberOfBranches();
  return used == CoordinateSpace::RAS ? FlipRASLPS(tree) : tree;
}

void
WriteCenterlineCSV(const itk::CenterlineTree & tree,
                   const std::string &         finalPath,
                   const std::string &         temporaryPath,
                   CoordinateSpace             space)
{
  const bool    ras = space == CoordinateSpace::RAS;
  std::ofstream output(temporaryPath);
  if (!output)
  {
    throw InputError("centerline output " + finalPath + ": cannot be created");
  }
  const bool withRadii = tree.HasRadii();
  output << (ras ? "branch,r,a,s" : "branch,x,y,z") << (withRadii ? ",radius" : "") << '\n';
  output.precision(std::numeric_limits<double>::max_digits10);
  for (const auto & branch : tree.GetBranches())
  {
    for (std::size_t k = 0; k < branch.Points.size(); ++k)
    {
      const auto point = ras ? LPSToRAS(branch.Points[k]) : branch.Points[k];
      output << branch.Id << ',' << point[0] << ',' << point[1] << ',' << point[2];
      if (withRadii)
      {
        output << ',' << branch.Radii[k];
      }
      output << '\n';
    }
  }
  output.close();
  if (!output)
  {
    throw InputError("centerline output " + finalPath + ": writing failed (disk full?)");
  }
}
} // namespace vr::detail
