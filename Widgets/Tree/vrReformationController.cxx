// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrReformationController.h"

#include "vrInputError.h"
#include "vrSurfacePreview.h"

#include <QMetaObject>

#include <vtkPolyData.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace vr
{
namespace
{
/** The logic's stage counts of \a after minus \a before. */
ReformationStageCounts
Difference(const ReformationStageCounts & after, const ReformationStageCounts & before)
{
  ReformationStageCounts counts;
  counts.Conversion = after.Conversion - before.Conversion;
  counts.Extraction = after.Extraction - before.Extraction;
  counts.Depth = after.Depth - before.Depth;
  counts.Relax = after.Relax - before.Relax;
  counts.Resample = after.Resample - before.Resample;
  counts.UnfilteredSamplings = after.UnfilteredSamplings - before.UnfilteredSamplings;
  counts.RelaxedSamplings = after.RelaxedSamplings - before.RelaxedSamplings;
  counts.Surface = after.Surface - before.Surface;
  return counts;
}

/** Registers the result types for queued signals once. */
void
RegisterMetaTypes()
{
  static const bool registered = []
  {
    qRegisterMetaType<std::shared_ptr<const ReformationResult>>();
    qRegisterMetaType<std::shared_ptr<const ReformationInputs>>();
    qRegisterMetaType<std::uint64_t>("std::uint64_t");
    return true;
  }();
  (void)registered;
}
} // namespace

ReformationController::ReformationController(QObject * parent)
  : QObject(parent)
{
  RegisterMetaTypes();
  m_Logic.SetProgressCallback([this](double fraction, const std::string & stage) { PostProgress(fraction, stage); });
  m_Logic.SetWarningCallback(
    [this](const std::string & message, const std::string &)
    {
      const QString text = QString::fromStdString(message);
      Post([this, text] { emit warningIssued(text); });
    });
  m_RefineTimer.setSingleShot(true);
  m_RefineTimer.setInterval(RefinementDelayMilliseconds);
  connect(&m_RefineTimer, &QTimer::timeout, this, [this] { Refine(); });
  m_Worker = std::thread([this] { WorkerLoop(); });
}

ReformationController::~ReformationController()
{
  {
    std::lock_guard<std::mutex> lock(m_Mutex);
    m_Quit = true;
    m_PendingJob.reset();
    m_PendingLoad.reset();
    m_PendingTasks.clear();
    if (m_Running)
    {
      m_Logic.AbortUpdate();
    }
  }
  m_Wake.notify_all();
  m_Worker.join();
}

void
ReformationController::PostProgress(double fraction, const std::string & stage)
{
  // Throttled by time: the relaxation reports every few iterations, the status bar needs a few steps per second,
  // and each repaint of the window costs the processor the logic runs on (its OpenGL views are composed again).
  const auto now = std::chrono::steady_clock::now();
  if (fraction < 1.0 && m_ProgressStarted &&
      std::chrono::duration<double>(now - m_LastProgressTime).count() < ProgressIntervalSeconds)
  {
    return;
  }
  m_ProgressStarted = true;
  m_LastProgressTime = now;
  const QString name = QString::fromStdString(stage);
  Post([this, fraction, name] { emit progressChanged(fraction, name); });
}

void
ReformationController::RunTask(const std::string & lane, Task task)
{
  {
    std::lock_guard<std::mutex> lock(m_Mutex);
    m_PendingTasks[lane] = std::move(task);
  }
  SetBusy(true);
  m_Wake.notify_all();
}

void
ReformationController::ReportTaskProgress(double fraction, const std::string & stage)
{
  PostProgress(fraction, stage);
}

void
ReformationController::RunPendingTasks(std::unique_lock<std::mutex> & lock)
{
  while (!m_Quit && !m_PendingTasks.empty())
  {
    const auto first = m_PendingTasks.begin();
    Task       task = std::move(first->second);
    m_PendingTasks.erase(first);
    lock.unlock();
    m_ProgressStarted = false;
    try
    {
      task.Run();
    }
    catch (...)
    {
      // A task reports its own failures (LogicWorker); nothing may leave the worker thread.
    }
    if (task.Done)
    {
      Post(std::move(task.Done));
    }
    lock.lock();
  }
}

void
ReformationController::LoadInputs(Loader loader, const QString & what, std::optional<ReformationParameters> parameters)
{
  {
    std::lock_guard<std::mutex> lock(m_Mutex);
    if (m_PendingJob)
    {
      ++m_Statistics.Superseded;
      m_PendingJob.reset();
    }
    m_PendingLoad = Load{ std::move(loader), what, std::move(parameters) };
    if (m_Running)
    {
      m_Logic.AbortUpdate();
    }
    // Results of every request made so far belong to the old inputs.
    m_DisplayFloor = m_NextId;
  }
  m_RefineTimer.stop();
  SetBusy(true);
  m_Wake.notify_all();
}

std::uint64_t
ReformationController::Request(const ReformationParameters & parameters, RequestKind kind)
{
  std::uint64_t id = 0;
  {
    std::lock_guard<std::mutex> lock(m_Mutex);
    id = m_NextId++;
    if (m_PendingJob)
    {
      ++m_Statistics.Superseded;
    }
    m_PendingJob = Job{ id, kind, parameters, std::chrono::steady_clock::now() };
    if (kind == RequestKind::Final)
    {
      m_DisplayFloor = id;
      if (m_Running && !m_RunningLoad)
      {
        m_Logic.AbortUpdate();
      }
    }
    else if (m_Running && !m_RunningLoad && m_RunningFactor == 1 &&
             (m_RunningKind == RequestKind::Final || m_RunningRefinement) && m_Preview.ChooseFactor() > 1)
    {
      // A new step of an interaction aborts a full-resolution update while previews are in use: its preview comes
      // sooner, and the full image follows when the interaction pauses or ends.
      m_Logic.AbortUpdate();
    }
  }
  if (kind == RequestKind::Interactive)
  {
    m_LastInteractiveId = id;
    m_LastInteractiveParameters = parameters;
    m_RefineTimer.start();
  }
  else
  {
    m_RefineTimer.stop();
  }
  SetBusy(true);
  m_Wake.notify_all();
  return id;
}

void
ReformationController::Refine()
{
  {
    std::lock_guard<std::mutex> lock(m_Mutex);
    if (m_NextId - 1 != m_LastInteractiveId || m_Preview.ChooseFactor() <= 1)
    {
      return; // a newer request came, or the step was at full resolution already
    }
    const std::uint64_t id = m_NextId++;
    if (m_PendingJob)
    {
      ++m_Statistics.Superseded;
    }
    m_PendingJob =
      Job{ id, RequestKind::Interactive, m_LastInteractiveParameters, std::chrono::steady_clock::now(), true };
  }
  SetBusy(true);
  m_Wake.notify_all();
}

void
ReformationController::SetPreviewFactor(unsigned int factor)
{
  std::lock_guard<std::mutex> lock(m_Mutex);
  m_Preview.SetForcedFactor(factor);
}

void
ReformationController::SetFrameBudget(double seconds)
{
  std::lock_guard<std::mutex> lock(m_Mutex);
  m_Preview.SetFrameBudget(seconds);
}

unsigned int
ReformationController::GetCurrentPreviewFactor() const
{
  std::lock_guard<std::mutex> lock(m_Mutex);
  return m_Preview.ChooseFactor();
}

std::shared_ptr<const ReformationInputs>
ReformationController::GetInputs() const
{
  return m_Inputs;
}

bool
ReformationController::IsIdle() const
{
  return !m_Busy;
}

ReformationStageCounts
ReformationController::GetStageCounts() const
{
  std::lock_guard<std::mutex> lock(m_Mutex);
  return m_Counts;
}

RequestStatistics
ReformationController::GetStatistics() const
{
  std::lock_guard<std::mutex> lock(m_Mutex);
  return m_Statistics;
}

std::shared_ptr<const ReformationResult>
ReformationController::GetLatestResult() const
{
  return m_Latest;
}

void
ReformationController::SetSurfaceWaitsForDisplay(bool wait, double maximumSeconds)
{
  {
    std::lock_guard<std::mutex> lock(m_Mutex);
    m_SurfaceWaitsForDisplay = wait;
    m_SurfaceWaitSeconds = std::max(0.0, maximumSeconds);
  }
  m_Wake.notify_all();
}

void
ReformationController::ImageShown(std::uint64_t requestId)
{
  {
    std::lock_guard<std::mutex> lock(m_Mutex);
    m_ShownId = std::max(m_ShownId, requestId);
    if (m_AwaitingDisplay && m_AwaitingDisplay->RequestId == requestId)
    {
      const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - m_AwaitingDisplay->Start).count();
      m_Preview.RecordTime(m_AwaitingDisplay->Factor, seconds);
      m_AwaitingDisplay.reset();
    }
  }
  m_Wake.notify_all();
}

