// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The rotation series (issue 24): the run-off phantom written to NRRD and read back, reformed at N angles, written as
// PNGs and a DICOM Secondary Capture series; the files are read back with ITK (PNG, GDCM) and compared with the
// logic's CPR at each angle through a window/level computed here.

#include "itkCTAPhantom.h"
#include "vrCenterlineIO.h"
#include "vrBurnedInLabels.h"
#include "vrInputError.h"
#include "vrIntensityWindow.h"
#include "vrNodeConversion.h"
#include "vrRotationSeries.h"
#include "vrSecondaryCaptureIO.h"
#include "vrTestFiles.h"
#include "vrVesselReformationLogic.h"
#include "vrVolumeIO.h"

#include "itkGDCMImageIO.h"
#include "itkGDCMSeriesFileNames.h"
#include "itkCastImageFilter.h"
#include "itkImageFileReader.h"
#include "itkImageSeriesWriter.h"
#include "itkMetaDataObject.h"
#include "itkPNGImageIO.h"

#include <gtest/gtest.h>

#include <sys/mount.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <set>
#include <sstream>
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

fs::path
TestFolder()
{
  return vr::test::FreshFolderForThisTest(fs::path(VR_TEST_OUTPUT_DIR) / "RotationSeries", "");
}

std::string
ReadText(const fs::path & path)
{
  std::ifstream      file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

/** DICOM pads odd-length values with a space (or a NUL for UIDs). */
std::string
Trimmed(std::string value)
{
  while (!value.empty() && (value.back() == ' ' || value.back() == '\0'))
  {
    value.pop_back();
  }
  return value;
}

struct DICOMFile
{
  itk::Image<unsigned char, 2>::Pointer Image;
  itk::MetaDataDictionary               Dictionary;

  bool
  Has(const std::string & tag) const
  {
    return Dictionary.HasKey(tag);
  }
  std::string
  Get(const std::string & tag) const
  {
    std::string value;
    itk::ExposeMetaData<std::string>(Dictionary, tag, value);
    return Trimmed(value);
  }
};

DICOMFile
ReadDICOM(const std::string & path)
{
  auto io = itk::GDCMImageIO::New();
  auto reader = itk::ImageFileReader<itk::Image<unsigned char, 2>>::New();
  reader->SetImageIO(io);
  reader->SetFileName(path);
  reader->Update();
  return { reader->GetOutput(), io->GetMetaDataDictionary() };
}

itk::Image<unsigned char, 2>::Pointer
ReadPNG(const std::string & path)
{
  auto reader = itk::ImageFileReader<itk::Image<unsigned char, 2>>::New();
  reader->SetImageIO(itk::PNGImageIO::New());
  reader->SetFileName(path);
  reader->Update();
  return reader->GetOutput();
}

/** Grey value of \a value through window/level, computed here: level - window/2 -> 0, + window/2 -> 255. */
unsigned int
Grey(float value, double window, double level)
{
  if (std::isnan(value))
  {
    return 0;
  }
  const double scaled = std::floor(255.0 * (value - level + window / 2.0) / window + 0.5);
  return static_cast<unsigned int>(std::min(255.0, std::max(0.0, scaled)));
}

/** The run-off phantom at 4 mm, written to NRRD and .vtp in \a folder and read back as a platform would. */
class RotationSeriesTest : public ::testing::Test
{
protected:
  void
  SetUp() override
  {
    m_Folder = TestFolder();
    itk::CTAPhantom phantom = itk::MakeCTAPhantom(itk::CTAPhantomKind::Runoff, 4.0);
    phantom.Source->Update();
    vr::WriteVolume(phantom.Source->GetOutput(), (m_Folder / "runoff.nrrd").string());
    vr::WriteCenterlines(phantom.Tree, (m_Folder / "runoff.vtp").string());
  }

  /** A logic on the NRRD and .vtp files, at a coarse view so that each angle takes little time. */
  void
  Configure(vr::VesselReformationLogic & logic, vr::VolumeNode ** volumeNode = nullptr)
  {
    auto volume = vr::ConvertItkImageToVolumeNode(vr::ReadVolume((m_Folder / "runoff.nrrd").string()), "runoff.nrrd");
    logic.SetVolumeNode(volume);
    logic.SetCenterlineNode(
      vr::ConvertTreeToCenterlineNode(vr::ReadCenterlines((m_Folder / "runoff.vtp").string()), "runoff.vtp"));
    vr::ReformationParameters parameters;
    parameters.PixelSpacing.Fill(4.0);
    parameters.Iterations = 40;
    logic.SetParameters(parameters);
    if (volumeNode != nullptr)
    {
      *volumeNode = volume;
    }
  }

  fs::path m_Folder;
};

TEST_F(RotationSeriesTest, FromNRRDWritesPNGsAndASecondaryCaptureSeriesWithAMadeUpIdentity)
{
  vr::VesselReformationLogic logic;
  Configure(logic);
  vr::RotationSeriesSettings settings;
  settings.Folder = (m_Folder / "series").string(); // missing: created
  settings.Angles = { 15.0, 90.0, 4 };
  // The CPR's own pixels (the display size and the labels: PicturesAtTheDisplaySizeWithTheirLabelsBurnedIn).
  settings.DisplayLongSide = 0;
  settings.BurnInLabels = false;
  std::vector<std::size_t>       viewsReported;
  const vr::RotationSeriesResult result =
    vr::ExportRotationSeries(logic,
                             settings,
                             [&](std::size_t view, std::size_t count, double)
                             {
                               EXPECT_EQ(count, 4u);
                               if (viewsReported.empty() || viewsReported.back() != view)
                               {
                                 viewsReported.push_back(view);
                               }
                               return true;
                             });
  EXPECT_EQ(viewsReported, (std::vector<std::size_t>{ 0, 1, 2, 3, 4 })) << "each view, then the end";
  EXPECT_EQ(logic.GetParameters().AngleInDegrees, 0.0) << "the logic's angle is restored";
  // The phantom is a CT (air at -1000 HU): the CTA window.
  EXPECT_EQ(result.Window, 900.0);
  EXPECT_EQ(result.Level, 200.0);
  EXPECT_TRUE(result.IdentityMadeUp);
  EXPECT_EQ(result.SeriesDescription, "mpCPR rotation 15..285 deg step 90, bilateral J 3 mm");

  std::set<std::string> names;
  for (const auto & entry : fs::directory_iterator(m_Folder / "series"))
  {
    names.insert(entry.path().filename().string());
  }
  EXPECT_EQ(names,
            (std::set<std::string>{ "rotation-000.png",
                                    "rotation-001.png",
                                    "rotation-002.png",
                                    "rotation-003.png",
                                    "rotation-000.dcm",
                                    "rotation-001.dcm",
                                    "rotation-002.dcm",
                                    "rotation-003.dcm",
                                    "rotation-angles.csv" }))
    << "nothing else: no staging folder left";
  EXPECT_EQ(
    ReadText(m_Folder / "series" / "rotation-angles.csv"),
    "view,angle_deg,png,dicom\n0,15,rotation-000.png,rotation-000.dcm\n1,105,rotation-001.png,rotation-001.dcm\n"
    "2,195,rotation-002.png,rotation-002.dcm\n3,285,rotation-003.png,rotation-003.dcm\n");

  // An independent logic at each angle, through the window computed here.
  vr::VesselReformationLogic reference;
  Configure(reference);
  std::set<std::string> sopInstances;
  std::string           seriesUID;
  std::string           studyUID;
  for (std::size_t k = 0; k < 4; ++k)
  {
    SCOPED_TRACE("view " + std::to_string(k));
    vr::ReformationParameters parameters = reference.GetParameters();
    parameters.AngleInDegrees = 15.0 + 90.0 * static_cast<double>(k);
    reference.SetParameters(parameters);
    const auto cpr = vr::ConvertVolumeNodeToDepthImage(reference.Update().CPR);
    const auto png = ReadPNG(result.PNGFiles[k]);
    const auto dicom = ReadDICOM(result.DICOMFiles[k]);
    ASSERT_EQ(png->GetLargestPossibleRegion().GetSize(), cpr->GetLargestPossibleRegion().GetSize());
    ASSERT_EQ(dicom.Image->GetLargestPossibleRegion().GetSize(), cpr->GetLargestPossibleRegion().GetSize());
    const std::size_t      count = cpr->GetLargestPossibleRegion().GetNumberOfPixels();
    std::size_t            pngMismatches = 0;
    std::size_t            dicomMismatches = 0;
    std::set<unsigned int> greys;
    for (std::size_t p = 0; p < count; ++p)
    {
      const unsigned int expected = Grey(cpr->GetBufferPointer()[p], 900.0, 200.0);
      greys.insert(expected);
      pngMismatches += png->GetBufferPointer()[p] != expected;
      dicomMismatches += dicom.Image->GetBufferPointer()[p] != expected;
    }
    EXPECT_EQ(pngMismatches, 0u);
    EXPECT_EQ(dicomMismatches, 0u);
    EXPECT_GT(greys.size(), 20u) << "a picture, not a flat image";

    EXPECT_EQ(dicom.Get("0008|0016"), vr::SecondaryCaptureSOPClassUID);
    EXPECT_EQ(dicom.Get("0008|0060"), "OT");
    EXPECT_EQ(dicom.Get("0008|0064"), "WSD");
    EXPECT_EQ(dicom.Get("0028|0004"), "MONOCHROME2");
    EXPECT_EQ(dicom.Get("0028|0100"), "8");
    EXPECT_EQ(dicom.Get("0020|0013"), std::to_string(k + 1)) << "Instance Number in angle order";
    EXPECT_NE(dicom.Get("0020|4000").find("at angle " + std::to_string(15 + 90 * k) + " deg"), std::string::npos)
      << dicom.Get("0020|4000");
    EXPECT_EQ(dicom.Get("0008|103e"), result.SeriesDescription);
    EXPECT_EQ(dicom.Get("0010|0010"), vr::MadeUpPatientName);
    EXPECT_EQ(dicom.Get("0010|0020"), result.PatientID);
    EXPECT_EQ(result.PatientID.rfind("VR-", 0), 0u);
    EXPECT_NE(dicom.Get("0010|4000").find("was not DICOM"), std::string::npos) << dicom.Get("0010|4000");
    EXPECT_NE(dicom.Get("0008|1030").find("made up"), std::string::npos) << dicom.Get("0008|1030");
    // A picture, not a slice: no Image Position or Orientation (Patient), nor a Frame of Reference.
    EXPECT_FALSE(dicom.Has("0020|0032"));
    EXPECT_FALSE(dicom.Has("0020|0037"));
    EXPECT_FALSE(dicom.Has("0020|0052"));
    sopInstances.insert(dicom.Get("0008|0018"));
    // One root for every UID made here (ITK's writer would otherwise switch the generator to its own).
    EXPECT_EQ(dicom.Get("0008|0018").rfind("1.2.826.0.1.3680043.2.1143.", 0), 0u) << dicom.Get("0008|0018");
    EXPECT_EQ(dicom.Get("0020|000e").rfind("1.2.826.0.1.3680043.2.1143.", 0), 0u) << dicom.Get("0020|000e");
    if (k == 0)
    {
      seriesUID = dicom.Get("0020|000e");
      studyUID = dicom.Get("0020|000d");
    }
    EXPECT_EQ(dicom.Get("0020|000e"), seriesUID);
    EXPECT_EQ(dicom.Get("0020|000d"), studyUID);
  }
  EXPECT_EQ(sopInstances.size(), 4u) << "a new SOP Instance UID per file";
  EXPECT_EQ(seriesUID, result.SeriesInstanceUID);
  EXPECT_EQ(studyUID, result.StudyInstanceUID);
  EXPECT_NE(seriesUID, studyUID);
  EXPECT_EQ(sopInstances.count(seriesUID), 0u);

  // GDCM's series reader sees one series of four files, which it orders by Instance Number as a PACS would.
  auto series = itk::GDCMSeriesFileNames::New();
  series->SetDirectory((m_Folder / "series").string());
  const auto uids = series->GetSeriesUIDs();
  ASSERT_EQ(uids.size(), 1u);
  const auto files = series->GetFileNames(uids.front());
  ASSERT_EQ(files.size(), 4u);

  // A second series gets a new series UID and, the input still not being DICOM, a new made-up patient.
  vr::RotationSeriesSettings again = settings;
  again.Folder = (m_Folder / "again").string();
  again.Angles = { 0.0, 10.0, 1 };
  const vr::RotationSeriesResult second = vr::ExportRotationSeries(logic, again);
  EXPECT_NE(second.SeriesInstanceUID, result.SeriesInstanceUID);
  EXPECT_NE(second.StudyInstanceUID, result.StudyInstanceUID);
  EXPECT_EQ(second.SeriesDescription, "mpCPR rotation 0..0 deg step 10, bilateral J 3 mm");
}

/** The grey of the CPR \a cpr enlarged to \a width x \a height pixels at pixel (i, j), computed here: bilinear in the
 * CPR's pixels at the centre of the output pixel (the same extent), clamped to the edge pixels, through the window. */
unsigned int
ScaledGrey(const vr::DepthImageType * cpr, long width, long height, long i, long j, double window, double level)
{
  const auto   size = cpr->GetLargestPossibleRegion().GetSize();
  const double x = std::clamp((i + 0.5) * size[0] / width - 0.5, 0.0, size[0] - 1.0);
  const double y = std::clamp((j + 0.5) * size[1] / height - 0.5, 0.0, size[1] - 1.0);
  const long   x0 = std::min(static_cast<long>(x), static_cast<long>(size[0]) - 2);
  const long   y0 = std::min(static_cast<long>(y), static_cast<long>(size[1]) - 2);
  const double fx = x - x0;
  const double fy = y - y0;
  const auto   at = [&](long a, long b) { return cpr->GetPixel({ { a, b } }); };
  const double value = (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x0 + 1, y0)) +
                       fy * ((1 - fx) * at(x0, y0 + 1) + fx * at(x0 + 1, y0 + 1));
  return Grey(static_cast<float>(value), window, level);
}

