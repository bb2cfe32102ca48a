// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The viewer window's saving: the outputs, a screenshot and a rotation series.
#include "vrViewerWindow.h"

#include "vrAtomicOutput.h"
#include "vrInputError.h"
#include "vrOutputWriter.h"

#include <QApplication>
#include <QDir>
#include <QDoubleSpinBox>
#include <QEventLoop>
#include <QFileDialog>
#include <QFileInfo>
#include <QImage>
#include <QInputDialog>
#include <QMessageBox>
#include <QProgressDialog>
#include <QStatusBar>

#include <atomic>
#include <cmath>
#include <thread>

namespace vr
{
bool
ViewerWindow::SaveOutputs(const QString & folder)
{
  const auto shown = m_CPRView->GetResult();
  if (!shown)
  {
    ShowError(tr("Cannot save outputs"), tr("There is no reformation on screen yet."));
    return false;
  }
  if (shown->IsPreview())
  {
    // A preview is a coarser stand-in while the view turns: its files would not be the reformation.
    ShowError(tr("Cannot save outputs"),
              tr("A preview is on screen; save again once the full-resolution image has replaced it."));
    return false;
  }
  // The full result of the request on screen, with its cut surface when it has been built.
  auto result = m_Controller->GetLatestResult();
  if (!result || result->RequestId != shown->RequestId)
  {
    result = shown;
  }
  const OutputSelection selection = m_Panel->GetOutputSelection();
  if (selection.CutSurface && !result->Outputs.Surface)
  {
    ShowError(tr("Cannot save outputs"),
              tr("cut-surface.vtp: the cut surface of this view is still being computed; save again in a moment"));
    return false;
  }
  try
  {
    const auto paths = WriteOutputs(result->Outputs,
                                    selection,
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

/** Writes \a widget as drawn into the PNG \a path: opaque RGB, compressed as much as PNG allows (quality 0), so
 * that screenshots stay small enough to share; atomic. \return an error, or empty. */
QString
WriteWidgetPNG(QWidget * widget, const QString & path)
{
  try
  {
    const QImage image = widget->grab().toImage().convertToFormat(QImage::Format_RGB888);
    if (image.isNull())
    {
      return QObject::tr("the window could not be rendered into an image");
    }
    AtomicOutput output(path.toStdString());
    if (!image.save(QString::fromStdString(output.TemporaryPath()), "PNG", 0))
    {
      return QObject::tr("%1: cannot write the PNG").arg(path);
    }
    output.Commit();
    return QString();
  }
  catch (const std::exception & error)
  {
    return QString::fromUtf8(error.what());
  }
}

QString
ViewerWindow::WriteScreenshot(const QString & path)
{
  return WriteWidgetPNG(this, path);
}

void
ViewerWindow::ChooseAndSaveOutputs()
{
  const QString folder = QFileDialog::getExistingDirectory(this, tr("Save the outputs into a folder"), StartFolder());
  if (!folder.isEmpty())
  {
    SaveOutputs(folder);
  }
}

int
ViewerWindow::ExportRotationSeries(const QString & folder, const RotationAngles & angles, unsigned int displayLongSide)
{
  const auto shown = m_CPRView->GetResult();
  if (!shown || !shown->Inputs)
  {
    ShowError(tr("Cannot export a rotation series"), tr("There is no reformation on screen yet."));
    return 0;
  }
  if (shown->IsPreview())
  {
    ShowError(tr("Cannot export a rotation series"),
              tr("A preview is on screen; export again once the full-resolution image has replaced it."));
    return 0;
  }
  RotationSeriesSettings settings;
  settings.Folder = folder.toStdString();
  settings.Angles = angles;
  settings.Window = m_Panel->GetWindowSpinBox()->value();
  settings.Level = m_Panel->GetLevelSpinBox()->value();
  settings.DisplayLongSide = displayLongSide;
  std::unique_ptr<RotationSeriesExport> series;
  try
  {
    series = std::make_unique<RotationSeriesExport>(settings, "the rotation series folder");
  }
  catch (const std::exception & error)
  {
    ShowError(tr("Cannot export a rotation series"), QString::fromUtf8(error.what()));
    return 0;
  }

  // A logic of its own, on the inputs and parameters of the image on screen, so the controller's work goes on.
  const auto               inputs = shown->Inputs;
  ReformationParameters    parameters = shown->Parameters;
  std::atomic<double>      fraction{ 0.0 };
  std::atomic<std::size_t> view{ 0 };
  std::atomic<bool>        cancel{ false };
  std::atomic<bool>        done{ false };
  std::string              failure;
  bool                     cancelled = false;
  RotationSeriesResult     result;
  std::thread              worker(
    [&]
    {
      try
      {
        VesselReformationLogic logic;
        logic.SetVolumeNode(inputs->Volume);
        if (inputs->Centerlines)
        {
          logic.SetCenterlineNode(inputs->Centerlines);
        }
        else
        {
          logic.SetSegmentationNode(inputs->Segmentation);
        }
        logic.SetParameters(parameters);
        result = series->Write(logic,
                               [&](std::size_t current, std::size_t, double overall)
                               {
                                 view = current;
                                 fraction = overall;
                                 return !cancel.load();
                               });
      }
      catch (const Cancelled &)
      {
        cancelled = true;
      }
      catch (const std::exception & error)
      {
        failure = error.what();
      }
      done = true;
    });

  QProgressDialog progress(tr("Exporting the rotation series…"), tr("Cancel"), 0, 1000, this);
  progress.setWindowTitle(tr("Rotation series"));
  progress.setWindowModality(Qt::WindowModal);
  progress.setMinimumDuration(0);
  progress.setValue(0);
  QEventLoop loop;
  QTimer     poll;
  connect(&poll,
          &QTimer::timeout,
          &loop,
          [&]
          {
            if (progress.wasCanceled())
            {
              cancel = true;
            }
            progress.setValue(std::min(999, static_cast<int>(1000.0 * fraction.load())));
            progress.setLabelText(tr("Exporting the rotation series: view %1 of %2…")
                                    .arg(std::min<std::size_t>(view.load() + 1, angles.Count))
                                    .arg(angles.Count));
            if (done)
            {
              loop.quit();
            }
          });
  poll.start(50);
  loop.exec();
  worker.join();
  progress.reset();

  if (cancelled)
  {
    statusBar()->showMessage(tr("Rotation series cancelled: nothing was written"), 10000);
    return 0;
  }
  try
  {
    if (!failure.empty())
    {
      throw InputError(failure);
    }
    series->Commit();
  }
  catch (const std::exception & error)
  {
    ShowError(tr("Cannot export a rotation series"), QString::fromUtf8(error.what()));
    return 0;
  }
  statusBar()->showMessage(
    tr("Exported a rotation series of %1 views (PNG and DICOM) to %2").arg(result.PNGFiles.size()).arg(folder), 10000);
  return static_cast<int>(result.PNGFiles.size());
}

void
ViewerWindow::ChooseAndExportRotationSeries()
{
  if (!m_CPRView->GetResult())
  {
    ShowError(tr("Cannot export a rotation series"), tr("There is no reformation on screen yet."));
    return;
  }
  const QString folder = QFileDialog::getExistingDirectory(
    this, tr("Export the rotation series into a folder (an empty one, or one without a series)"), StartFolder());
  if (folder.isEmpty())
  {
    return;
  }
  bool          accepted = false;
  const QString text = QInputDialog::getText(this,
                                             tr("Rotation series"),
                                             tr("Angles as start,step,count in degrees (36 views 10° apart: 0,10,36):"),
                                             QLineEdit::Normal,
                                             QStringLiteral("0,10,36"),
                                             &accepted);
  if (!accepted)
  {
    return;
  }
  const int size = QInputDialog::getInt(this,
                                        tr("Rotation series"),
                                        tr("Long side of the pictures, in pixels (a smaller CPR is enlarged; 0: the "
                                           "CPR's own size):"),
                                        static_cast<int>(RotationSeriesSettings::DefaultDisplayLongSide),
                                        0,
                                        static_cast<int>(RotationSeriesSettings::MaximumDisplayLongSide),
                                        64,
                                        &accepted);
  if (!accepted)
  {
    return;
  }
  try
  {
    ExportRotationSeries(
      folder, ParseRotationAngles(text.toStdString(), "the angles"), static_cast<unsigned int>(size));
  }
  catch (const std::exception & error)
  {
    ShowError(tr("Cannot export a rotation series"), QString::fromUtf8(error.what()));
  }
}

void
ViewerWindow::ChooseAndSaveScreenshot()
{
  const QString path = QFileDialog::getSaveFileName(
    this, tr("Save a screenshot"), QDir(StartFolder()).filePath(QStringLiteral("viewer.png")), tr("PNG (*.png)"));
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
