// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// A DICOM folder's images sorted into series, the choice of one, and the checks that every file of it agrees
// (vrDICOMSeriesGroups.h), on attributes written out by hand: what splits a Series Instance UID and how the list says
// so, choices by number and by UID, and each refusal naming the file, the attribute and both values.
#include "vrDICOMSeriesGroups.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace
{
using namespace vr::detail;
using namespace vr::detail::DICOMTag;

/** A file of a sound axial CT series: 512 x 512, unsigned 12 bits, slice \a k at z = 2 k. */
DICOMFileAttributes
CTFile(const std::string & name, int k, const std::string & uid = "1.2.3.4")
{
  DICOMFileAttributes file;
  file.File = "/in/" + name;
  auto set = [&](const DICOMAttributeTag & tag, const std::string & value) { file.Values[tag.Key()] = value; };
  set(TransferSyntaxUID, "1.2.840.10008.1.2.1");
  set(SOPInstanceUID, uid + "." + std::to_string(k));
  set(Modality, "CT");
  set(SeriesDescription, "CTA");
  set(SeriesInstanceUID, uid);
  set(SeriesNumber, "3");
  set(ImagePosition, "-100\\-120\\" + std::to_string(2 * k));
  set(ImageOrientation, "1\\0\\0\\0\\1\\0");
  set(FrameOfReferenceUID, "1.2.3.9");
  set(SamplesPerPixel, "1");
  set(PhotometricInterpretation, "MONOCHROME2");
  set(Rows, "512");
  set(Columns, "512");
  set(PixelSpacing, "0.7\\0.6");
  set(BitsAllocated, "16");
  set(BitsStored, "12");
  set(HighBit, "11");
  set(PixelRepresentation, "0");
  set(RescaleIntercept, "-1024");
  set(RescaleSlope, "1");
  return file;
}

std::vector<DICOMFileAttributes>
CTSeries(int count, const std::string & prefix = "IM", const std::string & uid = "1.2.3.4")
{
  std::vector<DICOMFileAttributes> files;
  for (int k = 0; k < count; ++k)
  {
    files.push_back(CTFile(prefix + std::to_string(k + 1) + ".dcm", k, uid));
  }
  return files;
}

bool
Contains(const std::string & text, const std::string & part)
{
  return text.find(part) != std::string::npos;
}

/** The refusal CheckDICOMImageSet gives for the files, all in one set. */
std::string
Check(const std::vector<DICOMFileAttributes> & files, DICOMImageLayout & layout)
{
  DICOMImageSet set;
  for (std::size_t k = 0; k < files.size(); ++k)
  {
    set.Files.push_back(k);
  }
  return CheckDICOMImageSet(files, set, layout);
}
} // namespace

TEST(DICOMSeriesGroups, TwoSeriesAreListedByNumberWithTheirFilesWhenFew)
{
  auto files = CTSeries(4);
  auto scout = CTSeries(2, "scout", "1.2.3.5");
  for (auto & file : scout)
  {
    file.Values[SeriesNumber.Key()] = "1";
    file.Values[SeriesDescription.Key()] = "Topogram";
    file.Values[Rows.Key()] = "256";
  }
  files.insert(files.end(), scout.begin(), scout.end());
  const auto sets = GroupDICOMImages(files);
  ASSERT_EQ(sets.size(), 2u);
  EXPECT_EQ(sets[0].Files, (std::vector<std::size_t>{ 4, 5 })) << "series 1 before series 3";
  EXPECT_EQ(sets[1].Files, (std::vector<std::size_t>{ 0, 1, 2, 3 }));
  const auto summaries = SummarizeDICOMImageSets(files, sets);
  ASSERT_EQ(summaries.size(), 2u);
  EXPECT_EQ(summaries[0].Number, 1u);
  EXPECT_EQ(summaries[0].SeriesInstanceUID, "1.2.3.5");
  EXPECT_EQ(summaries[0].Files, 2u);
  EXPECT_EQ(summaries[0].Rows, 256u);
  EXPECT_EQ(summaries[0].Columns, 512u);
  EXPECT_EQ(summaries[0].Detail, "files /in/scout1.dcm, /in/scout2.dcm");
  EXPECT_EQ(summaries[1].Detail, "") << "four files are not listed";
  EXPECT_EQ(vr::DescribeDICOMSeries(summaries[1]),
            "2: series 3 \"CTA\" (CT), 4 files of 512 x 512 pixels, Series Instance UID 1.2.3.4");
}