TEST_F(RotationSeriesTest, PicturesAtTheDisplaySizeWithTheirLabelsBurnedIn)
{
  vr::VesselReformationLogic logic;
  Configure(logic);
  vr::RotationSeriesSettings settings;
  settings.Folder = (m_Folder / "display").string();
  settings.Angles = { 0.0, 90.0, 2 };
  settings.Window = 900.0;
  settings.Level = 200.0;
  const vr::RotationSeriesResult result = vr::ExportRotationSeries(logic, settings);
  // The same series without labels: what lies under them.
  settings.Folder = (m_Folder / "plain").string();
  settings.BurnInLabels = false;
  const vr::RotationSeriesResult plain = vr::ExportRotationSeries(logic, settings);

  vr::VesselReformationLogic reference;
  Configure(reference);
  for (std::size_t k = 0; k < 2; ++k)
  {
    SCOPED_TRACE("view " + std::to_string(k));
    vr::ReformationParameters parameters = reference.GetParameters();
    parameters.AngleInDegrees = 90.0 * static_cast<double>(k);
    reference.SetParameters(parameters);
    const auto   cpr = vr::ConvertVolumeNodeToDepthImage(reference.Update().CPR);
    const auto   cprSize = cpr->GetLargestPossibleRegion().GetSize();
    const auto   png = ReadPNG(result.PNGFiles[k]);
    const auto   bare = ReadPNG(plain.PNGFiles[k]);
    const auto   dicom = ReadDICOM(result.DICOMFiles[k]);
    const auto   size = png->GetLargestPossibleRegion().GetSize();
    const double longest = static_cast<double>(std::max(cprSize[0], cprSize[1]));
    ASSERT_LT(longest, 512.0) << "the phantom's CPR is small: it is enlarged";
    // The long side 512 pixels, the aspect kept; the DICOM's Rows and Columns are the PNG's, its pixels too.
    EXPECT_EQ(std::max(size[0], size[1]), 512u);
    EXPECT_EQ(size[0], static_cast<unsigned long>(std::lround(cprSize[0] * 512.0 / longest)));
    EXPECT_EQ(size[1], static_cast<unsigned long>(std::lround(cprSize[1] * 512.0 / longest)));
    EXPECT_EQ(dicom.Image->GetLargestPossibleRegion().GetSize(), size);
    EXPECT_EQ(dicom.Get("0028|0010"), std::to_string(size[1])) << "Rows";
    EXPECT_EQ(dicom.Get("0028|0011"), std::to_string(size[0])) << "Columns";
    EXPECT_TRUE(std::equal(png->GetBufferPointer(),
                           png->GetBufferPointer() + png->GetLargestPossibleRegion().GetNumberOfPixels(),
                           dicom.Image->GetBufferPointer()));
    // The pixel spacing scaled with the size: the same millimetres.
    EXPECT_NEAR(dicom.Image->GetSpacing()[0] * size[0], cpr->GetSpacing()[0] * cprSize[0], 1e-3);
    // Without labels: the CPR enlarged by bilinear interpolation, within a grey level (rounding of the weights).
    std::size_t farOff = 0;
    for (long j = 0; j < static_cast<long>(size[1]); ++j)
    {
      for (long i = 0; i < static_cast<long>(size[0]); ++i)
      {
        const int expected = static_cast<int>(ScaledGrey(cpr, size[0], size[1], i, j, 900.0, 200.0));
        farOff += std::abs(static_cast<int>(bare->GetPixel({ { i, j } })) - expected) > 1;
      }
    }
    EXPECT_EQ(farOff, 0u);
    // With labels: the labelled picture is the bare one with the labels burned in by vr::BurnInViewLabels, at the
    // view's axes (docs/design.md, "View"): up = S; at 0 degrees v = P and u = v x up = L; at 90 degrees v
    // is turned about up to R, and u = P.
    auto labelled = vr::MaskImageType::New();
    labelled->SetRegions(bare->GetLargestPossibleRegion());
    labelled->Allocate();
    std::copy(bare->GetBufferPointer(),
              bare->GetBufferPointer() + bare->GetLargestPossibleRegion().GetNumberOfPixels(),
              labelled->GetBufferPointer());
    itk::Vector<double, 3> u;
    u.Fill(0.0);
    u[k == 0 ? 0 : 1] = 1.0;
    itk::Vector<double, 3> up;
    up.Fill(0.0);
    up[2] = 1.0;
    vr::BurnInViewLabels(labelled, u, up, 90.0 * static_cast<double>(k));
    EXPECT_TRUE(std::equal(png->GetBufferPointer(),
                           png->GetBufferPointer() + png->GetLargestPossibleRegion().GetNumberOfPixels(),
                           labelled->GetBufferPointer()))
      << "the labels at the view's axes";
    std::size_t changed = 0;
    for (std::size_t p = 0; p < png->GetLargestPossibleRegion().GetNumberOfPixels(); ++p)
    {
      changed += png->GetBufferPointer()[p] != bare->GetBufferPointer()[p];
    }
    EXPECT_GT(changed, 200u) << "labels are burned in";
    EXPECT_LT(changed, size[0] * size[1] / 10) << "and cover little of the picture";
  }
  // The letters of each edge, and the angle's text.
  EXPECT_EQ(vr::OrientationLetters(Lps(1.0, 0.0, 0.0)), "L");
  EXPECT_EQ(vr::OrientationLetters(Lps(-1.0, 0.0, 0.0)), "R");
  EXPECT_EQ(vr::OrientationLetters(Lps(0.0, -1.0, 0.0)), "A");
  EXPECT_EQ(vr::OrientationLetters(Lps(0.0, 0.0, -1.0)), "I");
  EXPECT_EQ(vr::OrientationLetters(Lps(0.7071, -0.7071, 0.0)), "LA");
  EXPECT_EQ(vr::OrientationLetters(Lps(0.2, 0.95, 0.0)), "P");
  EXPECT_EQ(vr::OrientationLetters(Lps(0.5, 0.0, -0.8)), "IL");
  // Refused sizes name the flag; 0 keeps the CPR's own size.
  settings.DisplayLongSide = vr::RotationSeriesSettings::MaximumDisplayLongSide + 1;
  settings.Folder = (m_Folder / "huge").string();
  EXPECT_THROW(vr::RotationSeriesExport(settings, "--rotationSeriesSize"), vr::InputError);
}

