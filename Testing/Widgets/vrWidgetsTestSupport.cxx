// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrWidgetsTestSupport.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QMouseEvent>
#include <QTest>

#include <vtkImageData.h>

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
} // namespace vr::test
