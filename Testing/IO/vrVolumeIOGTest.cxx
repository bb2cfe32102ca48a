// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Volume reader and writer (issue 3): ITK formats keep geometry and values, a DICOM folder is read as the series
// with the most files, and bad volumes are input errors that name the file.
#include "vrDICOMSeriesChoice.h"
#include "vrDICOMSeriesProcess.h"
#include "vrParameterName.h"
#include "vrInputError.h"
#include "vrTestFiles.h"
#include "vrVolumeIO.h"

#include "itkCPRVectorHelpers.h"
#include "itkGDCMImageIO.h"
#include "itkImageFileWriter.h"
#include "itkImageSeriesWriter.h"
#include "itkMetaDataObject.h"
#include "itkVector.h"

#include "vrTestImages.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>

namespace
{
using vr::VolumeImageType;

using vr::test::InputErrorOf;

#define EXPECT_MESSAGE_HAS(message, part)                                                                              \
  EXPECT_NE((message).find(part), std::string::npos) << "message: " << (message) << "\nmissing: " << (part)

/** A 4 x 5 x 6 volume with anisotropic spacing, an offset origin, a 90 degree rotation about z, and voxel value
 * 0.5 x + 10 y - 3 z + 0.25 (distinct, exact in float). */
template<typename TImage = VolumeImageType>
typename TImage::Pointer
MakeVolume(unsigned int slices = 6)
{
  auto                        volume = TImage::New();
  typename TImage::RegionType region;
  region.SetSize({ { 4, 5, slices } });
  volume->SetRegions(region);
  volume->SetSpacing(itk::detail::MakeVector3(0.5, 0.75, 1.25));
  typename TImage::PointType origin;
  origin[0] = 10.0;
  origin[1] = -20.0;
  origin[2] = 30.0;
  volume->SetOrigin(origin);
  typename TImage::DirectionType direction;
  direction.Fill(0.0);
  direction(0, 1) = -1.0;
  direction(1, 0) = 1.0;
  direction(2, 2) = 1.0;
  volume->SetDirection(direction);
  volume->Allocate();
  for (unsigned int z = 0; z < slices; ++z)
  {
    for (unsigned int y = 0; y < 5; ++y)
    {
      for (unsigned int x = 0; x < 4; ++x)
      {
        volume->SetPixel({ { x, y, z } }, static_cast<typename TImage::PixelType>(0.5 * x + 10 * y - 3.0 * z + 0.25));
      }
    }
  }
  return volume;
}

template<typename TImage>
void
WriteWithITK(const TImage * image, const std::string & path)
{
  auto writer = itk::ImageFileWriter<TImage>::New();
  writer->SetInput(image);
  writer->SetFileName(path);
  writer->Update();
}

void
ExpectSameVolume(const VolumeImageType * expected, const VolumeImageType * actual, double geometryTolerance)
{
  ASSERT_EQ(actual->GetLargestPossibleRegion().GetSize(), expected->GetLargestPossibleRegion().GetSize());
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    EXPECT_NEAR(actual->GetSpacing()[axis], expected->GetSpacing()[axis], geometryTolerance);
    EXPECT_NEAR(actual->GetOrigin()[axis], expected->GetOrigin()[axis], geometryTolerance);
    for (unsigned int column = 0; column < 3; ++column)
    {
      EXPECT_NEAR(actual->GetDirection()(axis, column), expected->GetDirection()(axis, column), geometryTolerance);
    }
  }
  const std::size_t count = expected->GetLargestPossibleRegion().GetNumberOfPixels();
  for (std::size_t k = 0; k < count; ++k)
  {
    ASSERT_EQ(actual->GetBufferPointer()[k], expected->GetBufferPointer()[k]) << "voxel " << k;
  }
}

TEST(VolumeIO, ReadsTheAortaMetaImageWithItsGeometry)
{
  const std::string folder = vr::test::AortaDataFolder();
  if (folder.empty())
  {
    GTEST_FAIL() << "VMTK's aorta (vmtk-aorta-mra) is missing from VR_SHARED_DATA_DIR (Testing/Data by default)";
  }
  const VolumeImageType::Pointer volume = vr::ReadVolume(folder + "/aorta.mha");
  // The values of the MetaImage header (README: 157 x 393 x 34, direction diag(-1, -1, 1)).
  EXPECT_EQ(volume->GetLargestPossibleRegion().GetSize(), (itk::Size<3>{ { 157, 393, 34 } }));
  EXPECT_NEAR(volume->GetSpacing()[0], 0.878906, 1e-6);
  EXPECT_NEAR(volume->GetSpacing()[2], 1.50009, 1e-6);
  EXPECT_NEAR(volume->GetOrigin()[0], -156.445, 1e-6);
  EXPECT_NEAR(volume->GetOrigin()[1], -24.6094, 1e-6);
  EXPECT_EQ(volume->GetDirection()(0, 0), -1.0);
  EXPECT_EQ(volume->GetDirection()(1, 1), -1.0);
  EXPECT_EQ(volume->GetDirection()(2, 2), 1.0);
}

