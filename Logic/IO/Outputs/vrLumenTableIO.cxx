// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrLumenTableIO.h"

#include "vrAtomicOutput.h"
#include "vrCoordinateFrames.h"
#include "vrInputError.h"
#include "vrText.h"

#include <cmath>
#include <fstream>

namespace vr
{
namespace
{
/** A number, or nothing for NaN. */
void
Cell(std::ostream & output, char separator, double value)
{
  output << separator;
  if (!std::isnan(value))
  {
    output << value;
  }
}

/** Text without the separator, the comment mark at its start or a line break, which would break the table. */
std::string
Clean(std::string text, char separator)
{
  for (char & c : text)
  {
    if (c == separator || c == '\n' || c == '\r')
    {
      c = separator == ';' ? ',' : ';';
    }
  }
  return text;
}
} // namespace

LumenTable
MakeLumenTable(const itk::VesselLumenProfile & profile)
{
  constexpr std::size_t columns = LumenTableProfileColumns;
  const double          empty = std::nan("");
  const bool            segmentation = profile.Source == itk::VesselLumenSource::Segmentation;
  LumenTable            table;
  table.Source = itk::ToString(profile.Source);
  table.Rows = profile.Sections.size();
  table.Numbers.resize(columns);
  for (std::size_t column = 0; column < columns; ++column)
  {
    if (column != LumenTableSourceColumn)
    {
      table.Numbers[column].reserve(table.Rows);
    }
  }
  for (const auto & section : profile.Sections)
  {
    const auto   ras = LPSToRAS(section.Center);
    const bool   inside = segmentation && section.CenterInSegmentation;
    const double values[] = { section.ArcLength,
                              ras[0],
                              ras[1],
                              ras[2],
                              section.Area,
                              section.EquivalentDiameter,
                              section.MinimumDiameter,
                              section.MaximumDiameter,
                              section.ReferenceDiameter,
                              section.Diameter,
                              section.InscribedDiameter,
                              section.ReferenceArea,
                              section.ReferenceDiameter > 0.0
                                ? 100.0 * (1.0 - section.Diameter / section.ReferenceDiameter)
                                : empty,
                              empty, // source: text
                              segmentation ? (section.CenterInSegmentation ? 1.0 : 0.0) : empty,
                              inside ? (section.RegionClipped ? 1.0 : 0.0) : empty,
                              static_cast<double>(section.BranchId) };
    static_assert(sizeof(values) / sizeof(values[0]) == columns, "one value per column of the lumen table");
    for (std::size_t column = 0; column < columns; ++column)
    {
      if (column != LumenTableSourceColumn)
      {
        table.Numbers[column].push_back(values[column]);
      }
    }
  }
  return table;
}

char
LumenTableSeparator(const std::string & path)
{
  if (HasExtension(path, ".csv"))
  {
    return ',';
  }
  if (HasExtension(path, ".tsv"))
  {
    return '\t';
  }
  throw InputError("lumen table " + path +
                   ": unknown table format; use .csv (comma-separated) or .tsv (tab-separated)");
}

void
WriteLumenTable(const itk::VesselLumenProfile & profile, const std::string & path, const LumenTableNotes & notes)
{
  const char separator = LumenTableSeparator(path);
  if (!notes.Rows.empty() && notes.Rows.size() != profile.Sections.size())
  {
    throw InputError("lumen table " + path + ": " + std::to_string(notes.Rows.size()) + " rows of marks for " +
                     std::to_string(profile.Sections.size()) + " sections");
  }
  AtomicOutput staged(path);
  {
    std::ofstream output(staged.TemporaryPath());
    if (!output)
    {
      throw InputError("lumen table " + path + ": cannot be created");
    }
    output.precision(10);
    for (const std::string & comment : notes.Comments)
    {
      std::string line = comment;
      for (char & c : line)
      {
        c = (c == '\n' || c == '\r') ? ' ' : c;
      }
      output << "# " << line << '\n';
    }
    bool first = true;
    for (const char * column : LumenTableColumns)
    {
      output << (first ? "" : std::string(1, separator)) << column;
      first = false;
    }
    output << '\n';
    const LumenTable table = MakeLumenTable(profile);
    for (std::size_t row = 0; row < table.Rows; ++row)
    {
      for (std::size_t column = 0; column < table.Numbers.size(); ++column)
      {
        if (column == LumenTableSourceColumn)
        {
          output << separator << table.Source;
        }
        else if (column == 0)
        {
          output << table.Numbers[column][row];
        }
        else
        {
          Cell(output, separator, table.Numbers[column][row]);
        }
      }
      output << separator;
      if (row < notes.Rows.size() && notes.Rows[row].Segment > 0)
      {
        const auto & marks = notes.Rows[row];
        output << marks.Segment << separator << (marks.Candidate ? 1 : 0) << separator
               << Clean(marks.ExcludedBecause, separator);
      }
      else
      {
        output << separator << separator; // three empty cells
      }
      output << '\n';
    }
    output.close();
    if (!output)
    {
      throw InputError("lumen table " + path + ": writing failed (disk full?)");
    }
  }
  staged.Commit();
}
} // namespace vr
