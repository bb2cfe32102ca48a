// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The DICOM reader process's hand-over (issue 40, docs/dicom-series.md "Where it runs" and "Values"): the voxels come
// back in the series' stored type with its one rescale, in the memfd the child wrote them into, mapped as the image's
// buffer; float where the files' rescales differ. A hand-over cut short, or one the child never finished, is refused
// with a message and leaves nothing behind: no temporary folder, no open memfd, no mapping. The series are written
// byte by byte (vrDICOMTestSeries, no GDCM), so the expected values are the ones the files were made from.
#include "vrDICOMSeriesProcess.h"
#include "vrDICOMTestSeries.h"
#include "vrStoredVolume.h"
#include "vrTestFiles.h"
#include "vrTestProcess.h"
#include "vrVolumeIO.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace
{
namespace fs = std::filesystem;
using namespace vr::test;

constexpr const char * MemfdName = "memfd:vrReadDICOMSeries volume";

/** A 12 x 10 x 6 CT of whole HU in [-1000, 2000], LPS at (-40, 25, 100) mm, 0.75 x 0.75 x 2 mm. */
vr::VolumeImageType::Pointer
MakeCT()
{
  auto                            volume = vr::VolumeImageType::New();
  vr::VolumeImageType::RegionType region;
  region.SetSize({ { 12, 10, 6 } });
  volume->SetRegions(region);
  vr::VolumeImageType::SpacingType spacing;
  spacing[0] = 0.75;
  spacing[1] = 0.75;
  spacing[2] = 2.0;
  volume->SetSpacing(spacing);
  vr::VolumeImageType::PointType origin;
  origin[0] = -40.0;
  origin[1] = 25.0;
  origin[2] = 100.0;
  volume->SetOrigin(origin);
  volume->Allocate();
  for (unsigned int z = 0; z < 6; ++z)
  {
    for (unsigned int y = 0; y < 10; ++y)
    {
      for (unsigned int x = 0; x < 12; ++x)
      {
        volume->SetPixel(
          { { x, y, z } },
          static_cast<float>(-1000 + 13 * static_cast<int>(x) + 17 * static_cast<int>(y) + 500 * static_cast<int>(z)));
      }
    }
  }
  return volume;
}

/** The largest difference between the volume read (its rescale applied) and \a reference at each voxel; the
 * geometry must be the reference's. */
double
LargestDifference(const vr::StoredVolume & read, const vr::VolumeImageType * reference)
{
  const auto intensities = vr::ConvertStoredVolumeToFloat(read);
  EXPECT_EQ(intensities->GetLargestPossibleRegion(), reference->GetLargestPossibleRegion());
  for (unsigned int d = 0; d < 3; ++d)
  {
    EXPECT_NEAR(intensities->GetOrigin()[d], reference->GetOrigin()[d], 1e-9);
    EXPECT_NEAR(intensities->GetSpacing()[d], reference->GetSpacing()[d], 1e-9);
  }
  EXPECT_TRUE(intensities->GetDirection().GetVnlMatrix().is_identity(1e-12));
  if (intensities->GetLargestPossibleRegion() != reference->GetLargestPossibleRegion())
  {
    return INFINITY;
  }
  double            largest = 0.0;
  const std::size_t count = reference->GetLargestPossibleRegion().GetNumberOfPixels();
  for (std::size_t k = 0; k < count; ++k)
  {
    largest = std::max(
      largest, std::abs(static_cast<double>(intensities->GetBufferPointer()[k]) - reference->GetBufferPointer()[k]));
  }
  return largest;
}

/** Whether \a address lies in one of this process's mappings of the reader process's memfd of at least \a bytes. */
bool
InHandOverMapping(const void * address, std::size_t bytes)
{
  const auto at = reinterpret_cast<std::uintptr_t>(address);
  for (const ProcessMapping & mapping : MappingsNamed(MemfdName))
  {
    if (mapping.Start <= at && at + bytes <= mapping.End)
    {
      return true;
    }
  }
  return false;
}

/** Sets TMPDIR to a folder of the test's for its lifetime: where the reader's scratch folder is made. */
class ScopedTemporaryDirectory
{
public:
  explicit ScopedTemporaryDirectory(const fs::path & folder)
  {
    if (const char * old = std::getenv("TMPDIR"))
    {
      m_Old = old;
    }
    fs::create_directories(folder);
    ::setenv("TMPDIR", folder.c_str(), 1);
  }
  ~ScopedTemporaryDirectory()
  {
    if (m_Old.empty())
    {
      ::unsetenv("TMPDIR");
    }
    else
    {
      ::setenv("TMPDIR", m_Old.c_str(), 1);
    }
  }
  ScopedTemporaryDirectory(const ScopedTemporaryDirectory &) = delete;
  ScopedTemporaryDirectory &
  operator=(const ScopedTemporaryDirectory &) = delete;

private:
  std::string m_Old;
};
} // namespace

