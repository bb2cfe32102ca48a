// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrReformationController_h
#define vrReformationController_h

#include "vrLogicWorker.h"
#include "vrPreviewPolicy.h"
#include "vrProgressiveRefinement.h"
#include "vrReformationInputs.h"
#include "vrReformationParameters.h"
#include "vrVesselReformationLogic.h"

#include <QObject>
#include <QString>
#include <QTimer>

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <map>
#include <optional>
#include <string>
#include <array>
#include <thread>
#include <vector>

class vtkPolyData;

namespace vr
{
/** How a request treats the update running when it arrives.
 * \ingroup VesselReformation
 */
enum class RequestKind
{
  /** Any change the user settled on (a spin box, a released slider, the end of a drag): aborts a running update
   * and replaces a pending request. Its cut surface is built after its images are shown. */
  Final,
  /** A step of a drag: replaces a pending request but lets a running preview finish and be shown, so that a drag
   * shows a new image each time the logic finishes one, at most one update behind the mouse. While previews are in
   * use (progressive refinement, docs/progressive-refinement.md) it is computed at k times the pixel spacing, aborts
   * a running full-resolution update, and a pause of RefinementDelayMilliseconds brings the full-resolution image.
   * No cut surface (the 3D view shows the preview surface). */
  Interactive
};

/** One displayed reformation: the logic's outputs for one request, with what the views need beside them.
 * \ingroup VesselReformation
 */
struct ReformationResult
{
  /** The request it answers (increasing in the order requests were made). */
  std::uint64_t RequestId{ 0 };
  RequestKind   Kind{ RequestKind::Final };
  /** The parameters it was computed with (a preview's: vr::PreviewParameters of the request's). */
  ReformationParameters Parameters;
  /** k: 1 for a full-resolution result, 2 or 4 for a preview at k times the pixel spacing of FullView. */
  unsigned int PreviewFactor{ 1 };
  /** The full-resolution view the result stands for (Outputs.View itself when PreviewFactor is 1): a view places a
   * preview over the same millimetres. */
  itk::CPRViewGeometry FullView;
  /** The logic's output nodes (the logic makes new nodes when a stage reruns, so these stay as they are). Surface is
   * null in the first result of a request and set in the second one (Final requests only). OcclusionProfile is set
   * in full-resolution results (at the full view's spacing), null in previews. */
  ReformationOutputs Outputs;
  /** The data the outputs were computed from (the overlays' centerlines, branch names). */
  std::shared_ptr<const ReformationInputs> Inputs;
  /** The cut surface at every PreviewStride-th pixel (vr::BuildPreviewSurface), for the 3D view while dragging. */
  vtkSmartPointer<vtkPolyData> PreviewSurface;
  unsigned int                 PreviewStride{ 1 };
  /** How many times each stage ran for this result (the logic's stage counts, after minus before). */
  ReformationStageCounts StagesRun;
  /** The logic's stage counts after this result's update. */
  ReformationStageCounts CountsAfter;
  /** Wall time of VesselReformationLogic::Update() for this result, in seconds. */
  double UpdateSeconds{ 0.0 };
  /** Wall time of building PreviewSurface on the worker after the update, in seconds (0 when not built). */
  double PreviewSeconds{ 0.0 };
  /** When the request was made, when the worker began its update, and when the worker handed the result to the GUI
   * thread (the time from this to the display is the GUI's). */
  std::chrono::steady_clock::time_point RequestTime;
  std::chrono::steady_clock::time_point StartTime;
  std::chrono::steady_clock::time_point ReadyTime;
  /** The window and level the logic gives for display (VesselReformationLogic::GetDisplayWindowLevel). */
  double LogicWindow{ 1.0 };
  double LogicLevel{ 0.0 };
  /** The warnings that hold for this result's inputs. */
  std::vector<std::string> Warnings;
  /** True for the second result of a Final request, the one with the full cut surface. */
  bool
  HasFullSurface() const
  {
    return Outputs.Surface != nullptr;
  }
  /** True for a preview (PreviewFactor > 1). */
  bool
  IsPreview() const
  {
    return PreviewFactor > 1;
  }
};

/** Counts of what happened to requests, for the status bar and for tests.
 * \ingroup VesselReformation
 */
struct RequestStatistics
{
  /** Requests whose images were shown. */
  unsigned int Displayed{ 0 };
  /** Requests replaced while they waited, never started. */
  unsigned int Superseded{ 0 };
  /** Updates stopped by VesselReformationLogic::AbortUpdate(), their vr::Cancelled dropped. */
  unsigned int Aborted{ 0 };
  /** Results that finished after a newer Final request was made, dropped without being shown. */
  unsigned int Stale{ 0 };
  /** Requests the logic refused (vr::InputError). */
  unsigned int Failed{ 0 };
  /** Of the Displayed, the previews (coarser images while an interaction went on). */
  unsigned int Previews{ 0 };
  /** Full-resolution updates started after a pause of an interaction (not counting Final requests). */
  unsigned int Refinements{ 0 };
};

/** \class ReformationController
 * \brief Runs the module logic on a worker thread for the widgets: they hand it parameters, it hands back results
 * to display. It computes nothing of its own.
 *
 * One vr::VesselReformationLogic lives on one worker thread, which alone calls it (AbortUpdate() aside, which is
 * thread-safe). At most one request waits: a new request replaces the waiting one (latest wins), and a Final request
 * also aborts the running update through the logic's AbortUpdate() (ITK's abort flag), whose vr::Cancelled is
 * dropped. So a fast drag never queues work. A result that finishes after a newer Final request was made is dropped
 * too (stale). Results come back on the thread that owns the controller (the GUI thread) through resultReady().
 *
 * Each request runs in two steps: the images (depth, relaxation, both CPRs) with the logic's cut surface off, shown
 * at once with a preview surface; then, for Final requests not yet superseded, the cut surface alone (the logic reruns
 * only that stage), shown as a second result of the same request. With SetSurfaceWaitsForDisplay(true), the cut
 * surface waits until ImageShown() says the images are on screen (or a time limit passes), so that it does not
 * compete with the drawing of the images for the processor.
 *
 * Inputs are loaded on the worker thread as well (files, phantoms): a loader that throws vr::InputError leaves the
 * inputs in use as they were and reports its message through inputsFailed(). Inputs with a segmentation are checked
 * by the logic before they are taken: it extracts their centerlines (one Update() of the logic with the load's
 * parameters, without the cut surface), and when that fails the logic goes back to the inputs in use and the message
 * comes through inputsFailed() as a file's would; inputsLoaded() carries the extracted centerlines.
 *
 * It is the viewer's vr::LogicWorker as well: the other features' tasks (the one-vessel reading's,
 * vr::VesselPathPanel) run on the same worker thread, between the reformation's updates and before waiting requests,
 * each feature's logic touched by its own tasks only; their progress comes through progressChanged() as the
 * reformation's does, and IsIdle() waits for them too.
 *
 * \sa VesselReformationLogic, CPRView, ThreeDView, LogicWorker
 * \ingroup VesselReformation
 */
class ReformationController
  : public QObject
  , public LogicWorker
{
  Q_OBJECT

public:
  using Loader = std::function<ReformationInputs()>;

  explicit ReformationController(QObject * parent = nullptr);
  /** Aborts a running update and joins the worker. */
  ~ReformationController() override;

  /** Loads new inputs on the worker: \a loader runs there. A running update is aborted and a waiting request dropped
   * (they were for the old data). Emits inputsLoaded() or inputsFailed(). A later Request() runs on the new inputs.
   * \param loader reads files or makes a phantom; throws vr::InputError on bad input.
   * \param what names what is loaded in messages ("aorta.mha").
   * \param parameters the parameters the logic extracts a segmentation's centerlines with (the view a request will
   *        ask for next, so that it reruns nothing); without them, the logic's current ones. */
  void
  LoadInputs(Loader loader, const QString & what, std::optional<ReformationParameters> parameters = std::nullopt);

  /** Asks for a reformation with \a parameters (see RequestKind for how it treats a running update).
   * \return the request's id. */
  std::uint64_t
  Request(const ReformationParameters & parameters, RequestKind kind);

  void
  RunTask(const std::string & lane, Task task) override;
  void
  ReportTaskProgress(double fraction, const std::string & stage) override;

  /** \return the inputs the next request runs on (null before the first load). GUI thread. */
  std::shared_ptr<const ReformationInputs>
  GetInputs() const;
  /** \return true while nothing runs or waits (loads included). */
  bool
  IsIdle() const;
  /** \return the logic's stage counts after its latest update (any thread). */
  ReformationStageCounts
  GetStageCounts() const;
  /** \return what happened to requests so far. */
  RequestStatistics
  GetStatistics() const;
  /** \return the most recent result shown, or null. */
  std::shared_ptr<const ReformationResult>
  GetLatestResult() const;

  /** Whether a Final request's cut surface waits for ImageShown() of its images (default false: it follows at once),
   * and for at most \a maximumSeconds (then it is built anyway, e.g. when no view is on screen). */
  void
  SetSurfaceWaitsForDisplay(bool wait, double maximumSeconds = 1.0);
  /** Says that the images of request \a requestId (or a later one) are on screen. Any thread. */
  void
  ImageShown(std::uint64_t requestId);
  /** The least time between two progressChanged() signals, in seconds (the first and the last always come). */
  static constexpr double ProgressIntervalSeconds = 0.1;

  /** Progressive refinement (docs/progressive-refinement.md). \a factor 0 (the default) chooses the preview factor k
   * from the measured times of recent updates and the frame budget (vr::ChoosePreviewFactor); 1 turns previews off
   * (every step at full resolution, as a test of exact images wants); 2 or 4 previews every step at that factor. */
  void
  SetPreviewFactor(unsigned int factor);
  /** The time a step's update should take, in seconds (default 0.05: 20 images a second). */
  void
  SetFrameBudget(double seconds);
  /** \return the factor the next Interactive step would be computed at. */
  unsigned int
  GetCurrentPreviewFactor() const;
  /** The pause after the latest Interactive step that starts the full-resolution update (when the step was a
   * preview). */
  static constexpr int RefinementDelayMilliseconds = 150;

signals:
  void
  inputsLoaded(std::shared_ptr<const vr::ReformationInputs> inputs);
  void
  inputsFailed(const QString & what, const QString & message);
  /** A result to display (stale ones are never emitted). */
  void
  resultReady(std::shared_ptr<const vr::ReformationResult> result);
  /** The logic refused request \a requestId: \a message names the parameter or node; \a parameter is the parameter by
   * meaning (vr::ParameterName) or empty. */
  void
  requestFailed(std::uint64_t requestId, const QString & message, const QString & parameter);
  /** Overall progress of the running update in [0, 1] and its stage. */
  void
  progressChanged(double fraction, const QString & stage);
  /** A warning of the logic (centerlines outside the volume, backend fallback). */
  void
  warningIssued(const QString & message);
  /** Becomes true when work starts and false when nothing runs or waits. */
  void
  busyChanged(bool busy);

private:
  struct Job
  {
    std::uint64_t                         Id{ 0 };
    RequestKind                           Kind{ RequestKind::Final };
    ReformationParameters                 Parameters;
    std::chrono::steady_clock::time_point Time;
    /** The full-resolution update after a pause of an interaction: never a preview. */
    bool Refinement{ false };
  };
  struct Load
  {
    Loader                               Run;
    QString                              What;
    std::optional<ReformationParameters> Parameters;
  };

  void
  WorkerLoop();
  /** Runs the waiting tasks, \a lock (on m_Mutex) released while each runs; their Done goes to the GUI thread. */
  void
  RunPendingTasks(std::unique_lock<std::mutex> & lock);
  /** Posts the check that sets busy off once nothing runs or waits. */
  void
  PostIdle();
  /** Posts progress to the GUI thread, at most every ProgressIntervalSeconds (worker thread). */
  void
  PostProgress(double fraction, const std::string & stage);
  void
  RunLoad(Load & load);
  void
  RunJob(const Job & job);
  /** Hands \a inputs' nodes to the logic: the volume, and the centerline or the segmentation node. */
  void
  SetLogicInputs(const ReformationInputs & inputs);
  /** Has the logic extract the centerlines of segmentation \a inputs; on failure the logic gets the inputs in use
   * back and the exception goes on. \return the inputs with their centerlines. */
  ReformationInputs
  ExtractCenterlines(const ReformationInputs & inputs, const std::optional<ReformationParameters> & parameters);
  /** Runs one logic update of \a parameters (the job's, or its preview's at \a factor) with the cut surface on or
   * off; returns the result, or null when cancelled or failed. */
  std::shared_ptr<ReformationResult>
  Update(const Job & job, const ReformationParameters & parameters, unsigned int factor, bool surface);
  /** The pause after an Interactive step ended: the full-resolution update when the step was a preview. GUI thread. */
  void
  Refine();
  /** Posts \a call to the GUI thread. */
  void
  Post(std::function<void()> call);
  void
  Deliver(std::shared_ptr<ReformationResult> result);
  void
  SetBusy(bool busy);

  // Worker-only state.
  VesselReformationLogic                   m_Logic;
  std::shared_ptr<const ReformationInputs> m_WorkerInputs;
  std::chrono::steady_clock::time_point    m_LastProgressTime;
  bool                                     m_ProgressStarted{ false };

  // Shared state, under m_Mutex.
  mutable std::mutex      m_Mutex;
  std::condition_variable m_Wake;
  std::optional<Job>      m_PendingJob;
  std::optional<Load>     m_PendingLoad;
  /** The waiting task of each lane. */
  std::map<std::string, Task> m_PendingTasks;
  bool                        m_Running{ false };
  /** The running work is a load: requests do not abort it (a newer load does). */
  bool        m_RunningLoad{ false };
  RequestKind m_RunningKind{ RequestKind::Final };
  /** The running update's factor (1: full resolution). */
  unsigned int m_RunningFactor{ 1 };
  bool         m_RunningRefinement{ false };
  /** The preview factor of each step and its parameters (docs/progressive-refinement.md); the times it chooses from
   * are those of updates whose view changed, until their image was on screen where the view reports that
   * (ImageShown()). */
  PreviewPolicy m_Preview;
  /** An angle step whose time runs until ImageShown() reports its image on screen. */
  struct DisplayTiming
  {
    std::uint64_t                         RequestId{ 0 };
    unsigned int                          Factor{ 1 };
    std::chrono::steady_clock::time_point Start;
  };
  std::optional<DisplayTiming> m_AwaitingDisplay;
  bool                         m_Quit{ false };
  std::uint64_t                m_NextId{ 1 };
  ReformationStageCounts       m_Counts;
  RequestStatistics            m_Statistics;
  bool                         m_SurfaceWaitsForDisplay{ false };
  double                       m_SurfaceWaitSeconds{ 1.0 };
  std::uint64_t                m_ShownId{ 0 };
  /** The latest request whose images were handed to the GUI thread. */
  std::uint64_t m_DeliveredId{ 0 };

  // GUI-thread state.
  std::shared_ptr<const ReformationInputs> m_Inputs;
  std::shared_ptr<const ReformationResult> m_Latest;
  /** Results of requests older than this one are stale. */
  std::uint64_t m_DisplayFloor{ 0 };
  bool          m_Busy{ false };
  /** Starts Refine() once an interaction pauses; the latest Interactive step's id and parameters. */
  QTimer                m_RefineTimer;
  std::uint64_t         m_LastInteractiveId{ 0 };
  ReformationParameters m_LastInteractiveParameters;

  std::thread m_Worker;
};
} // namespace vr

Q_DECLARE_METATYPE(std::shared_ptr<const vr::ReformationResult>)
Q_DECLARE_METATYPE(std::shared_ptr<const vr::ReformationInputs>)

#endif