TEST(RotationSeriesOfThePhantom, TheThoraxAtItsRealSizeReadsOnAReadingRoomScreen)
{
  // The thoracic phantom as the viewer opens it (1.5 mm voxels), its default view (169 x 264 pixels): every picture
  // 512 pixels high, the DICOM the PNG's size, the labels burned in. The pictures stay in the test's output folder
  // (RotationSeries/<this test>/series) for a person to look at.
  const fs::path  folder = TestFolder();
  itk::CTAPhantom phantom = itk::MakeCTAPhantom(itk::CTAPhantomKind::Thorax, 1.5);
  phantom.Source->Update();
  vr::VesselReformationLogic logic;
  logic.SetVolumeNode(vr::ConvertItkImageToVolumeNode(phantom.Source->GetOutput(), "thorax phantom"));
  logic.SetCenterlineNode(vr::ConvertTreeToCenterlineNode(phantom.Tree, "thorax phantom"));
  vr::RotationSeriesSettings settings;
  settings.Folder = (folder / "series").string();
  settings.Angles = { 0.0, 90.0, 4 };
  const vr::RotationSeriesResult result = vr::ExportRotationSeries(logic, settings);
  ASSERT_EQ(result.PNGFiles.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k)
  {
    const auto png = ReadPNG(result.PNGFiles[k]);
    const auto dicom = ReadDICOM(result.DICOMFiles[k]);
    const auto size = png->GetLargestPossibleRegion().GetSize();
    std::cout << result.PNGFiles[k] << ": " << size[0] << " x " << size[1] << " pixels, DICOM Rows "
              << dicom.Get("0028|0010") << ", Columns " << dicom.Get("0028|0011") << std::endl;
    EXPECT_EQ(std::max(size[0], size[1]), 512u);
    EXPECT_EQ(dicom.Image->GetLargestPossibleRegion().GetSize(), size);
    EXPECT_EQ(dicom.Get("0028|0010"), std::to_string(size[1]));
    EXPECT_EQ(dicom.Get("0028|0011"), std::to_string(size[0]));
    EXPECT_TRUE(std::equal(png->GetBufferPointer(),
                           png->GetBufferPointer() + png->GetLargestPossibleRegion().GetNumberOfPixels(),
                           dicom.Image->GetBufferPointer()));
  }
}

