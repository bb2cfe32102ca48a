// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// VesselReformation --rotationSeries / --rotationAngles (issue 24) as a shell runs it: the run-off phantom written
// to NRRD, the series read back with ITK's PNG and GDCM IO, bad values refused naming the flag with nothing written.

#include "itkCTAPhantom.h"
#include "vrCenterlineIO.h"
#include "vrBurnedInLabels.h"
#include "vrImageIO.h"
#include "vrModuleRuns.h"
#include "vrTestFiles.h"
#include "vrVolumeIO.h"

#include "itkGDCMImageIO.h"
#include "itkGDCMSeriesFileNames.h"
#include "itkImageFileReader.h"
#include "itkMetaDataObject.h"
#include "itkPNGImageIO.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

namespace
{
/** An LPS direction. */
itk::Vector<double, 3>
Lps(double x, double y, double z)
{
  itk::Vector<double, 3> v;
  v[0] = x;
  v[1] = y;
  v[2] = z;
  return v;
}

namespace fs = std::filesystem;
using vr::test::Contains;
using vr::test::FolderEntries;
using vr::test::RunProgram;

const std::string ReformationExecutable = VR_REFORMATION_EXE;

using GreyImage = itk::Image<unsigned char, 2>;

GreyImage::Pointer
ReadGrey(const std::string & path, itk::ImageIOBase * io, itk::MetaDataDictionary * dictionary = nullptr)
{
  auto reader = itk::ImageFileReader<GreyImage>::New();
  reader->SetImageIO(io);
  reader->SetFileName(path);
  reader->Update();
  if (dictionary != nullptr)
  {
    *dictionary = io->GetMetaDataDictionary();
  }
  return reader->GetOutput();
}

std::string
Tag(const itk::MetaDataDictionary & dictionary, const std::string & tag)
{
  std::string value;
  itk::ExposeMetaData<std::string>(dictionary, tag, value);
  while (!value.empty() && (value.back() == ' ' || value.back() == '\0'))
  {
    value.pop_back();
  }
  return value;
}

class RotationSeriesCLI : public ::testing::Test
{
protected:
  void
  SetUp() override
  {
    m_Folder = vr::test::FreshFolderForThisTest(VR_TEST_OUTPUT_DIR, "RotationSeriesCLI-");
    itk::CTAPhantom phantom = itk::MakeCTAPhantom(itk::CTAPhantomKind::Runoff, 4.0);
    phantom.Source->Update();
    vr::WriteVolume(phantom.Source->GetOutput(), (m_Folder / "runoff.nrrd").string());
    vr::WriteCenterlines(phantom.Tree, (m_Folder / "runoff.vtp").string());
    vr::test::WriteTextFile((m_Folder / "cpr.nrrd").string(), "an earlier result that must survive");
  }

  vr::test::ModuleRun
  Run(const std::vector<std::string> & flags) const
  {
    std::vector<std::string> arguments{ ReformationExecutable, "--spacing", "4,4", "--iterations", "40" };
    arguments.insert(arguments.end(), flags.begin(), flags.end());
    arguments.insert(
      arguments.end(),
      { (m_Folder / "runoff.nrrd").string(), (m_Folder / "runoff.vtp").string(), (m_Folder / "cpr.nrrd").string() });
    return RunProgram(arguments, 120.0);
  }

  /** Runs with \a flags, expects exit 1 naming \a flag, and nothing written. */
  void
  ExpectRejected(const std::vector<std::string> & flags, const std::string & flag)
  {
    const auto before = FolderEntries(m_Folder);
    const auto result = Run(flags);
    EXPECT_FALSE(result.Crashed);
    EXPECT_EQ(result.ExitCode, 1) << result.Err;
    EXPECT_TRUE(Contains(result.Err, "VesselReformation: error: " + flag)) << result.Err;
    EXPECT_EQ(FolderEntries(m_Folder), before) << "a file or folder appeared or vanished";
    EXPECT_EQ(vr::test::ReadTextFile((m_Folder / "cpr.nrrd").string()), "an earlier result that must survive");
  }

