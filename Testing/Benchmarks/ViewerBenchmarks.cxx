// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// VesselReformationViewerBenchmarks: what a user of the viewer waits for, on the run-off phantom (1.5 mm voxels) at
// 512 x 1024 pixels, 500 iterations of the CPU relaxation, w = 1, a = 0.5, in the whole viewer window (1600 x 1000,
// module panel, CPR view and 3D view) under a virtual X server (Mesa's software OpenGL). Each figure stands beside the
// logic's own time for the same change, measured in the same run:
//   AngleChange        a new angle typed or released (a Final request): from the change to the new CPR on screen (the
//                      CPR view's frame swapped). Counters, for each change: logic_ms, VesselReformationLogic::Update()
//                      on the worker thread; gui_overhead_ms, the rest, made of to_request_ms (panel to controller),
//                      to_worker_ms (until the worker starts the update), preview_surface_ms (the 3D view's preview
//                      surface, on the worker), worker_rest_ms, show_ms (from the worker's hand-over to the window
//                      having handled the result, render_2d_ms of it drawing the CPR view) and to_frame_ms (until Qt
//                      swapped the frame). Their median and p95 over the repetitions come with the time's.
//   Drag               a left-drag in the CPR view at 60 mouse events a second, 2 pixels (1 degree) each, for 3 s:
//                      images shown per second, and for each shown image the time from the mouse event that asked for
//                      its angle to its frame (latency), with the logic's time of those updates; then the release: the
//                      time from it to the full-resolution image at the final angle on screen (release_to_full). The
//                      argument is the controller's preview factor (docs/progressive-refinement.md): 0 adaptive (the
//                      viewer's default), 1 previews off (every step at full resolution, as before previews existed).
//                      preview_fraction: the share of the drag's images that were previews.
//   Logic_AngleChange  the logic alone (no window) for the same changes: depth, relaxation, both CPRs.
//   Window_Repaint     one synchronous repaint of the whole window (a spin box's or the progress bar's change costs
//   it). ThreeDView_Render/full, /preview   one frame of the 3D view with the full 512 x 1024 cut surface, and with the
//                      preview surface (every 4th pixel) drawn while dragging.
//   VesselPathRoll     the single-vessel panel (docs/viewer.md) on the phantom's longest path (40 mm wide, 1.5 mm
//                      pixels): one mouse event of a left-drag on the straightened CPR, 2 pixels (1 degree), from the
//                      event to the new straightened CPR painted on screen (the logic's resampling of the CPR on the
//                      viewer's worker, then the result's synchronous repaint of the view on the GUI thread). Counter
//                      logic_ms: VesselPathLogic::Update() of those steps.
// Repetitions are single changes (or single drags); median and p95 are computed over them. The same on full-size
// studies opened from their files, beside the phantom: ViewerFullSizeBenchmarks.cxx.
#include "vrReformationInputs.h"
#include "vrStraightenedCPRView.h"
#include "vrVesselReformationLogic.h"
#include "vrViewerBenchmarkSupport.h"
#include "vrViewerWindow.h"

#include <QApplication>
#include <QCoreApplication>
#include <QEventLoop>
#include <QMouseEvent>
#include <QTimer>
#include <QVTKOpenGLNativeWidget.h>

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <vector>

namespace
{
using vr::benchmarks::BenchmarkParameters;
using vr::benchmarks::BenchmarkViewer;
using vr::benchmarks::Clock;
using vr::benchmarks::P95;
using vr::benchmarks::Percentile;
using vr::benchmarks::RunUntil;
using vr::benchmarks::Seconds;
constexpr double DesignAngle = vr::benchmarks::ViewerDesignAngle;

using vr::benchmarks::PhantomInputs;
using vr::benchmarks::PhantomViewer;

void
AngleChange(benchmark::State & state)
{
  BenchmarkViewer & viewer = PhantomViewer();
  // One change per repetition: its parts go into counters, whose median and p95 over the repetitions Google
  // Benchmark reports beside the time's.
  vr::benchmarks::AngleChangeTimes times;
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    std::string error;
    if (!vr::benchmarks::TimeSettledAngleChange(viewer, times, error))
    {
      state.SkipWithError(error.c_str());
      break;
    }
    state.SetIterationTime(times.Total);
  }
  state.counters["logic_ms"] = 1000.0 * times.Logic;
  state.counters["gui_overhead_ms"] = 1000.0 * (times.Total - times.Logic);
  state.counters["to_request_ms"] = 1000.0 * times.ToRequest;
  state.counters["to_worker_ms"] = 1000.0 * times.ToWorker;
  state.counters["worker_rest_ms"] = 1000.0 * times.WorkerRest;
  state.counters["preview_surface_ms"] = 1000.0 * times.PreviewSurface;
  state.counters["show_ms"] = 1000.0 * times.Show;
  state.counters["render_2d_ms"] = 1000.0 * times.RenderCPR;
  state.counters["to_frame_ms"] = 1000.0 * times.ToFrame;
  viewer.Settle();
}

