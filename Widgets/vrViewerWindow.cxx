// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrViewerWindow.h"

#include "itkCTAPhantom.h"
#include "vrAtomicOutput.h"
#include "vrInputError.h"
#include "vrModuleDescription.h"
#include "vrOutputWriter.h"

#include <QAction>
#include <QActionGroup>
#include <QDoubleSpinBox>
#include <QApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QImage>
#include <QLabel>
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
  m_ThreeDView = new ThreeDView;

  auto * scroll = new QScrollArea;
  scroll->setWidget(m_Panel);
  scroll->setWidgetResizable(true);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
  m_Panel->setMinimumWidth(m_Panel->minimumSizeHint().width());
  scroll->setMinimumWidth(m_Panel->minimumSizeHint().width() + scroll->verticalScrollBar()->sizeHint().width() + 40);
  auto * splitter = new QSplitter(Qt::Horizontal);
  splitter->addWidget(scroll);
  splitter->addWidget(m_CPRView);
  splitter->addWidget(m_ThreeDView);
  splitter->setStretchFactor(0, 0);
  splitter->setStretchFactor(1, 3);
  splitter->setStretchFactor(2, 2);
  setCentralWidget(splitter);

  m_Readout = new QLabel;
  m_Readout->setToolTip(tr("The pixel under the mouse: column and row, its RAS position in mm, the intensity (HU), the "
                           "depth along the view direction (mm) and the branch owning it."));
  m_Times = new QLabel;
  m_Times->setToolTip(tr("The time of each stage of the latest update (the logic's own), and of drawing it."));
  m_Progress = new QProgressBar;
  m_Progress->setRange(0, 1000);
  m_Progress->setMaximumWidth(160);
  m_Progress->setTextVisible(false);
  m_Progress->setVisible(false);
  m_ProgressDelay = new QTimer(this);
  m_ProgressDelay->setSingleShot(true);
  m_ProgressDelay->setTimerType(Qt::PreciseTimer);
  m_ProgressDelay->setInterval(ProgressDelayMilliseconds);
  connect(m_ProgressDelay, &QTimer::timeout, m_Progress, [this] { m_Progress->setVisible(true); });
  statusBar()->addWidget(m_Readout, 1);
  statusBar()->addPermanentWidget(m_Times);
  statusBar()->addPermanentWidget(m_Progress);

  BuildMenus();
  ConnectParts();
  ApplyDisplay();
  resize(1600, 1000);
}

ViewerWindow::~ViewerWindow() = default;

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
  file->addSeparator();
  file->addAction(
    tr("&Save outputs…"), this, [this] { ChooseAndSaveOutputs(); }, QKeySequence::Save);
  file->addAction(tr("Save screens&hot…"), this, [this] { ChooseAndSaveScreenshot(); });
  file->addSeparator();
  file->addAction(tr("&Quit"), this, &QWidget::close, QKeySequence::Quit);

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

  QMenu * help = menuBar()->addMenu(tr("&Help"));
  help->addAction(tr("&About Vessel Reformation"), this, [this] { ShowAbout(); });
}

void
ViewerWindow::ConnectParts()
{
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
  connect(m_CPRView,
          &CPRView::windowLevelChanged,
          this,
          [this](double window, double level) { m_Panel->SetWindowLevel(window, level); });
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
            m_Panel->SetInputDescription(QString::fromStdString(inputs->VolumeSource),
                                         QString::fromStdString(inputs->CenterlineSource),
                                         inputs->Segmentation ? QString::fromStdString(inputs->Segmentation->GetName())
                                                              : QString());
            m_ThreeDView->SetInputs(inputs);
            m_Panel->SetIntensityUnit(QString::fromStdString(inputs->IntensityUnit));
            if (inputs->IsPhantom)
            {
              m_Panel->ShowPhantom(QString::fromStdString(inputs->PhantomName));
              m_Panel->ApplyPreset(QString::fromLatin1(CTAPreset.Name), 0.0, 0.0);
            }
            else
            {
              m_FullRangeOnNextResult = true;
            }
            const QString loaded = inputs->IsPhantom && inputs->CenterlineSource.find('/') == std::string::npos
                                     ? tr("Loaded %1").arg(QString::fromStdString(inputs->VolumeSource))
                                     : tr("Loaded %1 and %2")
                                         .arg(QFileInfo(QString::fromStdString(inputs->VolumeSource)).fileName(),
                                              QFileInfo(QString::fromStdString(inputs->CenterlineSource)).fileName());
            statusBar()->showMessage(loaded, 5000);
            for (const auto & warning : inputs->Warnings)
            {
              statusBar()->showMessage(tr("Warning: %1").arg(QString::fromStdString(warning)), 15000);
            }
            RequestReformation(RequestKind::Final);
          });
  connect(m_Controller,
          &ReformationController::inputsFailed,
          this,
          [this](const QString & what, const QString & message)
          { ShowError(tr("Cannot open %1").arg(what), message); });
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
          [this](const QString & message) { statusBar()->showMessage(tr("Warning: %1").arg(message), 15000); });
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
ViewerWindow::LoadPhantom(const QString & name, double spacing)
{
  const std::string phantom = name.toStdString();
  m_Controller->LoadInputs([phantom, spacing] { return MakePhantomInputs(phantom, spacing); },
                           tr("the %1 phantom").arg(name));
}

