// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// A host of its own: the module widgets linked without the viewer application (Applications/VesselReformationViewer),
// as a platform hosts a module's widgets. This executable links VesselReformationWidgets alone (Testing/Widgets/
// CMakeLists.txt); that it links at all is half the test.

#include "vrCPRView.h"
#include "vrFilterSettingsText.h"
#include "vrModulePanel.h"
#include "vrNodeConversion.h"
#include "vrReformationController.h"
#include "vrReformationInputs.h"
#include "vrVesselReformationLogic.h"

#include <QCoreApplication>
#include <QElapsedTimer>

#include <gtest/gtest.h>

#include <memory>
#include <vector>

namespace
{
std::vector<float>
Pixels(vr::VolumeNode * node)
{
  const auto image = vr::ConvertVolumeNodeToDepthImage(node);
  return { image->GetBufferPointer(),
           image->GetBufferPointer() + image->GetLargestPossibleRegion().GetNumberOfPixels() };
}
} // namespace

TEST(WidgetsAlone, AHostOfItsOwnShowsTheLogicsCPR)
{
  vr::ReformationParameters parameters;
  parameters.ImageSize[0] = 48;
  parameters.ImageSize[1] = 96;
  parameters.Iterations = 20;
  parameters.Backend = vr::RelaxBackend::CPU;

  vr::ModulePanel                              panel;
  vr::CPRView                                  view;
  vr::ReformationController                    controller;
  std::shared_ptr<const vr::ReformationResult> shown;
  QObject::connect(&controller,
                   &vr::ReformationController::resultReady,
                   &view,
                   [&](std::shared_ptr<const vr::ReformationResult> result)
                   {
                     view.SetResult(result);
                     shown = result;
                   });
  controller.LoadInputs([] { return vr::MakePhantomInputs("runoff", 3.0); }, QStringLiteral("the run-off phantom"));
  controller.Request(parameters, vr::RequestKind::Final);
  QElapsedTimer timer;
  timer.start();
  while (!(shown && shown->PreviewFactor == 1) && timer.elapsed() < 300000)
  {
    QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
  }
  ASSERT_TRUE(shown && shown->PreviewFactor == 1) << "no full-resolution result within 300 s";

  // The reference: the logic alone on the same phantom and parameters.
  const vr::ReformationInputs inputs = vr::MakePhantomInputs("runoff", 3.0);
  vr::VesselReformationLogic  logic;
  logic.SetVolumeNode(inputs.Volume);
  logic.SetCenterlineNode(inputs.Centerlines);
  logic.SetParameters(parameters);
  EXPECT_EQ(Pixels(shown->Outputs.CPR), Pixels(logic.Update().CPR));
  EXPECT_EQ(view.GetCaption(false).toStdString(), "bilateral: J = 3 mm, w = 1\n20 iterations");
  EXPECT_TRUE(panel.GetOutputSelection().CutSurface) << "the panel asks for every output by default";
}