TEST(BurnedInLabels, GlyphsAreWhiteOnABlackOutlineAndClippedAtTheEdges)
{
  auto                        image = vr::MaskImageType::New();
  vr::MaskImageType::SizeType size = { { 40, 20 } };
  image->SetRegions(size);
  image->Allocate();
  image->FillBuffer(128);
  // "1" at scale 2 from (4, 3): its stem is font column 2, rows 0-6 -> image columns 8-9, rows 3-16.
  vr::BurnInText(image, "1", 4, 3, 2);
  EXPECT_EQ(image->GetPixel({ { 8, 10 } }), 255);
  EXPECT_EQ(image->GetPixel({ { 9, 16 } }), 255);
  // The outline one pixel around the stem's side (column 7 is left of the stem, beside its middle rows).
  EXPECT_EQ(image->GetPixel({ { 7, 10 } }), 0);
  // Away from the glyph: untouched.
  EXPECT_EQ(image->GetPixel({ { 30, 10 } }), 128);
  long width = 0;
  long height = 0;
  vr::BurnedInTextSize("30\xC2\xB0", 3, width, height);
  EXPECT_EQ(width, (3 * 6 - 1) * 3) << "three characters: the degree sign is one";
  EXPECT_EQ(height, 21);
  // Text running off the image is clipped: the part inside is drawn ("L"'s stem, font column 0, at columns 36-37).
  vr::BurnInText(image, "LLLL", 36, 2, 2);
  EXPECT_EQ(image->GetPixel({ { 36, 10 } }), 255);
  EXPECT_EQ(image->GetPixel({ { 37, 10 } }), 255);
  EXPECT_EQ(image->GetLargestPossibleRegion().GetSize(), size);
}

