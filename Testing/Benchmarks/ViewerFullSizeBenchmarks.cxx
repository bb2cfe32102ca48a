// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The viewer on a full-size study (issue 40; docs/benchmarks.md "Full-size volumes"): the run-off phantom drawn as a
// clinical run-off CTA of 512 x 512 x N int16 voxels (vr::test::MakeClinicalVolume, a raw NRRD, with the phantom's
// centerlines in a .vtp), opened from its files as a user opens them:
//   FullSize_FirstImage/slices:N   a new viewer window (1600 x 1000, the viewer's default parameters, as the command
//                                  line gives them), shown and idle; then ViewerWindow::OpenFiles() of the two files,
//                                  as the File menu's dialogs call it once the files are chosen: the time from that
//                                  call to the first CPR on screen (the CPR view's frame swapped). Counters: load_ms
//                                  (until the inputs were loaded on the worker: the file read, the centerlines, the
//                                  volume's display range), logic_ms (the first update of the logic), full_surface_ms
//                                  (until the 3D view drew the full cut surface), view_width and view_height (the
//                                  first image's size, fitted to the tree at the volume's voxel spacing), and
//                                  file_read_ms: the plain reference, the same file's bytes read with read() into one
//                                  new buffer just before (which also puts the file in the page cache for every
//                                  repetition alike). Each repetition has a window of its own, closed after it.
//   FullSize_AngleChange/slices:N  a settled angle change (as AngleChange of ViewerBenchmarks.cxx: 512 x 1024, 500 CPU
//                                  passes, w = 1, a = 0.5; typed into the panel, to the new CPR on screen) on the
//                                  full-size study and on the run-off phantom (1.5 mm, float) in two windows of the
//                                  same process, alternately, one change on each per repetition (the order swapped
//                                  every repetition). The time is the full-size study's; counters: phantom_ms,
//                                  ratio (full size / phantom, of the same repetition), logic_ms and
//                                  phantom_logic_ms (the logic's update of each), render_2d_ms.
// The studies are written once per process into the temporary folder (about 40 s per 1 200 slices on 2 cores, not
// timed) and removed at its end, unless VR_FULL_SIZE_STUDIES names a folder holding runoff-N.nrrd and runoff.vtp as
// WriteClinicalVolume writes them (then those are used and kept).
#include "vrCenterlineIO.h"
#include "vrClinicalVolume.h"
#include "vrViewerBenchmarkSupport.h"
#include "vrVesselReformationLogic.h"
#include "vrViewerWindow.h"

#include "itkCTAPhantom.h"
#include "itkImageFileWriter.h"

#include <QApplication>
#include <QCoreApplication>

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <unistd.h>

