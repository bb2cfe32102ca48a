// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The DICOM reader process's check of a series' geometry attributes (vrDICOMSliceGeometry.h) on series written out
// by hand: decimal strings against DICOM's grammar (the corrupt values are those of the mutation campaign), and
// series with one file missing an attribute, at another orientation or spacing, or off the line of slices, each named;
// a series with a missing slice or stored top-down passes.
#include "vrDICOMSliceGeometry.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace
{
using vr::detail::CheckDICOMSliceGeometry;
using vr::detail::DICOMSliceAttributes;
using vr::detail::ParseDecimalStrings;

/** An axial series of \a count files IM0001.dcm ... at z = 0, 2, 4, ... mm, 0.5 mm pixels. */
std::vector<DICOMSliceAttributes>
Series(std::size_t count)
{
  std::vector<DICOMSliceAttributes> slices;
  for (std::size_t k = 0; k < count; ++k)
  {
    slices.push_back({ "/in/IM000" + std::to_string(k + 1) + ".dcm",
                       "-156.445\\-24.6094\\" + std::to_string(2 * k),
                       "1\\0\\0\\0\\1\\0 ",
                       ".5\\.5 " });
  }
  return slices;
}

bool
Contains(const std::string & text, const std::string & part)
{
  return text.find(part) != std::string::npos;
}
} // namespace

TEST(DICOMSliceGeometry, DecimalStringsFollowDICOMsGrammar)
{
  EXPECT_EQ(ParseDecimalStrings("-156.445\\-24.6094\\27.00162", 3),
            (std::vector<double>{ -156.445, -24.6094, 27.00162 }));
  EXPECT_EQ(ParseDecimalStrings(" 1.5e-3\\+2 \\3.", 3), (std::vector<double>{ 1.5e-3, 2.0, 3.0 }));
  EXPECT_EQ(ParseDecimalStrings(".878906\\.878906 ", 2), (std::vector<double>{ 0.878906, 0.878906 }));
  EXPECT_EQ(ParseDecimalStrings("-156.44531250000001\\0\\0", 3)->front(), -156.44531250000001) << "over 16 characters";
  // What the campaign's byte changes made of positions (GDCM reads each leniently, as a wrong number).
  for (const char * corrupt : { "-1.6.445\\-24.6094\\27.00162",
                                "-156..45\\-24.6094\\13.50081",
                                "-156.445.-24.6094\\34.50207",
                                "-156\\445\\-24.6094\\34.50207",
                                "-15v.445\\-24.6094\\24.00144",
                                "-156\xff"
                                "445\\-24.6094\\3.00018 ",
                                "1\\2",
                                "1\\\\2",
                                "1e\\2\\3",
                                "nan\\0\\0",
                                "1e999\\0\\0",
                                "" })
  {
    EXPECT_FALSE(ParseDecimalStrings(corrupt, 3)) << corrupt;
  }
}

// One file alone, as the reader process checks each before GDCM sorts the folder: the syntax only.
TEST(DICOMSliceGeometry, OneFileAloneIsCheckedForSyntax)
{
  const DICOMSliceAttributes sound = Series(1).front();
  EXPECT_EQ(vr::detail::CheckDICOMSliceAttributes(sound), "");
  EXPECT_EQ(vr::detail::CheckDICOMSliceAttributes({ "/in/bare.dcm", std::nullopt, std::nullopt, std::nullopt }), "");
  DICOMSliceAttributes corrupt = sound;
  corrupt.Position = "-156.445\\?24.6094\\19.50117";
  EXPECT_TRUE(Contains(vr::detail::CheckDICOMSliceAttributes(corrupt), "/in/IM0001.dcm: its Image Position (Patient)"));
  corrupt = sound;
  corrupt.PixelSpacing = ".8\x9f"
                         "8906\\.878906 ";
  EXPECT_TRUE(Contains(vr::detail::CheckDICOMSliceAttributes(corrupt),
                       "its Pixel Spacing (0028,0030) is \".8?8906\\.878906 \", not 2"));
}