void
ReformationController::WorkerLoop()
{
  for (;;)
  {
    std::optional<Job>  job;
    std::optional<Load> load;
    {
      std::unique_lock<std::mutex> lock(m_Mutex);
      m_Wake.wait(lock, [this] { return m_Quit || m_PendingLoad || m_PendingJob || !m_PendingTasks.empty(); });
      // The other features' tasks go before a request: they are short beside a reformation, so none waits behind one.
      if (!m_Quit && !m_PendingLoad && !m_PendingTasks.empty())
      {
        m_Running = true;
        RunPendingTasks(lock);
        m_Running = false;
        if (!m_PendingJob && !m_PendingLoad)
        {
          lock.unlock();
          PostIdle();
          continue;
        }
      }
      if (!m_Quit && !m_PendingLoad && m_PendingJob && m_PendingJob->Kind == RequestKind::Interactive &&
          m_SurfaceWaitsForDisplay && m_ShownId < m_DeliveredId)
      {
        // One image of a drag in flight: the next step starts once the view has shown the last one (or a time limit
        // passed), so that the worker's threads leave the processor to the drawing, and the steps that came meanwhile
        // merge into the latest.
        m_Wake.wait_for(lock,
                        std::chrono::duration<double>(m_SurfaceWaitSeconds),
                        [this]
                        {
                          return m_Quit || m_PendingLoad || !m_PendingJob || m_PendingJob->Kind == RequestKind::Final ||
                                 !m_SurfaceWaitsForDisplay || m_ShownId >= m_DeliveredId || !m_PendingTasks.empty();
                        });
        if (!m_PendingTasks.empty())
        {
          continue; // the tasks first, the step after them
        }
      }
      if (!m_Quit && !m_PendingLoad && !m_PendingJob)
      {
        continue;
      }
      if (m_Quit)
      {
        return;
      }
      // A load goes first: requests made after it are for its data.
      m_RunningLoad = m_PendingLoad.has_value();
      if (m_PendingLoad)
      {
        load.swap(m_PendingLoad);
      }
      else
      {
        job.swap(m_PendingJob);
        m_RunningKind = job->Kind;
        m_RunningRefinement = job->Refinement;
        m_RunningFactor = 1;
      }
      m_Running = true;
    }
    if (load)
    {
      RunLoad(*load);
    }
    else
    {
      RunJob(*job);
    }
    bool idle = false;
    {
      std::lock_guard<std::mutex> lock(m_Mutex);
      m_Running = false;
      idle = !m_PendingJob && !m_PendingLoad && m_PendingTasks.empty();
    }
    if (idle)
    {
      PostIdle();
    }
  }
}

