// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The lumen table (docs/lumen-measurement.md): its columns, the centre in RAS, empty cells, CSV or TSV by the
// extension, the grading's comment lines and row marks, and nothing written for an unknown one.
#include "vrLumenTableIO.h"
#include "vrTestFiles.h"

#include "vrText.h"

#include "gtest/gtest.h"

#include <cmath>
#include <sstream>

namespace
{
itk::VesselLumenProfile
TwoSections()
{
  itk::VesselLumenProfile profile;
  profile.Source = itk::VesselLumenSource::Segmentation;
  itk::VesselLumenSection inside;
  inside.ArcLength = 0.5;
  inside.Center[0] = 10.0;  // L
  inside.Center[1] = -20.0; // P
  inside.Center[2] = 30.0;  // S
  inside.CenterInSegmentation = true;
  inside.Area = 12.5;
  inside.EquivalentDiameter = 4.0;
  inside.MinimumDiameter = 3.5;
  inside.MaximumDiameter = 4.5;
  inside.Diameter = 4.0;
  inside.ReferenceDiameter = 8.0;
  inside.ReferenceArea = 50.25;
  inside.BranchId = 3;
  itk::VesselLumenSection outside;
  outside.ArcLength = 1.5;
  outside.Center[0] = -1.0;
  outside.Center[1] = 2.0;
  outside.Center[2] = -3.0;
  outside.InscribedDiameter = 6.0;
  outside.ReferenceDiameter = 7.0;
  outside.BranchId = 3;
  profile.Sections = { inside, outside };
  return profile;
}

std::vector<std::string>
Lines(const std::string & text)
{
  std::vector<std::string> lines;
  std::istringstream       stream(text);
  for (std::string line; std::getline(stream, line);)
  {
    lines.push_back(line);
  }
  return lines;
}

TEST(LumenTableIO, ColumnsAndRASSigns)
{
  vr::test::ScopedTemporaryFolder folder;
  const std::string               path = folder.File("lumen.csv");
  vr::WriteLumenTable(TwoSections(), path);
  const auto lines = Lines(vr::test::ReadTextFile(path));
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0],
            "arc_length_mm,ras_r_mm,ras_a_mm,ras_s_mm,area_mm2,equivalent_diameter_mm,min_diameter_mm,"
            "max_diameter_mm,reference_diameter_mm,diameter_mm,inscribed_diameter_mm,reference_area_mm2,"
            "diameter_stenosis_percent,source,in_segmentation,region_clipped,branch_id,segment,mld_candidate,"
            "excluded_because");
  // ras_r = -L, ras_a = -P, ras_s = S; local stenosis 100 (1 - 4 / 8) = 50; no marks without notes.
  EXPECT_EQ(lines[1], "0.5,-10,20,30,12.5,4,3.5,4.5,8,4,,50.25,50,segmentation,1,0,3,,,");
  // Outside the segmentation: nothing measured, empty cells; its 2r and reference stay.
  EXPECT_EQ(lines[2], "1.5,1,-2,-3,,,,,7,,6,,,segmentation,0,,3,,,");
  EXPECT_EQ(vr::SplitAndTrim(lines[0], ',').size(), std::size(vr::LumenTableColumns));
}

TEST(LumenTableIO, TabSeparatedByExtensionAndRadiusSourceLeavesInSegmentationEmpty)
{
  vr::test::ScopedTemporaryFolder folder;
  const std::string               path = folder.File("lumen.TSV");
  auto                            profile = TwoSections();
  profile.Source = itk::VesselLumenSource::CenterlineRadius;
  profile.Sections.resize(1);
  profile.Sections[0].Area = std::nan("");
  vr::WriteLumenTable(profile, path);
  const auto lines = Lines(vr::test::ReadTextFile(path));
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].rfind("arc_length_mm\tras_r_mm\tras_a_mm\tras_s_mm\tarea_mm2\t", 0), 0u);
  EXPECT_EQ(lines[1], "0.5\t-10\t20\t30\t\t4\t3.5\t4.5\t8\t4\t\t50.25\t50\tcenterline radius\t\t\t3\t\t\t");
}

TEST(LumenTableIO, NotesAreCommentsBeforeTheHeaderAndMarksAtTheEnd)
{
  vr::test::ScopedTemporaryFolder folder;
  const std::string               path = folder.File("lumen.csv");
  vr::LumenTableNotes             notes;
  notes.Comments = { "reference: interpolated within each segment", "two\nlines" };
  notes.Rows = { { 1, true, "" }, { 2, false, "origin of branch 4, and more" } };
  vr::WriteLumenTable(TwoSections(), path, notes);
  const auto lines = Lines(vr::test::ReadTextFile(path));
  ASSERT_EQ(lines.size(), 5u);
  EXPECT_EQ(lines[0], "# reference: interpolated within each segment");
  EXPECT_EQ(lines[1], "# two lines"); // a line break would end the comment
  EXPECT_EQ(lines[2].rfind("arc_length_mm,", 0), 0u);
  EXPECT_EQ(lines[3].substr(lines[3].size() - 5), ",1,1,");
  // The separator inside a reason would shift the columns: it becomes a semicolon.
  EXPECT_EQ(lines[4].substr(lines[4].rfind(",3,") + 3), "2,0,origin of branch 4; and more");
  // Marks for another number of rows: refused, nothing written.
  notes.Rows.pop_back();
  const std::string other = folder.File("other.csv");
  const std::string message = vr::test::InputErrorOf([&] { vr::WriteLumenTable(TwoSections(), other, notes); });
  EXPECT_TRUE(vr::test::Contains(message, "1 rows of marks for 2 sections")) << message;
  EXPECT_EQ(folder.Entries(), std::vector<std::string>{ "lumen.csv" });
}

TEST(LumenTableIO, UnknownExtensionWritesNothing)
{
  vr::test::ScopedTemporaryFolder folder;
  for (const std::string name : { "lumen.txt", "lumen", "lumen.csv.gz" })
  {
    const std::string path = folder.File(name);
    const std::string message = vr::test::InputErrorOf([&] { vr::WriteLumenTable(TwoSections(), path); });
    EXPECT_TRUE(vr::test::Contains(message, path)) << message;
    EXPECT_TRUE(vr::test::Contains(message, ".csv")) << message;
  }
  EXPECT_TRUE(folder.Entries().empty());
  EXPECT_EQ(vr::LumenTableSeparator("a/B.CsV"), ',');
  // A folder that does not exist: named, nothing written.
  const std::string missing = folder.File("no-such-folder/lumen.csv");
  EXPECT_TRUE(
    vr::test::Contains(vr::test::InputErrorOf([&] { vr::WriteLumenTable(TwoSections(), missing); }), "no-such-folder"));
  EXPECT_TRUE(folder.Entries().empty());
}

TEST(LumenTableIO, ExistingTableReplacedWhole)
{
  vr::test::ScopedTemporaryFolder folder;
  const std::string               path = folder.File("lumen.csv");
  vr::test::WriteTextFile(path, "old\n");
  vr::WriteLumenTable(TwoSections(), path);
  EXPECT_EQ(Lines(vr::test::ReadTextFile(path)).size(), 3u);
  EXPECT_EQ(folder.Entries(), std::vector<std::string>{ "lumen.csv" });
}
} // namespace
