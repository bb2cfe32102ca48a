// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrStageMonitor_h
#define vrStageMonitor_h

#include "itkProcessObject.h"

#include <array>
#include <atomic>
#include <chrono>
#include <functional>
#include <string>
#include <vector>

namespace vr
{
/** Receives each start of a filter of either feature's logic (vr::VesselReformationLogic, vr::VesselPathLogic), on
 * the thread that runs it: what a host or a test watches to see where the logics run (docs/viewer.md, "Threads").
 * \ingroup VesselReformation */
using FilterStartObserver = std::function<void(const itk::ProcessObject & filter)>;
/** Sets the one process-wide observer of filter starts (empty: none, the default). Thread-safe; the observer is
 * called on the filters' threads and must be. */
void
SetFilterStartObserver(FilterStartObserver observer);

namespace detail
{
/** Has \a filter's starts reported to the observer of SetFilterStartObserver(): every filter a logic runs. */
void
ObserveFilterStarts(itk::ProcessObject * filter);

/** The stages of a reformation update, in the order they run. */
enum class Stage : unsigned int
{
  Extraction,
  Depth,
  Relax,
  UnfilteredSampling,
  RelaxedSampling
};
constexpr std::size_t NumberOfStages = 5;

/** Watches the filters of the module logic's pipeline (docs/design.md "Module logic"): counts and times each stage's
 * runs, maps each filter's progress into its stage's share of the whole update, and raises a filter's abort flag from
 * within the filter's own progress report once RequestAbort() was called (on the filter's thread, so no race on ITK's
 * flag). It calls back only the progress callback it is given; the logic reads counts and times from it. */
class StageMonitor
{
public:
  using ProgressCallback = std::function<void(double fraction, const std::string & stage)>;

  void
  SetProgressCallback(ProgressCallback callback);
  /** Reports \a fraction of the whole update, in stage \a stage, to the progress callback if there is one. */
  void
  ReportProgress(double fraction, const std::string & stage) const;

  /** Watches \a filter as stage \a stage (several filters may share one stage, e.g. the CPU and OpenCL relaxation);
   * \a name is what progress reports call it. The monitor must outlive the filter's observers. */
  void
  Watch(itk::ProcessObject * filter, Stage stage, const char * name);

  /** How often the stage's filters ran, and how long the latest run took. */
  unsigned int
  GetRuns(Stage stage) const;
  double
  GetSeconds(Stage stage) const;

  /** The stage's share of the progress bar, [from, to]. */
  void
  SetShare(Stage stage, double from, double to);
  double
  GetShareEnd(Stage stage) const;
  /** Divides the progress bar after \a base among the stages Depth … RelaxedSampling that will run (\a runs, in
   * that order): relaxation dominates unless \a iterations is small; the cut surface, when \a surface, takes a
   * share too. */
  void
  PlanShares(const std::array<bool, 4> & runs, unsigned int iterations, bool surface, double base);

  /** Marks an update as running and no abort as asked. */
  void
  BeginUpdate();
  /** Ends the update: clears every abort flag (the monitor's and \a filters') so that the next update runs. */
  void
  EndUpdate(const std::vector<itk::ProcessObject *> & filters);
  /** Asks a running update to stop (any thread); nothing when none runs. */
  void
  RequestAbort();
  bool
  IsAbortRequested() const;

  /** Updates \a filter's whole output (also when the view's size changed since its last run); an ITK error becomes
   * vr::InputError named after \a stage, an abort vr::Cancelled. */
  void
  Run(itk::ProcessObject * filter, const char * stage) const;

private:
  using Clock = std::chrono::steady_clock;
  struct StageWatch
  {
    unsigned int      Runs{ 0 };
    Clock::time_point Start;
    double            Seconds{ 0.0 };
    double            From{ 0.0 };
    double            To{ 1.0 };
  };
  StageWatch &
  WatchOf(Stage stage)
  {
    return m_Watches[static_cast<std::size_t>(stage)];
  }
  const StageWatch &
  WatchOf(Stage stage) const
  {
    return m_Watches[static_cast<std::size_t>(stage)];
  }

  std::array<StageWatch, NumberOfStages> m_Watches;
  ProgressCallback                       m_Progress;
  std::atomic<bool>                      m_Running{ false };
  std::atomic<bool>                      m_AbortRequested{ false };
};

/** Whether updating \a output will run its source: ITK's own test in DataObject::UpdateOutputData. */
bool
WillRun(itk::DataObject * output);

/** Turns a filter's itk::ExceptionObject into the one error type the logic reports (an abort into vr::Cancelled),
 * prefixed with \a stage. */
[[noreturn]] void
RethrowFilterError(const std::string & stage, const itk::ExceptionObject & error);
} // namespace detail
} // namespace vr

#endif