class VolumeFormatRoundTrip : public ::testing::TestWithParam<std::string>
{
};

TEST_P(VolumeFormatRoundTrip, KeepsValuesSpacingOriginAndDirection)
{
  vr::test::ScopedTemporaryFolder folder;
  const auto                      volume = MakeVolume();
  const std::string               path = folder.File("volume" + GetParam());
  vr::WriteVolume(volume, path);
  EXPECT_EQ(folder.Entries(), std::vector<std::string>{ "volume" + GetParam() });
  // NIfTI keeps the geometry as a float quaternion; the others as decimal or double text.
  ExpectSameVolume(volume, vr::ReadVolume(path), GetParam() == ".nii.gz" ? 1e-5 : 1e-12);
}

INSTANTIATE_TEST_SUITE_P(NRRDNIfTIMetaImage,
                         VolumeFormatRoundTrip,
                         ::testing::Values(".nrrd", ".nii.gz", ".mha"),
                         [](const auto & info)
                         {
                           std::string name = info.param.substr(1);
                           name.erase(std::remove(name.begin(), name.end(), '.'), name.end());
                           return name;
                         });

using DICOMVolumeType = itk::Image<short, 3>;

/** Writes \a volume as a DICOM series of one file per slice, the way ITK's DICOM series examples do: each slice
 * gets its position, orientation and the shared series UID in its own dictionary. */
void
WriteDICOMSeries(const DICOMVolumeType * volume,
                 const std::string &     folder,
                 const std::string &     prefix,
                 const std::string &     seriesUID)
{
  using SliceType = itk::Image<short, 2>;
  auto io = itk::GDCMImageIO::New();
  auto writer = itk::ImageSeriesWriter<DICOMVolumeType, SliceType>::New();
  std::vector<std::unique_ptr<itk::MetaDataDictionary>> owned;
  std::vector<itk::MetaDataDictionary *>                dictionaries;
  std::vector<std::string>                              names;
  const unsigned int                                    slices = volume->GetLargestPossibleRegion().GetSize()[2];
  io->KeepOriginalUIDOn();
  for (unsigned int z = 0; z < slices; ++z)
  {
    auto dictionary = std::make_unique<itk::MetaDataDictionary>();
    auto put = [&](const char * tag, const std::string & value)
    { itk::EncapsulateMetaData<std::string>(*dictionary, tag, value); };
    itk::Point<double, 3> position;
    volume->TransformIndexToPhysicalPoint({ { 0, 0, static_cast<itk::IndexValueType>(z) } }, position);
    std::ostringstream positionText;
    positionText << position[0] << "\\" << position[1] << "\\" << position[2];
    put("0008|0060", "CT");
    put("0008|0016", "1.2.840.10008.5.1.4.1.1.2");
    put("0020|000d", "1.2.826.0.1.3680043.2.1125.1.1");
    put("0020|000e", seriesUID);
    put("0020|0052", "1.2.826.0.1.3680043.2.1125.1.3");
    put("0008|0018", seriesUID + "." + std::to_string(z + 1));
    put("0020|0013", std::to_string(z + 1));
    put("0020|0032", positionText.str());
    put("0020|0037", "1\\0\\0\\0\\1\\0");
    put("0018|0050", std::to_string(volume->GetSpacing()[2]));
    dictionaries.push_back(dictionary.get());
    owned.push_back(std::move(dictionary));
    names.push_back(folder + "/" + prefix + std::to_string(z + 1) + ".dcm");
  }
  writer->SetInput(volume);
  writer->SetImageIO(io);
  writer->SetFileNames(names);
  writer->SetMetaDataDictionaryArray(&dictionaries);
  writer->Update();
}

DICOMVolumeType::Pointer
MakeDICOMVolume(unsigned int slices)
{
  auto                        volume = DICOMVolumeType::New();
  DICOMVolumeType::RegionType region;
  region.SetSize({ { 6, 5, slices } });
  volume->SetRegions(region);
  volume->SetSpacing(itk::detail::MakeVector3(0.75, 0.75, 2.5));
  DICOMVolumeType::PointType origin;
  origin[0] = -100.0;
  origin[1] = 50.0;
  origin[2] = 12.5;
  volume->SetOrigin(origin);
  volume->Allocate();
  for (unsigned int z = 0; z < slices; ++z)
  {
    for (unsigned int y = 0; y < 5; ++y)
    {
      for (unsigned int x = 0; x < 6; ++x)
      {
        volume->SetPixel({ { x, y, z } }, static_cast<short>(-1000 + 7 * x + 100 * y + 600 * z));
      }
    }
  }
  return volume;
}

