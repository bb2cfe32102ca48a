// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// vrReadDICOMSeries <folder> <descriptor> <report file> [<series>]: reads one DICOM series of <folder> into the file
// open at <descriptor> (the caller's hand-over file, vrDICOMVolumeHandOver.h: the voxels in the series' stored type
// with its rescale, or float intensities where the files' rescales differ or a slice is interpolated), as
// docs/dicom-series.md says: the folder's files examined one by one with
// GDCM, sorted into series; one series read (the only one, or <series>: its number in the list or its Series Instance
// UID), or the series listed and none read; every file of it checked against the others; its geometry from the files'
// positions. It runs as a child process of the volume reader (vrDICOMSeriesProcess.cxx) because Debian's GDCM asserts,
// i.e. aborts the process, on some corrupt files: here an abort ends this process only. What it says goes to the
// report file, one line each (vrDICOMReaderReport.h); a "file <path>" line is written before GDCM opens each file, so
// that the caller can name the file a crash happened in.
// Exit status: 0 done, 1 error (said in the report), 2 wrong arguments.
#include "vrDICOMFolderExamination.h"
#include "vrDICOMPixelData.h"
#include "vrDICOMReaderReport.h"
#include "vrDICOMSeriesGroups.h"
#include "vrDICOMSliceGeometry.h"
#include "vrDICOMVolumeHandOver.h"

#include "itkObject.h"

