// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Where a DICOM series' slices lie (vrDICOMSliceGeometry.h), on positions written out by hand: decimal strings against
// DICOM's grammar (the corrupt values are those of issue 25's mutation campaign); the grid of a sound series in any
// file order, head or feet first, oblique; a gap of whole slices interpolated with a warning naming the files and the
// positions made up, and what is refused instead, each naming the files: a larger gap, uneven steps, a file off the
// line, a tilted gantry, two images at one position. The expected grids are worked out by hand in each test.
#include "vrDICOMSliceGeometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace
{
using vr::detail::DICOMSliceGrid;
using vr::detail::DICOMSlicePosition;
using vr::detail::ParseDecimalStrings;
using vr::detail::PlanDICOMSliceGrid;

constexpr std::array<double, 6> Axial{ 1, 0, 0, 0, 1, 0 };

/** Files /in/IM0001.dcm ... at (x, y, z) for each z of \a zs. */
std::vector<DICOMSlicePosition>
AtHeights(const std::vector<double> & zs, double x = -156.445, double y = -24.6094)
{
  std::vector<DICOMSlicePosition> files;
  for (std::size_t k = 0; k < zs.size(); ++k)
  {
    char name[32];
    std::snprintf(name, sizeof(name), "/in/IM%04zu.dcm", k + 1);
    files.push_back({ name, { x, y, zs[k] } });
  }
  return files;
}

bool
Contains(const std::string & text, const std::string & part)
{
  return text.find(part) != std::string::npos;
}

/** Plans with every pair of files at one position holding the same pixels when \a same. */
std::string
Plan(const std::vector<DICOMSlicePosition> & files,
     DICOMSliceGrid &                        grid,
     const std::array<double, 6> &           orientation = Axial,
     bool                                    same = true)
{
  return PlanDICOMSliceGrid(
    files, orientation, 0.5, [same](std::size_t, std::size_t) { return same; }, std::nullopt, grid);
}

/** The input index of each grid slice that is one file's; -1 for an interpolated one. */
std::vector<int>
FileOfEachSlice(const DICOMSliceGrid & grid)
{
  std::vector<int> files;
  for (const auto & slice : grid.Slices)
  {
    files.push_back(slice.Weight == 0.0 ? static_cast<int>(slice.First) : -1);
  }
  return files;
}
} // namespace