void
ReformationController::PostIdle()
{
  // Posted after the results, so when busyChanged(false) arrives every result has been delivered.
  Post(
    [this]
    {
      bool idleNow = false;
      {
        std::lock_guard<std::mutex> lock(m_Mutex);
        idleNow = !m_Running && !m_PendingJob && !m_PendingLoad && m_PendingTasks.empty();
      }
      if (idleNow)
      {
        SetBusy(false);
      }
    });
}

void
ReformationController::RunLoad(Load & load)
{
  try
  {
    ReformationInputs loaded = load.Run();
    if (loaded.Segmentation)
    {
      loaded = ExtractCenterlines(loaded, load.Parameters);
    }
    auto inputs = std::make_shared<const ReformationInputs>(std::move(loaded));
    m_WorkerInputs = inputs;
    // New data: its view and its update times are still to be measured.
    {
      std::lock_guard<std::mutex> lock(m_Mutex);
      m_Preview.Forget();
    }
    SetLogicInputs(*inputs);
    Post(
      [this, inputs]
      {
        m_Inputs = inputs;
        emit inputsLoaded(inputs);
      });
  }
  catch (const Cancelled &)
  {
    // A newer load aborted the extraction: it follows.
  }
  catch (const std::exception & error)
  {
    const QString what = load.What;
    const QString message = QString::fromStdString(error.what());
    Post([this, what, message] { emit inputsFailed(what, message); });
  }
}

void
ReformationController::SetLogicInputs(const ReformationInputs & inputs)
{
  m_Logic.SetVolumeNode(inputs.Volume);
  if (inputs.Segmentation)
  {
    m_Logic.SetCenterlineNode(nullptr);
    m_Logic.SetSegmentationNode(inputs.Segmentation);
  }
  else
  {
    m_Logic.SetSegmentationNode(nullptr);
    m_Logic.SetCenterlineNode(inputs.Centerlines);
  }
}

