// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrOcclusionTableIO.h"

#include "vrAtomicOutput.h"
#include "vrInputError.h"

#include <fstream>

namespace vr
{
namespace
{
/** A CSV field: quoted, with quotes doubled, when it holds a separator, a quote or a line break. */
std::string
Field(const std::string & text)
{
  if (text.find_first_of(",\"\r\n") == std::string::npos)
  {
    return text;
  }
  std::string quoted = "\"";
  for (const char c : text)
  {
    quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  }
  return quoted + "\"";
}

double
Percent(double part, double whole)
{
  return whole > 0.0 ? 100.0 * part / whole : 0.0;
}

template<typename TWrite>
void
WriteTable(const std::string & what, const std::string & path, const TWrite & write)
{
  AtomicOutput staged(path);
  {
    std::ofstream output(staged.TemporaryPath());
    if (!output)
    {
      throw InputError(what + " " + path + ": cannot be created");
    }
    output.precision(10);
    write(output);
    output.close();
    if (!output)
    {
      throw InputError(what + " " + path + ": writing failed (disk full?)");
    }
  }
  staged.Commit();
}
} // namespace

void
WriteHiddenLengthTable(const std::vector<BranchOcclusionRow> & rows, double angle, const std::string & path)
{
  WriteTable("hidden-length table",
             path,
             [&](std::ostream & output)
             {
               bool first = true;
               for (const char * column : HiddenLengthColumns)
               {
                 output << (first ? "" : ",") << column;
                 first = false;
               }
               output << '\n';
               BranchOcclusionRow tree{ 0, "whole tree", 0.0, 0.0, {} };
               for (const BranchOcclusionRow & row : rows)
               {
                 output << row.BranchId << ',' << Field(row.Name) << ',' << row.Length << ',' << row.HiddenLength << ','
                        << Percent(row.HiddenLength, row.Length) << ',' << angle << '\n';
                 tree.Length += row.Length;
                 tree.HiddenLength += row.HiddenLength;
               }
               output << tree.BranchId << ',' << tree.Name << ',' << tree.Length << ',' << tree.HiddenLength << ','
                      << Percent(tree.HiddenLength, tree.Length) << ',' << angle << '\n';
             });
}

void
WriteOcclusionProfileTable(const itk::CPROcclusionProfile & profile, const std::string & path)
{
  if (profile.HiddenLength.empty())
  {
    throw InputError("occlusion profile " + path + ": no profile was computed");
  }
  WriteTable("occlusion profile",
             path,
             [&](std::ostream & output)
             {
               output << "angle_degrees,hidden_length_mm,hidden_percent\n";
               for (unsigned int angle = 0; angle < profile.HiddenLength.size(); ++angle)
               {
                 output << angle << ',' << profile.HiddenLength[angle] << ',' << 100.0 * profile.HiddenFraction(angle)
                        << '\n';
               }
             });
}
} // namespace vr
