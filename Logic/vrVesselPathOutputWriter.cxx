// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrVesselPathOutputWriter.h"

#include "vrImageIO.h"
#include "vrInputError.h"
#include "vrLumenTableIO.h"
#include "vrVolumeIO.h"

#include <algorithm>

namespace vr
{
void
VesselPathOutputWriter::Add(VesselPathOutput output, const std::string & path, const std::string & flag)
{
  if (output == VesselPathOutput::LumenTable)
  {
    try
    {
      LumenTableSeparator(path);
    }
    catch (const InputError & error)
    {
      throw InputError(flag + ": " + error.what());
    }
  }
  m_Reserved.push_back({ output, m_Staged.Add(path, flag), flag });
}

bool
VesselPathOutputWriter::Has(VesselPathOutput output) const
{
  return std::any_of(
    m_Reserved.begin(), m_Reserved.end(), [output](const Reserved & reserved) { return reserved.Output == output; });
}

void
VesselPathOutputWriter::Write(const VesselPathResults & results)
{
  for (const Reserved & reserved : m_Reserved)
  {
    const auto missing = [&reserved](const char * what)
    { throw InputError(reserved.Flag + ": " + what + " was not computed"); };
    m_Staged.Write(reserved.Handle,
                   [&](const std::string & path)
                   {
                     switch (reserved.Output)
                     {
                       case VesselPathOutput::CPR:
                         WriteImage2D(results.CPR.GetPointer(), path);
                         break;
                       case VesselPathOutput::CrossSections:
                         if (!results.CrossSections)
                         {
                           missing("the cross-section stack");
                         }
                         WriteVolume(results.CrossSections, path);
                         break;
                       case VesselPathOutput::Points:
                         if (!results.Points)
                         {
                           missing("the point image");
                         }
                         WriteImage2D(results.Points.GetPointer(), path);
                         break;
                       case VesselPathOutput::FoldMask:
                         WriteImage2D(results.FoldMask.GetPointer(), path);
                         break;
                       case VesselPathOutput::LumenTable:
                         if (!results.HasLumen)
                         {
                           throw InputError(reserved.Flag +
                                            ": no lumen to tabulate: the centerlines carry no radii and no "
                                            "segmentation was given");
                         }
                         WriteLumenTable(results.Lumen, path);
                         break;
                     }
                   });
  }
}

void
VesselPathOutputWriter::CommitAll()
{
  m_Staged.CommitAll();
}
} // namespace vr