ReformationInputs
ReformationController::ExtractCenterlines(const ReformationInputs &                    inputs,
                                          const std::optional<ReformationParameters> & parameters)
{
  SetLogicInputs(inputs);
  if (parameters)
  {
    m_Logic.SetParameters(*parameters);
  }
  m_Logic.SetSurfaceEnabled(false);
  m_ProgressStarted = false;
  try
  {
    const ReformationOutputs & outputs = m_Logic.Update();
    {
      std::lock_guard<std::mutex> lock(m_Mutex);
      m_Counts = m_Logic.GetStageCounts();
    }
    return WithExtractedCenterlines(inputs, outputs.ExtractedCenterlines);
  }
  catch (...)
  {
    // The logic goes back to the inputs in use, so that the next request reforms the data on screen.
    if (m_WorkerInputs)
    {
      SetLogicInputs(*m_WorkerInputs);
    }
    else
    {
      m_Logic.SetSegmentationNode(nullptr);
    }
    std::lock_guard<std::mutex> lock(m_Mutex);
    m_Counts = m_Logic.GetStageCounts();
    throw;
  }
}

void
ReformationController::RunJob(const Job & job)
{
  // A step of an interaction: a preview of the same view when previews are in use and the full view is known.
  unsigned int          factor = 1;
  ReformationParameters parameters = job.Parameters;
  if (job.Kind == RequestKind::Interactive && !job.Refinement)
  {
    std::lock_guard<std::mutex> lock(m_Mutex);
    const PreviewPolicy::Step   step = m_Preview.PlanStep(job.Parameters);
    parameters = step.Parameters;
    factor = step.Factor;
  }
  {
    std::lock_guard<std::mutex> lock(m_Mutex);
    m_RunningFactor = factor;
    if (job.Refinement)
    {
      ++m_Statistics.Refinements;
    }
  }
  auto images = Update(job, parameters, factor, false);
  if (!images)
  {
    return;
  }
  Deliver(images);
  if (job.Kind != RequestKind::Final)
  {
    return;
  }
  {
    std::unique_lock<std::mutex> lock(m_Mutex);
    const auto                   superseded = [this] { return m_PendingJob || m_PendingLoad || m_Quit; };
    if (m_SurfaceWaitsForDisplay)
    {
      // Tasks that come meanwhile run while the surface waits.
      const auto deadline =
        std::chrono::steady_clock::now() + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                                             std::chrono::duration<double>(m_SurfaceWaitSeconds));
      const auto shown = [&] { return superseded() || !m_SurfaceWaitsForDisplay || m_ShownId >= job.Id; };
      while (!shown() && m_Wake.wait_until(lock, deadline, [&] { return shown() || !m_PendingTasks.empty(); }))
      {
        RunPendingTasks(lock);
      }
    }
    if (superseded())
    {
      return; // superseded: its surface would be stale before it is drawn
    }
  }
  auto surface = Update(job, parameters, factor, true);
  if (surface)
  {
    surface->PreviewSurface = images->PreviewSurface;
    surface->PreviewStride = images->PreviewStride;
    Deliver(surface);
  }
}

