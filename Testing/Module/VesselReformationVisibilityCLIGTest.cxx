// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The VesselReformation module in Visibility mode (issue 38): VMTK's aorta and the thoracic phantom at a sweep of
// angles (exit 0, the hidden lengths returned and tabled), --angle best against the occlusion profile it writes,
// centerlines without radii (a warning, a valid result), branches that all coincide in projection, and the flags that
// make no sense outside visibility mode (refused before the work, nothing written).

#include "itkCTAPhantom.h"
#include "vrCenterlineIO.h"
#include "vrImageIO.h"
#include "vrModuleRuns.h"
#include "vrTestFiles.h"
#include "vrText.h"
#include "vrVolumeIO.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace
{
namespace fs = std::filesystem;
using vr::test::RunProgram;

const std::string Executable = VR_REFORMATION_EXE;
const fs::path    AortaFolder = fs::path(VR_SHARED_DATA_DIR) / "vmtk-aorta-mra";

fs::path
Folder()
{
  return vr::test::FreshFolderForThisTest(VR_TEST_OUTPUT_DIR, "visibility-");
}

/** The "name = value" lines of a return-parameter file. */
std::map<std::string, std::string>
ReturnedValues(const fs::path & file)
{
  std::map<std::string, std::string> values;
  std::ifstream                      lines(file);
  for (std::string line; std::getline(lines, line);)
  {
    const auto at = line.find(" = ");
    if (at != std::string::npos)
    {
      values[line.substr(0, at)] = line.substr(at + 3);
    }
  }
  return values;
}

double
Number(const std::string & text)
{
  double value = 0.0;
  return vr::ParseWholeDouble(text, value) ? value : std::nan("");
}

/** The rows of a CSV file, split at commas (no quoted fields expected here). */
std::vector<std::vector<std::string>>
ReadCSV(const fs::path & file)
{
  std::vector<std::vector<std::string>> rows;
  std::ifstream                         lines(file);
  for (std::string line; std::getline(lines, line);)
  {
    rows.push_back(vr::SplitAndTrim(line, ','));
  }
  return rows;
}

/** The thoracic phantom at 2 mm as files a user would have: a NRRD volume and VMTK-style centerlines. */
struct ThoraxFiles
{
  std::string Volume;
  std::string Centerlines;
};

const ThoraxFiles &
Thorax()
{
  static const ThoraxFiles files = []
  {
    const fs::path folder = fs::path(VR_TEST_OUTPUT_DIR) / "visibility-thorax-phantom";
    fs::create_directories(folder);
    auto phantom = itk::MakeCTAPhantom(itk::CTAPhantomKind::Thorax, 2.0);
    phantom.Source->Update();
    ThoraxFiles written{ (folder / "thorax.nrrd").string(), (folder / "thorax-centerlines.vtp").string() };
    vr::WriteVolume(phantom.Source->GetOutput(), written.Volume);
    vr::WriteCenterlines(phantom.Tree, written.Centerlines);
    return written;
  }();
  return files;
}

/** Runs the module in visibility mode on \a volume and \a centerlines at \a angle, with the tables and the returned
 * values; checks exit 0 and that the returned hidden length is the table's. \return the returned values. */
std::map<std::string, std::string>
RunVisibility(const std::string &              volume,
              const std::string &              centerlines,
              const std::string &              angle,
              const fs::path &                 folder,
              const std::vector<std::string> & more = {})
{
  const fs::path           returned = folder / ("returned-" + angle + ".params");
  const fs::path           table = folder / ("hidden-" + angle + ".csv");
  std::vector<std::string> arguments = { Executable,
                                         "--mode",
                                         "visibility",
                                         "--angle",
                                         angle,
                                         "--size",
                                         "256,512",
                                         "--iterations",
                                         "50",
                                         "--backend",
                                         "cpu",
                                         "--returnparameterfile",
                                         returned.string(),
                                         "--outputHiddenLengths",
                                         table.string() };
  arguments.insert(arguments.end(), more.begin(), more.end());
  arguments.insert(arguments.end(), { volume, centerlines, (folder / ("cpr-" + angle + ".nrrd")).string() });
  const vr::test::ModuleRun run = RunProgram(arguments);
  EXPECT_EQ(run.ExitCode, 0) << run.Err;
  auto       values = ReturnedValues(returned);
  const auto rows = ReadCSV(table);
  EXPECT_GE(rows.size(), 3u);
  if (rows.size() >= 3)
  {
    EXPECT_EQ(rows.back()[1], "whole tree");
    EXPECT_NEAR(Number(rows.back()[3]), Number(values["hiddenLength"]), 1e-3 + 1e-6 * Number(rows.back()[3]));
  }
  EXPECT_TRUE(vr::test::Contains(run.Out, "hidden behind other vessels at")) << run.Out;
  return values;
}
} // namespace