#include <gdcmTrace.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace
{
using namespace vr::detail;
int ReportFile = -1;
/** The hand-over file's descriptor (vrDICOMVolumeHandOver.h). */
int HandOver = -1;

/** Appends \a line to the report at once (no buffer a crash could lose). */
void
Report(const std::string & line)
{
  const std::string text = line + "\n";
  std::size_t       written = 0;
  while (written < text.size())
  {
    const ssize_t count = ::write(ReportFile, text.data() + written, text.size() - written);
    if (count <= 0)
    {
      return;
    }
    written += static_cast<std::size_t>(count);
  }
}

/** Ends with "error <kind>" and the reason on the line after it. */
int
Fail(const std::string & kind, const std::string & reason)
{
  Report("error " + kind);
  Report(ReportText(reason));
  return 1;
}

/** The most voxels a volume may have (vr::MaximumVolumeVoxels, 2^32). */
constexpr std::uint64_t MaximumVoxels = std::uint64_t{ 1 } << 32;

/** The chosen series and what reading it needs. */
struct Series
{
  const std::vector<vr::detail::DICOMFileAttributes> & Files;
  const DICOMImageSet &                                Set;
  DICOMImageLayout                                     Layout;

  const std::string &
  File(std::size_t j) const
  {
    return Files[Set.Files[j]].File;
  }
  /** Reads the pixels of the set's file \a j, rescaled, into \a slice (Columns x Rows values). */
  std::string
  Pixels(std::size_t j, float * slice) const
  {
    Report("file " + File(j));
    return ReadDICOMPixels(File(j), Layout, Layout.Slopes[j], Layout.Intercepts[j], slice);
  }
  /** Reads the pixels of file \a j into \a slice as ReadDICOMPixels() reads them as \a pixelType. */
  std::string
  Pixels(std::size_t j, itk::IOComponentEnum pixelType, void * slice, itk::IOComponentEnum & decoded) const
  {
    Report("file " + File(j));
    return ReadDICOMPixels(File(j), Layout, Layout.Slopes[j], Layout.Intercepts[j], pixelType, slice, decoded);
  }
  std::string
  Pixels(std::size_t j, std::vector<float> & slice) const
  {
    slice.resize(std::size_t{ Layout.Columns } * Layout.Rows);
    return Pixels(j, slice.data());
  }
};

/** Whether the set's files \a a and \a b hold the same rescaled pixels; \a failure receives why one cannot be read. */
bool
SamePixels(const Series & series, std::size_t a, std::size_t b, std::string & failure)
{
  std::vector<float> first;
  std::vector<float> second;
  failure = series.Pixels(a, first);
  if (failure.empty())
  {
    failure = series.Pixels(b, second);
  }
  return failure.empty() && first == second;
}

/** Leaves out the later of two files with one SOP Instance UID (one instance, copied twice) when they hold the same
 * position and pixels. \return the files kept (set indices), or empty with \a refusal set. */
std::vector<std::size_t>
WithoutRepeatedInstances(const Series & series, std::vector<std::string> & warnings, std::string & refusal)
{
  std::map<std::string, std::size_t> first;
  std::vector<std::size_t>           kept;
  for (std::size_t j = 0; j < series.Set.Files.size(); ++j)
  {
    const auto uid = series.Files[series.Set.Files[j]].Get(DICOMTag::SOPInstanceUID);
    if (!uid || uid->empty() || first.count(*uid) == 0)
    {
      if (uid && !uid->empty())
      {
        first[*uid] = j;
      }
      kept.push_back(j);
      continue;
    }
    const std::size_t i = first[*uid];
    const auto &      p = series.Layout.Positions;
    const double      apart =
      std::sqrt((p[i][0] - p[j][0]) * (p[i][0] - p[j][0]) + (p[i][1] - p[j][1]) * (p[i][1] - p[j][1]) +
                (p[i][2] - p[j][2]) * (p[i][2] - p[j][2]));
    std::string failure;
    if (apart <= 0.01 && SamePixels(series, i, j, failure))
    {
      warnings.push_back("the DICOM file " + series.File(j) + " is a copy of " + series.File(i) +
                         " (the same SOP Instance UID " + *uid + ", position and pixels): a duplicate, left out");
      continue;
    }
    refusal = !failure.empty()
                ? failure
                : "the DICOM files " + series.File(i) + " and " + series.File(j) + " share the SOP Instance UID " +
                    *uid + " but hold " + (apart > 0.01 ? "different positions" : "different pixels") +
                    ": one instance cannot be two images; remove the one that does not belong";
    return {};
  }
  return kept;
}

/** The warning for the files of the chosen set's Series Instance UID that belong to other sets. */
std::string
OtherSetsOfTheUID(const std::vector<DICOMFileAttributes> & files,
                  const std::vector<DICOMImageSet> &       sets,
                  std::size_t                              chosen)
{
  const auto  uid = files[sets[chosen].Files.front()].Get(DICOMTag::SeriesInstanceUID).value_or("");
  std::string text;
  std::size_t count = 0;
  for (std::size_t s = 0; s < sets.size(); ++s)
  {
    if (s == chosen || files[sets[s].Files.front()].Get(DICOMTag::SeriesInstanceUID).value_or("") != uid)
    {
      continue;
    }
    count += sets[s].Files.size();
    text += (text.empty() ? "" : "; ") + files[sets[s].Files.front()].File +
            (sets[s].Files.size() > 1 ? " and " + std::to_string(sets[s].Files.size() - 1) + " more" : "") + " (" +
            (sets[s].Difference.empty() ? std::string("another set") : sets[s].Difference) + ")";
  }
  if (count == 0)
  {
    return std::string();
  }
  return std::to_string(count) + (count == 1 ? " other file" : " other files") + " of the Series Instance UID " + uid +
         " differ from the series chosen and " + (count == 1 ? "was" : "were") + " not read: " + text;
}

/** The warning for the chosen set's files whose data set GDCM read with implicit VR under a Transfer Syntax UID that
 * declares explicit VR: their pixels and attributes pass every check, so the series is read, and the user learns that
 * the files' meta information is wrong. */
std::string
ImplicitUnderExplicitClaimWarning(const std::vector<DICOMFileAttributes> & files, const DICOMImageSet & set)
{
  std::vector<std::size_t> misdeclared;
  for (const std::size_t j : set.Files)
  {
    if (files[j].ImplicitUnderExplicitClaim)
    {
      misdeclared.push_back(j);
    }
  }
  if (misdeclared.empty())
  {
    return std::string();
  }
  const DICOMFileAttributes & first = files[misdeclared.front()];
  const std::size_t           others = misdeclared.size() - 1;
  const std::string           more =
    others > 0 ? " and " + std::to_string(others) + (others == 1 ? " other file" : " other files") + " of the series"
                         : "";
  return "the DICOM file " + first.File + more + (misdeclared.size() > 1 ? " declare" : " declares") +
         " explicit VR (Transfer Syntax UID " + first.Shown(DICOMTag::TransferSyntaxUID) + ") but " +
         (misdeclared.size() > 1 ? "their data sets are" : "its data set is") +
         " written with implicit VR: read as written, as GDCM does, since every check of the series holds for " +
         (misdeclared.size() > 1 ? "them" : "it") + "; the file meta information is wrong (check the files' source)";
}
} // namespace