TEST(VolumeIO, AFolderOfTwoDICOMSeriesIsListedAndTheOneChosenIsRead)
{
  // Issue 37: the series with the most files is no longer taken silently; the two are listed and one is chosen.
  vr::test::ScopedTemporaryFolder folder;
  const auto                      volume = MakeDICOMVolume(5);
  WriteDICOMSeries(volume, folder.Path().string(), "ct", "1.2.826.0.1.3680043.2.1125.1.2.1");
  WriteDICOMSeries(MakeDICOMVolume(2), folder.Path().string(), "scout", "1.2.826.0.1.3680043.2.1125.1.2.2");

  try
  {
    vr::ReadVolume(folder.Path().string());
    ADD_FAILURE() << "a folder of two series was read without a choice";
  }
  catch (const vr::DICOMSeriesChoiceRequired & choice)
  {
    const std::string message = choice.what();
    EXPECT_MESSAGE_HAS(message, "volume folder " + folder.Path().string() + ": holds 2 DICOM series; choose one");
    EXPECT_EQ(choice.Parameter(), vr::ParameterName::DICOMSeries);
    ASSERT_EQ(choice.GetSeries().size(), 2u);
    EXPECT_EQ(choice.GetSeries()[0].SeriesInstanceUID, "1.2.826.0.1.3680043.2.1125.1.2.1");
    EXPECT_EQ(choice.GetSeries()[0].Files, 5u);
    EXPECT_EQ(choice.GetSeries()[1].Files, 2u);
    EXPECT_EQ(choice.GetSeries()[1].Columns, 6u);
    EXPECT_EQ(choice.GetSeries()[1].Rows, 5u);
    EXPECT_MESSAGE_HAS(message,
                       "\n  1: CT, 5 files of 6 x 5 pixels, Series Instance UID 1.2.826.0.1.3680043.2.1125.1.2.1");
    EXPECT_MESSAGE_HAS(message,
                       "\n  2: CT, 2 files of 6 x 5 pixels, Series Instance UID 1.2.826.0.1.3680043.2.1125.1.2.2");
  }

  for (const std::string & choice : { std::string("1"), std::string("1.2.826.0.1.3680043.2.1125.1.2.1") })
  {
    vr::VolumeReadOptions options;
    options.DICOMSeries = choice;
    vr::VolumeReadReport           report;
    const VolumeImageType::Pointer read = vr::ReadVolume(folder.Path().string(), options, &report);
    EXPECT_TRUE(report.Warnings.empty());
    ASSERT_EQ(read->GetLargestPossibleRegion().GetSize(), volume->GetLargestPossibleRegion().GetSize());
    for (unsigned int axis = 0; axis < 3; ++axis)
    {
      EXPECT_NEAR(read->GetSpacing()[axis], volume->GetSpacing()[axis], 1e-6);
      EXPECT_NEAR(read->GetOrigin()[axis], volume->GetOrigin()[axis], 1e-6);
    }
    EXPECT_EQ(read->GetDirection(), volume->GetDirection());
    for (std::size_t k = 0; k < volume->GetLargestPossibleRegion().GetNumberOfPixels(); ++k)
    {
      ASSERT_EQ(read->GetBufferPointer()[k], static_cast<float>(volume->GetBufferPointer()[k])) << "voxel " << k;
    }
  }
  vr::VolumeReadOptions none;
  none.DICOMSeries = "3";
  EXPECT_MESSAGE_HAS(InputErrorOf([&] { vr::ReadVolume(folder.Path().string(), none); }),
                     "the DICOM series chosen, 3, is no series of the folder");
}