TEST(VesselReformationVisibility, AortaAndThoraxAtASweepOfAnglesReturnTheirHiddenLengths)
{
  const fs::path folder = Folder();
  const auto &   thorax = Thorax();
  fs::create_directories(folder / "thorax");
  for (const int angle : { 0, 30, 60, 90, 120, 150 })
  {
    SCOPED_TRACE(angle);
    const auto aorta = RunVisibility((AortaFolder / "aorta.mha").string(),
                                     (AortaFolder / "aorta-centerline.vtp").string(),
                                     std::to_string(angle),
                                     folder,
                                     { "--up", "auto" });
    EXPECT_EQ(Number(aorta.at("angleUsed")), angle);
    EXPECT_GE(Number(aorta.at("hiddenLength")), 0.0);
    EXPECT_LE(Number(aorta.at("hiddenPercent")), 100.0);
    const auto phantom = RunVisibility(thorax.Volume, thorax.Centerlines, std::to_string(angle), folder / "thorax");
    EXPECT_GE(Number(phantom.at("hiddenLength")), 0.0);
    std::cout << "angle " << angle << ": aorta " << aorta.at("hiddenLength") << " mm (" << aorta.at("hiddenPercent")
              << " %), thorax " << phantom.at("hiddenLength") << " mm (" << phantom.at("hiddenPercent") << " %)\n";
  }
}

TEST(VesselReformationVisibility, AngleBestReturnsTheMinimumOfTheProfileItWrites)
{
  const fs::path folder = Folder();
  const auto &   thorax = Thorax();
  const auto     values = RunVisibility(thorax.Volume,
                                    thorax.Centerlines,
                                    "best",
                                    folder,
                                    { "--outputOcclusionProfile", (folder / "profile.csv").string() });
  const auto     profile = ReadCSV(folder / "profile.csv");
  ASSERT_EQ(profile.size(), 181u);
  EXPECT_EQ(profile[0], (std::vector<std::string>{ "angle_degrees", "hidden_length_mm", "hidden_percent" }));
  double       least = std::numeric_limits<double>::infinity();
  unsigned int at = 0;
  for (unsigned int row = 1; row < profile.size(); ++row)
  {
    const double hidden = Number(profile[row][1]);
    if (hidden < least)
    {
      least = hidden;
      at = row - 1;
    }
  }
  EXPECT_EQ(Number(values.at("angleUsed")), at);
  // The profile says which angle hides the most: the thorax's arch hides its descending part there.
  double most = 0.0;
  for (unsigned int row = 1; row < profile.size(); ++row)
  {
    most = std::max(most, Number(profile[row][1]));
  }
  EXPECT_GT(most, 50.0);
}

TEST(VesselReformationVisibility, CenterlinesWithoutRadiiWarnAndGiveAValidResult)
{
  const fs::path folder = Folder();
  // The thorax's centerlines as CSV without a radius column.
  auto                phantom = itk::MakeCTAPhantom(itk::CTAPhantomKind::Thorax, 2.0);
  itk::CenterlineTree bare = phantom.Tree;
  for (auto & branch : bare.GetBranches())
  {
    branch.Radii.clear();
  }
  const std::string csv = (folder / "bare.csv").string();
  vr::WriteCenterlines(bare, csv);
  const vr::test::ModuleRun run = RunProgram({ Executable,
                                               "--mode",
                                               "visibility",
                                               "--angle",
                                               "90",
                                               "--size",
                                               "128,256",
                                               "--iterations",
                                               "20",
                                               "--outputDepth",
                                               (folder / "depth.nrrd").string(),
                                               "--outputHiddenLabels",
                                               (folder / "hidden.nrrd").string(),
                                               Thorax().Volume,
                                               csv,
                                               (folder / "cpr.nrrd").string() });
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  // The file's six branches, split where a child leaves a trunk as the reader merges VMTK-style paths: all without.
  EXPECT_TRUE(vr::test::Contains(run.Err, "9 of 9 branches have no lumen radius")) << run.Err;
  EXPECT_TRUE(vr::test::Contains(run.Err, "--mode")) << run.Err;
  const auto depth = vr::ReadDepthImage((folder / "depth.nrrd").string());
  for (std::size_t k = 0; k < depth->GetLargestPossibleRegion().GetNumberOfPixels(); ++k)
  {
    ASSERT_TRUE(std::isfinite(depth->GetBufferPointer()[k])) << k;
  }
}