TEST_F(RotationSeriesTest, ADICOMVolumeGivesItsPatientAndStudy)
{
  vr::VesselReformationLogic logic;
  vr::VolumeNode *           volume = nullptr;
  Configure(logic, &volume);
  volume->SetAttribute(vr::DICOMAttribute::PatientName, "Doe^Jane");
  volume->SetAttribute(vr::DICOMAttribute::PatientID, "PAT-0042");
  volume->SetAttribute(vr::DICOMAttribute::PatientBirthDate, "19600101");
  volume->SetAttribute(vr::DICOMAttribute::PatientSex, "F");
  volume->SetAttribute(vr::DICOMAttribute::StudyInstanceUID, "1.2.826.0.1.3680043.9.7777.1.2.3");
  volume->SetAttribute(vr::DICOMAttribute::StudyID, "S17");
  volume->SetAttribute(vr::DICOMAttribute::StudyDate, "20260102");
  volume->SetAttribute(vr::DICOMAttribute::StudyTime, "101500");
  volume->SetAttribute(vr::DICOMAttribute::AccessionNumber, "ACC9");
  volume->SetAttribute(vr::DICOMAttribute::StudyDescription, "CTA run-off");
  vr::RotationSeriesSettings settings;
  settings.Folder = (m_Folder / "series").string();
  settings.Angles = { 0.0, 180.0, 2 };
  settings.Window = 600.0;
  settings.Level = 100.0;
  const vr::RotationSeriesResult result = vr::ExportRotationSeries(logic, settings);
  EXPECT_FALSE(result.IdentityMadeUp);
  EXPECT_EQ(result.Window, 600.0) << "the window given";
  for (std::size_t k = 0; k < 2; ++k)
  {
    const auto dicom = ReadDICOM(result.DICOMFiles[k]);
    EXPECT_EQ(dicom.Get("0010|0010"), "Doe^Jane");
    EXPECT_EQ(dicom.Get("0010|0020"), "PAT-0042");
    EXPECT_EQ(dicom.Get("0010|0030"), "19600101");
    EXPECT_EQ(dicom.Get("0010|0040"), "F");
    EXPECT_EQ(dicom.Get("0020|000d"), "1.2.826.0.1.3680043.9.7777.1.2.3");
    EXPECT_EQ(dicom.Get("0020|0010"), "S17");
    EXPECT_EQ(dicom.Get("0008|0020"), "20260102");
    EXPECT_EQ(dicom.Get("0008|0050"), "ACC9");
    EXPECT_EQ(dicom.Get("0008|1030"), "CTA run-off");
    EXPECT_FALSE(dicom.Has("0010|4000")) << "nothing made up to say";
    EXPECT_NE(dicom.Get("0020|000e"), "1.2.826.0.1.3680043.9.7777.1.2.3") << "a new series in the input's study";
    EXPECT_EQ(dicom.Get("0020|0013"), std::to_string(k + 1));
  }
}

/** Writes the phantom as a CT DICOM series of one file per slice (as a scanner would, with its patient and study),
 * the way ITK's DICOM series examples do. */