TEST(BadVolumeInput, MissingCorruptTwoDimensionalVectorAndEmptyFolder)
{
  vr::test::ScopedTemporaryFolder folder;
  std::string                     message = InputErrorOf([&] { vr::ReadVolume(folder.File("missing.nrrd")); });
  EXPECT_MESSAGE_HAS(message, folder.File("missing.nrrd"));
  EXPECT_MESSAGE_HAS(message, "no such file");

  const std::string corrupt = folder.File("corrupt.nrrd");
  vr::test::WriteTextFile(corrupt, "NRRD0004\ntype: float\ndimension: 3\nsizes: 4 x 4\nencoding: raw\n\n");
  message = InputErrorOf([&] { vr::ReadVolume(corrupt); });
  EXPECT_MESSAGE_HAS(message, corrupt);
  EXPECT_MESSAGE_HAS(message, "header");
  EXPECT_MESSAGE_HAS(message, "sizes"); // the NRRD field that is wrong

  const std::string flat = folder.File("flat.nrrd");
  auto              slice = itk::Image<float, 2>::New();
  slice->SetRegions(itk::ImageRegion<2>({ { 0, 0 } }, { { 3, 3 } }));
  slice->Allocate(true);
  WriteWithITK(slice.GetPointer(), flat);
  message = InputErrorOf([&] { vr::ReadVolume(flat); });
  EXPECT_MESSAGE_HAS(message, flat);
  EXPECT_MESSAGE_HAS(message, "is 2D (3 x 3 pixels); a volume must be 3D");

  const std::string vectors = folder.File("vectors.nrrd");
  using VectorVolume = itk::Image<itk::Vector<float, 3>, 3>;
  auto field = VectorVolume::New();
  field->SetRegions(itk::ImageRegion<3>({ { 0, 0, 0 } }, { { 2, 2, 2 } }));
  field->Allocate(true);
  WriteWithITK(field.GetPointer(), vectors);
  message = InputErrorOf([&] { vr::ReadVolume(vectors); });
  EXPECT_MESSAGE_HAS(message, vectors);
  EXPECT_MESSAGE_HAS(message, "3 ");
  EXPECT_MESSAGE_HAS(message, "must be scalar");

  const std::string empty = folder.File("empty-folder");
  std::filesystem::create_directory(empty);
  message = InputErrorOf([&] { vr::ReadVolume(empty); });
  EXPECT_MESSAGE_HAS(message, empty);
  EXPECT_MESSAGE_HAS(message, "holds no DICOM image");

  const std::string truncated = folder.File("truncated.nrrd");
  vr::test::WriteTextFile(truncated,
                          "NRRD0004\ntype: float\ndimension: 3\nsizes: 4 4 4\nendian: little\n"
                          "encoding: raw\n\n0123456789");
  message = InputErrorOf([&] { vr::ReadVolume(truncated); });
  EXPECT_MESSAGE_HAS(message, truncated);
  EXPECT_MESSAGE_HAS(message, "voxel data");
}

TEST(BadVolumeInput, CorruptDICOMFilesEndTheReaderProcessNotThisOne)
{
  // Files that made Debian's GDCM assert (abort) (issue 25), and one with 50448 bits allocated: the series is read
  // in a child process, so this test's process survives each, and the message names the file.
  vr::test::ScopedTemporaryFolder folder;
  const auto                      volume = MakeDICOMVolume(4);
  for (const char * finding : { "dicom-meta-explicit-assert/IM0018.dcm",
                                "dicom-meta-implicit-assert/IM0009.dcm",
                                "dicom-samples-per-pixel-assert/IM0017.dcm",
                                "dicom-truncated-assert/IM0011.dcm",
                                "dicom-bits-allocated-unhandled/IM0030.dcm",
                                "dicom-acr-nema-assert/IM0027.dcm" })
  {
    const std::filesystem::path file = std::filesystem::path(VR_FINDINGS_DIR) / finding;
    std::string                 message = InputErrorOf([&] { vr::ReadVolume(file.parent_path().string()); });
    EXPECT_MESSAGE_HAS(message, "the DICOM file " + file.string());

    // In a folder of good files: nothing is read, and the corrupt one is named (as the file GDCM died on or that
    // is refused, or as a second series of one file: these come from another series than the good one's).
    if (std::string(finding).find("assert") != std::string::npos)
    {
      const std::filesystem::path mixed = folder.Path() / file.parent_path().filename();
      std::filesystem::create_directories(mixed);
      WriteDICOMSeries(volume, mixed.string(), "ct", "1.2.826.0.1.3680043.2.1125.1.2.1");
      std::filesystem::copy_file(file, mixed / file.filename());
      message = InputErrorOf([&] { vr::ReadVolume(mixed.string()); });
      EXPECT_MESSAGE_HAS(message, (mixed / file.filename()).string());
      EXPECT_TRUE(message.find("is not read") != std::string::npos ||
                  message.find("(nothing was read)") != std::string::npos)
        << message;
    }

    // A corrupt DICOM file named like a volume file: GDCM is not asked in this process whether it reads it.
    const std::string named = folder.File(file.stem().string() + ".nrrd");
    std::filesystem::copy_file(file, named);
    message = InputErrorOf([&] { vr::ReadVolume(named); });
    EXPECT_MESSAGE_HAS(message, named);
  }
}

