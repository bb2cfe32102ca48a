// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrViewerWindow.h"

#include "itkCTAPhantom.h"
#include "vrInputError.h"
#include "vrModuleDescription.h"
#include "vrViewerLayout.h"
#include "vrViewerStatusBar.h"
#include "vrWindowKeyPolicy.h"

#include <QAction>
#include <QActionGroup>
#include <QDoubleSpinBox>
#include <QApplication>
#include <QFileDialog>
#include <QImage>
#include <QLineEdit>
#include <QLabel>
#include <QDir>
#include <QCloseEvent>
#include <QKeySequence>
#include <QTextBrowser>
#include <QDialog>
#include <QVBoxLayout>
#include <QPushButton>
#include <QHBoxLayout>
#include <QFrame>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QProgressBar>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QSlider>
#include <QSplitter>
#include <QStatusBar>
#include <QTimer>

#include <vtkImageData.h>
#include <vtkPointData.h>

#include <algorithm>
#include <cmath>

namespace vr
{
namespace
{
QString
Milliseconds(double seconds)
{
  return QStringLiteral("%1 ms").arg(std::lround(1000.0 * seconds));
}
} // namespace

ViewerWindow::ViewerWindow(QWidget * parent)
  : QMainWindow(parent)
{
  setWindowTitle(QStringLiteral("%1 %2").arg(QString::fromUtf8(ModuleDescription::Title),
                                             QString::fromUtf8(ModuleDescription::Version)));
  m_Controller = new ReformationController(this);
  m_Panel = new ModulePanel;
  m_CPRView = new CPRView;
  m_OcclusionStrip = new OcclusionStrip;
  m_ThreeDView = new ThreeDView;
  m_PathPanel = new VesselPathPanel;
  m_PathPanel->setVisible(false);
  // Both features' logics run on the one worker (docs/viewer.md, "Threads").
  m_PathPanel->SetWorker(m_Controller);

  auto * scroll = new QScrollArea;
  scroll->setWidget(m_Panel);
  scroll->setWidgetResizable(true);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  m_Panel->setMinimumWidth(m_Panel->minimumSizeHint().width());
  scroll->setMinimumWidth(m_Panel->minimumSizeHint().width() + scroll->verticalScrollBar()->sizeHint().width() + 40);
  auto * splitter = new QSplitter(Qt::Horizontal);
  m_Splitter = splitter;
  splitter->addWidget(scroll);
  // The CPR view with the occlusion strip under it, one pane of the splitter.
  auto * cprPane = new QWidget;
  auto * cprLayout = new QVBoxLayout(cprPane);
  cprLayout->setContentsMargins(0, 0, 0, 0);
  cprLayout->setSpacing(0);
  cprLayout->addWidget(m_CPRView, 1);
  cprLayout->addWidget(m_OcclusionStrip, 0);
  splitter->addWidget(cprPane);
  splitter->addWidget(m_ThreeDView);
  splitter->addWidget(m_PathPanel);
  splitter->setStretchFactor(0, 0);
  splitter->setStretchFactor(1, 3);
  splitter->setStretchFactor(2, 2);
  splitter->setStretchFactor(3, 3);
  m_Layout = new ViewerLayout(splitter);
  m_KeyPolicy = new WindowKeyPolicy(this);

  // Warnings in full above the views, until dismissed or new data is opened.
  m_WarningBanner = new QFrame;
  m_WarningBanner->setObjectName(QStringLiteral("warningBanner"));
  m_WarningBanner->setStyleSheet(QStringLiteral("#warningBanner { background: #fff3c4; border: 1px solid #d9a400; }"));
  m_WarningText = new QLabel;
  m_WarningText->setWordWrap(true);
  m_WarningText->setTextInteractionFlags(Qt::TextSelectableByMouse);
  auto * dismiss = new QPushButton(tr("Dismiss"));
  connect(dismiss, &QPushButton::clicked, this, [this] { ClearWarnings(); });
  auto * bannerLayout = new QHBoxLayout(m_WarningBanner);
  bannerLayout->addWidget(m_WarningText, 1);
  bannerLayout->addWidget(dismiss, 0, Qt::AlignTop);
  m_WarningBanner->setVisible(false);
  auto * central = new QWidget;
  auto * centralLayout = new QVBoxLayout(central);
  centralLayout->setContentsMargins(0, 0, 0, 0);
  centralLayout->addWidget(m_WarningBanner);
  centralLayout->addWidget(splitter, 1);
  setCentralWidget(central);

  // Messages, the readout, the times and the progress each in a field of their own.
  auto * status = new ViewerStatusBar;
  setStatusBar(status);
  m_Readout = status->GetReadoutField();
  m_Readout->setToolTip(tr("The pixel under the mouse: column and row, its RAS position in mm, the intensity (HU), the "
                           "depth along the view direction (mm) and the branch owning it."));
  m_Times = status->GetTimesField();
  m_Times->setToolTip(tr("The time of each stage of the latest update (the logic's own), and of drawing it."));
  m_Progress = status->GetProgressBar();
  m_ProgressDelay = new QTimer(this);
  m_ProgressDelay->setSingleShot(true);
  m_ProgressDelay->setTimerType(Qt::PreciseTimer);
  m_ProgressDelay->setInterval(ProgressDelayMilliseconds);
  connect(m_ProgressDelay, &QTimer::timeout, m_Progress, [this] { m_Progress->setVisible(true); });

  BuildMenus();
  ConnectParts();
  ApplyDisplay();
  resize(1600, 1000);
}

ViewerWindow::~ViewerWindow()
{
  // The layout watches the splitter and the path panel through event filters: it goes first, so that the parts'
  // own destruction (children removed, hidden) never reaches a filter that asks the half-destroyed splitter.
  delete m_Layout;
  m_Layout = nullptr;
  // The worker may go before the panel among the window's children.
  m_PathPanel->SetWorker(nullptr);
}

bool
ViewerWindow::IsProgressShown() const
{
  return m_Progress->isVisible();
}

void
ViewerWindow::BuildMenus()
{
  QMenu * file = menuBar()->addMenu(tr("&File"));
  file->addAction(
    tr("Open &volume…"), this, [this] { ChooseAndOpenVolume(false); }, QKeySequence::Open);
  file->addAction(tr("Open &DICOM folder…"), this, [this] { ChooseAndOpenVolume(true); });
  file->addAction(tr("Open &centerlines…"), this, [this] { ChooseAndOpenCenterlines(); });
  file->addAction(tr("Open volume &and centerlines…"), this, [this] { ChooseAndOpenVolumeAndCenterlines(); })
    ->setObjectName(QStringLiteral("openVolumeAndCenterlines"));
  file->addAction(tr("Open a vessel se&gmentation…"), this, [this] { ChooseAndOpenSegmentation(); })
    ->setObjectName(QStringLiteral("openSegmentation"));
  QMenu * phantoms = file->addMenu(tr("Open &phantom"));
  for (const auto & name : PhantomNames())
  {
    // "thorax: synthetic thoracic CTA (aortic arch and its branches)": the factory's own description.
    const QString text = QString::fromStdString(name);
    const QString description = QString::fromStdString(itk::MakeCTAPhantom(itk::ParseCTAPhantomKind(name)).Description);
    QAction *     action =
      phantoms->addAction(tr("%1: %2").arg(text, description), this, [this, text] { LoadPhantom(text); });
    action->setObjectName(QStringLiteral("openPhantom_%1").arg(text));
  }
  m_RecentMenu = file->addMenu(tr("Open &recent"));
  m_RecentMenu->setObjectName(QStringLiteral("recentMenu"));
  connect(m_RecentMenu, &QMenu::aboutToShow, this, [this] { FillRecentMenu(); });
  file->addSeparator();
  file->addAction(
    tr("&Save outputs…"), this, [this] { ChooseAndSaveOutputs(); }, QKeySequence::Save);
  file->addAction(tr("Save screens&hot…"), this, [this] { ChooseAndSaveScreenshot(); });
  file->addAction(tr("Export &rotation series…"), this, [this] { ChooseAndExportRotationSeries(); })
    ->setObjectName(QStringLiteral("exportRotationSeries"));
  file->addSeparator();
  file->addAction(tr("&Quit"), this, &QWidget::close, QKeySequence::Quit);

  QMenu * edit = menuBar()->addMenu(tr("&Edit"));
  m_UndoOpen = edit->addAction(
    tr("&Undo open"), this, [this] { UndoOpen(); }, QKeySequence::Undo);
  m_UndoOpen->setObjectName(QStringLiteral("undoOpen"));
  m_UndoOpen->setToolTip(tr("Go back to the volume and centerlines shown before the latest open"));
  m_UndoOpen->setEnabled(false);

  QMenu * view = menuBar()->addMenu(tr("&View"));
  view->addAction(tr("&Fit the CPR image"),
                  this,
                  [this]
                  {
                    m_CPRView->FitImage();
                    m_CPRView->Render();
                  });
  view->addAction(tr("&Reset the 3D camera"),
                  this,
                  [this]
                  {
                    m_ThreeDView->ResetCamera();
                    m_ThreeDView->ScheduleRender();
                  });

  BuildViewKeys(view);

  BuildVesselPathMenu();

  QMenu * help = menuBar()->addMenu(tr("&Help"));
  help
    ->addAction(
      tr("Vessel Reformation &help"), this, [this] { ShowHelp(); }, QKeySequence::HelpContents)
    ->setObjectName(QStringLiteral("showHelp"));
  help->addAction(tr("&About Vessel Reformation"), this, [this] { ShowAbout(); });
}

bool
ViewerWindow::GoToBestView()
{
  const auto profile = m_OcclusionStrip->GetProfile();
  if (!profile || profile->HiddenLength.empty())
  {
    statusBar()->showMessage(tr("Best view: the occlusion profile is not computed yet"), 5000);
    return false;
  }
  const unsigned int angle = profile->LeastOccludedAngle();
  statusBar()->showMessage(tr("Best view: %1° hides %2 mm (%3 % of the tree)")
                             .arg(angle)
                             .arg(profile->HiddenLength[angle], 0, 'f', 0)
                             .arg(100.0 * profile->HiddenFraction(angle), 0, 'f', 1),
                           8000);
  m_Panel->SetAngle(static_cast<double>(angle), RequestKind::Final);
  return true;
}

void
ViewerWindow::ConnectParts()
{
  ConnectVesselPath();
  connect(m_Panel, &ModulePanel::parametersChanged, this, [this](RequestKind kind) { RequestReformation(kind); });
  connect(m_Panel, &ModulePanel::displayChanged, this, [this] { ApplyDisplay(); });
  connect(m_Panel,
          &ModulePanel::fullRangeRequested,
          this,
          [this]
          {
            vtkImageData * image = m_CPRView->GetDisplayedImage(false);
            if (image->GetPointData() == nullptr || image->GetPointData()->GetScalars() == nullptr)
            {
              m_FullRangeOnNextResult = true;
              return;
            }
            double range[2];
            image->GetScalarRange(range);
            m_Panel->ApplyPreset(
              QStringLiteral("Full range"), std::max(range[1] - range[0], 1.0), 0.5 * (range[0] + range[1]));
          });
  connect(m_Panel, &ModulePanel::openVolumeRequested, this, [this] { ChooseAndOpenVolume(false); });
  connect(m_Panel, &ModulePanel::openCenterlinesRequested, this, [this] { ChooseAndOpenCenterlines(); });
  connect(m_Panel, &ModulePanel::openSegmentationRequested, this, [this] { ChooseAndOpenSegmentation(); });
  connect(m_Panel, &ModulePanel::loadPhantomRequested, this, [this](const QString & name) { LoadPhantom(name); });
  connect(m_Panel, &ModulePanel::saveOutputsRequested, this, [this] { ChooseAndSaveOutputs(); });
  connect(m_Panel->GetAngleSlider(), &QSlider::sliderPressed, this, [this] { m_ThreeDView->SetInteracting(true); });
  connect(m_Panel->GetAngleSlider(), &QSlider::sliderReleased, this, [this] { m_ThreeDView->SetInteracting(false); });

  connect(m_CPRView,
          &CPRView::rotationStarted,
          this,
          [this]
          {
            m_DragStartAngle = m_Panel->GetAngle();
            m_Turning = true;
            m_ThreeDView->SetInteracting(true);
          });
  connect(m_CPRView,
          &CPRView::rotationDragged,
          this,
          [this](double degrees, bool finished)
          {
            const double angle = WrapAngle(m_DragStartAngle + degrees);
            if (finished)
            {
              m_Turning = false;
              m_ThreeDView->SetInteracting(false);
              m_Panel->SetAngle(angle, RequestKind::Final);
              return;
            }
            RequestTurn(angle);
          });
  connect(m_OcclusionStrip,
          &OcclusionStrip::angleClicked,
          this,
          [this](double degrees) { m_Panel->SetAngle(degrees, RequestKind::Final); });
  connect(m_CPRView,
          &CPRView::windowLevelChanged,
          this,
          [this](double window, double level) { m_Panel->SetWindowLevel(window, level, /*byHand=*/true); });
  connect(m_CPRView,
          &CPRView::readoutChanged,
          this,
          [this](const PixelReadout & readout) { m_Readout->setText(readout.ToText()); });
  // The cut surface of a Final request is built once its images are on screen, not while they are drawn.
  m_Controller->SetSurfaceWaitsForDisplay(true);
  connect(m_CPRView,
          &CPRView::imageDisplayed,
          this,
          [this](std::uint64_t requestId)
          {
            m_Controller->ImageShown(requestId);
            m_ThreeDView->ScheduleRender();
          });
  connect(m_ThreeDView, &ThreeDView::rendered, this, [this] { ShowTimes(); });

  connect(m_Controller,
          &ReformationController::inputsLoaded,
          this,
          [this](std::shared_ptr<const ReformationInputs> inputs)
          {
            // What was on screen can be had back (Edit > Undo open), unless this load was that undo.
            if (m_CurrentInputs && !m_Undoing)
            {
              m_UndoInputs.push_back(m_CurrentInputs);
              if (m_UndoInputs.size() > MaximumUndoSteps)
              {
                m_UndoInputs.erase(m_UndoInputs.begin());
              }
            }
            m_Undoing = false;
            if (m_PendingRecent && m_Settings)
            {
              m_Settings->AddRecent(*m_PendingRecent);
            }
            m_PendingRecent.reset();
            // A new volume opens on the window that suits it; new centerlines or a segmentation keep the user's.
            const bool newVolume = !m_CurrentInputs || m_CurrentInputs->Volume != inputs->Volume;
            m_CurrentInputs = inputs;
            m_UndoOpen->setEnabled(!m_UndoInputs.empty());
            m_Panel->SetInputDescription(QString::fromStdString(inputs->VolumeSource),
                                         QString::fromStdString(inputs->CenterlineSource),
                                         inputs->Segmentation ? QString::fromStdString(inputs->Segmentation->GetName())
                                                              : QString());
            m_ThreeDView->SetInputs(inputs);
            CloseVesselPath();
            m_PathPanel->SetInputs(inputs);
            m_Panel->SetIntensityUnit(QString::fromStdString(inputs->IntensityUnit));
            m_Panel->SetPercentileWindow(inputs->PercentileWindow, inputs->PercentileLevel);
            if (inputs->IsPhantom)
            {
              m_Panel->ShowPhantom(QString::fromStdString(inputs->PhantomName));
            }
            if (newVolume)
            {
              // A CT in the CTA preset; data without HU (MR) on its own 1-99 % percentiles.
              m_Panel->ApplyPreset(inputs->IntensityUnit == "HU" ? QString::fromLatin1(CTAPreset.Name)
                                                                 : QString::fromUtf8(PercentilePresetName),
                                   0.0,
                                   0.0);
            }
            const QString loaded = inputs->IsPhantom && inputs->CenterlineSource.find('/') == std::string::npos
                                     ? tr("Loaded %1").arg(QString::fromStdString(inputs->VolumeSource))
                                     : tr("Loaded %1 and %2")
                                         .arg(QFileInfo(QString::fromStdString(inputs->VolumeSource)).fileName(),
                                              QFileInfo(QString::fromStdString(inputs->CenterlineSource)).fileName());
            QStringList   notes;
            for (const auto & note : inputs->Notes)
            {
              notes << QString::fromStdString(note);
            }
            // What was skipped changes nothing in the image: the status bar, not the warning banner.
            statusBar()->showMessage(notes.isEmpty() ? loaded : loaded + QStringLiteral("; ") + notes.join("; "),
                                     notes.isEmpty() ? 5000 : 15000);
            ClearWarnings();
            for (const auto & warning : inputs->Warnings)
            {
              ShowWarning(QString::fromStdString(warning));
            }
            RequestReformation(RequestKind::Final);
          });
  connect(m_Controller,
          &ReformationController::inputsFailed,
          this,
          [this](const QString & what, const QString & message)
          {
            m_Undoing = false;
            m_PendingRecent.reset();
            ShowError(tr("Cannot open %1").arg(what), message);
          });
  connect(m_Controller,
          &ReformationController::resultReady,
          this,
          [this](std::shared_ptr<const ReformationResult> result) { ShowResult(result); });
  connect(m_Controller,
          &ReformationController::requestFailed,
          this,
          [this](std::uint64_t, const QString & message, const QString & parameter)
          {
            if (parameter.isEmpty())
            {
              ShowError(tr("The reformation failed"), message);
              return;
            }
            m_Panel->MarkParameterError(parameter, message);
            m_LastError = tr("Invalid %1: %2").arg(parameter, message);
            statusBar()->showMessage(m_LastError);
            emit errorShown(tr("Invalid %1").arg(parameter), message);
          });
  connect(m_Controller,
          &ReformationController::warningIssued,
          this,
          [this](const QString & message) { ShowWarning(message); });
  connect(m_Controller,
          &ReformationController::progressChanged,
          this,
          [this](double fraction, const QString & stage)
          {
            m_Progress->setValue(static_cast<int>(std::lround(1000.0 * fraction)));
            m_Progress->setFormat(stage);
          });
  connect(m_Controller,
          &ReformationController::busyChanged,
          this,
          [this](bool busy)
          {
            // Work that ends within the delay never shows the bar (and never repaints the window for it).
            if (busy)
            {
              m_Progress->setValue(0);
              m_ProgressDelay->start();
            }
            else
            {
              m_ProgressDelay->stop();
              m_Progress->setVisible(false);
            }
          });
}

void
ViewerWindow::RequestReformation(RequestKind kind)
{
  ReformationParameters parameters;
  try
  {
    parameters = m_Panel->GetParameters();
  }
  catch (const InputError & error)
  {
    m_Panel->MarkParameterError(QString::fromStdString(error.Parameter()), QString::fromUtf8(error.what()));
    statusBar()->showMessage(QString::fromUtf8(error.what()));
    return;
  }
  if (!m_Controller->GetInputs())
  {
    return; // the request follows the load
  }
  m_Controller->Request(parameters, kind);
}

void
ViewerWindow::RequestTurn(double angle)
{
  ReformationParameters parameters;
  try
  {
    parameters = m_Panel->GetParameters();
  }
  catch (const InputError &)
  {
    return; // the panel marks its invalid parameter; the release's Final request reports it
  }
  parameters.AngleInDegrees = angle;
  if (m_Controller->GetInputs())
  {
    m_Controller->Request(parameters, RequestKind::Interactive);
  }
}

void
ViewerWindow::ApplyDisplay()
{
  const double window = m_Panel->GetWindowSpinBox()->value();
  const double level = m_Panel->GetLevelSpinBox()->value();
  m_CPRView->SetOverlays(m_Panel->GetOverlays());
  m_CPRView->SetComparison(m_Panel->GetComparison());
  m_CPRView->SetWindowLevel(window, level);
  m_ThreeDView->SetWindowLevel(window, level);
  m_PathPanel->SetWindowLevel(window, level);
  m_ThreeDView->ScheduleRender();
}

void
ViewerWindow::ShowResult(const std::shared_ptr<const ReformationResult> & result)
{
  m_Panel->MarkParameterError(QString(), QString());
  if (result->HasFullSurface())
  {
    m_ShownSurface = result;
    m_ThreeDView->SetResult(result);
    m_ThreeDView->ScheduleRender();
  }
  else
  {
    m_Shown = result;
    m_ShownSurface.reset();
    ShowRelaxBackend(result->Outputs);
    if (m_Turning && result->Kind == RequestKind::Interactive)
    {
      // The panel follows the drag at the pace of the images, without asking for another reformation.
      const QSignalBlocker quiet(m_Panel);
      m_Panel->SetAngle(result->Parameters.AngleInDegrees, RequestKind::Interactive);
    }
    m_CPRView->SetResult(result);
    if (result->Outputs.OcclusionProfile)
    {
      m_OcclusionStrip->SetProfile(result->Outputs.OcclusionProfile); // previews have none: the last one stays
    }
    m_OcclusionStrip->SetCurrentAngle(result->Outputs.View.GetAngleInDegrees());
    m_ThreeDView->SetResult(result);
    m_PathPanel->SetViewParameters(result->Parameters);
    if (m_FullRangeOnNextResult)
    {
      m_FullRangeOnNextResult = false;
      double range[2];
      m_CPRView->GetDisplayedImage(false)->GetScalarRange(range);
      m_Panel->ApplyPreset(
        QStringLiteral("Full range"), std::max(range[1] - range[0], 1.0), 0.5 * (range[0] + range[1]));
    }
  }
  for (const auto & warning : result->Warnings)
  {
    ShowWarning(QString::fromStdString(warning));
  }
  ShowTimes();
}

void
ViewerWindow::ShowRelaxBackend(const ReformationOutputs & outputs)
{
  const QString backend = QString::fromStdString(outputs.RelaxBackendUsed);
  const QString reason = QString::fromStdString(outputs.RelaxBackendReason);
  m_Panel->SetRelaxBackendReport(backend, reason);
  m_Times->setToolTip(tr("The time of each stage of the latest update (the logic's own), and of drawing it. The "
                         "relaxation ran on %1: %2.")
                        .arg(backend, reason));
  if (!reason.isEmpty() && reason != m_ShownBackendReason)
  {
    // Said once in the status bar when the choice changes, and always under the backend choice in the panel.
    m_ShownBackendReason = reason;
    m_BackendMessage = tr("Relaxation on %1: %2").arg(backend, reason);
    m_BackendMessageTime.start();
    ShowBackendMessage();
  }
}

void
ViewerWindow::ShowBackendMessage()
{
  const qint64 remaining = 10000 - m_BackendMessageTime.elapsed();
  if (m_BackendMessage.isEmpty() || remaining <= 0)
  {
    return;
  }
  // Elided to the room the stage times leave (again whenever they change); the whole reason is in the panel and the
  // times' tooltip.
  const int     room = std::max(150, statusBar()->width() - m_Times->sizeHint().width() - m_Progress->width() - 40);
  const QString shown = statusBar()->fontMetrics().elidedText(m_BackendMessage, Qt::ElideRight, room);
  if (statusBar()->currentMessage() != shown)
  {
    statusBar()->showMessage(shown, static_cast<int>(remaining));
  }
}

void
ViewerWindow::ShowTimes()
{
  if (!m_Shown)
  {
    return;
  }
  const StageTimes & times = m_Shown->Outputs.Times;
  QStringList        parts;
  if (m_Shown->StagesRun.Depth > 0)
  {
    parts << tr("depth %1").arg(Milliseconds(times.Depth));
  }
  if (m_Shown->StagesRun.Relax > 0)
  {
    parts
      << tr("relax %1 (%2)").arg(Milliseconds(times.Relax), QString::fromStdString(m_Shown->Outputs.RelaxBackendUsed));
  }
  if (m_Shown->StagesRun.Resample > 0)
  {
    parts << tr("resample %1").arg(Milliseconds(times.Resample));
  }
  parts << tr("logic %1").arg(Milliseconds(m_Shown->UpdateSeconds));
  if (m_ShownSurface && m_ShownSurface->RequestId == m_Shown->RequestId)
  {
    parts << tr("surface %1").arg(Milliseconds(m_ShownSurface->Outputs.Times.Surface));
  }
  parts << tr("2D draw %1").arg(Milliseconds(m_CPRView->GetLastRenderSeconds()));
  parts << tr("3D draw %1 (%2 points)")
             .arg(Milliseconds(m_ThreeDView->GetLastRenderSeconds()))
             .arg(m_ThreeDView->GetLastRenderedSurfacePoints());
  m_Times->setText(parts.join(QStringLiteral(" · ")));
  if (statusBar()->currentMessage().startsWith(tr("Relaxation on")))
  {
    ShowBackendMessage();
  }
}

void
ViewerWindow::SetErrorHandler(ErrorHandler handler)
{
  m_ErrorHandler = std::move(handler);
}

void
ViewerWindow::UseSettings(std::shared_ptr<ViewerSettings> settings)
{
  m_Settings = std::move(settings);
  if (!m_Settings)
  {
    return;
  }
  const QByteArray geometry = m_Settings->Value(QStringLiteral("window/geometry"));
  if (!geometry.isEmpty())
  {
    restoreGeometry(geometry);
  }
  // Checked: a split that would hide the CPR or the 3D view is not restored (ViewerLayout).
  m_Layout->Restore(m_Settings->Value(QStringLiteral("window/splitter")));
  const QByteArray overlays = m_Settings->Value(QStringLiteral("display/overlays"));
  if (overlays.size() == 4)
  {
    m_Panel->SetOverlays(CPROverlays{ overlays[0] == '1', overlays[1] == '1', overlays[2] == '1', overlays[3] == '1' });
  }
}

void
ViewerWindow::closeEvent(QCloseEvent * event)
{
  if (m_Settings)
  {
    m_Settings->SetValue(QStringLiteral("window/geometry"), saveGeometry());
    m_Settings->SetValue(QStringLiteral("window/splitter"), m_Splitter->saveState());
    const CPROverlays overlays = m_Panel->GetOverlays();
    QByteArray        shown;
    for (const bool on : { overlays.Centerlines, overlays.FixedMask, overlays.OwnerLabels, overlays.DepthMap })
    {
      shown.append(on ? '1' : '0');
    }
    m_Settings->SetValue(QStringLiteral("display/overlays"), shown);
    m_Settings->Sync();
  }
  QMainWindow::closeEvent(event);
}

QStringList
ViewerWindow::GetShownWarnings() const
{
  return m_WarningBanner->isHidden() ? QStringList() : m_Warnings;
}

void
ViewerWindow::ShowWarning(const QString & message)
{
  if (!m_Warnings.contains(message))
  {
    m_Warnings.append(message);
    m_WarningText->setText(m_Warnings.join(QStringLiteral("\n")));
  }
  m_WarningBanner->setVisible(true);
  statusBar()->showMessage(tr("Warning (in full above the views)"), 15000);
}

void
ViewerWindow::ClearWarnings()
{
  m_Warnings.clear();
  m_WarningText->clear();
  m_WarningBanner->setVisible(false);
}

void
ViewerWindow::ShowError(const QString & title, const QString & message)
{
  m_LastError = title + QStringLiteral(": ") + message;
  statusBar()->showMessage(m_LastError, 15000);
  if (m_ErrorHandler)
  {
    m_ErrorHandler(title, message);
  }
  else
  {
    auto * box = new QMessageBox(QMessageBox::Warning, title, message, QMessageBox::Ok, this);
    box->setObjectName(QStringLiteral("errorDialog"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    box->open();
  }
  emit errorShown(title, message);
}

QString
ViewerWindow::AboutText()
{
  auto    html = [](const char * text) { return QString::fromUtf8(text).toHtmlEscaped(); };
  QString text = QStringLiteral("<h3>%1 %2</h3><p>%3</p><p><b>Method.</b> %4</p><p>%5. %6</p>")
                   .arg(html(ModuleDescription::Title),
                        html(ModuleDescription::Version),
                        html(ModuleDescription::Help),
                        html(ModuleDescription::Acknowledgements),
                        html(ModuleDescription::Contributors),
                        html(ModuleDescription::License));
  text += QStringLiteral("<p><b>Mouse in the CPR view:</b> left-drag turns the view (%1 degrees per pixel), right-drag "
                         "sets window and level, the wheel zooms, middle-drag pans, double-click fits.</p>")
            .arg(-CPRView::DegreesPerPixel);
  return text;
}

void
ViewerWindow::TurnBy(double degrees)
{
  m_Panel->SetAngle(WrapAngle(m_Panel->GetAngle() + degrees), RequestKind::Final);
}

QString
ViewerWindow::HelpText()
{
  return tr("<h3>Vessel Reformation: how to use it</h3>"
            "<p>The CPR view (middle) shows the whole vessel tree cut along a curved surface through every centerline "
            "and flattened, as seen from the view direction; the 3D view (right) shows that surface in place. The "
            "depth of the surface is relaxed by a bilateral filter so that small seams between vessels vanish while "
            "large depth jumps stay.</p>"
            "<h4>Mouse in the CPR view</h4><ul>"
            "<li>Left-drag: turn the view about the up axis (%1° per pixel).</li>"
            "<li>Right-drag: window (horizontal) and level (vertical); the preset then reads Custom.</li>"
            "<li>Wheel: zoom. Middle-drag: pan. Double-click: fit the image.</li>"
            "<li>Hover: the status bar reads the pixel, its RAS position, intensity, depth and the vessel's name.</li>"
            "<li>Ctrl+click a vessel: open its path in the vessel path panel (right).</li>"
            "</ul><h4>The vessel path panel</h4><ul>"
            "<li>Straightened CPR: left-drag rolls it about the path; right-click puts the cross-section there.</li>"
            "<li>Wheel over the straightened CPR or the cross-section, or Up / Down anywhere while a path is open: "
            "move the cross-section by one section (Page Up / Down: ten); a click on the lumen plot moves it "
            "there.</li>"
            "<li>Report: the stenosis graded segment by segment on the scale of its vessel (CAD-RADS for a coronary "
            "artery, NASCET for a carotid, the peripheral categories otherwise; the aorta's maximum diameter). "
            "Settings: width, range, slab, reference and scale.</li>"
            "<li>The cross-section's point is marked in the CPR view (cross) and the 3D view (sphere).</li>"
            "<li>Vessel menu: the longest path, a segmentation to measure the lumen on, export of the lumen table "
            "and of the path's images.</li>"
            "</ul><h4>Keys</h4><ul>"
            "<li>Left / Right: turn by 1°; with Shift by 10°.</li>"
            "<li>Home: angle 0, image fitted, 3D camera along the view.</li>"
            "<li>The keys work wherever the focus is; a text field keeps its keys while you type in it.</li>"
            "<li>Ctrl+1 … Ctrl+4: CTA, bone, soft tissue, 1–99 % window.</li>"
            "<li>Ctrl+O: open a volume. Ctrl+Z: undo the latest open. Ctrl+S: save the outputs. F1: this page.</li>"
            "</ul><h4>The panel</h4><ul>"
            "<li>Inputs: the volume, the centerlines or a vessel segmentation (centerlines are extracted from it).</li>"
            "<li>View: angle, up axis, image size and pixel spacing.</li>"
            "<li>Filter: relaxation w, jump threshold J (mm) or anisotropy a, iterations or the steady solver, "
            "backend (CPU or OpenCL), lumen fixing.</li>"
            "<li>Sampling: interpolation and slab (MIP, MinIP, mean).</li>"
            "<li>Display: window presets, overlays (centerlines, fixed mask, owner labels, depth) and comparison "
            "with the unfiltered image.</li></ul>"
            "<p>File &gt; Export rotation series: the CPR at N angles (default 36 × 10°) at the current settings "
            "and window, as numbered PNGs and a DICOM Secondary Capture series for the PACS.</p>"
            "<p>Warnings about the inputs appear in full in a banner above the views.</p>"
            "<p><b>Method:</b> C. Kretschmer, B. Preim, M. Stamminger, <i>Bilateral Depth Filtering for Enhanced "
            "Vessel Reformation</i>, EuroVis 2014 short paper.</p>")
    .arg(-CPRView::DegreesPerPixel);
}

void
ViewerWindow::ShowHelp()
{
  auto * dialog = findChild<QDialog *>(QStringLiteral("helpDialog"));
  if (dialog == nullptr)
  {
    dialog = new QDialog(this);
    dialog->setObjectName(QStringLiteral("helpDialog"));
    dialog->setWindowTitle(tr("Vessel Reformation help"));
    auto * browser = new QTextBrowser;
    browser->setHtml(HelpText());
    auto * close = new QPushButton(tr("Close"));
    connect(close, &QPushButton::clicked, dialog, &QDialog::close);
    auto * layout = new QVBoxLayout(dialog);
    layout->addWidget(browser);
    layout->addWidget(close, 0, Qt::AlignRight);
    dialog->resize(640, 620);
  }
  dialog->show();
  dialog->raise();
}

void
ViewerWindow::ShowAbout()
{
  QMessageBox::about(this, tr("About Vessel Reformation"), AboutText());
}

} // namespace vr