void
WriteDICOMSeries(const vr::VolumeImageType * volume, const fs::path & folder)
{
  using DICOMVolume = itk::Image<short, 3>;
  using Slice = itk::Image<short, 2>;
  auto cast = itk::CastImageFilter<vr::VolumeImageType, DICOMVolume>::New();
  cast->SetInput(volume);
  cast->Update();
  const DICOMVolume * shorts = cast->GetOutput();
  auto                io = itk::GDCMImageIO::New();
  io->KeepOriginalUIDOn();
  auto                                                  writer = itk::ImageSeriesWriter<DICOMVolume, Slice>::New();
  std::vector<std::unique_ptr<itk::MetaDataDictionary>> owned;
  std::vector<itk::MetaDataDictionary *>                dictionaries;
  std::vector<std::string>                              names;
  const unsigned int                                    slices = shorts->GetLargestPossibleRegion().GetSize()[2];
  for (unsigned int z = 0; z < slices; ++z)
  {
    auto dictionary = std::make_unique<itk::MetaDataDictionary>();
    auto put = [&](const char * tag, const std::string & value)
    { itk::EncapsulateMetaData<std::string>(*dictionary, tag, value); };
    itk::Point<double, 3> position;
    shorts->TransformIndexToPhysicalPoint({ { 0, 0, static_cast<itk::IndexValueType>(z) } }, position);
    std::ostringstream positionText;
    positionText << position[0] << "\\" << position[1] << "\\" << position[2];
    put("0008|0060", "CT");
    put("0008|0016", "1.2.840.10008.5.1.4.1.1.2");
    put("0010|0010", "Runoff^Phantom");
    put("0010|0020", "PHANTOM-7");
    put("0010|0040", "O");
    put("0008|0020", "20260301");
    put("0008|0030", "101500");
    put("0008|0050", "A-77");
    put("0008|1030", "CTA run-off phantom");
    put("0020|0010", "77");
    put("0020|000d", "1.2.826.0.1.3680043.9.7777.24.1");
    put("0020|000e", "1.2.826.0.1.3680043.9.7777.24.2");
    put("0020|0052", "1.2.826.0.1.3680043.9.7777.24.3");
    put("0008|0018", "1.2.826.0.1.3680043.9.7777.24.2." + std::to_string(z + 1));
    put("0020|0013", std::to_string(z + 1));
    put("0020|0032", positionText.str());
    put("0020|0037", "1\\0\\0\\0\\1\\0");
    put("0018|0050", std::to_string(shorts->GetSpacing()[2]));
    dictionaries.push_back(dictionary.get());
    owned.push_back(std::move(dictionary));
    names.push_back((folder / ("slice" + std::to_string(z + 1) + ".dcm")).string());
  }
  writer->SetInput(shorts);
  writer->SetImageIO(io);
  writer->SetFileNames(names);
  writer->SetMetaDataDictionaryArray(&dictionaries);
  writer->Update();
}

TEST_F(RotationSeriesTest, FromADICOMFolderTheSeriesJoinsTheInputsPatientAndStudy)
{
  // The phantom as a DICOM folder, read as the modules read it (the reader process hands the first file's patient
  // and study over with the voxels, and the node conversion makes them the node's attributes).
  const fs::path dicomFolder = m_Folder / "dicom";
  fs::create_directories(dicomFolder);
  WriteDICOMSeries(vr::ReadVolume((m_Folder / "runoff.nrrd").string()), dicomFolder);
  auto       volume = vr::ConvertItkImageToVolumeNode(vr::ReadVolume(dicomFolder.string()), "dicom");
  const auto attribute = [&](const char * key) -> std::string
  {
    const char * value = volume->GetAttribute(key);
    return value != nullptr ? value : "(none)";
  };
  EXPECT_EQ(attribute(vr::DICOMAttribute::PatientID), "PHANTOM-7") << "without DICOM's padding";
  EXPECT_EQ(attribute(vr::DICOMAttribute::PatientName), "Runoff^Phantom");
  EXPECT_EQ(attribute(vr::DICOMAttribute::StudyInstanceUID), "1.2.826.0.1.3680043.9.7777.24.1");
  EXPECT_EQ(attribute(vr::DICOMAttribute::StudyTime), "101500");
  EXPECT_EQ(attribute(vr::DICOMAttribute::PatientBirthDate), "(none)") << "absent in the file: not set";
  // The same as DICOMAttributesOf gives for the first file read here in-process (these files are sound).
  auto header = itk::GDCMImageIO::New();
  header->SetFileName((dicomFolder / "slice1.dcm").string());
  header->ReadImageInformation();
  const auto attributes = vr::DICOMAttributesOf(header->GetMetaDataDictionary());
  EXPECT_EQ(attributes.size(), 9u) << "name, ID, sex, study UID, date, time, accession, description, study ID";
  for (const auto & [key, value] : attributes)
  {
    EXPECT_EQ(attribute(key.c_str()), value) << key;
  }
  vr::VesselReformationLogic logic;
  logic.SetVolumeNode(volume);
  logic.SetCenterlineNode(
    vr::ConvertTreeToCenterlineNode(vr::ReadCenterlines((m_Folder / "runoff.vtp").string()), "runoff.vtp"));
  vr::ReformationParameters parameters;
  parameters.PixelSpacing.Fill(4.0);
  parameters.Iterations = 40;
  logic.SetParameters(parameters);
  vr::RotationSeriesSettings settings;
  settings.Folder = (m_Folder / "series").string();
  settings.Angles = { 0.0, 120.0, 3 };
  const vr::RotationSeriesResult result = vr::ExportRotationSeries(logic, settings);
  EXPECT_FALSE(result.IdentityMadeUp);
  EXPECT_EQ(result.Window, 900.0) << "a CT: the CTA window";

  auto series = itk::GDCMSeriesFileNames::New();
  series->SetDirectory((m_Folder / "series").string());
  ASSERT_EQ(series->GetSeriesUIDs().size(), 1u);
  EXPECT_EQ(series->GetSeriesUIDs().front().find("1.2.826.0.1.3680043.9.7777.24.2"), std::string::npos)
    << "a new series, not the input's";
  for (std::size_t k = 0; k < 3; ++k)
  {
    const auto dicom = ReadDICOM(result.DICOMFiles[k]);
    EXPECT_EQ(dicom.Get("0010|0020"), "PHANTOM-7");
    EXPECT_EQ(dicom.Get("0010|0010"), "Runoff^Phantom");
    EXPECT_EQ(dicom.Get("0020|000d"), "1.2.826.0.1.3680043.9.7777.24.1");
    EXPECT_EQ(dicom.Get("0008|0050"), "A-77");
    EXPECT_EQ(dicom.Get("0008|0030"), "101500");
    EXPECT_NE(dicom.Get("0020|000e"), "1.2.826.0.1.3680043.9.7777.24.2");
    EXPECT_EQ(dicom.Get("0020|0013"), std::to_string(k + 1));
    EXPECT_EQ(dicom.Get("0008|0016"), vr::SecondaryCaptureSOPClassUID);
    EXPECT_FALSE(dicom.Has("0020|0032")) << "the input's slices had positions; the pictures have none";
    EXPECT_FALSE(dicom.Has("0020|0037"));
    EXPECT_FALSE(dicom.Has("0020|0052"));
  }
}