TEST(VesselReformationVisibility, BranchesThatAllCoincideInProjectionGiveADepthMapWithOneVisible)
{
  // Three tubes along the same line of the image (x = 0, z from 40 to -40), at depths -30, 0 and 30 mm, in a volume of
  // the thorax's grid: one is visible, the others hidden behind it; nothing is NaN.
  const fs::path      folder = Folder();
  itk::CenterlineTree tree;
  for (int id = 1; id <= 3; ++id)
  {
    itk::CenterlineBranch branch;
    branch.Id = id;
    for (int z = 40; z >= -40; z -= 2)
    {
      itk::Point<double, 3> point;
      point[0] = 0.0;
      point[1] = -30.0 + 30.0 * (id - 1);
      point[2] = static_cast<double>(z) - 60.0;
      branch.Points.push_back(point);
      branch.Radii.push_back(5.0);
    }
    tree.AddBranch(branch);
  }
  const std::string centerlines = (folder / "coincident.csv").string();
  vr::WriteCenterlines(tree, centerlines);
  const fs::path            returned = folder / "returned.params";
  const vr::test::ModuleRun run = RunProgram({ Executable,
                                               "--mode",
                                               "visibility",
                                               "--size",
                                               "64,128",
                                               "--iterations",
                                               "20",
                                               "--returnparameterfile",
                                               returned.string(),
                                               "--outputDepth",
                                               (folder / "depth.nrrd").string(),
                                               "--outputLabels",
                                               (folder / "labels.nrrd").string(),
                                               "--outputHiddenLabels",
                                               (folder / "hidden.nrrd").string(),
                                               Thorax().Volume,
                                               centerlines,
                                               (folder / "cpr.nrrd").string() });
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  const auto depth = vr::ReadDepthImage((folder / "depth.nrrd").string());
  const auto cpr = vr::ReadDepthImage((folder / "cpr.nrrd").string());
  for (std::size_t k = 0; k < depth->GetLargestPossibleRegion().GetNumberOfPixels(); ++k)
  {
    ASSERT_TRUE(std::isfinite(depth->GetBufferPointer()[k]));
    ASSERT_TRUE(std::isfinite(cpr->GetBufferPointer()[k]));
  }
  // Two of the three tubes' 80 mm lie behind the front one (ends included, up to their radius more).
  const double hidden = Number(ReturnedValues(returned).at("hiddenLength"));
  EXPECT_GE(hidden, 2 * 80.0 - 1.0);
  EXPECT_LE(hidden, 2 * 80.0 + 1.0);
}

TEST(VesselReformationVisibility, WhatLiesHiddenIsRefusedOutsideVisibilityModeAndABadAngleIsNamed)
{
  const fs::path folder = Folder();
  for (const char * flag : { "--outputHiddenLabels", "--outputHiddenLengths" })
  {
    const std::string         output = (folder / (std::string(flag).substr(2) + ".out")).string();
    const vr::test::ModuleRun run =
      RunProgram({ Executable,
                   "--size",
                   "32,64",
                   flag,
                   std::string(flag) == "--outputHiddenLabels" ? output + ".nrrd" : output + ".csv",
                   Thorax().Volume,
                   Thorax().Centerlines,
                   (folder / "cpr.nrrd").string() });
    EXPECT_EQ(run.ExitCode, 1) << flag;
    EXPECT_TRUE(vr::test::Contains(run.Err, flag)) << run.Err;
    EXPECT_TRUE(vr::test::Contains(run.Err, "--mode visibility")) << run.Err;
    EXPECT_FALSE(fs::exists(folder / "cpr.nrrd")) << "nothing written";
  }
  for (const char * angle : { "bestest", "nan", "12degrees", "" })
  {
    const vr::test::ModuleRun run = RunProgram(
      { Executable, "--angle", angle, Thorax().Volume, Thorax().Centerlines, (folder / "cpr.nrrd").string() });
    EXPECT_EQ(run.ExitCode, 1) << angle;
    EXPECT_TRUE(vr::test::Contains(run.Err, "--angle")) << run.Err;
    EXPECT_FALSE(fs::exists(folder / "cpr.nrrd"));
  }
}
