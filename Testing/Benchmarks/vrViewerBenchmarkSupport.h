// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// What the viewer benchmarks share (ViewerBenchmarks.cxx on the phantom, ViewerFullSizeBenchmarks.cxx on full-size
// studies): the clock, percentiles, the benchmark's parameters, running the event loop until something holds, a viewer
// window with its inputs loaded, and the timing of one settled angle change in it.
#ifndef vrViewerBenchmarkSupport_h
#define vrViewerBenchmarkSupport_h

#include "vrReformationInputs.h"
#include "vrReformationParameters.h"
#include "vrViewerWindow.h"

#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace vr::benchmarks
{
using Clock = std::chrono::steady_clock;

/** The run-off phantom's design angle (degrees), where every angle change of the viewer benchmarks starts. */
constexpr double ViewerDesignAngle = 30.0;

double
Seconds(Clock::time_point start, Clock::time_point end);

/** The value at \a fraction of the sorted values, interpolated linearly between ranks; 0 for none. */
double
Percentile(std::vector<double> values, double fraction);

double
P95(const std::vector<double> & values);

/** The viewer benchmarks' view and filter: 512 x 1024 pixels at \a angle, 500 CPU Jacobi passes, w = 1, a = 0.5,
 * the CTA window. */
ReformationParameters
BenchmarkParameters(double angle);

/** Runs the event loop until \a done() (checked after each event batch) or \a seconds pass; a 1 ms heartbeat wakes the
 * loop so that the check also runs when no event comes. \return done(). */
bool
RunUntil(const std::function<bool()> & done, double seconds = 120.0);

/** A viewer window (1600 x 1000, shown) with \a parameters in its panel, whose inputs \a open starts to load (e.g.
 * ViewerWindow::LoadPhantom or OpenFiles); the constructor returns when the first CPR is on screen and the window has
 * settled. */
class BenchmarkViewer
{
public:
  BenchmarkViewer(const std::function<void(ViewerWindow &)> & open, const ReformationParameters & parameters);
  ~BenchmarkViewer();
  BenchmarkViewer(const BenchmarkViewer &) = delete;
  BenchmarkViewer &
  operator=(const BenchmarkViewer &) = delete;

  ViewerWindow &
  Window()
  {
    return *m_Window;
  }

  /** Waits until nothing runs and the 3D view has drawn the full surface of the latest request. */
  void
  Settle();

  /** The next angle: 30.5, 31, ... 39.5, 30, ... (the panel's angle has one decimal). */
  double
  NextAngle();

  /** Whether the 3D view's last frame drew the full cut surface of the latest result. */
  bool
  HasRenderedFull() const
  {
    return m_RenderedFull;
  }

private:
  std::unique_ptr<ViewerWindow> m_Window;
  std::size_t                   m_Step{ 0 };
  bool                          m_RenderedFull{ false };
};

/** The run-off phantom at 1.5 mm (vr::MakePhantomInputs), made once. */
const ReformationInputs &
PhantomInputs();

/** The viewer window on the phantom with BenchmarkParameters(ViewerDesignAngle), made once (destroyed before the
 * application), settled after every use. */
BenchmarkViewer &
PhantomViewer();

/** The parts of one settled angle change, in seconds (see ViewerBenchmarks.cxx, AngleChange). */
struct AngleChangeTimes
{
  double Total{ 0.0 };
  double Logic{ 0.0 };
  double PreviewSurface{ 0.0 };
  double ToRequest{ 0.0 };
  double ToWorker{ 0.0 };
  double WorkerRest{ 0.0 };
  double Show{ 0.0 };
  double RenderCPR{ 0.0 };
  double ToFrame{ 0.0 };
  /** The logic's stages in that update (StageTimes): depth, relaxation, both resamplings, and the rest of its update
   * (the conversion of the inputs, the occlusion profile, the output nodes). */
  double Depth{ 0.0 };
  double Relax{ 0.0 };
  double Resample{ 0.0 };
  double LogicRest{ 0.0 };
  /** Whether the status bar's progress bar was shown during the change (it is shown once an update has run
   * ViewerWindow::ProgressDelayMilliseconds; showing it repaints the window). */
  bool ProgressShown{ false };
  /** The processor time the whole process (all its threads) spent from the change to the new CPR on screen. */
  double ProcessCPU{ 0.0 };
};

/** Settles \a viewer, types the next angle into its panel (a Final request) and runs the event loop until the new
 * angle's CPR is on screen (the CPR view's frame swapped). \return false, with \a error said, when the change was not
 * taken or not shown, or did not rerun the depth and the relaxation. */
bool
TimeSettledAngleChange(BenchmarkViewer & viewer, AngleChangeTimes & times, std::string & error);
} // namespace vr::benchmarks

#endif