void
ViewerWindow::OpenFiles(const QString & volume, const QString & centerlines)
{
  const std::string volumePath = volume.toStdString();
  const std::string centerlinePath = centerlines.toStdString();
  m_Controller->LoadInputs([volumePath, centerlinePath]
                           { return MakeInputs(ReadVolumeNode(volumePath), ReadCenterlineNode(centerlinePath)); },
                           tr("%1 and %2").arg(QFileInfo(volume).fileName(), QFileInfo(centerlines).fileName()));
}

void
ViewerWindow::OpenVolume(const QString & path)
{
  auto current = m_Controller->GetInputs();
  if (!current)
  {
    ShowError(tr("Cannot open %1").arg(path), tr("Open the centerlines as well: the viewer needs both."));
    return;
  }
  const std::string volumePath = path.toStdString();
  m_Controller->LoadInputs(
    [volumePath, current]
    {
      if (current->Segmentation)
      {
        // The segmentation stays: the logic extracts its centerlines again against the new volume.
        ReformationInputs inputs = MakeSegmentationInputs(ReadVolumeNode(volumePath), current->Segmentation);
        inputs.CenterlineSource = current->CenterlineSource;
        return inputs;
      }
      ReformationInputs inputs = MakeInputs(ReadVolumeNode(volumePath), current->Centerlines);
      inputs.BranchNames = current->BranchNames;
      inputs.CenterlineSource = current->CenterlineSource;
      return inputs;
    },
    QFileInfo(path).fileName(),
    PanelParameters());
}

void
ViewerWindow::OpenCenterlines(const QString & path)
{
  auto current = m_Controller->GetInputs();
  if (!current)
  {
    ShowError(tr("Cannot open %1").arg(path), tr("Open a volume as well: the viewer needs both."));
    return;
  }
  const std::string centerlinePath = path.toStdString();
  m_Controller->LoadInputs(
    [centerlinePath, current]
    {
      ReformationInputs inputs = MakeInputs(current->Volume, ReadCenterlineNode(centerlinePath));
      inputs.VolumeSource = current->VolumeSource;
      inputs.IsPhantom = current->IsPhantom;
      return inputs;
    },
    QFileInfo(path).fileName());
}

std::optional<ReformationParameters>
ViewerWindow::PanelParameters() const
{
  try
  {
    return m_Panel->GetParameters();
  }
  catch (const InputError &)
  {
    return std::nullopt;
  }
}

void
ViewerWindow::OpenSegmentation(const QStringList & paths)
{
  auto current = m_Controller->GetInputs();
  if (!current)
  {
    ShowError(tr("Cannot open %1").arg(paths.join(QStringLiteral(", "))),
              tr("Open a volume as well: the viewer needs both."));
    return;
  }
  std::vector<std::string> files;
  QStringList              names;
  for (const QString & path : paths)
  {
    files.push_back(path.toStdString());
    names << QFileInfo(path).fileName();
  }
  m_Controller->LoadInputs(
    [files, current]
    {
      std::vector<std::string> warnings;
      std::vector<std::string> descriptions;
      ReformationInputs        inputs =
        MakeSegmentationInputs(current->Volume, ReadSegmentationNode(files, warnings, descriptions));
      inputs.VolumeSource = current->VolumeSource;
      inputs.IsPhantom = current->IsPhantom;
      inputs.PhantomName = current->PhantomName;
      inputs.Warnings = warnings;
      return inputs;
    },
    names.join(QStringLiteral(", ")),
    PanelParameters());
}