TEST(DICOMHandOver, ASeriesOfOneRescaleStaysInItsStoredTypeInTheMappingTheReaderWrote)
{
  const ScopedTemporaryFolder folder;
  const auto                  ct = MakeCT();
  struct Case
  {
    std::string          Name;
    CTSeriesOptions      Options;
    itk::IOComponentEnum PixelType;
    double               Slope;
    double               Intercept;
  };
  std::vector<Case> cases(4);
  // MakeCTSeries: unsigned, 12 bits stored, intercept -1024 (a scanner's usual CT).
  cases[0] = { "unsigned", {}, itk::IOComponentEnum::USHORT, 1.0, -1024.0 };
  cases[1] = { "signed", {}, itk::IOComponentEnum::SHORT, 1.0, 0.0 };
  cases[1].Options.Signed = true;
  // One rescale that is not the identity's slope: the stored values are twice the HU plus 6.
  cases[2] = { "signed-slope-0.5", {}, itk::IOComponentEnum::SHORT, 0.5, -3.0 };
  cases[2].Options.Signed = true;
  cases[2].Options.Rescale = [](unsigned int) { return std::pair<double, double>(0.5, -3.0); };
  // Each file its own rescale: one stored type cannot hold them with one rescale, so float intensities.
  cases[3] = { "rescale-per-file", {}, itk::IOComponentEnum::FLOAT, 1.0, 0.0 };
  cases[3].Options.Rescale = [](unsigned int slice)
  { return std::pair<double, double>(slice % 2 == 0 ? 1.0 : 0.5, -1024.0 - slice); };
  for (const Case & c : cases)
  {
    SCOPED_TRACE(c.Name);
    const std::string series = folder.File(c.Name);
    WriteDICOMTestFolder(series, MakeCTSeries(ct, c.Options));
    const vr::StoredVolume read = vr::ReadStoredVolume(series);
    ASSERT_TRUE(read.Image);
    EXPECT_EQ(read.GetPixelType(), c.PixelType);
    EXPECT_EQ(read.Rescale.Slope, c.Slope);
    EXPECT_EQ(read.Rescale.Intercept, c.Intercept);
    // Whole or half HU, rescaled exactly in double and held exactly in float: no tolerance.
    EXPECT_EQ(LargestDifference(read, ct), 0.0);
    // The buffer is the memfd the reader process wrote the voxels into, mapped here: no copy was made.
    EXPECT_TRUE(InHandOverMapping(read.GetBufferPointer(), read.GetVoxelBytes()));
    EXPECT_EQ(read.GetVoxelBytes(), 12u * 10u * 6u * vr::StoredPixelBytes(c.PixelType));
  }
  // Unmapped with the last image that reads it: none of them is left.
  EXPECT_TRUE(MappingsNamed(MemfdName).empty());
  EXPECT_TRUE(OpenFilesNamed(MemfdName).empty());
}

TEST(DICOMHandOver, AHandOverCutShortOrUnfinishedIsRefusedAndNothingIsLeftBehind)
{
  const ScopedTemporaryFolder folder;
  const std::string           series = folder.File("series");
  WriteDICOMTestFolder(series, MakeCTSeries(MakeCT()));
  const std::string reader = vr::detail::DICOMSeriesReaderPath();
  ASSERT_FALSE(reader.empty());
  struct StandIn
  {
    std::string Name;
    std::string Script; // after "#!/bin/sh\n"; $REAL is the real reader, fd 3 the hand-over file
    std::string Message;
  };
  const std::vector<StandIn> standIns{
    // The real reader, then the hand-over cut 100 bytes short (a process that stopped in its last slice).
    { "cut-short",
      "\"$REAL\" \"$@\" || exit $?\nsize=$(stat -L -c %s /proc/self/fd/3)\ntruncate -s $((size - 100)) "
      "/proc/self/fd/3\n",
      "the DICOM reader process handed over 1340 bytes of voxels where the volume (12 x 10 x 6) has 1440 (cut short)" },
    // The real reader, then the file emptied: a child that never reached its volume.
    { "empty",
      "\"$REAL\" \"$@\" || exit $?\ntruncate -s 0 /proc/self/fd/3\n",
      "the DICOM reader process handed over no volume (0 bytes, not even its header" },
    // A file of the right size whose header was never finished (the child stopped before its last write).
    { "unfinished",
      "truncate -s 5536 /proc/self/fd/3\n",
      "the DICOM reader process handed over a volume it did not finish" },
    // The real reader, then an abort: its exit status says it died, whatever the file holds.
    { "aborted",
      "\"$REAL\" \"$@\" || exit $?\nulimit -c 0\nkill -ABRT $$\n",
      "the DICOM reader process died handing the series it read over (SIGABRT, an assertion or abort)" },
  };
  for (const StandIn & standIn : standIns)
  {
    SCOPED_TRACE(standIn.Name);
    const std::string script = folder.File(standIn.Name + ".sh");
    WriteTextFile(script, "#!/bin/sh\nREAL='" + reader + "'\n" + standIn.Script);
    fs::permissions(script, fs::perms::owner_all);
    const fs::path scratch = folder.Path() / ("tmp-" + standIn.Name);
    std::string    message;
    {
      const ScopedTemporaryDirectory temporary(scratch);
      ::setenv("VR_DICOM_SERIES_READER", script.c_str(), 1);
      message = InputErrorOf([&] { vr::ReadStoredVolume(series); });
      ::unsetenv("VR_DICOM_SERIES_READER");
    }
    EXPECT_TRUE(Contains(message, "volume folder " + series + ": ")) << message;
    EXPECT_TRUE(Contains(message, standIn.Message)) << message;
    EXPECT_TRUE(Contains(message, "the series is not read")) << message;
    // Nothing left: the scratch folder (report, messages) removed, the memfd closed and never mapped.
    EXPECT_EQ(FolderEntries(scratch), std::set<std::string>());
    EXPECT_TRUE(MappingsNamed(MemfdName).empty());
    EXPECT_TRUE(OpenFilesNamed(MemfdName).empty());
  }
  // The real reader reads the series.
  EXPECT_EQ(vr::ReadStoredVolume(series).GetPixelType(), itk::IOComponentEnum::USHORT);
}
