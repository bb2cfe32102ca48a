// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The soak of issue 14: the VesselReformation executable run 200 times, each run killed with SIGKILL at a random
// moment, must leave after every kill (once the next run has recovered the staging) and after a final clean run
// exactly one complete, consistent output set and no stray file.

#include "vrModuleRuns.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{
namespace fs = std::filesystem;
using vr::test::RunLimits;
using vr::test::RunProgram;
using RunResult = vr::test::ModuleRun;

const std::string ReformationExecutable = VR_REFORMATION_EXE;
const fs::path    DataFolder = fs::path(VR_SHARED_DATA_DIR) / "vmtk-aorta-mra";

std::string
ReadText(const fs::path & path)
{
  std::ifstream      file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

std::set<std::string>
Entries(const fs::path & folder)
{
  std::set<std::string> names;
  for (const auto & entry : fs::directory_iterator(folder))
  {
    names.insert(entry.path().filename().string());
  }
  return names;
}

/** The outputs of one run: five in the main folder, one in a second folder (so a run publishes across folders). */
struct OutputSet
{
  fs::path Main;
  fs::path Other;

  std::vector<std::string>
  Arguments(int angle) const
  {
    return { ReformationExecutable,
             "--angle",
             std::to_string(angle),
             "--size",
             "96,160",
             "--iterations",
             "100",
             "--backend",
             "cpu",
             "--outputDepth",
             (Main / "depth.nrrd").string(),
             "--outputMask",
             (Main / "mask.nrrd").string(),
             "--outputPNG",
             (Main / "cpr.png").string(),
             "--outputSurface",
             (Main / "surface.vtp").string(),
             "--outputLabels",
             (Other / "labels.nrrd").string(),
             (DataFolder / "aorta.mha").string(),
             (DataFolder / "aorta-centerline.vtp").string(),
             (Main / "cpr.nrrd").string() };
  }

  /** The angle every output of the published set was made at: -1 when nothing is published yet. Fails the test
   * when the set is incomplete, mixed, has a truncated file, or the folders hold anything else. */
  int
  CheckConsistent(const std::string & when) const
  {
    const std::set<std::string> mainFiles = Entries(Main);
    const std::set<std::string> otherFiles = Entries(Other);
    if (mainFiles.empty() && otherFiles.empty())
    {
      return -1;
    }
    EXPECT_EQ(mainFiles, (std::set<std::string>{ "cpr.nrrd", "cpr.png", "depth.nrrd", "mask.nrrd", "surface.vtp" }))
      << when;
    EXPECT_EQ(otherFiles, std::set<std::string>{ "labels.nrrd" }) << when;
    std::set<std::string> angles;
    for (const fs::path & nrrd : { Main / "cpr.nrrd", Main / "depth.nrrd", Main / "mask.nrrd", Other / "labels.nrrd" })
    {
      const std::string text = ReadText(nrrd);
      const auto        at = text.find("CPR_AngleDegrees:=");
      EXPECT_NE(at, std::string::npos) << when << ": " << nrrd << " has no view";
      if (at != std::string::npos)
      {
        angles.insert(text.substr(at + 18, text.find('\n', at) - at - 18));
      }
    }
    EXPECT_EQ(angles.size(), 1u) << when << ": the NRRD outputs come from different runs";
    const std::string png = ReadText(Main / "cpr.png");
    EXPECT_TRUE(png.size() > 12 && png.compare(png.size() - 12, 8, std::string("\0\0\0\0IEND", 8)) == 0)
      << when << ": cpr.png is incomplete";
    const std::string surface = ReadText(Main / "surface.vtp");
    EXPECT_NE(surface.find("</VTKFile>"), std::string::npos) << when << ": surface.vtp is incomplete";
    return angles.size() == 1 ? std::stoi(*angles.begin()) : -2;
  }
};

TEST(Soak, TwoHundredKilledRunsLeaveOneCompleteConsistentOutputSet)
{
  if (!fs::exists(DataFolder / "aorta.mha"))
  {
    GTEST_FAIL() << "VMTK's aorta is missing: " << DataFolder << " (VR_SHARED_DATA_DIR, Testing/Data by default)";
  }
  const fs::path folder = fs::path(VR_TEST_OUTPUT_DIR) / "Soak";
  fs::remove_all(folder);
  OutputSet outputs{ folder / "outputs", folder / "outputs-2" };
  fs::create_directories(outputs.Main);
  fs::create_directories(outputs.Other);

  // How long a whole run takes (the fastest of three, the first being slowed by cold caches) decides the spread of
  // the kill times: uniform over the run and a little beyond, so that about one run in ten completes.
  double runSeconds = 1e9;
  for (int warmUp = 0; warmUp < 3; ++warmUp)
  {
    const RunResult clean = RunProgram(outputs.Arguments(0));
    ASSERT_EQ(clean.ExitCode, 0) << clean.Err;
    runSeconds = std::min(runSeconds, clean.Seconds);
  }
  ASSERT_EQ(outputs.CheckConsistent("after the first runs"), 0);

  std::mt19937             random(14);
  double                   spread = 1.1 * runSeconds;
  int                      completedLately = 0;
  int                      killed = 0;
  int                      completed = 0;
  int                      rolledForward = 0;
  int                      published = 0;
  std::vector<std::string> probe = outputs.Arguments(0);
  probe[probe.size() - 3] = (folder / "no-such-volume.mha").string(); // fails after the outputs' folders recovered
  for (int run = 1; run <= 200; ++run)
  {
    RunLimits limits;
    limits.KillAfterSeconds = std::uniform_real_distribution<double>(0.0, spread)(random);
    const RunResult result = RunProgram(outputs.Arguments(run), limits);
    ASSERT_FALSE(result.Crashed) << "run " << run << ": " << result.Err;
    if (result.TimedOut)
    {
      ++killed;
    }
    else
    {
      ASSERT_EQ(result.ExitCode, 0) << "run " << run << ": " << result.Err;
      ++completed;
      ++completedLately;
    }
    // A busy machine (a parallel build, a sanitizer) makes runs slower than the warm-up ones, and then every kill
    // would fall early in the run: when none of the last 20 runs completed, the spread widens so that kills reach
    // the commit point and the end of the run again.
    if (run % 20 == 0)
    {
      spread *= completedLately == 0 ? 1.5 : 1.0;
      completedLately = 0;
    }
    // The next run in these folders recovers what this one left: here, a run that fails on its missing input right
    // after reserving its outputs.
    const RunResult recovery = RunProgram(probe);
    ASSERT_EQ(recovery.ExitCode, 1) << recovery.Err;
    const int angle = outputs.CheckConsistent("after run " + std::to_string(run) +
                                              (result.TimedOut ? " (killed)" : " (completed)") + " and a recovery");
    ASSERT_FALSE(::testing::Test::HasFailure()) << "stopping at run " << run;
    if (angle == run)
    {
      ++published;
      rolledForward += result.TimedOut ? 1 : 0;
    }
  }
  const RunResult last = RunProgram(outputs.Arguments(201));
  ASSERT_EQ(last.ExitCode, 0) << last.Err;
  EXPECT_EQ(outputs.CheckConsistent("after the final clean run"), 201);
  EXPECT_EQ(Entries(folder), (std::set<std::string>{ "outputs", "outputs-2" })) << "a stray file beside the folders";
  std::cout << "soak: a whole run takes " << runSeconds << " s, kills spread over " << spread << " s; of 200 runs "
            << killed << " were killed and " << completed << " completed; " << published << " published their set, "
            << rolledForward << " of them killed after their commit point and rolled forward by the next run"
            << std::endl;
  // Most runs must have been killed, at moments spread over the whole run, or the soak proved little.
  EXPECT_GE(killed, 100);
  EXPECT_GE(completed, 5);
  fs::remove_all(folder);
}
} // namespace