TEST(DICOMSliceGeometry, ASoundSeriesPasses)
{
  EXPECT_EQ(CheckDICOMSliceGeometry(Series(8)), "");
  EXPECT_EQ(CheckDICOMSliceGeometry(Series(1)), "");
  EXPECT_EQ(CheckDICOMSliceGeometry({}), "");
  auto missing = Series(8); // the fourth slice is missing: a double step between two regular ones
  missing.erase(missing.begin() + 3);
  EXPECT_EQ(CheckDICOMSliceGeometry(missing), "");
  auto downwards = Series(8);
  std::reverse(downwards.begin(), downwards.end());
  EXPECT_EQ(CheckDICOMSliceGeometry(downwards), "");
  auto bare = Series(8); // no geometry attributes at all: ITK's defaults, nothing to compare
  for (auto & slice : bare)
  {
    slice.Position = slice.Orientation = slice.PixelSpacing = std::nullopt;
  }
  EXPECT_EQ(CheckDICOMSliceGeometry(bare), "");
}

TEST(DICOMSliceGeometry, EachFaultNamesItsFile)
{
  auto corrupt = Series(8);
  corrupt[4].Position = "-1.6.445\\-24.6094\\8";
  const std::string malformed = CheckDICOMSliceGeometry(corrupt);
  EXPECT_TRUE(Contains(malformed,
                       "/in/IM0005.dcm: its Image Position (Patient) (0020,0032) is \"-1.6.445\\-24.6094\\8\", "
                       "not 3 decimal numbers"))
    << malformed;

  auto lacking = Series(8);
  lacking[2].Orientation.reset();
  EXPECT_TRUE(
    Contains(CheckDICOMSliceGeometry(lacking),
             "/in/IM0003.dcm lacks the Image Orientation (Patient) (0020,0037) that the series' other files have"));

  auto firstLacking = Series(8); // ITK would take the origin from the first file, which has none
  firstLacking[0].Position.reset();
  EXPECT_TRUE(Contains(CheckDICOMSliceGeometry(firstLacking), "/in/IM0001.dcm lacks the Image Position (Patient)"));

  auto turned = Series(8);
  turned[6].Orientation = "0\\1\\0\\1\\0\\0";
  EXPECT_TRUE(Contains(CheckDICOMSliceGeometry(turned), "/in/IM0007.dcm: its Image Orientation (Patient) (0020,0037)"));

  auto firstTurned = Series(8); // the series' orientation is the files' median, not the first file's
  firstTurned[0].Orientation = "0\\1\\0\\1\\0\\0";
  EXPECT_TRUE(Contains(CheckDICOMSliceGeometry(firstTurned), "/in/IM0001.dcm: its Image Orientation"));

  auto spaced = Series(8);
  spaced[5].PixelSpacing = "0.6\\0.5";
  EXPECT_TRUE(
    Contains(CheckDICOMSliceGeometry(spaced), "/in/IM0006.dcm: its Pixel Spacing (0028,0030) (0.6, 0.5) differs"));

  auto shifted = Series(8); // in the plane, 5 mm off
  shifted[3].Position = "-151.445\\-24.6094\\6";
  const std::string off = CheckDICOMSliceGeometry(shifted);
  EXPECT_TRUE(Contains(off, "/in/IM0004.dcm lies off the series' line of slices")) << off;

  auto firstShifted = Series(8); // the first file, from which ITK takes the origin
  firstShifted[0].Position = "-156.445\\75.3906\\0";
  EXPECT_TRUE(Contains(CheckDICOMSliceGeometry(firstShifted), "/in/IM0001.dcm lies off the series' line of slices"));

  auto lastShifted = Series(8);
  lastShifted[7].Position = "-156.445\\-24.6094\\15";
  EXPECT_TRUE(Contains(CheckDICOMSliceGeometry(lastShifted), "/in/IM0008.dcm lies off"));
}
