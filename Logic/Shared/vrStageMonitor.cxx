// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrStageMonitor.h"

#include "vrInputError.h"

#include "itkProcessObject.h"

#include <algorithm>
#include <memory>
#include <mutex>

namespace vr
{
namespace
{
std::mutex                                 g_ObserverMutex;
std::shared_ptr<const FilterStartObserver> g_Observer;
} // namespace

void
SetFilterStartObserver(FilterStartObserver observer)
{
  const std::lock_guard<std::mutex> lock(g_ObserverMutex);
  g_Observer = observer ? std::make_shared<const FilterStartObserver>(std::move(observer)) : nullptr;
}

namespace detail
{
void
ObserveFilterStarts(itk::ProcessObject * filter)
{
  filter->AddObserver(itk::StartEvent(),
                      [filter](const itk::EventObject &)
                      {
                        std::shared_ptr<const FilterStartObserver> observer;
                        {
                          const std::lock_guard<std::mutex> lock(g_ObserverMutex);
                          observer = g_Observer;
                        }
                        if (observer)
                        {
                          (*observer)(*filter);
                        }
                      });
}

void
StageMonitor::SetProgressCallback(ProgressCallback callback)
{
  m_Progress = std::move(callback);
}

void
StageMonitor::ReportProgress(double fraction, const std::string & stage) const
{
  if (m_Progress)
  {
    m_Progress(fraction, stage);
  }
}

void
StageMonitor::Watch(itk::ProcessObject * filter, Stage stage, const char * name)
{
  StageWatch & watch = WatchOf(stage);
  ObserveFilterStarts(filter);
  filter->AddObserver(itk::StartEvent(),
                      [&watch](const itk::EventObject &)
                      {
                        ++watch.Runs;
                        watch.Start = Clock::now();
                      });
  filter->AddObserver(itk::EndEvent(),
                      [&watch](const itk::EventObject &)
                      { watch.Seconds = std::chrono::duration<double>(Clock::now() - watch.Start).count(); });
  filter->AddObserver(itk::ProgressEvent(),
                      [this, filter, &watch, name](const itk::EventObject &)
                      {
                        if (m_AbortRequested && !filter->GetAbortGenerateData())
                        {
                          filter->AbortGenerateDataOn();
                        }
                        ReportProgress(watch.From + (watch.To - watch.From) * filter->GetProgress(), name);
                      });
}

unsigned int
StageMonitor::GetRuns(Stage stage) const
{
  return WatchOf(stage).Runs;
}

double
StageMonitor::GetSeconds(Stage stage) const
{
  return WatchOf(stage).Seconds;
}

void
StageMonitor::SetShare(Stage stage, double from, double to)
{
  WatchOf(stage).From = from;
  WatchOf(stage).To = to;
}

double
StageMonitor::GetShareEnd(Stage stage) const
{
  return WatchOf(stage).To;
}

void
StageMonitor::PlanShares(const std::array<bool, 4> & runs, unsigned int iterations, bool surface, double base)
{
  const double                relaxWeight = 0.05 + 0.6 * std::min(1.0, static_cast<double>(iterations) / 100.0);
  const std::array<double, 4> weights{ 0.1, relaxWeight, 0.1, 0.1 };
  const std::array<Stage, 4>  stages{ Stage::Depth, Stage::Relax, Stage::UnfilteredSampling, Stage::RelaxedSampling };
  double                      total = surface ? 0.1 : 0.0;
  for (std::size_t k = 0; k < 4; ++k)
  {
    total += runs[k] ? weights[k] : 0.0;
  }
  double at = base;
  for (std::size_t k = 0; k < 4; ++k)
  {
    const double share = runs[k] && total > 0.0 ? (1.0 - base) * weights[k] / total : 0.0;
    SetShare(stages[k], at, at + share);
    at += share;
  }
}

void
StageMonitor::BeginUpdate()
{
  m_AbortRequested = false;
  m_Running = true;
}

void
StageMonitor::EndUpdate(const std::vector<itk::ProcessObject *> & filters)
{
  m_Running = false;
  m_AbortRequested = false;
  for (itk::ProcessObject * filter : filters)
  {
    // An aborted filter's output was never marked generated, so it reruns next time anyway.
    filter->SetAbortGenerateData(false);
  }
}

void
StageMonitor::RequestAbort()
{
  if (m_Running)
  {
    m_AbortRequested = true;
  }
}

bool
StageMonitor::IsAbortRequested() const
{
  return m_AbortRequested;
}

void
StageMonitor::Run(itk::ProcessObject * filter, const char * stage) const
{
  try
  {
    // Whole images, also when the view's size changed since the previous update.
    filter->UpdateLargestPossibleRegion();
  }
  catch (const itk::ExceptionObject & error)
  {
    RethrowFilterError(stage, error);
  }
  if (m_AbortRequested)
  {
    throw Cancelled(std::string(stage) + ": cancelled");
  }
}

bool
WillRun(itk::DataObject * output)
{
  output->UpdateOutputInformation();
  output->SetRequestedRegionToLargestPossibleRegion();
  output->PropagateRequestedRegion();
  return output->GetUpdateMTime() < output->GetPipelineMTime() || output->GetDataReleased() ||
         output->RequestedRegionIsOutsideOfTheBufferedRegion();
}

void
RethrowFilterError(const std::string & stage, const itk::ExceptionObject & error)
{
  if (dynamic_cast<const itk::ProcessAborted *>(&error) != nullptr)
  {
    // The filter says how far it got ("aborted after 2801 of 200000 iterations").
    throw Cancelled(stage + ": cancelled (" + error.GetDescription() + ")");
  }
  throw InputError(stage + ": " + error.GetDescription());
}
} // namespace detail
} // namespace vr
