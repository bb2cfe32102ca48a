// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The VesselReformationViewer: the module's widgets in a window of their own.
//
//   VesselReformationViewer [volume centerlines | volume --segmentation FILE[,FILE...]] [--angle DEG] [--size W,H]
//   [--iterations N] ... [--screenshot FILE.png]
//
// Without files it opens the built-in run-off phantom. With --screenshot it renders the window once, writes the PNG
// and exits: 0 on success, 1 with a message on bad input (scripted mode, for tests, the README and reports).
#include "vrViewerOptions.h"
#include "vrViewerWindow.h"

#include <QApplication>
#include <QSurfaceFormat>
#include <QTimer>
#include <QVTKOpenGLNativeWidget.h>

#include <vtkImageData.h>

#include <algorithm>
#include <memory>

#include <cstdlib>
#include <iostream>

namespace
{
constexpr const char * Program = "VesselReformationViewer";

int
Fail(const std::string & message)
{
  std::cerr << Program << ": error: " << message << std::endl;
  return EXIT_FAILURE;
}

/** True when Qt can reach a display (X11 or Wayland) or was told to use another platform. */
bool
HasDisplay()
{
  const char * platform = std::getenv("QT_QPA_PLATFORM");
  if (platform != nullptr && *platform != '\0')
  {
    return true;
  }
  const char * x11 = std::getenv("DISPLAY");
  const char * wayland = std::getenv("WAYLAND_DISPLAY");
  return (x11 != nullptr && *x11 != '\0') || (wayland != nullptr && *wayland != '\0');
}

int
RunViewer(int argc, char ** argv)
{
  vr::ViewerOptions options;
  std::string       message;
  if (const auto status = vr::ParseViewerOptions(argc, argv, options, message))
  {
    if (*status == 0)
    {
      std::cout << message << std::endl;
      return EXIT_SUCCESS;
    }
    return Fail(message);
  }
  if (!HasDisplay())
  {
    return Fail("no display: set DISPLAY, or run headless under a virtual X server, e.g. "
                "xvfb-run -a -s \"-screen 0 1920x1080x24\" VesselReformationViewer ...");
  }

  // VTK's OpenGL 3.2 core context for every QVTKOpenGLNativeWidget, before the application exists.
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication application(argc, argv);
  QApplication::setApplicationName(QString::fromLatin1(Program));

  vr::ViewerWindow window;
  window.GetPanel()->SetParameters(options.Parameters);
  window.GetPanel()->SetOverlays(options.Overlays);
  window.GetPanel()->SetComparison(options.Comparison);
  window.resize(options.WindowWidth, options.WindowHeight);

  const bool scripted = !options.ScreenshotPath.empty();
  int        exitStatus = EXIT_SUCCESS;
  // Read by the slots below while the event loop runs, so it lives as long as the loop (AddressSanitizer found it
  // declared in the block that connects them, out of scope by then).
  bool written = false;
  // Whether the 3D view's last render drew the full cut surface (not the preview).
  bool lastRenderFull = false;
  if (scripted)
  {
    window.SetErrorHandler(
      [&exitStatus](const QString & title, const QString & text)
      {
        std::cerr << Program << ": error: " << title.toStdString() << ": " << text.toStdString() << std::endl;
        exitStatus = EXIT_FAILURE;
        QApplication::exit(EXIT_FAILURE);
      });
    // Parameter errors are marked in the panel rather than shown in a dialog; in scripted mode they end the run.
    QObject::connect(&window,
                     &vr::ViewerWindow::errorShown,
                     &window,
                     [&exitStatus](const QString & title, const QString & text)
                     {
                       if (exitStatus == EXIT_SUCCESS)
                       {
                         std::cerr << Program << ": error: " << title.toStdString() << ": " << text.toStdString()
                                   << std::endl;
                         exitStatus = EXIT_FAILURE;
                       }
                       QApplication::exit(EXIT_FAILURE);
                     });
    // Done when the full cut surface is drawn in the 3D view and nothing else is due. The 3D view's last render and
    // the controller's turn to idle come in either order (busyChanged(false) is posted after the results, and the
    // view may draw the last result before it arrives), so each of them checks: checking at the render alone left a
    // run waiting forever when no render followed the turn to idle (seen twice, once in the sanitizer suite).
    auto writeWhenDone = [&]
    {
      if (written || !lastRenderFull || !window.GetController()->IsIdle() || !window.GetCPRView()->GetResult())
      {
        return;
      }
      written = true;
      QTimer::singleShot(100,
                         &window,
                         [&]
                         {
                           const QString problem =
                             window.WriteScreenshot(QString::fromStdString(options.ScreenshotPath));
                           if (!problem.isEmpty())
                           {
                             std::cerr << Program << ": error: " << problem.toStdString() << std::endl;
                             exitStatus = EXIT_FAILURE;
                             QApplication::exit(EXIT_FAILURE);
                             return;
                           }
                           std::cout << "Wrote " << options.ScreenshotPath << std::endl;
                           QApplication::exit(EXIT_SUCCESS);
                         });
    };
    QObject::connect(window.GetThreeDView(),
                     &vr::ThreeDView::rendered,
                     &window,
                     [&, writeWhenDone](double, bool fullSurface)
                     {
                       lastRenderFull = fullSurface;
                       writeWhenDone();
                     });
    QObject::connect(window.GetController(),
                     &vr::ReformationController::busyChanged,
                     &window,
                     [&, writeWhenDone](bool busy)
                     {
                       if (busy || written)
                       {
                         return;
                       }
                       if (lastRenderFull)
                       {
                         writeWhenDone();
                       }
                       else
                       {
                         // Nothing may be due to draw the last result yet: a render reports what it drew.
                         window.GetThreeDView()->ScheduleRender();
                       }
                     });
  }
  if (!scripted)
  {
    // A person's run remembers folders, recent files and the window; a scripted one leaves their settings alone.
    window.UseSettings(std::make_shared<vr::ViewerSettings>());
  }
  window.show();
  if (options.VolumePath.empty())
  {
    window.LoadPhantom(QString::fromStdString(options.Phantom), options.PhantomSpacing);
  }
  else if (!options.SegmentationPaths.empty())
  {
    QStringList segmentation;
    for (const auto & path : options.SegmentationPaths)
    {
      segmentation << QString::fromStdString(path);
    }
    window.OpenFilesWithSegmentation(
      QString::fromStdString(options.VolumePath), segmentation, QString::fromStdString(options.DICOMSeries));
  }
  else
  {
    window.OpenFiles(QString::fromStdString(options.VolumePath),
                     QString::fromStdString(options.CenterlinePath),
                     QString::fromStdString(options.DICOMSeries));
  }
  if (!options.Preset.empty() || options.HasWindowLevel)
  {
    // Once, on the first image: after the inputs' own default (CTA for a CT, 1-99 % for other data).
    auto connection = std::make_shared<QMetaObject::Connection>();
    *connection =
      QObject::connect(window.GetController(),
                       &vr::ReformationController::resultReady,
                       &window,
                       [&window, &options, connection](std::shared_ptr<const vr::ReformationResult>)
                       {
                         QObject::disconnect(*connection);
                         if (options.HasWindowLevel)
                         {
                           window.GetPanel()->SetWindowLevel(options.Parameters.Window, options.Parameters.Level);
                           return;
                         }
                         double range[2] = { 0.0, 1.0 };
                         window.GetCPRView()->GetDisplayedImage(false)->GetScalarRange(range);
                         window.GetPanel()->ApplyPreset(QString::fromStdString(options.Preset),
                                                        std::max(range[1] - range[0], 1.0),
                                                        0.5 * (range[0] + range[1]));
                       });
  }
  const int status = application.exec();
  return scripted ? (status == EXIT_SUCCESS ? exitStatus : EXIT_FAILURE) : status;
}
} // namespace

int
main(int argc, char ** argv)
{
  try
  {
    return RunViewer(argc, argv);
  }
  catch (const std::exception & error)
  {
    return Fail(error.what());
  }
  catch (...)
  {
    return Fail("an unknown exception");
  }
}