std::shared_ptr<ReformationResult>
ReformationController::Update(const Job &                   job,
                              const ReformationParameters & parameters,
                              unsigned int                  factor,
                              bool                          surface)
{
  using Clock = std::chrono::steady_clock;
  if (!m_WorkerInputs)
  {
    const std::uint64_t id = job.Id;
    Post([this, id] { emit requestFailed(id, tr("No volume and centerlines are loaded yet."), QString()); });
    return nullptr;
  }
  m_Logic.SetParameters(parameters);
  m_Logic.SetSurfaceEnabled(surface);
  // The occlusion strip's profile at the full view's spacing: a preview's would be computed again at its own.
  m_Logic.SetOcclusionProfileEnabled(factor == 1);
  m_ProgressStarted = false;
  const ReformationStageCounts before = m_Logic.GetStageCounts();
  const auto                   start = Clock::now();
  std::string                  failure;
  std::string                  parameter;
  try
  {
    const ReformationOutputs & outputs = m_Logic.Update();
    const double               seconds = std::chrono::duration<double>(Clock::now() - start).count();
    if (m_WorkerInputs->Segmentation && outputs.ExtractedCenterlines &&
        outputs.ExtractedCenterlines != m_WorkerInputs->Centerlines)
    {
      // The logic extracted again (its segmentation node came back after a failed load): the overlays follow.
      auto updated = std::make_shared<const ReformationInputs>(
        WithExtractedCenterlines(*m_WorkerInputs, outputs.ExtractedCenterlines));
      m_WorkerInputs = updated;
      Post([this, updated] { m_Inputs = updated; });
    }
    auto result = std::make_shared<ReformationResult>();
    result->RequestId = job.Id;
    result->Kind = job.Kind;
    result->Parameters = parameters;
    result->PreviewFactor = factor;
    {
      std::lock_guard<std::mutex> lock(m_Mutex);
      if (factor == 1)
      {
        result->FullView = outputs.View;
        m_Preview.RememberFullView(parameters, outputs.View);
      }
      else
      {
        result->FullView = m_Preview.FullViewOf(outputs.View);
      }
    }
    result->Outputs = outputs;
    result->Inputs = m_WorkerInputs;
    result->UpdateSeconds = seconds;
    result->RequestTime = job.Time;
    result->StartTime = start;
    result->CountsAfter = m_Logic.GetStageCounts();
    result->StagesRun = Difference(result->CountsAfter, before);
    m_Logic.GetDisplayWindowLevel(result->LogicWindow, result->LogicLevel);
    result->Warnings = m_Logic.GetWarnings();
    if (!surface)
    {
      const auto & size = outputs.View.GetSize();
      result->PreviewStride =
        PreviewSurfaceStride(static_cast<unsigned int>(size[0]), static_cast<unsigned int>(size[1]));
      const auto previewStart = Clock::now();
      result->PreviewSurface = BuildPreviewSurface(outputs, result->PreviewStride);
      result->PreviewSeconds = std::chrono::duration<double>(Clock::now() - previewStart).count();
      if (result->StagesRun.Depth > 0)
      {
        // A new view (an angle step): what the next step's choice of preview factor is made from. Where the view
        // reports its images on screen, the time runs until then (the drawing is part of each frame the user sees);
        // else it is the worker's part alone.
        std::lock_guard<std::mutex> lock(m_Mutex);
        if (m_SurfaceWaitsForDisplay)
        {
          m_AwaitingDisplay = DisplayTiming{ job.Id, factor, start };
        }
        else
        {
          m_Preview.RecordTime(factor, result->UpdateSeconds + result->PreviewSeconds);
        }
      }
    }
    std::lock_guard<std::mutex> lock(m_Mutex);
    m_Counts = result->CountsAfter;
    return result;
  }
  catch (const Cancelled &)
  {
    std::lock_guard<std::mutex> lock(m_Mutex);
    m_Counts = m_Logic.GetStageCounts();
    ++m_Statistics.Aborted;
    return nullptr;
  }
  catch (const InputError & error)
  {
    failure = error.what();
    parameter = error.Parameter();
  }
  catch (const std::exception & error)
  {
    failure = error.what();
  }
  {
    std::lock_guard<std::mutex> lock(m_Mutex);
    m_Counts = m_Logic.GetStageCounts();
    ++m_Statistics.Failed;
  }
  const std::uint64_t id = job.Id;
  const QString       message = QString::fromStdString(failure);
  const QString       name = QString::fromStdString(parameter);
  Post([this, id, message, name] { emit requestFailed(id, message, name); });
  return nullptr;
}

void
ReformationController::Post(std::function<void()> call)
{
  QMetaObject::invokeMethod(this, std::move(call), Qt::QueuedConnection);
}

void
ReformationController::Deliver(std::shared_ptr<ReformationResult> result)
{
  result->ReadyTime = std::chrono::steady_clock::now();
  if (!result->HasFullSurface())
  {
    std::lock_guard<std::mutex> lock(m_Mutex);
    m_DeliveredId = std::max(m_DeliveredId, result->RequestId);
  }
  Post(
    [this, result]
    {
      std::uint64_t floor = 0;
      {
        std::lock_guard<std::mutex> lock(m_Mutex);
        floor = m_DisplayFloor;
        if (result->RequestId < floor)
        {
          ++m_Statistics.Stale;
          // Never shown: the next step of a drag need not wait for it.
          m_ShownId = std::max(m_ShownId, result->RequestId);
          m_Wake.notify_all();
          return;
        }
        if (!result->HasFullSurface())
        {
          ++m_Statistics.Displayed;
          m_Statistics.Previews += result->IsPreview() ? 1 : 0;
        }
      }
      m_Latest = result;
      emit resultReady(result);
    });
}

void
ReformationController::SetBusy(bool busy)
{
  if (busy == m_Busy)
  {
    return;
  }
  m_Busy = busy;
  emit busyChanged(busy);
}
} // namespace vr