void
Drag(benchmark::State & state)
{
  BenchmarkViewer &   viewer = PhantomViewer();
  vr::ViewerWindow &  window = viewer.Window();
  QWidget *           target = window.GetCPRView()->GetRenderWidget();
  std::vector<double> latencies;
  std::vector<double> logicTimes;
  std::vector<double> releaseTimes;
  std::vector<double> cprRenderTimes;
  std::vector<double> threeDRenderTimes;
  double              dragSeconds = 0.0;
  double              framesPerSecond = 0.0;
  int                 previews = 0;
  int                 shownFrames = 0;
  window.GetController()->SetPreviewFactor(static_cast<unsigned int>(state.range(0)));
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    viewer.Settle();
    window.GetPanel()->SetAngle(DesignAngle, vr::RequestKind::Final);
    viewer.Settle();
    // Angle asked for by each mouse event, and when.
    std::map<long long, Clock::time_point> asked;
    std::vector<double>                    dragLatencies;
    int                                    frames = 0;
    auto                                   connection = QObject::connect(window.GetCPRView(),
                                       &vr::CPRView::imageDisplayed,
                                       window.GetCPRView(),
                                       [&](std::uint64_t)
                                       {
                                         const auto now = Clock::now();
                                         const auto result = window.GetCPRView()->GetResult();
                                         const auto key = std::llround(10.0 * result->Outputs.View.GetAngleInDegrees());
                                         const auto found = asked.find(key);
                                         if (found != asked.end() && result->Kind == vr::RequestKind::Interactive)
                                         {
                                           dragLatencies.push_back(Seconds(found->second, now));
                                           logicTimes.push_back(result->UpdateSeconds);
                                           ++frames;
                                           previews += result->IsPreview() ? 1 : 0;
                                           cprRenderTimes.push_back(window.GetCPRView()->GetLastRenderSeconds());
                                         }
                                       });
    // What the 3D view draws meanwhile (at most every ThreeDView::InteractiveRenderIntervalMilliseconds).
    auto          threeDConnection = QObject::connect(window.GetThreeDView(),
                                             &vr::ThreeDView::rendered,
                                             window.GetThreeDView(),
                                             [&](double seconds, bool) { threeDRenderTimes.push_back(seconds); });
    const QPointF origin(200.0, 400.0);
    auto send = [&](QEvent::Type type, const QPointF & position, Qt::MouseButton button, Qt::MouseButtons buttons)
    {
      QMouseEvent event(type, position, target->mapToGlobal(position.toPoint()), button, buttons, Qt::NoModifier);
      QApplication::sendEvent(target, &event);
    };
    const auto start = Clock::now();
    send(QEvent::MouseButtonPress, origin, Qt::LeftButton, Qt::LeftButton);
    constexpr int    events = 180;          // 3 s at 60 Hz
    constexpr double pixelsPerEvent = -2.0; // leftwards: the angle grows by 1 degree per event
    for (int k = 1; k <= events; ++k)
    {
      const auto due = start + std::chrono::microseconds(16667 * k);
      RunUntil([&] { return Clock::now() >= due; }, 10.0);
      const double angle = vr::WrapAngle(DesignAngle + vr::CPRView::DegreesPerPixel * pixelsPerEvent * k);
      asked.emplace(std::llround(10.0 * angle), Clock::now());
      send(QEvent::MouseMove, origin + QPointF(pixelsPerEvent * k, 0.0), Qt::NoButton, Qt::LeftButton);
    }
    const double seconds = Seconds(start, Clock::now());
    QObject::disconnect(connection);
    QObject::disconnect(threeDConnection);
    const double      finalAngle = vr::WrapAngle(DesignAngle + vr::CPRView::DegreesPerPixel * pixelsPerEvent * events);
    bool              fullShown = false;
    Clock::time_point fullTime;
    auto              released = QObject::connect(window.GetCPRView(),
                                     &vr::CPRView::imageDisplayed,
                                     window.GetCPRView(),
                                     [&](std::uint64_t)
                                     {
                                       const auto result = window.GetCPRView()->GetResult();
                                       if (!fullShown && !result->IsPreview() &&
                                           result->Outputs.View.GetAngleInDegrees() == finalAngle)
                                       {
                                         fullShown = true;
                                         fullTime = Clock::now();
                                       }
                                     });
    const auto        release = Clock::now();
    send(QEvent::MouseButtonRelease, origin + QPointF(pixelsPerEvent * events, 0.0), Qt::LeftButton, Qt::NoButton);
    RunUntil([&] { return fullShown; }, 30.0);
    QObject::disconnect(released);
    if (fullShown)
    {
      releaseTimes.push_back(Seconds(release, fullTime));
    }
    state.SetIterationTime(seconds);
    framesPerSecond += frames / seconds;
    dragSeconds += seconds;
    shownFrames += frames;
    latencies.insert(latencies.end(), dragLatencies.begin(), dragLatencies.end());
  }
  viewer.Settle();
  const double iterations = static_cast<double>(state.iterations());
  state.counters["frames_per_s"] = framesPerSecond / iterations;
  state.counters["latency_median_ms"] = 1000.0 * Percentile(latencies, 0.5);
  state.counters["latency_p95_ms"] = 1000.0 * P95(latencies);
  state.counters["logic_median_ms"] = 1000.0 * Percentile(logicTimes, 0.5);
  state.counters["cpr_render_median_ms"] = 1000.0 * Percentile(cprRenderTimes, 0.5);
  state.counters["threeD_renders_per_s"] = static_cast<double>(threeDRenderTimes.size()) / dragSeconds;
  state.counters["threeD_render_median_ms"] = 1000.0 * Percentile(threeDRenderTimes, 0.5);
  state.counters["release_to_full_median_ms"] = 1000.0 * Percentile(releaseTimes, 0.5);
  state.counters["preview_fraction"] = shownFrames > 0 ? static_cast<double>(previews) / shownFrames : 0.0;
  window.GetController()->SetPreviewFactor(0);
}