namespace
{
using vr::benchmarks::BenchmarkParameters;
using vr::benchmarks::BenchmarkViewer;
using vr::benchmarks::Clock;
using vr::benchmarks::P95;
using vr::benchmarks::RunUntil;
using vr::benchmarks::Seconds;

/** How long a raised window is given to draw before a change is timed in it. */
constexpr double RaiseSettleSeconds = 1.0;

struct Study
{
  std::string Volume;
  std::string Centerlines;
};

/** The files of the 512 x 512 x slices study: VR_FULL_SIZE_STUDIES's, or written once into the temporary folder. */
const Study &
StudyOf(long slices)
{
  struct Written
  {
    std::map<long, Study>    Studies;
    std::string              Centerlines;
    std::vector<std::string> Paths; // to remove at the end
    ~Written()
    {
      for (const auto & path : Paths)
      {
        std::error_code error;
        std::filesystem::remove(path, error);
      }
    }
  };
  static Written written;
  auto &         study = written.Studies[slices];
  if (!study.Volume.empty())
  {
    return study;
  }
  const std::string name = "runoff-" + std::to_string(slices) + ".nrrd";
  if (const char * folder = std::getenv("VR_FULL_SIZE_STUDIES"); folder != nullptr && *folder != '\0')
  {
    const std::filesystem::path given(folder);
    if (std::filesystem::exists(given / name) && std::filesystem::exists(given / "runoff.vtp"))
    {
      study = { (given / name).string(), (given / "runoff.vtp").string() };
      return study;
    }
    std::cerr << "VR_FULL_SIZE_STUDIES=" << folder << " holds no " << name << " and runoff.vtp: writing them"
              << std::endl;
  }
  const auto prefix = std::filesystem::temp_directory_path() / ("vr-viewer-fullsize-" + std::to_string(getpid()));
  if (written.Centerlines.empty())
  {
    written.Centerlines = prefix.string() + "-runoff.vtp";
    vr::WriteCenterlines(itk::MakeCTAPhantom(itk::CTAPhantomKind::Runoff, 1.0).Tree, written.Centerlines);
    written.Paths.push_back(written.Centerlines);
  }
  const std::string volumePath = prefix.string() + "-" + name;
  {
    auto writer = itk::ImageFileWriter<itk::Image<short, 3>>::New();
    writer->SetInput(vr::test::MakeClinicalVolume<short>(itk::CTAPhantomKind::Runoff,
                                                         { { 512, 512, static_cast<itk::SizeValueType>(slices) } }));
    writer->SetFileName(volumePath);
    writer->Update();
  } // the volume made here goes before any timing
  written.Paths.push_back(volumePath);
  study = { volumePath, written.Centerlines };
  return study;
}

/** Reads the file's bytes with read() into one new buffer: \return the seconds it took. */
double
ReadPlainly(const std::string & path)
{
  const auto              start = Clock::now();
  const auto              bytes = static_cast<std::size_t>(std::filesystem::file_size(path));
  std::unique_ptr<char[]> buffer(new char[bytes]);
  const int               file = open(path.c_str(), O_RDONLY);
  std::size_t             done = 0;
  while (file >= 0 && done < bytes)
  {
    const ssize_t read = ::read(file, buffer.get() + done, bytes - done);
    if (read <= 0)
    {
      break;
    }
    done += static_cast<std::size_t>(read);
  }
  if (file >= 0)
  {
    close(file);
  }
  benchmark::DoNotOptimize(buffer.get());
  return Seconds(start, Clock::now());
}

void
FullSize_FirstImage(benchmark::State & state)
{
  const Study & study = StudyOf(state.range(0));
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    const double fileRead = ReadPlainly(study.Volume);
    // The window as the viewer opens it: its command line's default parameters in the panel, shown, idle.
    auto window = std::make_unique<vr::ViewerWindow>();
    window->resize(1600, 1000);
    window->GetPanel()->SetParameters(vr::ReformationParameters{});
    window->show();
    const auto shownAt = Clock::now();
    RunUntil([&] { return Seconds(shownAt, Clock::now()) > 0.5; });

    Clock::time_point loaded;
    Clock::time_point displayed;
    Clock::time_point fullSurface;
    bool              hasLoaded = false, hasDisplayed = false, hasFullSurface = false, failed = false;
    QObject::connect(window->GetController(),
                     &vr::ReformationController::inputsLoaded,
                     window.get(),
                     [&]
                     {
                       loaded = Clock::now();
                       hasLoaded = true;
                     });
    QObject::connect(window->GetController(),
                     &vr::ReformationController::inputsFailed,
                     window.get(),
                     [&](const QString &, const QString & message)
                     {
                       std::cerr << message.toStdString() << std::endl;
                       failed = true;
                     });
    QObject::connect(window->GetCPRView(),
                     &vr::CPRView::imageDisplayed,
                     window.get(),
                     [&](std::uint64_t)
                     {
                       if (!hasDisplayed)
                       {
                         displayed = Clock::now();
                         hasDisplayed = true;
                       }
                     });
    QObject::connect(window->GetThreeDView(),
                     &vr::ThreeDView::rendered,
                     window.get(),
                     [&](double, bool full)
                     {
                       if (full && hasDisplayed && !hasFullSurface && window->GetThreeDView()->IsShowingFullSurface())
                       {
                         fullSurface = Clock::now();
                         hasFullSurface = true;
                       }
                     });
    const auto start = Clock::now();
    window->OpenFiles(QString::fromStdString(study.Volume), QString::fromStdString(study.Centerlines));
    if (!RunUntil([&] { return hasDisplayed || failed; }, 300.0) || failed)
    {
      state.SkipWithError("the study's first image was not displayed");
      break;
    }
    RunUntil([&] { return hasFullSurface && window->GetController()->IsIdle(); }, 120.0);
    state.SetIterationTime(Seconds(start, displayed));
    const auto result = window->GetCPRView()->GetResult();
    state.counters["load_ms"] = 1000.0 * Seconds(start, loaded);
    state.counters["logic_ms"] = result ? 1000.0 * result->UpdateSeconds : 0.0;
    state.counters["full_surface_ms"] = hasFullSurface ? 1000.0 * Seconds(start, fullSurface) : 0.0;
    state.counters["file_read_ms"] = 1000.0 * fileRead;
    if (result)
    {
      state.counters["view_width"] = static_cast<double>(result->Outputs.View.GetSize()[0]);
      state.counters["view_height"] = static_cast<double>(result->Outputs.View.GetSize()[1]);
    }
    window.reset(); // the study's memory goes with the window, before the next repetition
  }
}