TEST(DICOMSeriesGroups, OneUIDIsSplitWhereSizeFormatOrientationOrFrameDifferAndTheOddFileIsSaidHow)
{
  for (const auto & [tag, value] :
       std::vector<std::pair<DICOMAttributeTag, std::string>>{ { Rows, "256" },
                                                               { Columns, "511" },
                                                               { BitsAllocated, "8" },
                                                               { BitsStored, "16" },
                                                               { PixelRepresentation, "1" },
                                                               { PhotometricInterpretation, "MONOCHROME1" },
                                                               { SamplesPerPixel, "3" },
                                                               { FrameOfReferenceUID, "1.2.3.10" },
                                                               { ImageOrientation, "1\\0\\0\\0\\0.9998\\0.0175" } })
  {
    auto files = CTSeries(5);
    files[2].Values[tag.Key()] = value;
    const auto sets = GroupDICOMImages(files);
    ASSERT_EQ(sets.size(), 2u) << tag.Name;
    const auto   summaries = SummarizeDICOMImageSets(files, sets);
    const auto & odd = summaries[0].Files == 1 ? summaries[0] : summaries[1];
    EXPECT_TRUE(Contains(odd.Detail, tag.Label() + " " + value + ", not ")) << odd.Detail;
    EXPECT_TRUE(Contains(odd.Detail, "(the other 4 files of this Series Instance UID); file /in/IM3.dcm"))
      << odd.Detail;
  }
  // The transfer syntax's family splits; its two little-endian forms do not.
  auto files = CTSeries(5);
  files[1].Values[TransferSyntaxUID.Key()] = "1.2.840.10008.1.2";
  EXPECT_EQ(GroupDICOMImages(files).size(), 1u);
  files[1].Values[TransferSyntaxUID.Key()] = "1.2.840.10008.1.2.2";
  const auto sets = GroupDICOMImages(files);
  ASSERT_EQ(sets.size(), 2u);
  EXPECT_TRUE(Contains(sets[1].Difference, "transfer syntax native big-endian, not native little-endian"))
    << sets[1].Difference;
  // An orientation within 1e-4 is the same.
  files = CTSeries(5);
  files[4].Values[ImageOrientation.Key()] = "1\\0\\0\\0\\0.99999\\0.00005";
  EXPECT_EQ(GroupDICOMImages(files).size(), 1u);
}

TEST(DICOMSeriesGroups, ASeriesIsChosenByItsNumberOrUIDAndAChoiceOfNoneIsSaid)
{
  auto files = CTSeries(3);
  auto other = CTSeries(2, "B", "1.2.3.5");
  files.insert(files.end(), other.begin(), other.end());
  auto sets = GroupDICOMImages(files);
  ASSERT_EQ(sets.size(), 2u);
  std::size_t chosen = 9;
  EXPECT_EQ(ChooseDICOMImageSet(files, sets, "2", chosen), "");
  EXPECT_EQ(chosen, 1u);
  EXPECT_EQ(ChooseDICOMImageSet(files, sets, "1.2.3.5", chosen), "");
  EXPECT_EQ(files[sets[chosen].Files.front()].File, "/in/B1.dcm");
  EXPECT_TRUE(Contains(ChooseDICOMImageSet(files, sets, "3", chosen),
                       "the DICOM series chosen, 3, is no series of the "
                       "folder: the folder holds 2 series"));
  EXPECT_TRUE(Contains(ChooseDICOMImageSet(files, sets, "0", chosen), "numbered from 1"));
  EXPECT_TRUE(Contains(ChooseDICOMImageSet(files, sets, "1.2.3.7", chosen), "no file has that Series Instance UID"));
  // A UID split in two is chosen by number only.
  files[0].Values[Rows.Key()] = "256";
  sets = GroupDICOMImages(files);
  ASSERT_EQ(sets.size(), 3u);
  EXPECT_TRUE(Contains(ChooseDICOMImageSet(files, sets, "1.2.3.4", chosen), "holds 2 sets of images"));
}

TEST(DICOMSeriesGroups, ASoundSetGivesItsLayoutFileByFile)
{
  auto files = CTSeries(3);
  files[1].Values[RescaleSlope.Key()] = "0.5";
  files[1].Values[RescaleIntercept.Key()] = "-1000";
  DICOMImageLayout layout;
  ASSERT_EQ(Check(files, layout), "");
  EXPECT_EQ(layout.Rows, 512u);
  EXPECT_EQ(layout.Columns, 512u);
  EXPECT_EQ(layout.BitsAllocated, 16u);
  EXPECT_EQ(layout.PixelSpacing, (std::array<double, 2>{ 0.7, 0.6 }));
  EXPECT_EQ(layout.Orientation, (std::array<double, 6>{ 1, 0, 0, 0, 1, 0 }));
  EXPECT_EQ(layout.Positions[2], (std::array<double, 3>{ -100, -120, 4 }));
  EXPECT_EQ(layout.Slopes, (std::vector<double>{ 1, 0.5, 1 }));
  EXPECT_EQ(layout.Intercepts, (std::vector<double>{ -1024, -1000, -1024 }));
  // No rescale in any file: the identity (an MR's values as stored).
  for (auto & file : files)
  {
    file.Values.erase(RescaleSlope.Key());
    file.Values.erase(RescaleIntercept.Key());
  }
  ASSERT_EQ(Check(files, layout), "");
  EXPECT_EQ(layout.Slopes, (std::vector<double>{ 1, 1, 1 }));
  EXPECT_EQ(layout.Intercepts, (std::vector<double>{ 0, 0, 0 }));
}

