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
WriteLumenTable(const itk::VesselLumenProfile & profile, const std::string & path)
{
  const char   separator = LumenTableSeparator(path);
  AtomicOutput staged(path);
  {
    std::ofstream output(staged.TemporaryPath());
    if (!output)
    {
      throw InputError("lumen table " + path + ": cannot be created");
    }
    output.precision(10);
    bool first = true;
    for (const char * column : LumenTableColumns)
    {
      output << (first ? "" : std::string(1, separator)) << column;
      first = false;
    }
    output << '\n';
    const bool        segmentation = profile.Source == itk::VesselLumenSource::Segmentation;
    const std::string source = itk::ToString(profile.Source);
    for (const auto & section : profile.Sections)
    {
      const auto ras = LPSToRAS(section.Center);
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
      output << separator << section.BranchId << '\n';
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