TEST_F(RotationSeriesTest, RefusedFoldersAndACancelWriteNothingAndKeepWhatWasThere)
{
  vr::VesselReformationLogic logic;
  Configure(logic);
  vr::RotationSeriesSettings settings;
  settings.Angles = { 0.0, 30.0, 3 };

  // A folder holding an earlier series: refused, the old file kept byte for byte.
  const fs::path old = m_Folder / "old";
  fs::create_directories(old);
  {
    std::ofstream(old / "rotation-000.png") << "an earlier series";
  }
  settings.Folder = old.string();
  try
  {
    vr::ExportRotationSeries(logic, settings, {}, "--rotationSeries");
    ADD_FAILURE() << "a folder holding a series was accepted";
  }
  catch (const vr::InputError & error)
  {
    EXPECT_NE(std::string(error.what()).find("--rotationSeries " + old.string()), std::string::npos) << error.what();
    EXPECT_NE(std::string(error.what()).find("already holds a rotation series"), std::string::npos) << error.what();
  }
  EXPECT_EQ(ReadText(old / "rotation-000.png"), "an earlier series");
  EXPECT_EQ(std::distance(fs::directory_iterator(old), fs::directory_iterator()), 1);

  // A missing parent, and a file where the folder should be.
  settings.Folder = (m_Folder / "missing" / "series").string();
  EXPECT_THROW(
    {
      try
      {
        vr::ExportRotationSeries(logic, settings, {}, "--rotationSeries");
      }
      catch (const vr::InputError & error)
      {
        EXPECT_NE(std::string(error.what()).find("parent folder"), std::string::npos) << error.what();
        throw;
      }
    },
    vr::InputError);
  EXPECT_FALSE(fs::exists(m_Folder / "missing"));
  settings.Folder = (m_Folder / "runoff.vtp").string();
  EXPECT_THROW(vr::ExportRotationSeries(logic, settings), vr::InputError);

  // Cancelled at the second view: nothing published, a created folder removed, another file left alone.
  const auto cancelAtSecondView = [](std::size_t view, std::size_t, double) { return view < 1; };
  settings.Folder = (m_Folder / "created").string();
  EXPECT_THROW(vr::ExportRotationSeries(logic, settings, cancelAtSecondView), vr::Cancelled);
  EXPECT_FALSE(fs::exists(m_Folder / "created"));
  const fs::path notes = m_Folder / "with-notes";
  fs::create_directories(notes);
  {
    std::ofstream(notes / "notes.txt") << "keep me";
  }
  settings.Folder = notes.string();
  EXPECT_THROW(vr::ExportRotationSeries(logic, settings, cancelAtSecondView), vr::Cancelled);
  EXPECT_EQ(std::distance(fs::directory_iterator(notes), fs::directory_iterator()), 1) << "no staging left";
  EXPECT_EQ(ReadText(notes / "notes.txt"), "keep me");

  // A failure of the logic at the first view (centerlines replaced by none): nothing written either.
  vr::VesselReformationLogic broken;
  broken.SetVolumeNode(logic.GetVolumeNode());
  settings.Folder = (m_Folder / "broken").string();
  EXPECT_THROW(vr::ExportRotationSeries(broken, settings), vr::InputError);
  EXPECT_FALSE(fs::exists(m_Folder / "broken"));

  // And then the same folder takes a series.
  settings.Folder = notes.string();
  EXPECT_EQ(vr::ExportRotationSeries(logic, settings).PNGFiles.size(), 3u);
  EXPECT_EQ(ReadText(notes / "notes.txt"), "keep me");
}

/** Mounts a tmpfs of \a bytes at \a folder (read-only when \a readOnly); false when this process may not mount. */
bool
MountSmallFileSystem(const fs::path & folder, std::size_t bytes, bool readOnly)
{
  fs::create_directories(folder);
  const std::string options = "size=" + std::to_string(bytes);
  if (::mount("tmpfs", folder.c_str(), "tmpfs", readOnly ? MS_RDONLY : 0, options.c_str()) != 0)
  {
    return false;
  }
  return true;
}

