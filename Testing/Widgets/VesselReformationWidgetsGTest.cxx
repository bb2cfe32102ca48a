// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The widgets and the viewer window, driven as a user would (slider, spin boxes, mouse events) under a virtual X
// server, checked against an independent run of the module logic on the same nodes.
// This file: the views and the controls driven by keyboard and mouse, the settings, the progress bar. The inputs and
// the panel with its outputs are in VesselReformationWidgets*GTest.cxx beside it; the checks they share, in
// vrWidgetsTestSupport.h; the fixture, in vrWindowTestFixture.h.
#include "vrWidgetsTestSupport.h"
#include "vrWindowTestFixture.h"

#include "ui_vrModulePanel.h"

#include "itkCPRViewGeometry.h"
#include "itkImageFileWriter.h"
#include "vrCenterlineIO.h"
#include "vrCoordinateFrames.h"
#include "vrCenterlineExtraction.h"
#include "vrImageIO.h"
#include "vrNodeConversion.h"
#include "vrOpenGLRenderer.h"
#include "vrInputError.h"
#include "vrFilterSettingsText.h"
#include "vrOutputWriter.h"
#include "vrSurfacePreview.h"
#include "vrTestFiles.h"
#include "vrVolumeIO.h"

#include <QAbstractButton>
#include <QAction>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QComboBox>
#include <QDialog>
#include <QDoubleSpinBox>
#include <QImage>
#include <QLabel>
#include <QMessageBox>
#include <QSlider>
#include <QTest>
#include <QWheelEvent>
#include <QVTKOpenGLNativeWidget.h>

#include <vtkCellData.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkImageData.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <functional>
#include <set>

