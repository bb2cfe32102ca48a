// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrWidgetsTestSupport.h"

#include "vrImageIO.h"
#include "vrWindowLevel.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QImage>
#include <QMessageBox>
#include <QMouseEvent>
#include <QTest>
#include <QVTKOpenGLNativeWidget.h>

#include <vtkImageData.h>

#include <gtest/gtest.h>

#include <cmath>

namespace vr::test
{
ReformationInputs
SmallPhantomInputs()
{
  static const ReformationInputs inputs = MakePhantomInputs("runoff", 3.0);
  return inputs;
}

ReformationParameters
TestParameters(double angle)
{
  ReformationParameters parameters;
  parameters.AngleInDegrees = angle;
  parameters.ImageSize[0] = 128;
  parameters.ImageSize[1] = 256;
  parameters.Anisotropy = 0.5;
  parameters.Iterations = 200;
  parameters.Backend = RelaxBackend::CPU;
  parameters.Window = 900.0;
  parameters.Level = 200.0;
  return parameters;
}

bool
WaitUntil(const std::function<bool()> & done, double seconds)
{
  QElapsedTimer timer;
  timer.start();
  while (!done())
  {
    if (timer.elapsed() > seconds * 1000.0)
    {
      return false;
    }
    QCoreApplication::processEvents(QEventLoop::AllEvents, 20);
    QTest::qWait(2);
  }
  return true;
}

bool
WaitUntilSettled(ViewerWindow & window, double seconds)
{
  if (!WaitUntil([&] { return window.GetController()->IsIdle(); }, seconds))
  {
    return false;
  }
  // The 3D view renders at its own pace after the CPR view's frame: let those events run.
  QTest::qWait(100);
  return WaitUntil([&] { return window.GetController()->IsIdle(); }, seconds);
}

std::unique_ptr<ViewerWindow>
MakeWindowOnSmallPhantom(double angle)
{
  auto window = std::make_unique<ViewerWindow>();
  window->resize(1400, 900);
  window->GetPanel()->SetParameters(TestParameters(angle));
  window->GetPanel()->SetOverlays(CPROverlays{ false, false, false, false });
  window->show();
  window->GetController()->LoadInputs([] { return SmallPhantomInputs(); }, QStringLiteral("the small phantom"));
  WaitUntil([&] { return window->GetCPRView()->GetResult() != nullptr; });
  WaitUntilSettled(*window);
  return window;
}

ReformationOutputs
ReferenceOutputs(const ReformationInputs & inputs, const ReformationParameters & parameters)
{
  VesselReformationLogic logic;
  logic.SetVolumeNode(inputs.Volume);
  logic.SetCenterlineNode(inputs.Centerlines);
  logic.SetParameters(parameters);
  return logic.Update();
}

void
SendMouse(QWidget * widget, int type, const QPointF & position, Qt::MouseButton button, Qt::MouseButtons buttons)
{
  QMouseEvent event(static_cast<QEvent::Type>(type),
                    position,
                    widget->mapTo(widget->window(), position.toPoint()),
                    widget->mapToGlobal(position.toPoint()),
                    button,
                    buttons,
                    Qt::NoModifier);
  QApplication::sendEvent(widget, &event);
}

std::vector<float>
NodePixels(VolumeNode * node)
{
  vtkImageData * data = node->GetImageData();
  const auto *   begin = static_cast<const float *>(data->GetScalarPointer());
  return std::vector<float>(begin, begin + data->GetNumberOfPoints());
}

Runs
Difference(const ReformationStageCounts & after, const ReformationStageCounts & before)
{
  return { after.Conversion - before.Conversion,
           after.Depth - before.Depth,
           after.Relax - before.Relax,
           after.Resample - before.Resample,
           after.UnfilteredSamplings - before.UnfilteredSamplings,
           after.RelaxedSamplings - before.RelaxedSamplings,
           after.Surface - before.Surface };
}

int
FrameGrey(const QImage & frame, const QPointF & position)
{
  const QColor color =
    frame.pixelColor(static_cast<int>(std::floor(position.x())), static_cast<int>(std::floor(position.y())));
  EXPECT_EQ(color.red(), color.green());
  EXPECT_EQ(color.green(), color.blue());
  return color.red();
}

void
ExpectSameImage(CPRView & view, VolumeNode * expected)
{
  vtkImageData * shown = view.GetDisplayedImage(false);
  int            dimensions[3], shownDimensions[3];
  expected->GetImageData()->GetDimensions(dimensions);
  shown->GetDimensions(shownDimensions);
  ASSERT_EQ(shownDimensions[0], dimensions[0]);
  ASSERT_EQ(shownDimensions[1], dimensions[1]);
  const std::vector<float> reference = NodePixels(expected);
  const auto *             pixels = static_cast<const float *>(shown->GetScalarPointer());
  std::size_t              different = 0;
  for (std::size_t k = 0; k < reference.size(); ++k)
  {
    different += pixels[k] == reference[k] ? 0 : 1;
  }
  EXPECT_EQ(different, 0u) << "of " << reference.size() << " pixels";
}

void
ExpectShows(ViewerWindow & window, VolumeNode * expected)
{
  CPRView * view = window.GetCPRView();
  ExpectSameImage(*view, expected);
  if (::testing::Test::HasFatalFailure())
  {
    return;
  }
  int dimensions[3];
  expected->GetImageData()->GetDimensions(dimensions);
  const std::vector<float> reference = NodePixels(expected);

  // On screen: pixel centres sampled on a grid, each image pixel spanning a few screen pixels (nearest interpolation).
  const QImage frame = view->GetRenderWidget()->grabFramebuffer();
  const double window_ = view->GetWindow();
  const double level = view->GetLevel();
  int          checked = 0;
  int          worst = 0;
  for (int j = 3; j < dimensions[1]; j += 17)
  {
    for (int i = 2; i < dimensions[0]; i += 11)
    {
      const QPointF position = view->WidgetPositionOfPixel(i, j, false);
      const int     expectedGrey =
        WindowLevelToByte(reference[static_cast<std::size_t>(j) * dimensions[0] + i], window_, level);
      worst = std::max(worst, std::abs(FrameGrey(frame, position) - expectedGrey));
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);
  EXPECT_LE(worst, 1) << "largest difference between the frame and the logic's CPR through window/level";
}

QMessageBox *
ErrorDialog(ViewerWindow & window)
{
  for (QMessageBox * box : window.findChildren<QMessageBox *>(QStringLiteral("errorDialog")))
  {
    if (box->isVisible())
    {
      return box;
    }
  }
  return nullptr;
}
} // namespace vr::test