  fs::path m_Folder;
};

TEST_F(RotationSeriesCLI, WritesPNGsAndADICOMSeriesBesideTheRunsOutputs)
{
  const fs::path series = m_Folder / "series";
  const auto     result =
    Run({ "--rotationSeries", series.string(), "--rotationAngles", "0,120,3", "--rotationSeriesSize", "0" });
  ASSERT_EQ(result.ExitCode, 0) << result.Err;
  EXPECT_TRUE(Contains(result.Out,
                       "rotation series of 3 views (\"mpCPR rotation 0..240 deg step 120, bilateral J 3 mm\", "
                       "window 900, level 200)"))
    << result.Out;
  EXPECT_TRUE(Contains(result.Out, "patient and study made up (the input was not DICOM)")) << result.Out;
  EXPECT_EQ(FolderEntries(series),
            (std::set<std::string>{ "rotation-000.png",
                                    "rotation-001.png",
                                    "rotation-002.png",
                                    "rotation-000.dcm",
                                    "rotation-001.dcm",
                                    "rotation-002.dcm",
                                    "rotation-angles.csv" }));

  // View 0 is at the run's own angle (0): at --rotationSeriesSize 0 its pixels are the run's CPR through the CTA window
  // (W 900, L 200; the phantom is a CT), computed here, with the labels of the view at 0 degrees burned in: u = L,
  // up = S (docs/design.md, "View").
  const auto cpr = vr::ReadDepthImage((m_Folder / "cpr.nrrd").string());
  const auto png = ReadGrey((series / "rotation-000.png").string(), itk::PNGImageIO::New());
  ASSERT_EQ(png->GetLargestPossibleRegion().GetSize(), cpr->GetLargestPossibleRegion().GetSize());
  auto expected = vr::MaskImageType::New();
  expected->SetRegions(cpr->GetLargestPossibleRegion());
  expected->Allocate();
  for (std::size_t p = 0; p < cpr->GetLargestPossibleRegion().GetNumberOfPixels(); ++p)
  {
    const double value = cpr->GetBufferPointer()[p];
    const double grey =
      std::isnan(value) ? 0.0 : std::min(255.0, std::max(0.0, std::floor(255.0 * (value + 250.0) / 900.0 + 0.5)));
    expected->GetBufferPointer()[p] = static_cast<unsigned char>(grey);
  }
  vr::BurnInViewLabels(expected, Lps(1.0, 0.0, 0.0), Lps(0.0, 0.0, 1.0), 0.0);
  std::size_t mismatches = 0;
  for (std::size_t p = 0; p < cpr->GetLargestPossibleRegion().GetNumberOfPixels(); ++p)
  {
    mismatches += png->GetBufferPointer()[p] != expected->GetBufferPointer()[p];
  }
  EXPECT_EQ(mismatches, 0u);

  auto names = itk::GDCMSeriesFileNames::New();
  names->SetDirectory(series.string());
  ASSERT_EQ(names->GetSeriesUIDs().size(), 1u);
  const auto files = names->GetFileNames(names->GetSeriesUIDs().front());
  ASSERT_EQ(files.size(), 3u);
  std::set<std::string> instances;
  for (int k = 0; k < 3; ++k)
  {
    itk::MetaDataDictionary dictionary;
    const auto              dicom =
      ReadGrey((series / ("rotation-00" + std::to_string(k) + ".dcm")).string(), itk::GDCMImageIO::New(), &dictionary);
    EXPECT_EQ(Tag(dictionary, "0020|0013"), std::to_string(k + 1));
    EXPECT_EQ(Tag(dictionary, "0008|0016"), "1.2.840.10008.5.1.4.1.1.7");
    EXPECT_EQ(Tag(dictionary, "0010|0010"), "VesselReformation^Unknown");
    EXPECT_FALSE(dictionary.HasKey("0020|0032"));
    EXPECT_FALSE(dictionary.HasKey("0020|0037"));
    instances.insert(Tag(dictionary, "0008|0018"));
    if (k == 0)
    {
      EXPECT_TRUE(std::equal(png->GetBufferPointer(),
                             png->GetBufferPointer() + png->GetLargestPossibleRegion().GetNumberOfPixels(),
                             dicom->GetBufferPointer()))
        << "the DICOM picture is the PNG's";
    }
  }
  EXPECT_EQ(instances.size(), 3u);
}

TEST_F(RotationSeriesCLI, BadValuesExit1NamingTheFlagAndWriteNothing)
{
  const std::string series = (m_Folder / "series").string();
  for (const char * angles : { "0,10,0", "0,10,3601", "0,0,5", "nan,10,3", "0,10", "0,10,2.5", "x,10,3" })
  {
    SCOPED_TRACE(angles);
    ExpectRejected({ "--rotationSeries", series, "--rotationAngles", angles }, "--rotationAngles");
  }
  // A display size beyond a PACS's pictures (the XML's constraint is a hint; the module checks it).
  ExpectRejected({ "--rotationSeries", series, "--rotationSeriesSize", "9000" }, "--rotationSeriesSize");
  ExpectRejected({ "--rotationSeries", series, "--rotationSeriesSize", "-1" }, "--rotationSeriesSize");
  // Without a folder the angles are still checked; good ones only warn, as 3D Slicer passes the default every time.
  ExpectRejected({ "--rotationAngles", "0,10,0" }, "--rotationAngles");
  const auto withoutFolder = Run({ "--rotationAngles", "0,10,3" });
  EXPECT_EQ(withoutFolder.ExitCode, 0) << withoutFolder.Err;
  EXPECT_TRUE(Contains(withoutFolder.Err, "warning: --rotationAngles has no effect without --rotationSeries"))
    << withoutFolder.Err;
  const auto slicerDefault = Run({ "--rotationAngles", "0,10,36" });
  EXPECT_EQ(slicerDefault.ExitCode, 0) << slicerDefault.Err;
  EXPECT_FALSE(Contains(slicerDefault.Err, "rotationAngles")) << slicerDefault.Err;
  vr::test::WriteTextFile((m_Folder / "cpr.nrrd").string(), "an earlier result that must survive");
  ExpectRejected({ "--rotationSeries", (m_Folder / "no-such-parent" / "series").string() }, "--rotationSeries");

  // A folder that holds a series already: refused, its files kept.
  fs::create_directories(m_Folder / "old");
  vr::test::WriteTextFile((m_Folder / "old" / "rotation-000.dcm").string(), "an earlier series");
  ExpectRejected({ "--rotationSeries", (m_Folder / "old").string() }, "--rotationSeries");
  EXPECT_EQ(vr::test::ReadTextFile((m_Folder / "old" / "rotation-000.dcm").string()), "an earlier series");

  // A failure after the folder was made (the centerlines do not exist): the folder goes again.
  const auto before = FolderEntries(m_Folder);
  const auto result = RunProgram({ ReformationExecutable,
                                   "--rotationSeries",
                                   series,
                                   (m_Folder / "runoff.nrrd").string(),
                                   (m_Folder / "missing.vtp").string(),
                                   (m_Folder / "cpr.nrrd").string() });
  EXPECT_EQ(result.ExitCode, 1) << result.Err;
  EXPECT_EQ(FolderEntries(m_Folder), before);
}
} // namespace
