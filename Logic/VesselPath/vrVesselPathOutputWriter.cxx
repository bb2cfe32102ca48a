// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrVesselPathOutputWriter.h"

#include "vrImageIO.h"
#include "vrLumenMeasurement.h"
#include "vrLumenTableIO.h"
#include "vrVolumeIO.h"

namespace vr
{
void
VesselPathOutputWriter::CheckPath(VesselPathOutput output, const std::string & path) const
{
  if (output == VesselPathOutput::LumenTable)
  {
    LumenTableSeparator(path);
  }
}

void
VesselPathOutputWriter::Write(const VesselPathOutputs & results)
{
  WriteReserved(
    [&results](VesselPathOutput output)
    {
      switch (output)
      {
        case VesselPathOutput::CrossSections:
          return results.CrossSections ? std::string() : std::string("the cross-section stack was not computed");
        case VesselPathOutput::Points:
          return results.Points ? std::string() : std::string("the point image was not computed");
        case VesselPathOutput::LumenTable:
          return results.HasLumen ? std::string()
                                  : std::string("no lumen to tabulate: the centerlines carry no radii and no "
                                                "segmentation was given");
        case VesselPathOutput::CPR:
        case VesselPathOutput::FoldMask:
          break;
      }
      return std::string();
    },
    [&results](VesselPathOutput output, const std::string & path)
    {
      switch (output)
      {
        case VesselPathOutput::CPR:
          WriteImage2D(results.CPR.GetPointer(), path);
          break;
        case VesselPathOutput::CrossSections:
          WriteVolume(results.CrossSections, path);
          break;
        case VesselPathOutput::Points:
          WriteImage2D(results.Points.GetPointer(), path);
          break;
        case VesselPathOutput::FoldMask:
          WriteImage2D(results.FoldMask.GetPointer(), path);
          break;
        case VesselPathOutput::LumenTable:
          WriteLumenTable(
            results.Lumen, path, LumenTableNotesOf({ results.Lumen, results.Stenosis }, DescribePath(results)));
          break;
      }
    });
}
} // namespace vr