TEST_F(RotationSeriesTest, AReadOnlyOrFullDiskWritesNothingAndKeepsWhatWasThere)
{
  if (::geteuid() != 0)
  {
    GTEST_SKIP() << "needs root to mount a small and a read-only tmpfs (permissions alone do not stop root)";
  }
  const fs::path readOnly = m_Folder / "read-only";
  const fs::path full = m_Folder / "full";
  if (!MountSmallFileSystem(readOnly, 1 << 20, true))
  {
    GTEST_SKIP() << "running as root without the right to mount a tmpfs";
  }
  struct Unmount
  {
    std::vector<fs::path> Points;
    ~Unmount()
    {
      for (const auto & point : Points)
      {
        ::umount2(point.c_str(), MNT_DETACH);
      }
    }
  } unmount{ { readOnly } };
  vr::VesselReformationLogic logic;
  Configure(logic);
  vr::RotationSeriesSettings settings;
  settings.Angles = { 0.0, 120.0, 3 };

  for (const fs::path & folder : { readOnly, readOnly / "series" })
  {
    settings.Folder = folder.string();
    try
    {
      vr::ExportRotationSeries(logic, settings, {}, "--rotationSeries");
      ADD_FAILURE() << folder << " was accepted";
    }
    catch (const vr::InputError & error)
    {
      EXPECT_NE(std::string(error.what()).find("--rotationSeries"), std::string::npos) << error.what();
      EXPECT_TRUE(std::string(error.what()).find("cannot be written") != std::string::npos ||
                  std::string(error.what()).find("cannot be created") != std::string::npos)
        << error.what();
    }
  }
  EXPECT_TRUE(fs::is_empty(readOnly));

  // Room for the first views only: the series fails part way, and nothing of it stays.
  ASSERT_TRUE(MountSmallFileSystem(full, 40 << 10, false));
  unmount.Points.push_back(full);
  {
    std::ofstream(full / "keep.txt") << "an earlier file";
  }
  settings.Folder = full.string();
  try
  {
    vr::ExportRotationSeries(logic, settings, {}, "--rotationSeries");
    ADD_FAILURE() << "a series larger than the disk was written";
  }
  catch (const vr::InputError & error)
  {
    EXPECT_NE(std::string(error.what()).find(full.string()), std::string::npos) << error.what();
  }
  std::set<std::string> left;
  for (const auto & entry : fs::directory_iterator(full))
  {
    left.insert(entry.path().filename().string());
  }
  EXPECT_EQ(left, std::set<std::string>{ "keep.txt" });
  EXPECT_EQ(ReadText(full / "keep.txt"), "an earlier file");
}

TEST(IntensityWindow, ACTGetsTheCTAWindowOtherDataItsPercentiles)
{
  // 10 x 10 x 10 voxels holding 0..999 once each (an MR's unitless intensities, shuffled by a stride): the 1st
  // percentile is rank round(0.01 * 999) = 10, the 99th rank 989.
  auto volume = vr::VolumeImageType::New();
  volume->SetRegions(vr::VolumeImageType::SizeType{ { 10, 10, 10 } });
  volume->Allocate();
  for (std::size_t k = 0; k < 1000; ++k)
  {
    volume->GetBufferPointer()[k] = static_cast<float>((k * 37) % 1000);
  }
  double window = 0.0;
  double level = 0.0;
  vr::DefaultWindowOf(vr::ConvertItkImageToVolumeNode(volume, "mra"), window, level);
  EXPECT_EQ(window, 979.0);
  EXPECT_EQ(level, 499.5);
  volume->GetBufferPointer()[0] = -1000.0f; // air in HU: a CT
  vr::DefaultWindowOf(vr::ConvertItkImageToVolumeNode(volume, "ct"), window, level);
  EXPECT_EQ(window, 900.0);
  EXPECT_EQ(level, 200.0);
  vr::DefaultWindowOf(nullptr, window, level);
  EXPECT_EQ(window, 0.0);
}

TEST(RotationAngles, DefaultsAndBadValuesNameTheFlag)
{
  const vr::RotationAngles defaults;
  EXPECT_EQ(defaults.Start, 0.0);
  EXPECT_EQ(defaults.Step, 10.0);
  EXPECT_EQ(defaults.Count, 36);
  EXPECT_EQ(defaults.At(35), 350.0);
  const vr::RotationAngles parsed = vr::ParseRotationAngles("-30, 2.5,13", "--rotationAngles");
  EXPECT_EQ(parsed.Start, -30.0);
  EXPECT_EQ(parsed.Step, 2.5);
  EXPECT_EQ(parsed.Count, 13);
  EXPECT_EQ(vr::ParseRotationAngles("5,0,1", "--rotationAngles").Count, 1) << "one view needs no step";
  for (const char * bad : { "0,10",
                            "0,10,36,4",
                            "0,10,",
                            "",
                            "0,10,0",
                            "0,10,-3",
                            "0,10,3601",
                            "0,10,2.5",
                            "0,0,5",
                            "nan,10,3",
                            "0,inf,3",
                            "a,b,c",
                            "0,10,36x",
                            "1e308,1e308,3" })
  {
    try
    {
      vr::ParseRotationAngles(bad, "--rotationAngles");
      ADD_FAILURE() << "accepted \"" << bad << "\"";
    }
    catch (const vr::InputError & error)
    {
      EXPECT_EQ(std::string(error.what()).rfind("--rotationAngles", 0), 0u) << bad << ": " << error.what();
    }
  }
  EXPECT_EQ(vr::ParseRotationAngles("0,10,3600", "--rotationAngles").Count, 3600);
}
} // namespace
