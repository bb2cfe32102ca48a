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
    const bool        segmentation = profile.Source == itk::VesselLumenSource::Segmentation;
    const std::string source = itk::ToString(profile.Source);
    for (std::size_t k = 0; k < profile.Sections.size(); ++k)
    {
      const auto & section = profile.Sections[k];
      const auto   ras = LPSToRAS(section.Center);
      output << section.ArcLength;
      Cell(output, separator, ras[0]);
      Cell(output, separator, ras[1]);
      Cell(output, separator, ras[2]);
      Cell(output, separator, section.Area);
      Cell(output, separator, section.EquivalentDiameter);
      Cell(output, separator, section.MinimumDiameter);
      Cell(output, separator, section.MaximumDiameter);
      Cell(output, separator, section.ReferenceDiameter);
      Cell(output, separator, section.Diameter);
      Cell(output, separator, section.InscribedDiameter);
      Cell(output, separator, section.ReferenceArea);
      Cell(output,
           separator,
           section.ReferenceDiameter > 0.0 ? 100.0 * (1.0 - section.Diameter / section.ReferenceDiameter)
                                           : std::nan(""));
      output << separator << source << separator;
      if (segmentation)
      {
        output << (section.CenterInSegmentation ? 1 : 0);
      }
      output << separator;
      if (segmentation && section.CenterInSegmentation)
      {
        output << (section.RegionClipped ? 1 : 0);
      }
      output << separator << section.BranchId << separator;
      if (k < notes.Rows.size() && notes.Rows[k].Segment > 0)
      {
        const auto & marks = notes.Rows[k];
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