TEST(BadVolumeInput, AMissingDICOMReaderProcessIsSaidSo)
{
  vr::test::ScopedTemporaryFolder folder;
  WriteDICOMSeries(MakeDICOMVolume(3), folder.Path().string(), "ct", "1.2.826.0.1.3680043.2.1125.1.2.1");
  ::setenv("VR_DICOM_SERIES_READER", folder.File("no-such-reader").c_str(), 1);
  const std::string message = InputErrorOf([&] { vr::ReadVolume(folder.Path().string()); });
  ::unsetenv("VR_DICOM_SERIES_READER");
  EXPECT_MESSAGE_HAS(message, folder.Path().string());
  EXPECT_MESSAGE_HAS(message, "vrReadDICOMSeries was not found");
  EXPECT_EQ(vr::ReadVolume(folder.Path().string())->GetLargestPossibleRegion().GetSize()[2], 3u);
}

TEST(BadVolumeInput, AHangingDICOMReaderProcessIsStoppedAtTheBound)
{
  // The bound by hand: 60 s plus a quarter second per file.
  ::unsetenv("VR_DICOM_SERIES_TIMEOUT");
  EXPECT_DOUBLE_EQ(vr::detail::DICOMSeriesTimeoutSeconds(0), 60.0);
  EXPECT_DOUBLE_EQ(vr::detail::DICOMSeriesTimeoutSeconds(500), 185.0);

  // A stand-in reader that says which file it opens and then hangs (as GDCM in a loop would): with a bound of 1 s,
  // the read fails after about a second, naming the folder and that file, instead of waiting for ever.
  vr::test::ScopedTemporaryFolder folder;
  const std::string               series = folder.File("series");
  std::filesystem::create_directories(series);
  WriteDICOMSeries(MakeDICOMVolume(3), series, "ct", "1.2.826.0.1.3680043.2.1125.1.2.1");
  const std::string reader = folder.File("hanging-reader.sh");
  vr::test::WriteTextFile(reader, "#!/bin/sh\necho \"file $1/IM-stuck.dcm\" >> \"$3\"\nexec sleep 600\n");
  std::filesystem::permissions(reader, std::filesystem::perms::owner_all);
  ::setenv("VR_DICOM_SERIES_READER", reader.c_str(), 1);
  ::setenv("VR_DICOM_SERIES_TIMEOUT", "1", 1);
  const auto        start = std::chrono::steady_clock::now();
  const std::string message = InputErrorOf([&] { vr::ReadVolume(series); });
  const double      seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_GE(seconds, 1.0);
  EXPECT_LT(seconds, 30.0);
  EXPECT_MESSAGE_HAS(message, "volume folder " + series);
  EXPECT_MESSAGE_HAS(message, "did not finish within 1 s (for 3 files");
  EXPECT_MESSAGE_HAS(message, "reading the file " + series + "/IM-stuck.dcm");

  // A bound that is not a positive number is said to be wrong, by the variable's name.
  ::setenv("VR_DICOM_SERIES_TIMEOUT", "-5", 1);
  const std::string wrongBound = InputErrorOf([&] { vr::ReadVolume(series); });
  EXPECT_MESSAGE_HAS(wrongBound, "volume folder " + series);
  EXPECT_MESSAGE_HAS(wrongBound, "VR_DICOM_SERIES_TIMEOUT is \"-5\"");
  ::unsetenv("VR_DICOM_SERIES_TIMEOUT");
  ::unsetenv("VR_DICOM_SERIES_READER");

  // The real reader is well within the default bound.
  EXPECT_EQ(vr::ReadVolume(series)->GetLargestPossibleRegion().GetSize()[2], 3u);
}

TEST(BadVolumeOutput, AFailedWriteLeavesTheExistingFile)
{
  vr::test::ScopedTemporaryFolder folder;
  const std::string               path = folder.File("volume.xyz");
  vr::test::WriteTextFile(path, "previous");
  const std::string message = InputErrorOf([&] { vr::WriteVolume(MakeVolume(), path); });
  EXPECT_MESSAGE_HAS(message, path);
  EXPECT_EQ(vr::test::ReadTextFile(path), "previous");
  EXPECT_EQ(folder.Entries(), std::vector<std::string>{ "volume.xyz" });

  EXPECT_MESSAGE_HAS(InputErrorOf([&] { vr::WriteVolume(MakeVolume(), folder.File("nowhere/volume.nrrd")); }),
                     "does not exist");
}
} // namespace