TEST(DICOMSliceGeometry, DecimalStringsFollowDICOMsGrammar)
{
  EXPECT_EQ(ParseDecimalStrings("-156.445\\-24.6094\\27.00162", 3),
            (std::vector<double>{ -156.445, -24.6094, 27.00162 }));
  EXPECT_EQ(ParseDecimalStrings(" 1.5e-3\\+2 \\3.", 3), (std::vector<double>{ 1.5e-3, 2.0, 3.0 }));
  EXPECT_EQ(ParseDecimalStrings(".878906\\.878906 ", 2), (std::vector<double>{ 0.878906, 0.878906 }));
  EXPECT_EQ(ParseDecimalStrings("-156.44531250000001\\0\\0", 3)->front(), -156.44531250000001) << "over 16 characters";
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

TEST(DICOMSliceGeometry, ASoundSeriesInAnyFileOrderIsOneSliceAFileAlongTheNormal)
{
  // Files named top-down (z 8, 6, 4, 2, 0): the grid runs up the normal, +z, from the lowest.
  DICOMSliceGrid    grid;
  const std::string refusal = Plan(AtHeights({ 8, 6, 4, 2, 0 }), grid);
  ASSERT_EQ(refusal, "");
  EXPECT_EQ(FileOfEachSlice(grid), (std::vector<int>{ 4, 3, 2, 1, 0 }));
  EXPECT_DOUBLE_EQ(grid.SliceSpacing, 2.0);
  EXPECT_NEAR(grid.Origin[0], -156.445, 1e-12);
  EXPECT_NEAR(grid.Origin[1], -24.6094, 1e-12);
  EXPECT_NEAR(grid.Origin[2], 0.0, 1e-12);
  EXPECT_EQ(grid.Normal, (std::array<double, 3>{ 0, 0, 1 }));
  EXPECT_TRUE(grid.Warnings.empty());
  EXPECT_TRUE(grid.Duplicates.empty());

  // Positions written with the last digit rounded (within 5 % of the step): the same grid.
  ASSERT_EQ(Plan(AtHeights({ 0, 2.004, 3.998, 6.002, 8 }), grid), "");
  EXPECT_EQ(grid.Slices.size(), 5u);
  EXPECT_NEAR(grid.SliceSpacing, 2.0, 0.005);
}

TEST(DICOMSliceGeometry, FeetFirstAndObliqueSeriesRunAlongTheirOwnNormal)
{
  // Feet first: rows run to the patient's left (-x), so the normal (-x) x (+y) is -z: the grid starts at the top.
  DICOMSliceGrid grid;
  ASSERT_EQ(Plan(AtHeights({ 0, 3, 6, 9 }), grid, { -1, 0, 0, 0, 1, 0 }), "");
  EXPECT_EQ(grid.Normal, (std::array<double, 3>{ 0, 0, -1 }));
  EXPECT_EQ(FileOfEachSlice(grid), (std::vector<int>{ 3, 2, 1, 0 }));
  EXPECT_NEAR(grid.Origin[2], 9.0, 1e-12);
  EXPECT_DOUBLE_EQ(grid.SliceSpacing, 3.0);

  // Turned 30 degrees about x: row (1, 0, 0), column (0, cos, sin), normal (0, -sin, cos); slices 1.25 mm apart on it.
  const double                    c = std::cos(M_PI / 6.0);
  const double                    s = std::sin(M_PI / 6.0);
  std::vector<DICOMSlicePosition> oblique;
  for (int k = 0; k < 6; ++k)
  {
    oblique.push_back({ "/in/O" + std::to_string(k) + ".dcm", { 10.0, 5.0 - 1.25 * k * s, -3.0 + 1.25 * k * c } });
  }
  ASSERT_EQ(Plan(oblique, grid, { 1, 0, 0, 0, c, s }), "");
  EXPECT_NEAR(grid.SliceSpacing, 1.25, 1e-12);
  EXPECT_NEAR(grid.Normal[1], -s, 1e-12);
  EXPECT_NEAR(grid.Normal[2], c, 1e-12);
  for (int d = 0; d < 3; ++d)
  {
    EXPECT_NEAR(grid.Origin[d], oblique.front().Position[d], 1e-12);
  }
}

TEST(DICOMSliceGeometry, AGapOfWholeSlicesIsInterpolatedAndSaidWithItsFilesAndPositions)
{
  // z 0, 2, 4, _, 8, 10: one slice missing at 6, halfway between IM0003.dcm and IM0004.dcm.
  DICOMSliceGrid grid;
  ASSERT_EQ(Plan(AtHeights({ 0, 2, 4, 8, 10 }), grid), "");
  EXPECT_EQ(FileOfEachSlice(grid), (std::vector<int>{ 0, 1, 2, -1, 3, 4 }));
  EXPECT_EQ(grid.Slices[3].First, 2u);
  EXPECT_EQ(grid.Slices[3].Second, 3u);
  EXPECT_DOUBLE_EQ(grid.Slices[3].Weight, 0.5);
  ASSERT_EQ(grid.Warnings.size(), 1u);
  const std::string & warning = grid.Warnings.front();
  EXPECT_TRUE(Contains(warning, "a gap of 4 mm between the files /in/IM0003.dcm and /in/IM0004.dcm")) << warning;
  EXPECT_TRUE(Contains(warning, "where it steps by 2 mm")) << warning;
  EXPECT_TRUE(Contains(warning, "the missing slice at (-156.445, -24.6094, 6) mm is interpolated linearly")) << warning;

  // Two missing (at 4 and 6): weights 1/3 and 2/3, both positions named.
  ASSERT_EQ(Plan(AtHeights({ 0, 2, 8, 10, 12 }), grid), "");
  EXPECT_EQ(FileOfEachSlice(grid), (std::vector<int>{ 0, 1, -1, -1, 2, 3, 4 }));
  EXPECT_NEAR(grid.Slices[2].Weight, 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(grid.Slices[3].Weight, 2.0 / 3.0, 1e-15);
  ASSERT_EQ(grid.Warnings.size(), 1u);
  EXPECT_TRUE(Contains(grid.Warnings.front(),
                       "2 missing slices, at (-156.445, -24.6094, 4), (-156.445, -24.6094, 6) mm, "
                       "are interpolated"))
    << grid.Warnings.front();

  // Four missing: refused, naming the two files around the gap.
  const std::string refusal = Plan(AtHeights({ 0, 2, 12, 14, 16 }), grid);
  EXPECT_TRUE(Contains(refusal, "the DICOM files /in/IM0002.dcm and /in/IM0003.dcm lie 10 mm apart")) << refusal;
  EXPECT_TRUE(Contains(refusal, "4 slices are missing between them, more than the 3")) << refusal;
}

TEST(DICOMSliceGeometry, UnevenStepsAreRefusedNamingTheFilesAroundThem)
{
  DICOMSliceGrid grid;
  // IM0004.dcm at 5.2 instead of 6 (40 % of a step): the step from IM0003.dcm is 1.2 mm.
  std::string refusal = Plan(AtHeights({ 0, 2, 4, 5.2, 8, 10 }), grid);
  EXPECT_TRUE(Contains(refusal,
                       "the DICOM files /in/IM0003.dcm and /in/IM0004.dcm lie 1.2 mm apart along the slice "
                       "normal, where the series steps by 2 mm"))
    << refusal;
  // Moved half a step, toward the other neighbour: a step of 3 looks like 1.5 steps, and is named.
  refusal = Plan(AtHeights({ 0, 2, 4, 6, 9, 10, 12, 14 }), grid);
  EXPECT_TRUE(Contains(refusal, "/in/IM0004.dcm and /in/IM0005.dcm lie 3 mm apart")) << refusal;
  // 0.2 mm off (10 % of a step, twice the tolerance): refused too.
  refusal = Plan(AtHeights({ 0, 2, 4.2, 6, 8 }), grid);
  EXPECT_TRUE(Contains(refusal, "/in/IM0002.dcm and /in/IM0003.dcm lie 2.2 mm apart")) << refusal;
}

TEST(DICOMSliceGeometry, AFileOffTheLineIsNamedAndATiltedSeriesIsRefusedWithItsAngle)
{
  DICOMSliceGrid grid;
  auto           files = AtHeights({ 0, 2, 4, 6, 8, 10 });
  files[3].Position[0] += 1.0;
  std::string refusal = Plan(files, grid);
  EXPECT_TRUE(Contains(refusal, "the DICOM file /in/IM0004.dcm lies off the series' line of slices")) << refusal;
  EXPECT_TRUE(Contains(refusal, "is 1 mm aside")) << refusal;

  // A gantry tilted 15 degrees: each slice 2 tan(15) = 0.536 mm further along y.
  auto tilted = AtHeights({ 0, 2, 4, 6, 8, 10 });
  for (auto & file : tilted)
  {
    file.Position[1] += std::tan(15.0 * M_PI / 180.0) * file.Position[2];
  }
  refusal = PlanDICOMSliceGrid(
    tilted, Axial, 0.5, [](std::size_t, std::size_t) { return true; }, std::string("15"), grid);
  EXPECT_TRUE(Contains(refusal, "the DICOM series is tilted (a gantry tilt)")) << refusal;
  EXPECT_TRUE(Contains(refusal, "at 15 degrees to their normal")) << refusal;
  EXPECT_TRUE(Contains(refusal, "Gantry/Detector Tilt (0018,1120): \"15\"")) << refusal;
  EXPECT_TRUE(Contains(refusal, "shear the anatomy by up to 2.68 mm")) << refusal; // 10 tan 15

  // Aside by less than 5 % of the 0.5 mm pixels (0.025 mm): read.
  files = AtHeights({ 0, 2, 4, 6, 8, 10 });
  files[2].Position[1] += 0.02;
  EXPECT_EQ(Plan(files, grid), "");
}

TEST(DICOMSliceGeometry, TwoFilesAtOnePositionAreOneWhenTheirPixelsAgreeAndRefusedWhenNot)
{
  DICOMSliceGrid grid;
  auto           files = AtHeights({ 0, 2, 4, 6 });
  files.push_back({ "/in/copy.dcm", files[2].Position });
  ASSERT_EQ(Plan(files, grid), "");
  EXPECT_EQ(FileOfEachSlice(grid), (std::vector<int>{ 0, 1, 2, 3 }));
  EXPECT_EQ(grid.Duplicates, (std::vector<std::size_t>{ 4 }));
  ASSERT_EQ(grid.Warnings.size(), 1u);
  EXPECT_TRUE(Contains(grid.Warnings.front(),
                       "the DICOM file /in/copy.dcm lies at the same position as /in/IM0003.dcm "
                       "and holds the same pixels: a duplicate, left out"))
    << grid.Warnings.front();

  const std::string refusal = Plan(files, grid, Axial, false);
  EXPECT_TRUE(Contains(refusal, "the DICOM files /in/IM0003.dcm and /in/copy.dcm both lie in the slice plane at 4 mm"))
    << refusal;
  EXPECT_TRUE(Contains(refusal, "hold different images")) << refusal;
}
