// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The command-line modules' runs: cancelling through 3D Slicer's structure, what the modules compute, the summary
// and the progress they report.
#include "vrCLITestSupport.h"

namespace
{
using namespace vr::test::cli;

// ---------------------------------------------------------------------------------------------------------------
// Cancelling through Slicer's structure (issue 12): 3D Slicer sets Abort while the module runs in its processing
// thread; the run must stop within the iteration it is in, write nothing, and return what Slicer's CLI logic reads
// as "Cancelled": 0 (a non-zero value turns the status into "Completed with errors").

/** What Slicer's progress callback sees during a run that it cancels as soon as the relaxation reports. */
struct CancelProbe
{
  SlicerProcessInformation * Information{ nullptr };
  bool                       AbortSet{ false };
  float                      ProgressAtAbort{ 0.0f };
  int                        CallsBeforeAbort{ 0 };
  int                        CallsAfterAbort{ 0 };
};

void
CancelWhenTheRelaxationReports(void * data)
{
  auto * probe = static_cast<CancelProbe *>(data);
  if (probe->AbortSet)
  {
    ++probe->CallsAfterAbort;
    return;
  }
  ++probe->CallsBeforeAbort;
  if (std::strcmp(probe->Information->ProgressMessage, "relax") == 0)
  {
    probe->Information->Abort = 1;
    probe->AbortSet = true;
    probe->ProgressAtAbort = probe->Information->Progress;
  }
}

/** Runs \a library in this process with \a arguments after Slicer's first three (target, the structure's flag and
 * address), cancelling at the first progress report of the relaxation. */
RunResult
RunCancelledInProcess(const std::string &      library,
                      const std::string &      target,
                      std::vector<std::string> arguments,
                      CancelProbe &            probe)
{
  static SlicerProcessInformation information;
  information = SlicerProcessInformation{};
  probe = CancelProbe{};
  probe.Information = &information;
  information.ProgressCallbackFunction = CancelWhenTheRelaxationReports;
  information.ProgressCallbackClientData = &probe;
  char address[64];
  std::snprintf(address, sizeof(address), "%p", static_cast<void *>(&information));
  arguments.insert(arguments.begin(), { target, "--processinformationaddress", address });
  return RunInProcess(library, arguments);
}

/** The iterations the relax filter did before it stopped, from its "aborted after N of M iterations". */
long
IterationsDoneBeforeTheAbort(const std::string & message, long & of)
{
  std::smatch      match;
  const std::regex pattern("aborted after ([0-9]+) of ([0-9]+) iterations");
  if (!std::regex_search(message, match, pattern))
  {
    return -1;
  }
  of = std::stol(match[2]);
  return std::stol(match[1]);
}

TEST(SlicerCancel, ReformationStopsMidRelaxationReturnsZeroAndWritesNothing)
{
  const fs::path folder = TestFolder();
  WriteText(folder / "cpr.nrrd", "an earlier result that must survive");
  const auto  before = FilesIn(folder);
  CancelProbe probe;
  // 200 000 iterations of 256 x 256 pixels: seconds of relaxation that a run ignoring Abort would go through,
  // reporting progress at every percent.
  const RunResult run = RunCancelledInProcess(ReformationLibrary,
                                              "VesselReformation",
                                              { "--up",
                                                "auto",
                                                "--size",
                                                "256,256",
                                                "--iterations",
                                                "200000",
                                                "--backend",
                                                "cpu",
                                                "--outputDepth",
                                                (folder / "depth.nrrd").string(),
                                                "--outputSurface",
                                                (folder / "surface.vtp").string(),
                                                "--returnparameterfile",
                                                (folder / "returned.params").string(),
                                                (DataFolder / "aorta.mha").string(),
                                                (DataFolder / "aorta-centerline.vtp").string(),
                                                (folder / "cpr.nrrd").string() },
                                              probe);
  ASSERT_TRUE(probe.AbortSet) << "the relaxation never reported: " << run.Err;
  EXPECT_EQ(run.ExitCode, 0) << "3D Slicer reads a non-zero value as 'Completed with errors'\n" << run.Err;
  EXPECT_TRUE(Contains(run.Err, "VesselReformation: relaxation: cancelled")) << run.Err;
  EXPECT_FALSE(Contains(run.Err, "error")) << run.Err;
  // Quickly: no progress report after the abort (a run that went on would report every percent), and the filter
  // stopped within an iteration of the one it was in when Slicer asked.
  EXPECT_EQ(probe.CallsAfterAbort, 0);
  long       of = 0;
  const long done = IterationsDoneBeforeTheAbort(run.Err, of);
  EXPECT_EQ(of, 200000) << run.Err;
  EXPECT_GT(done, 0) << run.Err;
  EXPECT_LT(done, 200000 / 20) << "the relaxation went on after Abort: " << run.Err;
  // Nothing written: no output, no return-parameter file, no stray file, the earlier result intact.
  EXPECT_EQ(FilesIn(folder), before);
  EXPECT_EQ(ReadText(folder / "cpr.nrrd"), "an earlier result that must survive");
  std::cout << "cancelled at overall progress " << probe.ProgressAtAbort << " after " << probe.CallsBeforeAbort
            << " progress reports; the relax filter stopped after " << done << " of " << of << " iterations"
            << std::endl;
}

TEST(SlicerCancel, RelaxModuleStopsMidRelaxationReturnsZeroAndWritesNothing)
{
  const fs::path folder = TestFolder();
  // A 512 x 512 depth map with a step: 100 000 iterations that a run ignoring Abort would go through.
  auto                                 depth = vr::DepthImageType::New();
  const vr::DepthImageType::RegionType region({ { 0, 0 } }, { { 512, 512 } });
  depth->SetRegions(region);
  depth->Allocate();
  for (unsigned int k = 0; k < 512 * 512; ++k)
  {
    depth->GetBufferPointer()[k] = (k % 512) < 256 ? 2.0f : 9.0f;
  }
  vr::WriteImage2D(depth.GetPointer(), (folder / "depth.nrrd").string());
  const auto      before = FilesIn(folder);
  CancelProbe     probe;
  const RunResult run = RunCancelledInProcess(RelaxLibrary,
                                              "BilateralDepthRelax",
                                              { "--iterations",
                                                "100000",
                                                "--backend",
                                                "cpu",
                                                "--returnparameterfile",
                                                (folder / "returned.params").string(),
                                                (folder / "depth.nrrd").string(),
                                                (folder / "relaxed.nrrd").string() },
                                              probe);
  ASSERT_TRUE(probe.AbortSet) << run.Err;
  EXPECT_EQ(run.ExitCode, 0) << run.Err;
  EXPECT_TRUE(Contains(run.Err, "BilateralDepthRelax: relaxation: cancelled")) << run.Err;
  EXPECT_FALSE(Contains(run.Err, "error")) << run.Err;
  EXPECT_EQ(probe.CallsAfterAbort, 0);
  // The module stopped at its next progress report: the relaxation's progress is its fraction of iterations done.
  EXPECT_LT(probe.ProgressAtAbort, 0.05f);
  EXPECT_EQ(FilesIn(folder), before);
}

// ---------------------------------------------------------------------------------------------------------------
// What the modules compute.

TEST(BilateralDepthRelaxModule, RelaxesByEquationOneAndHoldsTheMask)
{
  const fs::path folder = TestFolder();
  // [0, 10, 0] with w = 1, a = 0, one iteration: each pixel becomes the mean of its neighbours, [10, 0, 10].
  auto depth = vr::DepthImageType::New();
  depth->SetRegions(vr::DepthImageType::RegionType({ { 0, 0 } }, { { 3, 1 } }));
  depth->Allocate();
  depth->GetBufferPointer()[0] = 0.0f;
  depth->GetBufferPointer()[1] = 10.0f;
  depth->GetBufferPointer()[2] = 0.0f;
  itk::EncapsulateMetaData<std::string>(depth->GetMetaDataDictionary(), "CPR_Note", "kept");
  vr::WriteImage2D(depth.GetPointer(), (folder / "depth.nrrd").string());
  const RunResult free = RunProgram({ RelaxExecutable,
                                      "--relaxation",
                                      "1",
                                      "--anisotropy",
                                      "0",
                                      "--iterations",
                                      "1",
                                      "--backend",
                                      "cpu",
                                      (folder / "depth.nrrd").string(),
                                      (folder / "free.nrrd").string() });
  ASSERT_EQ(free.ExitCode, 0) << free.Err;
  auto relaxed = vr::ReadDepthImage((folder / "free.nrrd").string());
  EXPECT_FLOAT_EQ(relaxed->GetBufferPointer()[0], 10.0f);
  EXPECT_FLOAT_EQ(relaxed->GetBufferPointer()[1], 0.0f);
  EXPECT_FLOAT_EQ(relaxed->GetBufferPointer()[2], 10.0f);
  std::string note;
  EXPECT_TRUE(itk::ExposeMetaData<std::string>(relaxed->GetMetaDataDictionary(), "CPR_Note", note));
  EXPECT_EQ(note, "kept");

  // With the ends fixed: [0, 0, 0].
  auto mask = vr::MaskImageType::New();
  mask->SetRegions(depth->GetLargestPossibleRegion());
  mask->Allocate();
  mask->GetBufferPointer()[0] = 1;
  mask->GetBufferPointer()[1] = 0;
  mask->GetBufferPointer()[2] = 1;
  vr::WriteImage2D(mask.GetPointer(), (folder / "mask.nrrd").string());
  const RunResult held = RunProgram({ RelaxExecutable,
                                      "--mask",
                                      (folder / "mask.nrrd").string(),
                                      "--anisotropy",
                                      "0",
                                      "--iterations",
                                      "1",
                                      "--backend",
                                      "cpu",
                                      (folder / "depth.nrrd").string(),
                                      (folder / "held.nrrd").string() });
  ASSERT_EQ(held.ExitCode, 0) << held.Err;
  relaxed = vr::ReadDepthImage((folder / "held.nrrd").string());
  EXPECT_FLOAT_EQ(relaxed->GetBufferPointer()[0], 0.0f);
  EXPECT_FLOAT_EQ(relaxed->GetBufferPointer()[1], 0.0f);
  EXPECT_FLOAT_EQ(relaxed->GetBufferPointer()[2], 0.0f);
}

// Issue 13: --jumpThreshold J is the range kernel's scale, R(d) = exp(-(d/J)^2), 3 mm when neither it nor
// --anisotropy is given; --solver steady gives the fixed point. The hand-worked case of depths [0, 1, 3] with the ends
// fixed, w = 1: one Jacobi pass moves the middle to f(1), the steady solver to the fixed point x = f(x) that the
// passes approach from 1 (vr::test::ThreePixelMiddleAfterOnePass, ThreePixelMiddleFixedPoint).
TEST(BilateralDepthRelaxModule, JumpThresholdScalesTheRangeKernelAndSteadyFindsTheFixedPoint)
{
  const fs::path folder = TestFolder();
  vr::WriteImage2D(vr::test::MakeDepthImage(3, 1, { 0.0f, 1.0f, 3.0f }).GetPointer(), (folder / "depth.nrrd").string());
  vr::WriteImage2D(vr::test::MakeMaskImage(3, 1, { 1, 0, 1 }).GetPointer(), (folder / "mask.nrrd").string());
  auto middle = [&](std::vector<std::string> flags, const std::string & name)
  {
    std::vector<std::string> command = {
      RelaxExecutable, "--mask", (folder / "mask.nrrd").string(), "--backend", "cpu"
    };
    command.insert(command.end(), flags.begin(), flags.end());
    command.push_back((folder / "depth.nrrd").string());
    command.push_back((folder / name).string());
    const RunResult run = RunProgram(command);
    EXPECT_EQ(run.ExitCode, 0) << run.Err;
    return static_cast<double>(vr::ReadDepthImage((folder / name).string())->GetBufferPointer()[1]);
  };
  auto expected = [](double J) { return vr::test::ThreePixelMiddleAfterOnePass(1.0, J); };
  EXPECT_NEAR(middle({ "--iterations", "1", "--jumpThreshold", "2" }, "j2.nrrd"), expected(2.0), 1e-6);
  EXPECT_NEAR(middle({ "--iterations", "1", "--anisotropy", "0.25" }, "a025.nrrd"), expected(2.0), 1e-6);
  EXPECT_NEAR(middle({ "--iterations", "1" }, "default.nrrd"), expected(3.0), 1e-6);
  EXPECT_NEAR(middle({ "--iterations", "1", "--jumpThreshold", "0.5" }, "j05.nrrd"), expected(0.5), 1e-6);
  const double fixedPoint = vr::test::ThreePixelMiddleFixedPoint(2.0);
  ASSERT_GT(std::abs(expected(2.0) - fixedPoint), 0.1) << "one Jacobi pass is not the fixed point here";
  EXPECT_NEAR(middle({ "--solver", "steady", "--jumpThreshold", "2" }, "steady.nrrd"), fixedPoint, 1e-3);
}

/** Numbers in a "CPR_*" metadata entry. */
std::vector<double>
MetadataNumbers(const vr::DepthImageType * image, const std::string & key)
{
  std::string text;
  itk::ExposeMetaData<std::string>(image->GetMetaDataDictionary(), key, text);
  std::istringstream  stream(text);
  std::vector<double> values;
  double              value = 0.0;
  while (stream >> value)
  {
    values.push_back(value);
  }
  return values;
}

TEST(VesselReformationModule, RealAortaCenterlinePixelsShowLumenAndFixedPixelsIgnoreRelaxation)
{
  const fs::path    folder = TestFolder();
  const std::string volume = (DataFolder / "aorta.mha").string();
  const std::string centerlines = (DataFolder / "aorta-centerline.vtp").string();
  constexpr float   lumen = 1850.0f;
  constexpr float   background = 230.0f;

  // Centerline pixels alone are fixed with --fixLumen off: each must show lumen.
  const RunResult centerlineRun = RunProgram({ ReformationExecutable,
                                               "--up",
                                               "auto",
                                               "--fixLumen",
                                               "off",
                                               "--backend",
                                               "cpu",
                                               "--outputMask",
                                               (folder / "centerline-mask.nrrd").string(),
                                               volume,
                                               centerlines,
                                               (folder / "centerline-cpr.nrrd").string() });
  ASSERT_EQ(centerlineRun.ExitCode, 0) << centerlineRun.Err;
  EXPECT_FALSE(Contains(centerlineRun.Err, "outside the volume")) << centerlineRun.Err;
  auto        cpr = vr::ReadDepthImage((folder / "centerline-cpr.nrrd").string());
  auto        mask = vr::ReadMaskImage((folder / "centerline-mask.nrrd").string());
  const auto  count = cpr->GetLargestPossibleRegion().GetNumberOfPixels();
  std::size_t centerlinePixels = 0;
  float       darkest = lumen;
  for (std::size_t k = 0; k < count; ++k)
  {
    if (mask->GetBufferPointer()[k])
    {
      ++centerlinePixels;
      darkest = std::min(darkest, cpr->GetBufferPointer()[k]);
    }
  }
  EXPECT_GT(centerlinePixels, 100u);
  EXPECT_GT(darkest, 0.5f * (lumen + background)) << "a centerline pixel shows background";

  // --up auto found the scan's y axis, along which the vessels run.
  const auto up = MetadataNumbers(cpr, "CPR_Up");
  ASSERT_EQ(up.size(), 3u);
  EXPECT_GT(std::abs(up[1]), 0.999) << up[0] << " " << up[1] << " " << up[2];

  // With lumen fixing (the default) and without relaxation, the fixed pixels are the same.
  const RunResult relaxedRun = RunProgram({ ReformationExecutable,
                                            "--up",
                                            "auto",
                                            "--backend",
                                            "cpu",
                                            "--outputMask",
                                            (folder / "mask.nrrd").string(),
                                            volume,
                                            centerlines,
                                            (folder / "relaxed-cpr.nrrd").string() });
  const RunResult unrelaxedRun = RunProgram({ ReformationExecutable,
                                              "--up",
                                              "auto",
                                              "--backend",
                                              "cpu",
                                              "--relaxation",
                                              "0",
                                              volume,
                                              centerlines,
                                              (folder / "unrelaxed-cpr.nrrd").string() });
  ASSERT_EQ(relaxedRun.ExitCode, 0) << relaxedRun.Err;
  ASSERT_EQ(unrelaxedRun.ExitCode, 0) << unrelaxedRun.Err;
  auto        relaxed = vr::ReadDepthImage((folder / "relaxed-cpr.nrrd").string());
  auto        unrelaxed = vr::ReadDepthImage((folder / "unrelaxed-cpr.nrrd").string());
  auto        fixedMask = vr::ReadMaskImage((folder / "mask.nrrd").string());
  std::size_t fixed = 0;
  std::size_t changed = 0;
  for (std::size_t k = 0; k < count; ++k)
  {
    if (fixedMask->GetBufferPointer()[k])
    {
      ++fixed;
      EXPECT_EQ(relaxed->GetBufferPointer()[k], unrelaxed->GetBufferPointer()[k]) << "fixed pixel " << k;
    }
    else if (relaxed->GetBufferPointer()[k] != unrelaxed->GetBufferPointer()[k])
    {
      ++changed;
    }
  }
  std::cout << "aorta: " << cpr->GetLargestPossibleRegion().GetSize() << " pixels, " << centerlinePixels
            << " centerline pixels, darkest " << darkest << "; " << fixed << " fixed pixels with lumen fixing, "
            << changed << " others changed by relaxation" << std::endl;
  EXPECT_GT(fixed, centerlinePixels) << "lumen fixing should fix more than the centerline";
  EXPECT_GT(changed, 0u) << "the relaxation changed no pixel";
}

TEST(VesselReformationModule, ReportsProgressInSlicersFormat)
{
  const fs::path  folder = TestFolder();
  const RunResult run = RunProgram({ ReformationExecutable,
                                     "--up",
                                     "auto",
                                     "--iterations",
                                     "20",
                                     "--backend",
                                     "cpu",
                                     (DataFolder / "aorta.mha").string(),
                                     (DataFolder / "aorta-centerline.vtp").string(),
                                     (folder / "cpr.nrrd").string() });
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  const auto start = run.Out.find("<filter-start>");
  const auto end = run.Out.find("<filter-end>");
  ASSERT_NE(start, std::string::npos) << run.Out;
  ASSERT_NE(end, std::string::npos) << run.Out;
  EXPECT_TRUE(Contains(run.Out, "<filter-name>VesselReformation</filter-name>"));
  std::vector<double> fractions;
  const std::regex    line("<filter-progress>([0-9.eE+-]+)</filter-progress>");
  for (auto it = std::sregex_iterator(run.Out.begin(), run.Out.end(), line); it != std::sregex_iterator(); ++it)
  {
    EXPECT_GT(static_cast<std::size_t>(it->position()), start);
    EXPECT_LT(static_cast<std::size_t>(it->position()), end);
    fractions.push_back(std::stod((*it)[1]));
  }
  ASSERT_GE(fractions.size(), 3u);
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_EQ(fractions.back(), 1.0);
}

// The summary states the relaxation's settings in the one wording every caption uses (vr::DescribeFilterSettings),
// worked out here by hand from the flags: the kernel as given, then w and N, or the steady solver.
TEST(VesselReformationModule, SummaryStatesTheFilterSettingsAsEveryCaptionDoes)
{
  const fs::path  folder = TestFolder();
  const RunResult jacobi = RunProgram({ ReformationExecutable,
                                        "--up",
                                        "auto",
                                        "--jumpThreshold",
                                        "2",
                                        "--relaxation",
                                        "0.5",
                                        "--iterations",
                                        "20",
                                        "--backend",
                                        "cpu",
                                        (DataFolder / "aorta.mha").string(),
                                        (DataFolder / "aorta-centerline.vtp").string(),
                                        (folder / "jacobi.nrrd").string() });
  ASSERT_EQ(jacobi.ExitCode, 0) << jacobi.Err;
  EXPECT_TRUE(Contains(jacobi.Out, "(cpu, J = 2 mm, w = 0.5, 20 iterations)")) << jacobi.Out;
  vr::ReformationParameters parameters;
  parameters.JumpThreshold = 2.0;
  parameters.Relaxation = 0.5;
  parameters.Iterations = 20;
  EXPECT_TRUE(Contains(jacobi.Out, "(cpu, " + vr::DescribeFilterSettings(parameters) + ")")) << jacobi.Out;

  const RunResult steady = RunProgram({ ReformationExecutable,
                                        "--up",
                                        "auto",
                                        "--anisotropy",
                                        "0.25",
                                        "--solver",
                                        "steady",
                                        "--backend",
                                        "cpu",
                                        (DataFolder / "aorta.mha").string(),
                                        (DataFolder / "aorta-centerline.vtp").string(),
                                        (folder / "steady.nrrd").string() });
  ASSERT_EQ(steady.ExitCode, 0) << steady.Err;
  EXPECT_TRUE(Contains(steady.Out, "(cpu, a = 0.25 mm^-2, steady solver)")) << steady.Out;
}

TEST(CLIProgress, DrawsABarOnATerminal)
{
  std::ostringstream out;
  vr::CLIProgress    progress("VesselReformation", "comment", nullptr, out, /*terminal=*/true);
  progress.Start();
  progress.Update(0.42, "relax");
  std::ostringstream warnings;
  progress.Print(warnings, "warning: something");
  progress.Update(0.5, "relax");
  progress.End();
  EXPECT_EQ(warnings.str(), "warning: something\n");
  // The bar was ended before the warning went out, and redrawn after it.
  EXPECT_TRUE(Contains(out.str(), "relax     \n\r")) << out.str();
  EXPECT_FALSE(Contains(out.str(), "<filter")) << out.str();
  EXPECT_TRUE(Contains(out.str(), " 42% relax")) << out.str();
  EXPECT_TRUE(Contains(out.str(), "100%")) << out.str();
  EXPECT_EQ(out.str().back(), '\n');
}

} // namespace