int
main(int argc, char * argv[])
{
  if (argc != 4 && argc != 5)
  {
    return 2;
  }
  const std::string folder = argv[1];
  // The descriptor the caller opened the hand-over file at.
  if (std::string(argv[2]) != std::to_string(DICOMVolumeHandOverDescriptor))
  {
    return 2;
  }
  HandOver = DICOMVolumeHandOverDescriptor;
  const std::string choice = argc == 5 ? argv[4] : "";
  ReportFile = ::open(argv[3], O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC, 0600);
  if (ReportFile < 0)
  {
    return 2;
  }
  // A corrupt file is reported by the caller; a core dump of this process would only fill the user's disk.
  const rlimit noCore{ 0, 0 };
  ::setrlimit(RLIMIT_CORE, &noCore);
  // GDCM's and ITK's own messages would reach the terminal: the caller reports in its words.
  gdcm::Trace::SetDebug(false);
  gdcm::Trace::SetWarning(false);
  gdcm::Trace::SetError(false);
  itk::Object::GlobalWarningDisplayOff();

  // One series: the folder's images sorted into sets that can each be one volume.
  Report("step examine");
  const DICOMFolderExamination examination =
    ExamineDICOMFolder(folder, [](const std::string & file) { Report("file " + file); });
  Report("step choose");
  if (!examination.Refusal.empty())
  {
    return Fail("message", examination.Refusal + "; the series is not read");
  }
  const std::string note = SkippedEntriesNote(examination);
  if (!note.empty())
  {
    Report("note " + ReportText(note));
  }
  if (examination.Images.empty())
  {
    return Fail("none", "holds no DICOM image" + (note.empty() ? std::string() : " (" + note + ")"));
  }
  const auto &                     files = examination.Images;
  const std::vector<DICOMImageSet> sets = GroupDICOMImages(files);
  std::size_t                      chosen = 0;
  if (sets.size() > 1 || !choice.empty())
  {
    const std::string problem = choice.empty() ? "several" : ChooseDICOMImageSet(files, sets, choice, chosen);
    if (!problem.empty())
    {
      for (const vr::DICOMSeriesSummary & series : SummarizeDICOMImageSets(files, sets))
      {
        Report("series " + SeriesReportLine(series));
      }
      return choice.empty() ? Fail("choose", std::to_string(sets.size())) : Fail("choice", problem);
    }
  }
  std::vector<std::string> warnings;
  if (const std::string others = OtherSetsOfTheUID(files, sets, chosen); !others.empty())
  {
    warnings.push_back(others);
  }
  if (const std::string misdeclared = ImplicitUnderExplicitClaimWarning(files, sets[chosen]); !misdeclared.empty())
  {
    warnings.push_back(misdeclared);
  }

  // Every file agrees; one instance once; the geometry from the positions.
  Series series{ files, sets[chosen], {} };
  if (const std::string problem = CheckDICOMImageSet(files, series.Set, series.Layout); !problem.empty())
  {
    return Fail("message", problem + "; the series is not read");
  }
  if (!series.Layout.PixelSpacingSource.empty())
  {
    Report("note " + ReportText("the files have no Pixel Spacing (0028,0030): the pixels' spacing is their " +
                                series.Layout.PixelSpacingSource + ", as ITK and 3D Slicer read it"));
  }
  Report("step decode");
  std::string                    refusal;
  const std::vector<std::size_t> instances = WithoutRepeatedInstances(series, warnings, refusal);
  if (!refusal.empty())
  {
    return Fail("message", refusal + "; the series is not read");
  }
  std::vector<DICOMSlicePosition> positions;
  for (const std::size_t j : instances)
  {
    const auto & p = series.Layout.Positions[j];
    positions.push_back({ series.File(j), { p[0], p[1], p[2] } });
  }
  DICOMSliceGrid    grid;
  std::string       pixelFailure;
  const std::string geometry = PlanDICOMSliceGrid(
    positions,
    series.Layout.Orientation,
    std::min(series.Layout.PixelSpacing[0], series.Layout.PixelSpacing[1]),
    [&](std::size_t a, std::size_t b)
    { return pixelFailure.empty() && SamePixels(series, instances[a], instances[b], pixelFailure); },
    files[series.Set.Files.front()].Get(DICOMTag::GantryDetectorTilt),
    grid);
  if (!pixelFailure.empty())
  {
    return Fail("message", pixelFailure + "; the series is not read");
  }
  if (!geometry.empty())
  {
    return Fail("message", geometry + "; the series is not read");
  }
  if (grid.Slices.size() < 2)
  {
    return Fail("message",
                "the DICOM series is one 2D slice, the DICOM file " +
                  series.File(instances[grid.Slices.front().First]) + ": a volume must be 3D");
  }
  warnings.insert(warnings.end(), grid.Warnings.begin(), grid.Warnings.end());

  // The volume: each grid slice its file's pixels, or two files' interpolated.
  const std::uint64_t sliceVoxels = std::uint64_t{ series.Layout.Columns } * series.Layout.Rows;
  if (sliceVoxels * grid.Slices.size() > MaximumVoxels)
  {
    return Fail("message",
                "the DICOM series would be a volume of " + std::to_string(series.Layout.Columns) + " x " +
                  std::to_string(series.Layout.Rows) + " x " + std::to_string(grid.Slices.size()) +
                  " voxels, more than 2^32 (is a file's Rows or Columns corrupt?)");
  }
  // The voxels' type: the files' stored one, kept with their one rescale, where every file has the same rescale and
  // every slice is a file's; float intensities where the files' rescales differ (one stored type cannot hold them
  // with one rescale) or a slice is interpolated (its values fall between the stored ones), and for 32-bit integers.
  bool oneRescale = true;
  for (const std::size_t j : instances)
  {
    oneRescale = oneRescale && series.Layout.Slopes[j] == series.Layout.Slopes[instances.front()] &&
                 series.Layout.Intercepts[j] == series.Layout.Intercepts[instances.front()];
  }
  const bool interpolated = std::any_of(
    grid.Slices.begin(), grid.Slices.end(), [](const DICOMSliceGrid::Slice & slice) { return slice.Weight != 0.0; });
  const itk::IOComponentEnum storedType = DICOMStoredPixelType(series.Layout);
  itk::IOComponentEnum       pixelType =
    oneRescale && !interpolated && DICOMVolumePixelBytes(storedType) > 0 ? storedType : itk::IOComponentEnum::FLOAT;
  const std::uint64_t volumeVoxels = sliceVoxels * grid.Slices.size();

  // The first file read before the volume's memory is reserved: a series whose attributes are corrupt (Rows and
  // Columns that make gigabytes) is refused by its first file, not by the memory it asks for.
  {
    std::vector<float> first;
    if (std::string problem = series.Pixels(instances[grid.Slices.front().First], first); !problem.empty())
    {
      return Fail("message", problem + "; the series is not read");
    }
  }

  // The volume, written straight into the hand-over file: each grid slice its file's pixels, or two files'
  // interpolated. Read again in float should GDCM decode a file in another type than the attributes say.
  DICOMVolumeHandOverWriter handOver;
  for (bool done = false; !done;)
  {
    if (std::string problem = handOver.Open(HandOver, pixelType, volumeVoxels); !problem.empty())
    {
      return Fail("write", problem);
    }
    const std::size_t sliceBytes = sliceVoxels * DICOMVolumePixelBytes(pixelType);
    char *            voxels = static_cast<char *>(handOver.Voxels());
    done = true;
    for (std::size_t k = 0; k < grid.Slices.size() && done; ++k)
    {
      const DICOMSliceGrid::Slice & slice = grid.Slices[k];
      if (slice.Weight != 0.0)
      {
        continue;
      }
      itk::IOComponentEnum decoded = itk::IOComponentEnum::UNKNOWNCOMPONENTTYPE;
      if (std::string problem = series.Pixels(instances[slice.First], pixelType, voxels + k * sliceBytes, decoded);
          !problem.empty())
      {
        return Fail("message", problem + "; the series is not read");
      }
      if (pixelType != itk::IOComponentEnum::FLOAT && decoded != pixelType)
      {
        pixelType = itk::IOComponentEnum::FLOAT;
        done = false;
      }
    }
  }
  std::map<std::size_t, std::size_t> slicesOfFiles;
  for (std::size_t k = 0; k < grid.Slices.size(); ++k)
  {
    if (grid.Slices[k].Weight == 0.0)
    {
      slicesOfFiles[grid.Slices[k].First] = k;
    }
  }
  auto * floats = static_cast<float *>(handOver.Voxels());
  for (std::size_t k = 0; k < grid.Slices.size(); ++k)
  {
    const DICOMSliceGrid::Slice & slice = grid.Slices[k];
    if (slice.Weight == 0.0)
    {
      continue;
    }
    const float * a = floats + slicesOfFiles.at(slice.First) * sliceVoxels;
    const float * b = floats + slicesOfFiles.at(slice.Second) * sliceVoxels;
    float *       out = floats + k * sliceVoxels;
    for (std::uint64_t v = 0; v < sliceVoxels; ++v)
    {
      out[v] = static_cast<float>((1.0 - slice.Weight) * a[v] + slice.Weight * b[v]);
    }
  }

  // What the caller shows, then the volume handed over.
  for (const std::string & warning : warnings)
  {
    Report("warning " + ReportText(warning));
  }
  for (const auto & [key, value] : files[series.Set.Files.front()].Identity)
  {
    Report("identity " + ReportText(key) + "\t" + ReportText(value));
  }
  Report("step write");
  DICOMVolumeHeader header;
  header.Size[0] = series.Layout.Columns;
  header.Size[1] = series.Layout.Rows;
  header.Size[2] = grid.Slices.size();
  header.Spacing[0] = series.Layout.PixelSpacing[1];
  header.Spacing[1] = series.Layout.PixelSpacing[0];
  header.Spacing[2] = grid.SliceSpacing;
  for (unsigned int c = 0; c < 3; ++c)
  {
    header.Origin[c] = grid.Origin[c];
    header.Direction[3 * c + 0] = series.Layout.Orientation[c];
    header.Direction[3 * c + 1] = series.Layout.Orientation[3 + c];
    header.Direction[3 * c + 2] = grid.Normal[c];
  }
  if (pixelType != itk::IOComponentEnum::FLOAT)
  {
    header.Slope = series.Layout.Slopes[instances.front()];
    header.Intercept = series.Layout.Intercepts[instances.front()];
  }
  handOver.Finish(header);
  Report("done " + std::to_string(grid.Slices.size()));
  return 0;
}