void
Logic_AngleChange(benchmark::State & state)
{
  vr::VesselReformationLogic logic;
  logic.SetVolumeNode(PhantomInputs().Volume);
  logic.SetCenterlineNode(PhantomInputs().Centerlines);
  logic.SetSurfaceEnabled(false);
  logic.SetParameters(BenchmarkParameters(DesignAngle));
  logic.Update();
  std::size_t step = 0;
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    const auto start = Clock::now();
    logic.SetParameters(BenchmarkParameters(DesignAngle + 0.5 * static_cast<double>(++step % 20)));
    benchmark::DoNotOptimize(logic.Update().CPR.GetPointer());
    state.SetIterationTime(Seconds(start, Clock::now()));
  }
}

void
ThreeDView_Render(benchmark::State & state)
{
  BenchmarkViewer & viewer = PhantomViewer();
  vr::ThreeDView *  view = viewer.Window().GetThreeDView();
  const bool        full = state.range(0) == 1;
  viewer.Settle();
  view->SetInteracting(!full);
  long long points = 0;
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    view->Render();
    state.SetIterationTime(view->GetLastRenderSeconds());
    points = view->GetLastRenderedSurfacePoints();
  }
  view->SetInteracting(false);
  view->Render();
  state.counters["surface_points"] = static_cast<double>(points);
  state.SetLabel(full ? "full" : "preview");
  viewer.Settle();
}

/** A repaint of the whole window (what a changed spin box or progress bar costs: Qt composes the window with its two
 * OpenGL views through OpenGL, here Mesa's software one): the window marked dirty and its update request handled, as
 * Qt handles any widget's update. QWidget::repaint() of an unchanged window does no work after the first (it timed
 * 0 ms), so it does not stand for it. */
void
Window_Repaint(benchmark::State & state)
{
  BenchmarkViewer & viewer = PhantomViewer();
  viewer.Settle();
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    const auto start = Clock::now();
    viewer.Window().update();
    QCoreApplication::sendPostedEvents(nullptr, QEvent::UpdateRequest);
    QCoreApplication::processEvents(QEventLoop::ExcludeUserInputEvents);
    state.SetIterationTime(Seconds(start, Clock::now()));
  }
}