namespace
{
using namespace vr;
using namespace vr::test;

TEST_F(WidgetsTest, StartsOnThePhantomAndShowsTheLogicsCPR)
{
  const auto shown = Window().GetCPRView()->GetResult();
  EXPECT_DOUBLE_EQ(shown->Outputs.View.GetAngleInDegrees(), StartAngle);
  EXPECT_EQ(shown->Outputs.View.GetSize()[0], 128u);
  const ReformationOutputs reference = ReferenceOutputs(SmallPhantomInputs(), TestParameters(StartAngle));
  ExpectShows(Window(), reference.CPR);
  EXPECT_TRUE(Window().GetThreeDView()->IsShowingFullSurface());
}

TEST_F(WidgetsTest, MovingTheAngleSliderRerunsDepthRelaxAndResampleOnceAndShowsTheLogicsCPRAtThatAngle)
{
  const ReformationStageCounts before = Controller().GetStageCounts();
  Window().GetPanel()->GetAngleSlider()->setValue(-450); // tenths of a degree
  ASSERT_TRUE(WaitUntilSettled(Window()));
  const Runs runs = Difference(Controller().GetStageCounts(), before);
  EXPECT_EQ(runs.Conversion, 0u);
  EXPECT_EQ(runs.Depth, 1u);
  EXPECT_EQ(runs.Relax, 1u);
  EXPECT_EQ(runs.Resample, 1u);
  EXPECT_EQ(runs.UnfilteredSamplings, 1u);
  EXPECT_EQ(runs.RelaxedSamplings, 1u);
  EXPECT_EQ(runs.Surface, 1u);

  const auto shown = Window().GetCPRView()->GetResult();
  EXPECT_DOUBLE_EQ(Window().GetPanel()->GetAngleSpinBox()->value(), -45.0);
  EXPECT_DOUBLE_EQ(shown->Outputs.View.GetAngleInDegrees(), -45.0);
  const ReformationOutputs reference = ReferenceOutputs(SmallPhantomInputs(), TestParameters(-45.0));
  ExpectShows(Window(), reference.CPR);
  // And it differs from the image at the old angle, so the comparison can fail.
  const auto old = NodePixels(ReferenceOutputs(SmallPhantomInputs(), TestParameters(StartAngle)).CPR);
  EXPECT_NE(old, NodePixels(reference.CPR));
}

TEST(OpenGLRendererTest, SoftwareRasterisersAreToldFromGPUs)
{
  EXPECT_TRUE(vr::IsSoftwareRenderer("llvmpipe (LLVM 15.0.6, 256 bits), OpenGL 4.5 (Core Profile) Mesa 22.3.6"));
  EXPECT_TRUE(vr::IsSoftwareRenderer("Gallium 0.4 on softpipe"));
  EXPECT_TRUE(vr::IsSoftwareRenderer("Mesa X11 SWRAST"));
  EXPECT_TRUE(vr::IsSoftwareRenderer("Google SwiftShader"));
  EXPECT_TRUE(vr::IsSoftwareRenderer("GDI Generic"));
  EXPECT_FALSE(vr::IsSoftwareRenderer("NVIDIA H200/PCIe/SSE2, OpenGL 4.6.0 NVIDIA 550.54.15"));
  EXPECT_FALSE(vr::IsSoftwareRenderer("AMD Radeon RX 7900 XTX (radeonsi, navi31, LLVM 15.0.7)"));
  EXPECT_FALSE(vr::IsSoftwareRenderer("Mesa Intel(R) UHD Graphics 620 (KBL GT2)"));
}

// Under Xvfb the renderer is Mesa's llvmpipe: both views must draw without multisampling there, which made every frame
// about three times as dear (vrOpenGLRenderer.h).
TEST_F(WidgetsTest, OnASoftwareRendererTheViewsDrawWithoutMultisampling)
{
  const std::string renderer = vr::OpenGLRendererName();
  ASSERT_TRUE(vr::IsSoftwareRenderer(renderer)) << "the widget tests run under Xvfb's Mesa, here: " << renderer;
  EXPECT_EQ(vr::ViewMultiSamples(), 0);
  EXPECT_EQ(Window().GetCPRView()->GetRenderWidget()->renderWindow()->GetMultiSamples(), 0);
  EXPECT_EQ(Window().GetThreeDView()->GetRenderWidget()->renderWindow()->GetMultiSamples(), 0);
}

TEST_F(WidgetsTest, ChangingTheWindowRerunsNothingAndRedrawsThroughTheNewWindow)
{
  const ReformationStageCounts before = Controller().GetStageCounts();
  const RequestStatistics      requestsBefore = Controller().GetStatistics();
  const auto                   shownBefore = Window().GetCPRView()->GetResult();
  Window().GetPanel()->GetWindowSpinBox()->setValue(400.0);
  Window().GetPanel()->GetLevelSpinBox()->setValue(40.0);
  QTest::qWait(300);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  const Runs runs = Difference(Controller().GetStageCounts(), before);
  EXPECT_EQ(runs.Conversion + runs.Depth + runs.Relax + runs.Resample + runs.Surface, 0u);
  EXPECT_EQ(Controller().GetStatistics().Displayed, requestsBefore.Displayed);
  EXPECT_EQ(Window().GetCPRView()->GetResult(), shownBefore);
  EXPECT_DOUBLE_EQ(Window().GetCPRView()->GetWindow(), 400.0);
  EXPECT_DOUBLE_EQ(Window().GetCPRView()->GetLevel(), 40.0);
  ExpectShows(Window(), shownBefore->Outputs.CPR);

  // A right-drag changes the window too, and reruns nothing either.
  QWidget *     target = Window().GetCPRView()->GetRenderWidget();
  const QPointF start(200.0, 300.0);
  SendMouse(target, QEvent::MouseButtonPress, start, Qt::RightButton, Qt::RightButton);
  SendMouse(target, QEvent::MouseMove, start + QPointF(128.0, -64.0), Qt::NoButton, Qt::RightButton);
  SendMouse(target, QEvent::MouseButtonRelease, start + QPointF(128.0, -64.0), Qt::RightButton, Qt::NoButton);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  // Documented: window x (1 + dx / 256), level - window dy / 512.
  EXPECT_DOUBLE_EQ(Window().GetCPRView()->GetWindow(), 600.0);
  EXPECT_DOUBLE_EQ(Window().GetCPRView()->GetLevel(), 90.0);
  EXPECT_DOUBLE_EQ(Window().GetPanel()->GetWindowSpinBox()->value(), 600.0);
  const Runs after = Difference(Controller().GetStageCounts(), before);
  EXPECT_EQ(after.Conversion + after.Depth + after.Relax + after.Resample + after.Surface, 0u);
}

TEST_F(WidgetsTest, ARightDragTurnsThePresetIntoCustom)
{
  ASSERT_TRUE(Window().GetPanel()->ApplyPreset(QStringLiteral("Bone"), 0.0, 0.0));
  EXPECT_EQ(Window().GetPanel()->GetPresetName(), QStringLiteral("Bone"));
  QWidget *     target = Window().GetCPRView()->GetRenderWidget();
  const QPointF start(200.0, 300.0);
  SendMouse(target, QEvent::MouseButtonPress, start, Qt::RightButton, Qt::RightButton);
  SendMouse(target, QEvent::MouseMove, start + QPointF(128.0, -64.0), Qt::NoButton, Qt::RightButton);
  SendMouse(target, QEvent::MouseButtonRelease, start + QPointF(128.0, -64.0), Qt::RightButton, Qt::NoButton);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  // Bone's W 2000, L 500 dragged: 2000 x (1 + 128 / 256), 500 - 2000 x (-64) / 512.
  EXPECT_DOUBLE_EQ(Window().GetPanel()->GetWindowSpinBox()->value(), 3000.0);
  EXPECT_DOUBLE_EQ(Window().GetCPRView()->GetLevel(), 750.0);
  EXPECT_EQ(Window().GetPanel()->GetPresetName(), QStringLiteral("Custom"));
}

/** The value at rank round(q (n - 1)) of every voxel of \a volume: the percentile rule written out plainly. */
double
PlainPercentile(const VolumeImageType * volume, double q)
{
  std::vector<float> values(volume->GetBufferPointer(),
                            volume->GetBufferPointer() + volume->GetLargestPossibleRegion().GetNumberOfPixels());
  std::sort(values.begin(), values.end());
  return values[static_cast<std::size_t>(std::lround(q * static_cast<double>(values.size() - 1)))];
}

TEST_F(WidgetsTest, ACTOpensInTheCTAPresetAnMRAOnItsPercentilesAndAPresetSurvivesASegmentation)
{
  const std::string data = AortaDataFolder();
  ASSERT_FALSE(data.empty()) << "the VMTK aorta data beside the checkout";
  vr::test::ScopedTemporaryFolder folder;
  // A CT from files (not a phantom): the small phantom written as NRRD with its centerlines.
  const std::string ct = folder.File("ct.nrrd");
  const std::string ctCenterlines = folder.File("ct-centerlines.vtp");
  WriteVolume(ConvertVolumeNodeToItkImage(SmallPhantomInputs().Volume), ct);
  WriteCenterlines(SmallPhantomInputs().Tree, ctCenterlines);
  ASSERT_TRUE(Window().GetPanel()->ApplyPreset(QStringLiteral("Bone"), 0.0, 0.0));
  auto before = Controller().GetInputs();
  Window().OpenFiles(QString::fromStdString(ct), QString::fromStdString(ctCenterlines));
  ASSERT_TRUE(WaitUntil([&] { return Controller().GetInputs() != before; }, 60.0));
  ASSERT_TRUE(WaitUntilSettled(Window()));
  EXPECT_EQ(Window().GetPanel()->GetPresetName(), QStringLiteral("CTA"));
  EXPECT_DOUBLE_EQ(Window().GetCPRView()->GetWindow(), CTAPreset.Window);
  EXPECT_DOUBLE_EQ(Window().GetCPRView()->GetLevel(), CTAPreset.Level);

  // The MR angiography: no HU, so its 1st to 99th percentile, counted here over every voxel.
  const std::string mra = data + "/aorta.mha";
  before = Controller().GetInputs();
  Window().OpenFiles(QString::fromStdString(mra), QString::fromStdString(data + "/aorta-centerline-branches.vtp"));
  ASSERT_TRUE(WaitUntil([&] { return Controller().GetInputs() != before; }, 120.0));
  ASSERT_TRUE(WaitUntilSettled(Window()));
  const auto   volume = ReadVolume(mra);
  const double low = PlainPercentile(volume, 0.01);
  const double high = PlainPercentile(volume, 0.99);
  ASSERT_GT(high - low, 100.0);
  EXPECT_EQ(Window().GetPanel()->GetPresetName(), QString::fromUtf8(PercentilePresetName));
  EXPECT_NEAR(Window().GetCPRView()->GetWindow(), high - low, 1e-3 * (high - low));
  EXPECT_NEAR(Window().GetCPRView()->GetLevel(), 0.5 * (low + high), 1e-3 * (high - low));

  // A preset chosen by the user stays when a segmentation replaces the centerlines.
  ASSERT_TRUE(Window().GetPanel()->ApplyPreset(QStringLiteral("Soft tissue"), 0.0, 0.0));
  before = Controller().GetInputs();
  Window().OpenSegmentation({ QString::fromStdString(data + "/aorta-final-levelset.mha") });
  ASSERT_TRUE(WaitUntil([&] { return Controller().GetInputs() != before; }, 120.0));
  ASSERT_TRUE(WaitUntilSettled(Window(), 300.0));
  EXPECT_EQ(Window().GetPanel()->GetPresetName(), QStringLiteral("Soft tissue"));
  EXPECT_DOUBLE_EQ(Window().GetCPRView()->GetWindow(), SoftTissuePreset.Window);
}

TEST_F(WidgetsTest, ArrowKeysTurnByOneAndTenDegreesAndF1OpensTheHelpPage)
{
  QWidget * target = Window().GetCPRView()->GetRenderWidget();
  target->setFocus();
  QApplication::setActiveWindow(&Window());
  const double start = Window().GetPanel()->GetAngle();
  QTest::keyClick(target, Qt::Key_Right);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  EXPECT_DOUBLE_EQ(Window().GetPanel()->GetAngle(), start + 1.0);
  QTest::keyClick(target, Qt::Key_Left, Qt::ShiftModifier);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  EXPECT_DOUBLE_EQ(Window().GetPanel()->GetAngle(), start + 1.0 - 10.0);
  // The image follows: the logic's CPR at that angle.
  EXPECT_DOUBLE_EQ(Window().GetCPRView()->GetResult()->Outputs.View.GetAngleInDegrees(), start - 9.0);
  ExpectShows(Window(), ReferenceOutputs(SmallPhantomInputs(), TestParameters(start - 9.0)).CPR);
  // Ctrl+2: the bone window.
  QTest::keyClick(target, Qt::Key_2, Qt::ControlModifier);
  EXPECT_EQ(Window().GetPanel()->GetPresetName(), QStringLiteral("Bone"));
  EXPECT_DOUBLE_EQ(Window().GetCPRView()->GetWindow(), BonePreset.Window);

  QTest::keyClick(target, Qt::Key_F1);
  auto * help = Window().findChild<QDialog *>(QStringLiteral("helpDialog"));
  ASSERT_NE(help, nullptr);
  EXPECT_TRUE(help->isVisible());
  const QString text = ViewerWindow::HelpText();
  for (const char * part : { "Left / Right", "Right-drag", "Kretschmer", "Filter", "Display" })
  {
    EXPECT_TRUE(text.contains(QString::fromUtf8(part))) << part;
  }
  help->close();
}

TEST(ViewerSettingsTest, FoldersRecentFilesGeometryAndOverlaysSurviveARestart)
{
  vr::test::ScopedTemporaryFolder folder;
  const std::string               volume = folder.File("ct.nrrd");
  const std::string               centerlines = folder.File("ct-centerlines.vtp");
  WriteVolume(ConvertVolumeNodeToItkImage(SmallPhantomInputs().Volume), volume);
  WriteCenterlines(SmallPhantomInputs().Tree, centerlines);
  const QString ini = QString::fromStdString(folder.File("viewer.ini"));
  {
    auto window = MakeWindowOnSmallPhantom(0.0);
    window->UseSettings(std::make_shared<ViewerSettings>(ini));
    const auto before = window->GetController()->GetInputs();
    window->OpenFiles(QString::fromStdString(volume), QString::fromStdString(centerlines));
    ASSERT_TRUE(WaitUntil([&] { return window->GetController()->GetInputs() != before; }, 60.0));
    ASSERT_TRUE(WaitUntilSettled(*window));
    window->resize(1234, 777);
    window->GetPanel()->SetOverlays(CPROverlays{ false, true, false, true });
    window->close();
  }
  ASSERT_TRUE(std::filesystem::exists(ini.toStdString())) << "nothing was written";

  // A new window on the same settings: what a restart sees.
  ViewerSettings settings(ini);
  const auto     recent = settings.Recent();
  ASSERT_EQ(recent.size(), 1u);
  EXPECT_EQ(recent[0].Volume.toStdString(), volume);
  ASSERT_EQ(recent[0].Centerlines.size(), 1);
  EXPECT_EQ(recent[0].Centerlines[0].toStdString(), centerlines);
  EXPECT_FALSE(recent[0].Segmentation);

  auto window = std::make_unique<ViewerWindow>();
  window->UseSettings(std::make_shared<ViewerSettings>(ini));
  window->show();
  EXPECT_EQ(window->size(), QSize(1234, 777));
  const CPROverlays overlays = window->GetPanel()->GetOverlays();
  EXPECT_FALSE(overlays.Centerlines);
  EXPECT_TRUE(overlays.FixedMask);
  EXPECT_FALSE(overlays.OwnerLabels);
  EXPECT_TRUE(overlays.DepthMap);
  // File > Open recent's first entry opens the pair again.
  window->OpenRecent(0);
  ASSERT_TRUE(WaitUntil([&] { return window->GetCPRView()->GetResult() != nullptr; }, 60.0));
  ASSERT_TRUE(WaitUntilSettled(*window));
  EXPECT_EQ(window->GetController()->GetInputs()->VolumeSource, volume);
  EXPECT_EQ(window->GetController()->GetInputs()->CenterlineSource, centerlines);
}

TEST(ViewerSettingsTest, RecentKeepsEightLatestFirstWithoutRepeatsAndTheFolderOfTheLatestFile)
{
  vr::test::ScopedTemporaryFolder folder;
  ViewerSettings                  settings(QString::fromStdString(folder.File("viewer.ini")));
  for (int k = 0; k < 10; ++k)
  {
    settings.AddRecent({ QStringLiteral("/data/v%1.nrrd").arg(k), { QStringLiteral("/data/c%1.vtp").arg(k) }, false });
  }
  settings.AddRecent({ QStringLiteral("/data/v5.nrrd"), { QStringLiteral("/data/c5.vtp") }, false });
  const auto recent = settings.Recent();
  ASSERT_EQ(recent.size(), 8u);
  EXPECT_EQ(recent[0].Volume, QStringLiteral("/data/v5.nrrd"));
  EXPECT_EQ(recent[1].Volume, QStringLiteral("/data/v9.nrrd"));
  // v9 .. v2 were the eight latest; v5 moved to the front: v5 v9 v8 v7 v6 v4 v3 v2, no second v5.
  EXPECT_EQ(recent[5].Volume, QStringLiteral("/data/v4.nrrd"));
  EXPECT_EQ(recent[7].Volume, QStringLiteral("/data/v2.nrrd"));
  settings.RememberFolderOf(QString::fromStdString(folder.File("viewer.ini")));
  EXPECT_EQ(settings.LastFolder().toStdString(),
            std::filesystem::path(folder.File("viewer.ini")).parent_path().string());
}

TEST_F(WidgetsTest, AResizeKeepsTheImageFittedUntilTheUserZooms)
{
  CPRView * view = Window().GetCPRView();
  const int width = static_cast<int>(view->GetResult()->Outputs.View.GetSize()[0]);
  const int height = static_cast<int>(view->GetResult()->Outputs.View.GetSize()[1]);
  auto      corners = [&]
  {
    return std::make_pair(view->WidgetPositionOfPixel(0, 0, false),
                          view->WidgetPositionOfPixel(width - 1, height - 1, false));
  };
  const auto before = corners();
  Window().resize(1700, 1050);
  QTest::qWait(300);
  const auto resized = corners();
  EXPECT_NE(resized, before) << "the image kept its screen size in a larger view";
  view->FitImage();
  EXPECT_EQ(corners(), resized) << "after the resize the image was not fitted";

  // Zoomed by the user: a resize leaves the zoom alone.
  QWidget *     target = view->GetRenderWidget();
  const QPointF centre(target->width() / 2.0, target->height() / 2.0);
  QWheelEvent   wheel(centre,
                    QPointF(target->mapToGlobal(centre.toPoint())),
                    QPoint(),
                    QPoint(0, 240),
                    Qt::NoButton,
                    Qt::NoModifier,
                    Qt::NoScrollPhase,
                    false);
  QApplication::sendEvent(target, &wheel);
  const auto zoomed = corners();
  Window().resize(1400, 900);
  QTest::qWait(300);
  const auto afterZoomedResize = corners();
  view->FitImage();
  EXPECT_NE(corners(), afterZoomedResize) << "the zoom was undone by the resize";
  (void)zoomed;
}

TEST_F(WidgetsTest, TheHoverReadoutAtAPixelEqualsTheLogicsOutputsThere)
{
  const ReformationOutputs reference = ReferenceOutputs(SmallPhantomInputs(), TestParameters(StartAngle));
  const auto               cpr = NodePixels(reference.CPR);
  const auto               depth = NodePixels(reference.RelaxedDepth);
  vtkImageData *           labels = reference.OwnerLabels->GetImageData();
  vtkImageData *           mask = reference.FixedMask->GetImageData();
  const int                width = 128;
  const int                height = 256;
  // Pixels on vessels (fixed, so owned by a branch) and pixels between them.
  std::vector<std::pair<int, int>> pixels;
  for (int j = 20; j < height && pixels.size() < 6; j += 37)
  {
    for (int i = 0; i < width; ++i)
    {
      if (mask->GetScalarComponentAsDouble(i, j, 0, 0) > 0.0)
      {
        pixels.emplace_back(i, j);
        break;
      }
    }
  }
  ASSERT_GE(pixels.size(), 5u);
  pixels.emplace_back(0, 0);
  pixels.emplace_back(width - 1, height - 1);
  pixels.emplace_back(63, 128);

  // The independent reference for the position: docs/design.md "View"'s B(i, j) + d v from the view's C, u, v and up,
  // in LPS, then RAS by negating x and y.
  const itk::CPRViewGeometry & view = reference.View;
  QWidget *                    target = Window().GetCPRView()->GetRenderWidget();
  for (const auto & [i, j] : pixels)
  {
    const QPointF position = Window().GetCPRView()->WidgetPositionOfPixel(i, j, false);
    SendMouse(target,
              QEvent::MouseMove,
              QPointF(std::floor(position.x()), std::floor(position.y())),
              Qt::NoButton,
              Qt::NoButton);
    const PixelReadout & readout = Window().GetCPRView()->GetReadout();
    ASSERT_TRUE(readout.Inside) << i << "," << j;
    EXPECT_EQ(readout.Column, i);
    EXPECT_EQ(readout.Row, j);
    const std::size_t k = static_cast<std::size_t>(j) * width + i;
    EXPECT_EQ(readout.Intensity, cpr[k]) << i << "," << j;
    EXPECT_EQ(readout.Depth, depth[k]) << i << "," << j;
    const int branch = static_cast<int>(labels->GetScalarComponentAsDouble(i, j, 0, 0));
    EXPECT_EQ(readout.Branch, branch);
    EXPECT_EQ(readout.IntensityUnit, "HU") << "the phantom is a CT";
    EXPECT_TRUE(readout.ToText().contains(QStringLiteral(" HU  depth"))) << readout.ToText().toStdString();
    if (mask->GetScalarComponentAsDouble(i, j, 0, 0) > 0.0)
    {
      EXPECT_GT(branch, 0);
      EXPECT_GT(readout.Intensity, 150.0) << "a fixed pixel lies in the contrast-filled lumen";
      EXPECT_NE(readout.BranchName.find("iliac") == std::string::npos &&
                  readout.BranchName.find("femoral") == std::string::npos &&
                  readout.BranchName.find("aorta") == std::string::npos &&
                  readout.BranchName.find("tibial") == std::string::npos &&
                  readout.BranchName.find("popliteal") == std::string::npos &&
                  readout.BranchName.find("peroneal") == std::string::npos,
                true)
        << "the phantom's anatomical name, got " << readout.BranchName;
    }
    const double d = depth[k];
    double       lps[3];
    for (int axis = 0; axis < 3; ++axis)
    {
      lps[axis] = view.GetCenter()[axis] + (i - 0.5 * (width - 1)) * view.GetSpacing()[0] * view.GetU()[axis] -
                  (j - 0.5 * (height - 1)) * view.GetSpacing()[1] * view.GetUp()[axis] + d * view.GetV()[axis];
    }
    EXPECT_NEAR(readout.RAS[0], -lps[0], 1e-6);
    EXPECT_NEAR(readout.RAS[1], -lps[1], 1e-6);
    EXPECT_NEAR(readout.RAS[2], lps[2], 1e-6);
    // The same point as the logic's cut surface (float coordinates) at that pixel.
    double surfacePoint[3];
    reference.Surface->GetPoint(static_cast<vtkIdType>(k), surfacePoint);
    for (int axis = 0; axis < 3; ++axis)
    {
      EXPECT_NEAR(readout.RAS[axis], surfacePoint[axis], 1e-3);
    }
  }
  // Outside the image there is no readout.
  SendMouse(target, QEvent::MouseMove, QPointF(2.0, 2.0), Qt::NoButton, Qt::NoButton);
  EXPECT_FALSE(Window().GetCPRView()->GetReadout().Inside);
}

TEST_F(WidgetsTest, AHorizontalDragOfNPixelsTurnsTheViewByTheDocumentedAmount)
{
  QWidget *     target = Window().GetCPRView()->GetRenderWidget();
  const QPointF start(300.0, 400.0);
  constexpr int N = 40;
  SendMouse(target, QEvent::MouseButtonPress, start, Qt::LeftButton, Qt::LeftButton);
  for (int step = 1; step <= 4; ++step)
  {
    // Vertical motion does not turn the view.
    SendMouse(target, QEvent::MouseMove, start + QPointF(N * step / 4.0, 7.0 * step), Qt::NoButton, Qt::LeftButton);
    QTest::qWait(5);
  }
  // While the button is down the 3D view shows the preview surface.
  ASSERT_TRUE(WaitUntil([&] { return Controller().IsIdle(); }));
  QTest::qWait(50);
  EXPECT_FALSE(Window().GetThreeDView()->IsShowingFullSurface());
  const auto during = Window().GetCPRView()->GetResult();
  EXPECT_EQ(during->Kind, RequestKind::Interactive);
  // The panel follows the drag at the pace of the images shown.
  EXPECT_DOUBLE_EQ(Window().GetPanel()->GetAngle(), during->Outputs.View.GetAngleInDegrees());
  SendMouse(target, QEvent::MouseButtonRelease, start + QPointF(N, 28.0), Qt::LeftButton, Qt::NoButton);
  ASSERT_TRUE(WaitUntilSettled(Window()));

  const double expected = StartAngle + CPRView::DegreesPerPixel * N; // -0.5 degrees per pixel: 30 - 20 = 10
  EXPECT_DOUBLE_EQ(expected, 10.0);
  EXPECT_DOUBLE_EQ(Window().GetPanel()->GetAngle(), expected);
  const auto shown = Window().GetCPRView()->GetResult();
  EXPECT_EQ(shown->Kind, RequestKind::Final);
  EXPECT_DOUBLE_EQ(shown->Outputs.View.GetAngleInDegrees(), expected);
  ExpectShows(Window(), ReferenceOutputs(SmallPhantomInputs(), TestParameters(expected)).CPR);
  EXPECT_TRUE(Window().GetThreeDView()->IsShowingFullSurface());

  // Dragging left turns the other way, across the wrap at -180.
  Window().GetPanel()->SetAngle(-170.0, RequestKind::Final);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  SendMouse(target, QEvent::MouseButtonPress, start, Qt::LeftButton, Qt::LeftButton);
  SendMouse(target, QEvent::MouseMove, start + QPointF(60.0, 0.0), Qt::NoButton, Qt::LeftButton);
  SendMouse(target, QEvent::MouseButtonRelease, start + QPointF(60.0, 0.0), Qt::LeftButton, Qt::NoButton);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  EXPECT_DOUBLE_EQ(Window().GetPanel()->GetAngle(), 160.0); // -170 - 30 = -200, i.e. 160
  EXPECT_DOUBLE_EQ(Window().GetCPRView()->GetResult()->Outputs.View.GetAngleInDegrees(), 160.0);
}

TEST_F(WidgetsTest, TwoRequestsInQuickSuccessionDisplayOnlyTheSecond)
{
  std::vector<std::uint64_t> displayed;
  QObject::connect(Window().GetCPRView(),
                   &CPRView::imageDisplayed,
                   Window().GetCPRView(),
                   [&](std::uint64_t id) { displayed.push_back(id); });
  const RequestStatistics before = Controller().GetStatistics();
  Window().GetPanel()->SetAngle(50.0, RequestKind::Final);
  Window().GetPanel()->SetAngle(70.0, RequestKind::Final);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  ASSERT_EQ(displayed.size(), 1u);
  const auto shown = Window().GetCPRView()->GetResult();
  EXPECT_EQ(shown->RequestId, displayed.front());
  EXPECT_DOUBLE_EQ(shown->Outputs.View.GetAngleInDegrees(), 70.0);
  ExpectShows(Window(), ReferenceOutputs(SmallPhantomInputs(), TestParameters(70.0)).CPR);
  const RequestStatistics after = Controller().GetStatistics();
  EXPECT_EQ(after.Displayed - before.Displayed, 1u);
  EXPECT_EQ((after.Superseded - before.Superseded) + (after.Aborted - before.Aborted) + (after.Stale - before.Stale),
            1u)
    << "the first request was replaced while waiting, aborted while running, or dropped when it finished late";
}

TEST_F(WidgetsTest, ARequestArrivingDuringARelaxationAbortsItThroughTheLogic)
{
  // A long relaxation, then a new request as soon as the relaxation reports progress.
  ReformationParameters slow = TestParameters(StartAngle);
  slow.Iterations = 20000;
  Window().GetPanel()->SetParameters(slow);
  bool                       relaxing = false;
  auto                       connection = QObject::connect(Window().GetController(),
                                     &ReformationController::progressChanged,
                                     Window().GetController(),
                                     [&](double fraction, const QString & stage)
                                     { relaxing = relaxing || (stage == QLatin1String("relax") && fraction > 0.2); });
  std::vector<std::uint64_t> displayed;
  QObject::connect(Window().GetCPRView(),
                   &CPRView::imageDisplayed,
                   Window().GetCPRView(),
                   [&](std::uint64_t id) { displayed.push_back(id); });
  const RequestStatistics before = Controller().GetStatistics();
  Window().GetPanel()->SetAngle(80.0, RequestKind::Final);
  ASSERT_TRUE(WaitUntil([&] { return relaxing; }, 60.0));
  QObject::disconnect(connection);
  Window().GetPanel()->SetParameters(TestParameters(StartAngle));
  Window().GetPanel()->SetAngle(-80.0, RequestKind::Final);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  const RequestStatistics after = Controller().GetStatistics();
  EXPECT_EQ(after.Aborted - before.Aborted, 1u);
  EXPECT_EQ(after.Displayed - before.Displayed, 1u);
  ASSERT_EQ(displayed.size(), 1u);
  EXPECT_DOUBLE_EQ(Window().GetCPRView()->GetResult()->Outputs.View.GetAngleInDegrees(), -80.0);
  EXPECT_EQ(Window().GetCPRView()->GetResult()->Parameters.Iterations, 200);
  ExpectShows(Window(), ReferenceOutputs(SmallPhantomInputs(), TestParameters(-80.0)).CPR);
}

/** While the controller is busy: when the progress bar first showed, in seconds after the busy period began (negative
 * when it never did), and how long the busy period lasted. */
struct ProgressSighting
{
  double FirstShown{ -1.0 };
  double Busy{ 0.0 };
};

ProgressSighting
WatchProgressDuring(ViewerWindow & window, const std::function<void()> & request)
{
  using Clock = std::chrono::steady_clock;
  ProgressSighting  sighting;
  Clock::time_point busySince;
  bool              busy = false;
  bool              ended = false;
  auto              connection = QObject::connect(window.GetController(),
                                     &ReformationController::busyChanged,
                                     window.GetController(),
                                     [&](bool now)
                                     {
                                       if (now && !busy)
                                       {
                                         busySince = Clock::now();
                                       }
                                       if (!now && busy)
                                       {
                                         sighting.Busy =
                                           std::chrono::duration<double>(Clock::now() - busySince).count();
                                         ended = true;
                                       }
                                       busy = now;
                                     });
  request();
  WaitUntil(
    [&]
    {
      if (busy && sighting.FirstShown < 0.0 && window.IsProgressShown())
      {
        sighting.FirstShown = std::chrono::duration<double>(Clock::now() - busySince).count();
      }
      return ended;
    },
    120.0);
  QObject::disconnect(connection);
  EXPECT_TRUE(ended) << "the update did not end";
  EXPECT_FALSE(window.IsProgressShown()) << "the progress bar stays after the update";
  return sighting;
}

TEST_F(WidgetsTest, ThePhantomsWindowAndLevelAreInHU)
{
  EXPECT_EQ(Window().GetPanel()->GetUi().windowSpin->suffix(), QStringLiteral(" HU"));
  EXPECT_EQ(Window().GetPanel()->GetUi().levelSpin->suffix(), QStringLiteral(" HU"));
}

TEST_F(WidgetsTest, TheProgressBarShowsOnlyOnceAnUpdateHasRunForItsDelay)
{
  const double delay = ViewerWindow::ProgressDelayMilliseconds / 1000.0;
  // A quick update (the small phantom, 200 iterations): no bar unless it ran past the delay.
  const ProgressSighting quick =
    WatchProgressDuring(Window(), [this] { Window().GetPanel()->SetAngle(StartAngle + 5.0, RequestKind::Final); });
  if (quick.FirstShown >= 0.0)
  {
    EXPECT_GE(quick.FirstShown, delay - 0.002) << "shown before its delay";
  }
  else
  {
    EXPECT_GT(quick.Busy, 0.0);
  }
  // A long relaxation shows the bar, after the delay, and hides it when done.
  ReformationParameters slow = TestParameters(StartAngle);
  slow.Iterations = 100000;
  Window().GetPanel()->SetParameters(slow);
  const ProgressSighting lasting =
    WatchProgressDuring(Window(), [this] { Window().GetPanel()->SetAngle(StartAngle + 10.0, RequestKind::Final); });
  ASSERT_GT(lasting.Busy, delay) << "the long relaxation was not long";
  EXPECT_GE(lasting.FirstShown, delay - 0.002);
  EXPECT_LT(lasting.FirstShown, lasting.Busy);
  Window().GetPanel()->SetParameters(TestParameters(StartAngle));
  ASSERT_TRUE(WaitUntilSettled(Window()));
}
} // namespace
