// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrViewerBenchmarkSupport.h"

#include <QCoreApplication>
#include <QEvent>
#include <QEventLoop>
#include <QProgressBar>
#include <QTimer>

#include <algorithm>
#include <cmath>
#include <ctime>
#include <iostream>

namespace vr::benchmarks
{
double
Seconds(Clock::time_point start, Clock::time_point end)
{
  return std::chrono::duration<double>(end - start).count();
}

double
Percentile(std::vector<double> values, double fraction)
{
  if (values.empty())
  {
    return 0.0;
  }
  std::sort(values.begin(), values.end());
  const double position = fraction * static_cast<double>(values.size() - 1);
  const auto   low = static_cast<std::size_t>(std::floor(position));
  const auto   high = std::min(values.size() - 1, low + 1);
  return values[low] + (position - static_cast<double>(low)) * (values[high] - values[low]);
}

double
P95(const std::vector<double> & values)
{
  return Percentile(values, 0.95);
}

ReformationParameters
BenchmarkParameters(double angle)
{
  ReformationParameters parameters;
  parameters.AngleInDegrees = angle;
  parameters.ImageSize[0] = 512;
  parameters.ImageSize[1] = 1024;
  parameters.Iterations = 500;
  parameters.Relaxation = 1.0;
  parameters.Anisotropy = 0.5;
  parameters.Backend = RelaxBackend::CPU;
  parameters.Window = 900.0;
  parameters.Level = 200.0;
  return parameters;
}

bool
RunUntil(const std::function<bool()> & done, double seconds)
{
  QTimer heartbeat;
  heartbeat.start(1);
  const auto start = Clock::now();
  while (!done())
  {
    if (Seconds(start, Clock::now()) > seconds)
    {
      std::cerr << "timed out after " << seconds << " s" << std::endl;
      return false;
    }
    QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
  }
  return true;
}

BenchmarkViewer::BenchmarkViewer(const std::function<void(ViewerWindow &)> & open,
                                 const ReformationParameters &               parameters)
  : m_Window(std::make_unique<ViewerWindow>())
{
  m_Window->resize(1600, 1000);
  m_Window->GetPanel()->SetParameters(parameters);
  m_Window->show();
  QObject::connect(m_Window->GetThreeDView(),
                   &ThreeDView::rendered,
                   m_Window.get(),
                   [this](double, bool full) { m_RenderedFull = full; });
  QObject::connect(
    m_Window->GetController(), &ReformationController::resultReady, m_Window.get(), [this] { m_RenderedFull = false; });
  open(*m_Window);
  RunUntil([this] { return m_Window->GetCPRView()->GetResult() != nullptr; }, 600.0);
  Settle();
}

BenchmarkViewer::~BenchmarkViewer() = default;

void
BenchmarkViewer::Settle()
{
  if (!RunUntil(
        [this]
        {
          return m_Window->GetController()->IsIdle() && m_Window->GetThreeDView()->IsShowingFullSurface() &&
                 !m_Window->GetThreeDView()->IsInteracting() && m_RenderedFull;
        }))
  {
    std::cerr << "not settled: idle " << m_Window->GetController()->IsIdle() << ", full surface shown "
              << m_Window->GetThreeDView()->IsShowingFullSurface() << ", interacting "
              << m_Window->GetThreeDView()->IsInteracting() << ", rendered full " << m_RenderedFull << std::endl;
  }
}

double
BenchmarkViewer::NextAngle()
{
  return ViewerDesignAngle + 0.5 * static_cast<double>(++m_Step % 20);
}

const ReformationInputs &
PhantomInputs()
{
  static const ReformationInputs inputs = MakePhantomInputs("runoff", 1.5);
  return inputs;
}

BenchmarkViewer &
PhantomViewer()
{
  static std::unique_ptr<BenchmarkViewer> viewer;
  if (!viewer)
  {
    // The window must go before the QApplication it lives in: Qt calls its post routines first when it shuts down
    // (a static's destructor would run after main() has destroyed the application).
    qAddPostRoutine([] { viewer.reset(); });
    viewer = std::make_unique<BenchmarkViewer>(
      [](ViewerWindow & window)
      { window.GetController()->LoadInputs([] { return PhantomInputs(); }, QStringLiteral("the run-off phantom")); },
      BenchmarkParameters(ViewerDesignAngle));
  }
  return *viewer;
}

namespace
{
/** The processor time of the process, all threads, in seconds. */
double
ProcessSeconds()
{
  timespec time{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &time);
  return static_cast<double>(time.tv_sec) + 1e-9 * static_cast<double>(time.tv_nsec);
}

/** Notes when the widget it watches is shown. */
class ShowWatcher : public QObject
{
public:
  bool Shown{ false };

protected:
  bool
  eventFilter(QObject * watched, QEvent * event) override
  {
    if (event->type() == QEvent::Show)
    {
      Shown = true;
    }
    return QObject::eventFilter(watched, event);
  }
};
} // namespace

bool
TimeSettledAngleChange(BenchmarkViewer & viewer, AngleChangeTimes & times, std::string & error)
{
  ViewerWindow & window = viewer.Window();
  viewer.Settle();
  std::uint64_t     shownId = 0;
  Clock::time_point shownTime;
  Clock::time_point handledTime;
  auto              displayed = QObject::connect(window.GetCPRView(),
                                    &CPRView::imageDisplayed,
                                    window.GetCPRView(),
                                    [&](std::uint64_t id)
                                    {
                                      shownId = id;
                                      shownTime = Clock::now();
                                    });
  // Connected after the window's own slot, so it runs when the window has handled the result.
  auto        handled = QObject::connect(window.GetController(),
                                  &ReformationController::resultReady,
                                  window.GetCPRView(),
                                  [&](const std::shared_ptr<const ReformationResult> & result)
                                  {
                                    if (!result->HasFullSurface())
                                    {
                                      handledTime = Clock::now();
                                    }
                                  });
  ShowWatcher progress;
  for (auto * bar : window.findChildren<QProgressBar *>())
  {
    bar->installEventFilter(&progress);
  }
  const double angle = viewer.NextAngle();
  const double cpuStart = ProcessSeconds();
  const auto   start = Clock::now();
  window.GetPanel()->SetAngle(angle, RequestKind::Final);
  if (window.GetPanel()->GetAngle() != angle)
  {
    QObject::disconnect(displayed);
    QObject::disconnect(handled);
    error = "the panel did not take the angle";
    return false;
  }
  const bool shown = RunUntil(
    [&]
    {
      const auto result = window.GetCPRView()->GetResult();
      return shownId != 0 && result && result->RequestId == shownId &&
             result->Outputs.View.GetAngleInDegrees() == angle;
    });
  const double cpuEnd = ProcessSeconds();
  QObject::disconnect(displayed);
  QObject::disconnect(handled);
  if (!shown)
  {
    error = "the new angle's CPR was not displayed";
    return false;
  }
  const auto result = window.GetCPRView()->GetResult();
  times.Total = Seconds(start, shownTime);
  times.Logic = result->UpdateSeconds;
  times.PreviewSurface = result->PreviewSeconds;
  times.ToRequest = Seconds(start, result->RequestTime);
  times.ToWorker = Seconds(result->RequestTime, result->StartTime);
  times.WorkerRest = Seconds(result->StartTime, result->ReadyTime) - times.Logic - times.PreviewSurface;
  times.Show = Seconds(result->ReadyTime, handledTime);
  times.RenderCPR = window.GetCPRView()->GetLastRenderSeconds();
  times.ToFrame = Seconds(handledTime, shownTime);
  times.Depth = result->Outputs.Times.Depth;
  times.Relax = result->Outputs.Times.Relax;
  times.Resample = result->Outputs.Times.Resample;
  times.LogicRest = times.Logic - times.Depth - times.Relax - times.Resample;
  times.ProgressShown = progress.Shown;
  times.ProcessCPU = cpuEnd - cpuStart;
  if (result->StagesRun.Depth != 1 || result->StagesRun.Relax != 1)
  {
    error = "the angle change did not rerun depth and relaxation";
    return false;
  }
  return true;
}
} // namespace vr::benchmarks