/** The viewer window on the full-size study of \a slices slices with BenchmarkParameters, one at a time (the one of
 * another size goes first), destroyed before the application. */
BenchmarkViewer &
FullSizeViewer(long slices)
{
  static std::unique_ptr<BenchmarkViewer> viewer;
  static long                             viewerSlices = -1;
  static const bool                       routine = []
  {
    qAddPostRoutine([] { viewer.reset(); });
    return true;
  }();
  (void)routine;
  if (!viewer || viewerSlices != slices)
  {
    viewer.reset();
    const Study & study = StudyOf(slices);
    viewer = std::make_unique<BenchmarkViewer>(
      [&study](vr::ViewerWindow & window)
      { window.OpenFiles(QString::fromStdString(study.Volume), QString::fromStdString(study.Centerlines)); },
      BenchmarkParameters(vr::benchmarks::ViewerDesignAngle));
    viewerSlices = slices;
  }
  return *viewer;
}

/** Raises \a viewer's window above the other one and lets it draw what that uncovered: the whole window, composed
 * again with its two OpenGL views on the software renderer, takes both cores for a while after the raise, and an
 * angle change timed meanwhile would share them with it. */
void
Raise(BenchmarkViewer & viewer)
{
  if (QApplication::topLevelAt(viewer.Window().geometry().center()) != &viewer.Window())
  {
    viewer.Window().raise();
    const auto start = Clock::now();
    RunUntil([&] { return Seconds(start, Clock::now()) > RaiseSettleSeconds; });
  }
  viewer.Settle();
}

void
FullSize_AngleChange(benchmark::State & state)
{
  BenchmarkViewer & phantom = vr::benchmarks::PhantomViewer();
  BenchmarkViewer & full = FullSizeViewer(state.range(0));
  std::size_t       repetition = 0;
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    vr::benchmarks::AngleChangeTimes phantomTimes;
    vr::benchmarks::AngleChangeTimes fullTimes;
    std::string                      error;
    bool                             ok = true;
    // Alternately phantom first and full size first: neither is always the one after the other's work.
    for (int turn = 0; turn < 2 && ok; ++turn)
    {
      const bool onPhantom = (turn == 0) == (repetition % 2 == 0);
      Raise(onPhantom ? phantom : full);
      ok =
        vr::benchmarks::TimeSettledAngleChange(onPhantom ? phantom : full, onPhantom ? phantomTimes : fullTimes, error);
    }
    ++repetition;
    if (!ok)
    {
      state.SkipWithError(error.c_str());
      break;
    }
    state.SetIterationTime(fullTimes.Total);
    state.counters["phantom_ms"] = 1000.0 * phantomTimes.Total;
    state.counters["ratio"] = fullTimes.Total / phantomTimes.Total;
    state.counters["logic_ms"] = 1000.0 * fullTimes.Logic;
    state.counters["phantom_logic_ms"] = 1000.0 * phantomTimes.Logic;
    state.counters["render_2d_ms"] = 1000.0 * fullTimes.RenderCPR;
    state.counters["depth_ms"] = 1000.0 * fullTimes.Depth;
    state.counters["relax_ms"] = 1000.0 * fullTimes.Relax;
    state.counters["resample_ms"] = 1000.0 * fullTimes.Resample;
    state.counters["logic_rest_ms"] = 1000.0 * fullTimes.LogicRest;
    state.counters["phantom_resample_ms"] = 1000.0 * phantomTimes.Resample;
    state.counters["phantom_logic_rest_ms"] = 1000.0 * phantomTimes.LogicRest;
    state.counters["phantom_relax_ms"] = 1000.0 * phantomTimes.Relax;
    state.counters["cpu_ms"] = 1000.0 * fullTimes.ProcessCPU;
    state.counters["phantom_cpu_ms"] = 1000.0 * phantomTimes.ProcessCPU;
    state.counters["progress_shown"] = fullTimes.ProgressShown ? 1.0 : 0.0;
    state.counters["phantom_progress_shown"] = phantomTimes.ProgressShown ? 1.0 : 0.0;
  }
  full.Settle();
  phantom.Settle();
}