void
ViewerWindow::OpenFilesWithSegmentation(const QString & volume, const QStringList & segmentation)
{
  const std::string        volumePath = volume.toStdString();
  std::vector<std::string> files;
  QStringList              names;
  for (const QString & path : segmentation)
  {
    files.push_back(path.toStdString());
    names << QFileInfo(path).fileName();
  }
  m_Controller->LoadInputs(
    [volumePath, files]
    {
      std::vector<std::string> warnings;
      std::vector<std::string> descriptions;
      auto                     volumeNode = ReadVolumeNode(volumePath);
      ReformationInputs        inputs =
        MakeSegmentationInputs(volumeNode, ReadSegmentationNode(files, warnings, descriptions));
      inputs.Warnings = warnings;
      return inputs;
    },
    tr("%1 and %2").arg(QFileInfo(volume).fileName(), names.join(QStringLiteral(", "))),
    PanelParameters());
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
    m_ThreeDView->SetResult(result);
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
    statusBar()->showMessage(tr("Warning: %1").arg(QString::fromStdString(warning)), 15000);
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
ViewerWindow::ShowAbout()
{
  QMessageBox::about(this, tr("About Vessel Reformation"), AboutText());
}

bool
ViewerWindow::SaveOutputs(const QString & folder)
{
  const auto shown = m_CPRView->GetResult();
  if (!shown)
  {
    ShowError(tr("Cannot save outputs"), tr("There is no reformation on screen yet."));
    return false;
  }
  // The full result of the request on screen, with its cut surface when it has been built.
  auto result = m_Controller->GetLatestResult();
  if (!result || result->RequestId != shown->RequestId)
  {
    result = shown;
  }
  try
  {
    const auto paths = WriteOutputs(*result,
                                    m_Panel->GetOutputSelection(),
                                    folder.toStdString(),
                                    m_Panel->GetWindowSpinBox()->value(),
                                    m_Panel->GetLevelSpinBox()->value());
    statusBar()->showMessage(tr("Saved %1 files to %2").arg(paths.size()).arg(folder), 10000);
    return true;
  }
  catch (const std::exception & error)
  {
    ShowError(tr("Cannot save outputs"), QString::fromUtf8(error.what()));
    return false;
  }
}

QString
ViewerWindow::WriteScreenshot(const QString & path)
{
  try
  {
    // Opaque RGB, compressed as much as PNG allows (quality 0), so that screenshots stay small enough to share.
    const QImage image = grab().toImage().convertToFormat(QImage::Format_RGB888);
    if (image.isNull())
    {
      return tr("the window could not be rendered into an image");
    }
    AtomicOutput output(path.toStdString());
    if (!image.save(QString::fromStdString(output.TemporaryPath()), "PNG", 0))
    {
      return tr("%1: cannot write the PNG").arg(path);
    }
    output.Commit();
    return QString();
  }
  catch (const std::exception & error)
  {
    return QString::fromUtf8(error.what());
  }
}

void
ViewerWindow::ChooseAndOpenVolume(bool dicomFolder)
{
  const QString path =
    dicomFolder ? QFileDialog::getExistingDirectory(this, tr("Open a DICOM series folder"))
                : QFileDialog::getOpenFileName(this,
                                               tr("Open a volume"),
                                               QString(),
                                               tr("Volumes (*.nrrd *.nhdr *.nii *.nii.gz *.mha *.mhd);;All files (*)"));
  if (!path.isEmpty())
  {
    OpenVolume(path);
  }
}

void
ViewerWindow::ChooseAndOpenCenterlines()
{
  const QString path =
    QFileDialog::getOpenFileName(this,
                                 tr("Open centerlines"),
                                 QString(),
                                 tr("Centerlines (*.vtp *.vtk *.mrk.json *.json *.tre *.csv);;All files (*)"));
  if (!path.isEmpty())
  {
    OpenCenterlines(path);
  }
}

void
ViewerWindow::ChooseAndOpenSegmentation()
{
  const QStringList paths = QFileDialog::getOpenFileNames(
    this,
    tr("Open a vessel segmentation (several files are combined)"),
    QString(),
    tr("Segmentations: label maps, masks, level sets (*.nii *.nii.gz *.nrrd *.nhdr *.mha *.mhd);;All files (*)"));
  if (!paths.isEmpty())
  {
    OpenSegmentation(paths);
  }
}

void
ViewerWindow::ChooseAndSaveOutputs()
{
  const QString folder = QFileDialog::getExistingDirectory(this, tr("Save the outputs into a folder"));
  if (!folder.isEmpty())
  {
    SaveOutputs(folder);
  }
}

void
ViewerWindow::ChooseAndSaveScreenshot()
{
  const QString path =
    QFileDialog::getSaveFileName(this, tr("Save a screenshot"), QStringLiteral("viewer.png"), tr("PNG (*.png)"));
  if (path.isEmpty())
  {
    return;
  }
  const QString problem = WriteScreenshot(path);
  if (!problem.isEmpty())
  {
    ShowError(tr("Cannot save the screenshot"), problem);
  }
}
} // namespace vr