TEST(DICOMSeriesGroups, EachRefusalNamesTheFileTheAttributeAndTheValue)
{
  struct Case
  {
    int               Index;
    DICOMAttributeTag Tag;
    std::string       Value; // "" removes it
    std::string       Said;
  };
  const std::vector<Case> cases = {
    { 0, SamplesPerPixel, "3", "/in/IM1.dcm: its Samples per Pixel (0028,0002) is \"3\": a volume must be scalar" },
    { 0, PhotometricInterpretation, "RGB", "Photometric Interpretation (0028,0004) is \"RGB\": a volume must be grey" },
    { 0, BitsAllocated, "12", "Bits Allocated (0028,0100) is \"12\": 8, 16 or 32 is expected" },
    { 0, HighBit, "15", "High Bit (0028,0102) is \"15\": one below the 12 bits stored" },
    { 0, Rows, "not a 2-byte value", "Rows (0028,0010) is \"not a 2-byte value\"" },
    { 0,
      TransferSyntaxUID,
      "1.2.3.4.5",
      "Transfer Syntax UID (0002,0010) is \"1.2.3.4.5\": a transfer syntax the reader" },
    { 1,
      NumberOfFrames,
      "2",
      "/in/IM2.dcm: its Number of Frames (0028,0008) is \"2\": the reader reads series of "
      "single-frame images" },
    { 2, ImagePosition, "", "the DICOM file /in/IM3.dcm lacks the Image Position (Patient) (0020,0032)" },
    { 2,
      ImagePosition,
      "-100\\-120",
      "/in/IM3.dcm: its Image Position (Patient) (0020,0032) is \"-100\\-120\", not 3 "
      "decimal numbers" },
    { 1, PixelSpacing, "", "the DICOM file /in/IM2.dcm lacks the Pixel Spacing (0028,0030)" },
    { 1,
      PixelSpacing,
      "0.7\\0.65",
      "the DICOM file /in/IM2.dcm: its Pixel Spacing (0028,0030) (0.7, 0.65) mm differs "
      "from the series' (0.7, 0.6) mm" },
    { 1, PixelSpacing, "0\\0.6", "/in/IM2.dcm: its Pixel Spacing (0028,0030) is \"0\\0.6\": two spacings above 0 mm" },
    { 1, RescaleSlope, "inf", "/in/IM2.dcm: its Rescale Slope (0028,1053) is \"inf\", not a finite decimal number" },
    { 1, RescaleSlope, "0", "/in/IM2.dcm: its Rescale Slope (0028,1053) is \"0\": a slope of 0 or larger than 1e9" },
    { 1, RescaleSlope, "1e308", "/in/IM2.dcm: its Rescale Slope (0028,1053) is \"1e308\": a slope of 0 or larger" },
    { 2, RescaleIntercept, "-inf", "/in/IM3.dcm: its Rescale Intercept (0028,1052) is \"-inf\", not a finite decimal" },
    { 2,
      RescaleIntercept,
      "1e308",
      "/in/IM3.dcm: its Rescale Intercept (0028,1052) is \"1e308\": an intercept larger" },
    { 2,
      RescaleIntercept,
      "",
      "the DICOM file /in/IM3.dcm has a Rescale Slope (0028,1053) but no Rescale Intercept "
      "(0028,1052): its values cannot be told" },
  };
  for (const Case & c : cases)
  {
    auto files = CTSeries(3);
    if (c.Value.empty())
    {
      files[c.Index].Values.erase(c.Tag.Key());
    }
    else
    {
      files[c.Index].Values[c.Tag.Key()] = c.Value;
    }
    DICOMImageLayout  layout;
    const std::string refusal = Check(files, layout);
    EXPECT_TRUE(Contains(refusal, c.Said)) << c.Tag.Name << " " << c.Value << ": " << refusal;
  }
  // Neither rescale attribute in one file where the others have both.
  {
    auto files = CTSeries(3);
    files[1].Values.erase(RescaleSlope.Key());
    files[1].Values.erase(RescaleIntercept.Key());
    DICOMImageLayout layout;
    EXPECT_TRUE(Contains(Check(files, layout),
                         "the DICOM file /in/IM2.dcm lacks the Rescale Slope (0028,1053) that the series' other files "
                         "have"));
  }
  // No Pixel Spacing in any file: Nominal Scanned Pixel Spacing, as a secondary capture holds it, and said where from.
  {
    auto files = CTSeries(3);
    for (auto & file : files)
    {
      file.Values.erase(PixelSpacing.Key());
      file.Values[NominalScannedPixelSpacing.Key()] = "2\\2";
    }
    DICOMImageLayout layout;
    EXPECT_EQ(Check(files, layout), "");
    EXPECT_EQ(layout.PixelSpacing, (std::array<double, 2>{ 2, 2 }));
    EXPECT_EQ(layout.PixelSpacingSource, "Nominal Scanned Pixel Spacing (0018,2010)");
  }
  // An orientation that is no pair of orthogonal unit vectors, in every file.
  auto files = CTSeries(3);
  for (auto & file : files)
  {
    file.Values[ImageOrientation.Key()] = "1\\0\\0\\0.5\\1\\0";
  }
  DICOMImageLayout layout;
  EXPECT_TRUE(Contains(Check(files, layout), "two orthogonal unit vectors")) << Check(files, layout);
}