/** The logic alone (no window) on the full-size study's inputs read from its files and on the phantom's, the same
 * changes as FullSize_AngleChange, alternately. */
void
FullSize_Logic_AngleChange(benchmark::State & state)
{
  const Study &               study = StudyOf(state.range(0));
  const vr::ReformationInputs inputs =
    vr::MakeInputs(vr::ReadVolumeNode(study.Volume), vr::ReadCenterlineNode(study.Centerlines));
  vr::VesselReformationLogic full;
  vr::VesselReformationLogic phantom;
  full.SetVolumeNode(inputs.Volume);
  full.SetCenterlineNode(inputs.Centerlines);
  phantom.SetVolumeNode(vr::benchmarks::PhantomInputs().Volume);
  phantom.SetCenterlineNode(vr::benchmarks::PhantomInputs().Centerlines);
  for (auto * logic : { &full, &phantom })
  {
    logic->SetSurfaceEnabled(false);
    logic->SetParameters(BenchmarkParameters(vr::benchmarks::ViewerDesignAngle));
    logic->Update();
  }
  std::size_t step = 0;
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    ++step;
    const auto parameters =
      BenchmarkParameters(vr::benchmarks::ViewerDesignAngle + 0.5 * static_cast<double>(step % 20));
    double         seconds[2] = { 0.0, 0.0 };
    vr::StageTimes times[2];
    for (int turn = 0; turn < 2; ++turn)
    {
      const int                    which = (turn == 0) == (step % 2 == 0) ? 1 : 0; // 0: full size, 1: phantom
      vr::VesselReformationLogic & logic = which == 0 ? full : phantom;
      const auto                   start = Clock::now();
      logic.SetParameters(parameters);
      times[which] = logic.Update().Times;
      seconds[which] = Seconds(start, Clock::now());
    }
    state.SetIterationTime(seconds[0]);
    state.counters["phantom_ms"] = 1000.0 * seconds[1];
    state.counters["ratio"] = seconds[0] / seconds[1];
    state.counters["relax_ms"] = 1000.0 * times[0].Relax;
    state.counters["phantom_relax_ms"] = 1000.0 * times[1].Relax;
    state.counters["resample_ms"] = 1000.0 * times[0].Resample;
    state.counters["phantom_resample_ms"] = 1000.0 * times[1].Resample;
  }
}

const bool Registered = []
{
  // Each repetition one timed change (or one first image), reported as median and p95 over the repetitions.
  const auto registerTimed = [](const char * name, void (*function)(benchmark::State &), long slices, int repetitions)
  {
    benchmark::RegisterBenchmark(name, function)
      ->ArgName("slices")
      ->Arg(slices)
      ->Iterations(1)
      ->Repetitions(repetitions)
      ->UseManualTime()
      ->Unit(benchmark::kMillisecond)
      ->ComputeStatistics("p95", P95)
      ->ReportAggregatesOnly(true);
  };
  // The first images first: no other full-size study is open while one is read.
  for (const long slices : { 1200L, 2400L })
  {
    registerTimed("FullSize_FirstImage", FullSize_FirstImage, slices, 5);
  }
  for (const long slices : { 1200L, 2400L })
  {
    registerTimed("FullSize_Logic_AngleChange", FullSize_Logic_AngleChange, slices, 20);
    registerTimed("FullSize_AngleChange", FullSize_AngleChange, slices, 20);
  }
  return true;
}();
} // namespace