void
VesselPathRoll(benchmark::State & state)
{
  BenchmarkViewer &     viewer = PhantomViewer();
  vr::VesselPathPanel * panel = viewer.Window().GetPathPanel();
  viewer.Settle();
  if (!panel->HasPath() && !viewer.Window().OpenVesselPath(0))
  {
    state.SkipWithError("the longest path did not open");
    return;
  }
  RunUntil([panel] { return panel->HasPath() && !panel->IsUpdating(); });
  // Each repetition is one mouse step of a left-drag on the straightened CPR, 2 pixels (1 degree) on from the last
  // one's roll; the press before it and the release after it (which adds the cross-section stack) are not timed.
  vr::StraightenedCPRView * view = panel->GetStraightenedView();
  const QPointF             start(0.5 * view->width(), 0.5 * view->height());
  auto                      send = [view](QEvent::Type type, const QPointF & at, Qt::MouseButton button)
  {
    QMouseEvent event(type,
                      at,
                      view->mapToGlobal(at.toPoint()),
                      button,
                      type == QEvent::MouseButtonRelease ? Qt::NoButton : Qt::LeftButton,
                      Qt::NoModifier);
    QApplication::sendEvent(view, &event);
  };
  std::vector<double> logic;
  for (auto _ : state) // NOLINT(clang-analyzer-deadcode.DeadStores): Google Benchmark's loop
  {
    send(QEvent::MouseButtonPress, start, Qt::LeftButton);
    const auto begin = Clock::now();
    send(QEvent::MouseMove, start + QPointF(2.0, 0.0), Qt::NoButton);
    // The step is computed on the viewer's worker; the panel repaints the CPR as its result comes.
    RunUntil([panel] { return !panel->IsUpdating(); });
    state.SetIterationTime(Seconds(begin, Clock::now()));
    logic.push_back(1000.0 * panel->GetLastUpdateSeconds());
    send(QEvent::MouseButtonRelease, start + QPointF(2.0, 0.0), Qt::LeftButton);
    RunUntil([panel] { return !panel->IsUpdating(); });
  }
  const auto size = panel->GetOutputs().CPR->GetLargestPossibleRegion().GetSize();
  state.counters["logic_ms"] = Percentile(logic, 0.5);
  state.counters["cpr_rows"] = static_cast<double>(size[1]);
  state.counters["cpr_columns"] = static_cast<double>(size[0]);
  state.counters["sections"] = static_cast<double>(panel->GetOutputs().Sections.size());
}

constexpr int Repetitions = 30;

BENCHMARK(AngleChange)
  ->Iterations(1)
  ->Repetitions(Repetitions)
  ->UseManualTime()
  ->Unit(benchmark::kMillisecond)
  ->ComputeStatistics("p95", P95)
  ->ReportAggregatesOnly(true);
BENCHMARK(Logic_AngleChange)
  ->Iterations(1)
  ->Repetitions(Repetitions)
  ->UseManualTime()
  ->Unit(benchmark::kMillisecond)
  ->ComputeStatistics("p95", P95)
  ->ReportAggregatesOnly(true);
BENCHMARK(Drag)
  ->ArgName("preview_factor")
  ->Arg(0)
  ->Arg(1)
  ->Iterations(1)
  ->Repetitions(3)
  ->UseManualTime()
  ->Unit(benchmark::kMillisecond)
  ->ReportAggregatesOnly(true);
BENCHMARK(Window_Repaint)
  ->Iterations(1)
  ->Repetitions(Repetitions)
  ->UseManualTime()
  ->Unit(benchmark::kMillisecond)
  ->ComputeStatistics("p95", P95)
  ->ReportAggregatesOnly(true);
BENCHMARK(ThreeDView_Render)
  ->Arg(1)
  ->Arg(0)
  ->Iterations(1)
  ->Repetitions(10)
  ->UseManualTime()
  ->Unit(benchmark::kMillisecond)
  ->ComputeStatistics("p95", P95)
  ->ReportAggregatesOnly(true);
BENCHMARK(VesselPathRoll)
  ->Iterations(1)
  ->Repetitions(Repetitions)
  ->UseManualTime()
  ->Unit(benchmark::kMillisecond)
  ->ComputeStatistics("p95", P95)
  ->ReportAggregatesOnly(true);
} // namespace
