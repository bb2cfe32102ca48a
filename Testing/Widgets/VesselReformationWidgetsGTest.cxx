// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The widgets and the viewer window, driven as a user would (slider, spin boxes, mouse events) under a virtual X
// server, checked against an independent run of the module logic on the same nodes.
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

/** Whole-run stage counts after minus before. */
struct Runs
{
  unsigned int Conversion, Depth, Relax, Resample, UnfilteredSamplings, RelaxedSamplings, Surface;
};
Runs
Difference(const StageCounts & after, const StageCounts & before)
{
  return { after.Conversion - before.Conversion,
           after.Depth - before.Depth,
           after.Relax - before.Relax,
           after.Resample - before.Resample,
           after.UnfilteredSamplings - before.UnfilteredSamplings,
           after.RelaxedSamplings - before.RelaxedSamplings,
           after.Surface - before.Surface };
}

/** The grey value VTK shows for \a value through window/level, read back from the CPR view's frame. */
int
FrameGrey(const QImage & frame, const QPointF & position)
{
  const QColor color =
    frame.pixelColor(static_cast<int>(std::floor(position.x())), static_cast<int>(std::floor(position.y())));
  EXPECT_EQ(color.red(), color.green());
  EXPECT_EQ(color.green(), color.blue());
  return color.red();
}

/** Checks that the CPR view shows exactly \a expected (the logic's CPR): the image data its actor draws equals it
 * pixel for pixel, and the frame on screen shows those pixels through window/level. */
void
ExpectShows(ViewerWindow & window, VolumeNode * expected)
{
  CPRView *      view = window.GetCPRView();
  vtkImageData * shown = view->GetDisplayedImage(false);
  int            dimensions[3];
  expected->GetImageData()->GetDimensions(dimensions);
  int shownDimensions[3];
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

class WidgetsTest : public WindowOnSmallPhantomTest
{
};

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
  const StageCounts before = Controller().GetStageExecutionCounts();
  Window().GetPanel()->GetAngleSlider()->setValue(-450); // tenths of a degree
  ASSERT_TRUE(WaitUntilSettled(Window()));
  const Runs runs = Difference(Controller().GetStageExecutionCounts(), before);
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
  const StageCounts       before = Controller().GetStageExecutionCounts();
  const RequestStatistics requestsBefore = Controller().GetStatistics();
  const auto              shownBefore = Window().GetCPRView()->GetResult();
  Window().GetPanel()->GetWindowSpinBox()->setValue(400.0);
  Window().GetPanel()->GetLevelSpinBox()->setValue(40.0);
  QTest::qWait(300);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  const Runs runs = Difference(Controller().GetStageExecutionCounts(), before);
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
  const Runs after = Difference(Controller().GetStageExecutionCounts(), before);
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

  // The independent reference for the position: docs/design.md 3.2's B(i, j) + d v from the view's C, u, v and up, in
  // LPS, then RAS by negating x and y.
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

TEST_F(WidgetsTest, AnInputNameTooLongForItsLabelShowsBothEndsAroundAnEllipsis)
{
  QLabel *      label = Window().GetPanel()->GetUi().volumeLabel;
  const QString name = QStringLiteral("a-very-long-volume-file-name-of-a-study-with-its-series-description-v2.nrrd");
  Window().GetPanel()->SetInputDescription(QStringLiteral("/data/") + name, QStringLiteral("c.vtp"), QString());
  ASSERT_GT(label->width(), 10);
  ASSERT_GT(label->fontMetrics().horizontalAdvance(name), label->width()) << "the name must not fit for this test";
  // The beginning and the end of the name around one ellipsis.
  const QStringList parts = label->text().split(QChar(0x2026));
  ASSERT_EQ(parts.size(), 2) << label->text().toStdString();
  EXPECT_FALSE(parts[0].isEmpty());
  EXPECT_FALSE(parts[1].isEmpty());
  EXPECT_TRUE(name.startsWith(parts[0])) << label->text().toStdString();
  EXPECT_TRUE(name.endsWith(parts[1])) << label->text().toStdString();
  EXPECT_LE(label->fontMetrics().horizontalAdvance(label->text()), label->width());
  EXPECT_EQ(label->statusTip(), QStringLiteral("/data/") + name);
  // Wider, it shows more; a short name whole.
  const QString narrow = label->text();
  Window().GetPanel()->setFixedWidth(Window().GetPanel()->width() + 200);
  QApplication::processEvents();
  EXPECT_GT(label->text().size(), narrow.size());
  Window().GetPanel()->setMinimumWidth(0);
  Window().GetPanel()->setMaximumWidth(QWIDGETSIZE_MAX);
  Window().GetPanel()->SetInputDescription(QStringLiteral("/data/ct.nrrd"), QStringLiteral("c.vtp"), QString());
  EXPECT_EQ(label->text(), QStringLiteral("ct.nrrd"));
  // A description (not a file) keeps its beginning.
  const QString description =
    QStringLiteral("runoff phantom, synthetic leg run-off CTA with its exact centerlines (1.5 mm voxels)");
  Window().GetPanel()->SetInputDescription(description, QStringLiteral("c.vtp"), QString());
  ASSERT_GT(label->fontMetrics().horizontalAdvance(description), label->width());
  EXPECT_TRUE(label->text().endsWith(QChar(0x2026))) << label->text().toStdString();
  EXPECT_TRUE(description.startsWith(label->text().chopped(1))) << label->text().toStdString();
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

/** The error dialog the window opened, or null. */
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

TEST_F(WidgetsTest, OpeningACorruptFileShowsTheLogicsMessageAndThePreviousDataStays)
{
  ScopedTemporaryFolder folder;
  const std::string     corruptVolume = folder.File("corrupt.mha");
  WriteTextFile(
    corruptVolume,
    "ObjectType = Image\nNDims = 3\nDimSize = 40 40\nElementType = MET_FLOAT\nElementDataFile = LOCAL\n\x01\x02");
  const std::string corruptCenterlines = folder.File("corrupt.vtp");
  WriteTextFile(corruptCenterlines,
                "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\"><PolyData><Piece NumberOfPoints=\"");
  // ITK appends the C library's errno text ("; Reason: ..."), which depends on what ran before: left out of the
  // comparison.
  auto withoutReason = [](const std::string & message) { return message.substr(0, message.find("; Reason:")); };
  const std::string expectedVolumeMessage = withoutReason(InputErrorOf([&] { ReadVolume(corruptVolume); }));
  const std::string expectedCenterlineMessage =
    withoutReason(InputErrorOf([&] { ReadCenterlineNode(corruptCenterlines); }));
  ASSERT_FALSE(expectedVolumeMessage.empty());
  ASSERT_FALSE(expectedCenterlineMessage.empty());

  const auto inputsBefore = Controller().GetInputs();
  const auto shownBefore = Window().GetCPRView()->GetResult();
  const auto pixelsBefore = NodePixels(shownBefore->Outputs.CPR);
  int        errors = 0;
  QObject::connect(&Window(), &ViewerWindow::errorShown, &Window(), [&] { ++errors; });

  Window().OpenVolume(QString::fromStdString(corruptVolume));
  ASSERT_TRUE(WaitUntil([&] { return errors == 1; }, 60.0));
  ASSERT_TRUE(WaitUntilSettled(Window()));
  QMessageBox * dialog = ErrorDialog(Window());
  ASSERT_NE(dialog, nullptr);
  EXPECT_EQ(withoutReason(dialog->text().toStdString()), expectedVolumeMessage);
  EXPECT_NE(dialog->windowTitle().toStdString().find("corrupt.mha"), std::string::npos);
  EXPECT_NE(expectedVolumeMessage.find("corrupt.mha"), std::string::npos) << "the logic's message names the file";
  dialog->close();

  Window().OpenCenterlines(QString::fromStdString(corruptCenterlines));
  ASSERT_TRUE(WaitUntil([&] { return errors == 2; }, 60.0));
  ASSERT_TRUE(WaitUntilSettled(Window()));
  dialog = ErrorDialog(Window());
  ASSERT_NE(dialog, nullptr);
  EXPECT_EQ(withoutReason(dialog->text().toStdString()), expectedCenterlineMessage);
  dialog->close();

  Window().OpenVolume(QString::fromStdString(folder.File("missing.nrrd")));
  ASSERT_TRUE(WaitUntil([&] { return errors == 3; }, 60.0));
  ASSERT_TRUE(WaitUntilSettled(Window()));
  dialog = ErrorDialog(Window());
  ASSERT_NE(dialog, nullptr);
  EXPECT_NE(dialog->text().toStdString().find("missing.nrrd"), std::string::npos);
  dialog->close();

  // The previous data stays on screen and in use.
  EXPECT_EQ(Controller().GetInputs(), inputsBefore);
  EXPECT_EQ(Window().GetCPRView()->GetResult(), shownBefore);
  ExpectShows(Window(), shownBefore->Outputs.CPR);
  EXPECT_EQ(NodePixels(shownBefore->Outputs.CPR), pixelsBefore);
  Window().GetPanel()->SetAngle(-30.0, RequestKind::Final);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  EXPECT_EQ(Window().GetCPRView()->GetResult()->Inputs, inputsBefore);
  ExpectShows(Window(), ReferenceOutputs(SmallPhantomInputs(), TestParameters(-30.0)).CPR);
}

/** The small phantom's exact centerlines moved \a shift mm along LPS z, written as a .vtp into \a folder; \a outside
 * receives the fraction of their points outside the phantom's volume, counted here from the volume's grid. */
std::string
WriteShiftedPhantomCenterlines(const vr::test::ScopedTemporaryFolder & folder, double shift, double & outside)
{
  itk::CenterlineTree tree = SmallPhantomInputs().Tree;
  const auto          volume = ConvertVolumeNodeToItkImage(SmallPhantomInputs().Volume);
  std::size_t         out = 0;
  std::size_t         all = 0;
  for (auto & branch : tree.GetBranches())
  {
    for (auto & point : branch.Points)
    {
      point[2] += shift;
      itk::ContinuousIndex<double, 3> index;
      volume->TransformPhysicalPointToContinuousIndex(point, index);
      out += volume->GetLargestPossibleRegion().IsInside(index) ? 0 : 1;
      ++all;
    }
  }
  outside = static_cast<double>(out) / static_cast<double>(all);
  const std::string path = folder.File("shifted-" + std::to_string(static_cast<int>(shift)) + ".vtp");
  WriteCenterlines(tree, path);
  return path;
}

TEST_F(WidgetsTest, CenterlinesWithNoPointInTheVolumeAreRefusedWithADialogAndTheDataStays)
{
  vr::test::ScopedTemporaryFolder folder;
  double                          outside = 0.0;
  const std::string               far = WriteShiftedPhantomCenterlines(folder, 5000.0, outside);
  ASSERT_EQ(outside, 1.0);
  const auto inputsBefore = Controller().GetInputs();
  const auto shownBefore = Window().GetCPRView()->GetResult();
  int        errors = 0;
  QObject::connect(&Window(), &ViewerWindow::errorShown, &Window(), [&] { ++errors; });
  Window().OpenCenterlines(QString::fromStdString(far));
  ASSERT_TRUE(WaitUntil([&] { return errors == 1; }, 60.0));
  ASSERT_TRUE(WaitUntilSettled(Window()));
  QMessageBox * dialog = ErrorDialog(Window());
  ASSERT_NE(dialog, nullptr);
  const std::string text = dialog->text().toStdString();
  EXPECT_NE(text.find("shifted-5000.vtp"), std::string::npos) << text;
  EXPECT_NE(text.find("none of the"), std::string::npos) << text;
  EXPECT_NE(text.find("other coordinate system"), std::string::npos) << text;
  dialog->close();
  EXPECT_EQ(Controller().GetInputs(), inputsBefore);
  EXPECT_EQ(Window().GetCPRView()->GetResult(), shownBefore);
  EXPECT_FALSE(Window().CanUndoOpen()) << "nothing was replaced, so there is nothing to undo";
}

TEST_F(WidgetsTest, CenterlinesMostlyOutsideShowTheirWholeWarningAndUndoBringsThePreviousPairBack)
{
  vr::test::ScopedTemporaryFolder folder;
  // Moved up until between 60 and 90 % of the points leave the volume (counted by the helper).
  double      outside = 0.0;
  std::string moved;
  for (double shift = 50.0; shift < 1500.0 && !(outside > 0.6 && outside < 0.9); shift += 50.0)
  {
    moved = WriteShiftedPhantomCenterlines(folder, shift, outside);
  }
  ASSERT_GT(outside, 0.6);
  ASSERT_LT(outside, 0.9);
  const auto inputsBefore = Controller().GetInputs();
  EXPECT_TRUE(Window().GetShownWarnings().isEmpty());
  Window().OpenCenterlines(QString::fromStdString(moved));
  ASSERT_TRUE(WaitUntil([&] { return Controller().GetInputs() != inputsBefore; }, 60.0));
  ASSERT_TRUE(WaitUntilSettled(Window()));
  const QStringList warnings = Window().GetShownWarnings();
  ASSERT_FALSE(warnings.isEmpty());
  const std::string warning = warnings.join(QStringLiteral("\n")).toStdString();
  EXPECT_NE(warning.find(std::filesystem::path(moved).filename().string()), std::string::npos) << warning;
  EXPECT_NE(warning.find("points lie outside"), std::string::npos) << warning;
  EXPECT_NE(warning.find("The reformation continues."), std::string::npos) << "cut short: " << warning;
  // The banner shows the text whole on screen, not only in a list.
  const QLabel * label = nullptr;
  for (const QLabel * candidate : Window().findChildren<QLabel *>())
  {
    if (candidate->isVisible() && candidate->wordWrap() && candidate->text().contains(QStringLiteral("continues")))
    {
      label = candidate;
    }
  }
  ASSERT_NE(label, nullptr) << "no visible banner holds the warning";

  // Edit > Undo open: the phantom's own centerlines again, and their image.
  ASSERT_TRUE(Window().CanUndoOpen());
  QAction * undo = Window().findChild<QAction *>(QStringLiteral("undoOpen"));
  ASSERT_NE(undo, nullptr);
  const auto movedInputs = Controller().GetInputs();
  undo->trigger();
  ASSERT_TRUE(WaitUntil([&] { return Controller().GetInputs() != movedInputs; }, 60.0));
  ASSERT_TRUE(WaitUntilSettled(Window()));
  EXPECT_EQ(Controller().GetInputs()->Tree, inputsBefore->Tree);
  EXPECT_EQ(Controller().GetInputs()->Centerlines, inputsBefore->Centerlines);
  EXPECT_EQ(Controller().GetInputs()->Volume, inputsBefore->Volume);
  EXPECT_TRUE(Window().GetShownWarnings().isEmpty());
  EXPECT_FALSE(Window().CanUndoOpen());
  ExpectShows(Window(), ReferenceOutputs(SmallPhantomInputs(), Window().GetCPRView()->GetResult()->Parameters).CPR);
}

TEST_F(WidgetsTest, EveryInputFuzzingFoundIsRefusedWithADialogAndTheDataStays)
{
  // Volumes (NIfTI headers that aborted ITK, DICOM folders whose file aborted GDCM) and centerlines (legacy .vtk that
  // crashed VTK, a .vtp that asked for exabytes): each a dialog naming the file, and the data on screen kept.
  const std::filesystem::path               findings = VR_FINDINGS_DIR;
  const std::filesystem::path               corpus = VR_FUZZ_CORPUS_DIR;
  std::vector<std::pair<std::string, bool>> inputs; // path, is a volume
  for (const auto & entry : std::filesystem::directory_iterator(findings))
  {
    if (entry.is_directory() || entry.path().extension() == ".nii")
    {
      inputs.emplace_back(entry.path().string(), true);
    }
  }
  for (const char * file : { "vtk/crash-two-lines-sections.vtk",
                             "vtk/crash-metadata-lines-segv-2.vtk",
                             "vtp/crash-ascii-offsets-huge.vtp" })
  {
    inputs.emplace_back((corpus / file).string(), false);
  }
  ASSERT_GE(inputs.size(), 11u) << "the findings of issue 25 and the campaign's";

  const auto inputsBefore = Controller().GetInputs();
  const auto shownBefore = Window().GetCPRView()->GetResult();
  int        errors = 0;
  QObject::connect(&Window(), &ViewerWindow::errorShown, &Window(), [&] { ++errors; });
  for (const auto & [path, volume] : inputs)
  {
    const int before = errors;
    if (volume)
    {
      Window().OpenVolume(QString::fromStdString(path));
    }
    else
    {
      Window().OpenCenterlines(QString::fromStdString(path));
    }
    ASSERT_TRUE(WaitUntil([&] { return errors == before + 1; }, 120.0)) << path;
    ASSERT_TRUE(WaitUntilSettled(Window()));
    QMessageBox * dialog = ErrorDialog(Window());
    ASSERT_NE(dialog, nullptr) << path;
    const std::string text = dialog->text().toStdString();
    // The message names the file; a DICOM folder's names the corrupt file inside it.
    EXPECT_NE(text.find(std::filesystem::path(path).filename().string()), std::string::npos) << path << ": " << text;
    if (std::filesystem::is_directory(path))
    {
      for (const auto & file : std::filesystem::directory_iterator(path))
      {
        EXPECT_NE(text.find(file.path().filename().string()), std::string::npos) << path << ": " << text;
      }
    }
    dialog->close();
    EXPECT_EQ(Controller().GetInputs(), inputsBefore) << path;
  }
  EXPECT_EQ(Window().GetCPRView()->GetResult(), shownBefore);
  ExpectShows(Window(), shownBefore->Outputs.CPR);
}

/** The distinct values of a polydata's cell array. */
std::set<int>
DistinctCellValues(vtkPolyData * data, const char * name)
{
  std::set<int>  values;
  vtkDataArray * array = data != nullptr ? data->GetCellData()->GetArray(name) : nullptr;
  for (vtkIdType k = 0; array != nullptr && k < array->GetNumberOfTuples(); ++k)
  {
    values.insert(static_cast<int>(array->GetTuple1(k)));
  }
  return values;
}

TEST(WidgetsInputs, HounsfieldUnitsOnlyForAVolumeThatHoldsAir)
{
  auto volumeWithMinimum = [](float minimum)
  {
    auto image = VolumeImageType::New();
    image->SetRegions(VolumeImageType::RegionType({ { 0, 0, 0 } }, { { 4, 3, 2 } }));
    image->Allocate();
    image->FillBuffer(300.0f);
    image->GetBufferPointer()[5] = minimum;
    return ConvertItkImageToVolumeNode(image.GetPointer(), "volume");
  };
  EXPECT_EQ(IntensityUnitOf(volumeWithMinimum(-1024.0f)), "HU") << "a CT's air";
  EXPECT_EQ(IntensityUnitOf(volumeWithMinimum(-500.0f)), "HU");
  EXPECT_EQ(IntensityUnitOf(volumeWithMinimum(-499.0f)), "") << "above any air in HU";
  EXPECT_EQ(IntensityUnitOf(volumeWithMinimum(0.0f)), "") << "an MR's intensities";
  EXPECT_EQ(IntensityUnitOf(nullptr), "");
  EXPECT_EQ(MakePhantomInputs("runoff", 6.0).IntensityUnit, "HU");
}

TEST(WidgetsSegmentation, TheVMTKLevelSetGivesTheLogicsCPRAndItsThreeBranchesAndABadFileKeepsTheData)
{
  const std::string data = AortaDataFolder();
  if (data.empty())
  {
    GTEST_SKIP() << "the shared data folder vmtk-aorta-mra is not beside this checkout (VR_SHARED_DATA_DIR)";
  }
  const std::string     volume = data + "/aorta.mha";
  const std::string     levelSet = data + "/aorta-final-levelset.mha";
  ReformationParameters parameters = TestParameters(StartAngle);
  parameters.Window = 0.0; // the full range, as for files

  auto window = std::make_unique<ViewerWindow>();
  window->resize(1400, 900);
  window->GetPanel()->SetParameters(TestParameters(StartAngle));
  window->GetPanel()->SetOverlays(CPROverlays{ true, false, false, false });
  window->show();
  int     errors = 0;
  QString lastError;
  QObject::connect(window.get(),
                   &ViewerWindow::errorShown,
                   window.get(),
                   [&](const QString &, const QString & message)
                   {
                     ++errors;
                     lastError = message;
                   });
  window->OpenFilesWithSegmentation(QString::fromStdString(volume), { QString::fromStdString(levelSet) });
  ASSERT_TRUE(WaitUntil([&] { return window->GetCPRView()->GetResult() != nullptr || errors > 0; }, 600.0));
  ASSERT_EQ(errors, 0) << lastError.toStdString();
  ASSERT_TRUE(WaitUntilSettled(*window, 600.0));
  const auto shown = window->GetCPRView()->GetResult();
  const auto inputs = shown->Inputs;
  ASSERT_TRUE(inputs->Segmentation);
  EXPECT_EQ(window->GetPanel()->GetUi().segmentationLabel->property("fullText").toString(),
            QStringLiteral("aorta-final-levelset.mha"));

  // The reference: a logic of its own on the files, read anew.
  VesselReformationLogic   logic;
  std::vector<std::string> warnings;
  logic.SetVolumeNode(ReadVolumeNode(volume));
  logic.SetSegmentationNode(
    ConvertItkImageToVolumeNode(ReadSegmentation({ levelSet }, {}, warnings).Mask.GetPointer(), "level set"));
  logic.SetParameters(parameters);
  const auto                referenceCPR = NodePixels(logic.Update().CPR);
  const itk::CenterlineTree referenceTree = ConvertCenterlineNodeToTree(logic.GetOutputs().ExtractedCenterlines);
  ExpectShows(*window, logic.GetOutputs().CPR);

  // The overlays: the trunk and both iliacs, as the logic extracted them, in the CPR view and as tubes in 3D.
  ASSERT_EQ(referenceTree.GetBranches().size(), 3u);
  ASSERT_EQ(inputs->Tree.GetBranches().size(), 3u);
  for (std::size_t b = 0; b < 3; ++b)
  {
    const auto & ours = inputs->Tree.GetBranches()[b];
    const auto & theirs = referenceTree.GetBranches()[b];
    ASSERT_EQ(ours.Points.size(), theirs.Points.size());
    EXPECT_LT(ours.Points.front().EuclideanDistanceTo(theirs.Points.front()), 1e-3);
    EXPECT_LT(ours.Points.back().EuclideanDistanceTo(theirs.Points.back()), 1e-3);
  }
  EXPECT_EQ(window->GetCPRView()->GetCenterlineOverlay()->GetNumberOfLines(), 3);
  EXPECT_EQ(DistinctCellValues(window->GetThreeDView()->GetTubes(), "BranchIds").size(), 3u);

  // An MR angiography: its intensities are no Hounsfield units, and neither the window nor the readout says so.
  EXPECT_EQ(inputs->IntensityUnit, "");
  EXPECT_EQ(window->GetPanel()->GetUi().windowSpin->suffix(), QString());
  EXPECT_EQ(window->GetPanel()->GetUi().levelSpin->suffix(), QString());
  const PixelReadout mrReadout = ReadPixel(*shown, false, 10, 10);
  ASSERT_TRUE(mrReadout.Inside);
  EXPECT_FALSE(mrReadout.ToText().contains(QStringLiteral("HU"))) << mrReadout.ToText().toStdString();
  EXPECT_TRUE(mrReadout.ToText().contains(QStringLiteral("value "))) << mrReadout.ToText().toStdString();

  // A corrupt file: the reader's message in a dialog, and the data stays.
  ScopedTemporaryFolder folder;
  const std::string     corrupt = folder.File("corrupt-mask.nii");
  WriteTextFile(corrupt, "not a NIfTI header at all");
  auto withoutReason = [](const std::string & message) { return message.substr(0, message.find("; Reason:")); };
  const std::string expected = withoutReason(InputErrorOf([&] { ReadSegmentation({ corrupt }, {}, warnings); }));
  ASSERT_FALSE(expected.empty());
  EXPECT_NE(expected.find("corrupt-mask.nii"), std::string::npos) << expected;
  window->OpenSegmentation({ QString::fromStdString(corrupt) });
  ASSERT_TRUE(WaitUntil([&] { return errors == 1; }, 60.0));
  ASSERT_TRUE(WaitUntilSettled(*window));
  QMessageBox * dialog = ErrorDialog(*window);
  ASSERT_NE(dialog, nullptr);
  EXPECT_EQ(withoutReason(dialog->text().toStdString()), expected);
  dialog->close();

  // A segmentation that reads but that the logic refuses (half a metre from the scan): its message, the data stays.
  auto shifted = ReadSegmentation({ levelSet }, {}, warnings).Mask;
  auto origin = shifted->GetOrigin();
  origin[2] += 500.0;
  shifted->SetOrigin(origin);
  const std::string elsewhere = folder.File("elsewhere.nrrd");
  itk::WriteImage(shifted, elsewhere);
  VesselReformationLogic refusing;
  refusing.SetVolumeNode(ReadVolumeNode(volume));
  refusing.SetSegmentationNode(ReadSegmentationNode({ elsewhere }, warnings, warnings));
  refusing.SetParameters(parameters);
  const std::string refused = InputErrorOf([&] { refusing.Update(); });
  EXPECT_NE(refused.find("does not overlap"), std::string::npos) << refused;
  window->OpenSegmentation({ QString::fromStdString(elsewhere) });
  ASSERT_TRUE(WaitUntil([&] { return errors == 2; }, 120.0));
  ASSERT_TRUE(WaitUntilSettled(*window));
  dialog = ErrorDialog(*window);
  ASSERT_NE(dialog, nullptr);
  EXPECT_EQ(dialog->text().toStdString(), refused);
  dialog->close();

  EXPECT_EQ(window->GetController()->GetInputs(), inputs);
  EXPECT_EQ(window->GetCPRView()->GetResult(), shown);
  EXPECT_EQ(NodePixels(shown->Outputs.CPR), referenceCPR);
  // And the logic reforms the previous data at a new angle.
  window->GetPanel()->SetAngle(-30.0, RequestKind::Final);
  ASSERT_TRUE(WaitUntilSettled(*window, 300.0));
  EXPECT_EQ(errors, 2) << lastError.toStdString();
  parameters.AngleInDegrees = -30.0;
  logic.SetParameters(parameters);
  ExpectShows(*window, logic.Update().CPR);
  EXPECT_EQ(window->GetCPRView()->GetCenterlineOverlay()->GetNumberOfLines(), 3);
}

TEST_F(WidgetsTest, AnInvalidParameterIsMarkedAndTheImageStays)
{
  const auto shownBefore = Window().GetCPRView()->GetResult();
  QString    error;
  QObject::connect(&Window(),
                   &ViewerWindow::errorShown,
                   &Window(),
                   [&](const QString &, const QString & message) { error = message; });
  Window().GetPanel()->GetUi().heightSpin->setValue(0); // "fit" with a given width: the logic refuses the pair
  ASSERT_TRUE(WaitUntil([&] { return !error.isEmpty(); }, 60.0));
  ASSERT_TRUE(WaitUntilSettled(Window()));
  EXPECT_NE(error.toStdString().find("view size"), std::string::npos) << error.toStdString();
  EXPECT_FALSE(Window().GetPanel()->GetUi().widthSpin->styleSheet().isEmpty());
  EXPECT_FALSE(Window().GetPanel()->GetUi().heightSpin->styleSheet().isEmpty());
  EXPECT_EQ(Window().GetCPRView()->GetResult(), shownBefore);
  // A valid size again clears the mark and reforms.
  Window().GetPanel()->GetUi().heightSpin->setValue(256);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  EXPECT_TRUE(Window().GetPanel()->GetUi().widthSpin->styleSheet().isEmpty());
}

TEST_F(WidgetsTest, TheFilterSectionsRangeKernelAndSolverReachTheLogic)
{
  const Ui::ModulePanel & ui = Window().GetPanel()->GetUi();
  // The tests' view gives the kernel as a = 0.5 mm^-2: the panel shows it so, and the equivalent J beside it.
  ASSERT_EQ(ui.kernelCombo->currentIndex(), 1);
  EXPECT_TRUE(ui.anisotropySpin->isEnabled());
  EXPECT_FALSE(ui.jumpThresholdSpin->isEnabled());
  EXPECT_NEAR(ui.jumpThresholdSpin->value(), 1.41, 1e-9);
  const auto atHalf = NodePixels(Window().GetCPRView()->GetResult()->Outputs.CPR);

  // J = 2 mm: the logic gets a = 1/J^2 = 0.25 mm^-2, and no anisotropy of its own.
  ui.kernelCombo->setCurrentIndex(0);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  EXPECT_TRUE(ui.jumpThresholdSpin->isEnabled());
  EXPECT_FALSE(ui.anisotropySpin->isEnabled());
  ui.jumpThresholdSpin->setValue(2.0);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  auto shown = Window().GetCPRView()->GetResult();
  ASSERT_TRUE(shown->Parameters.JumpThreshold.has_value());
  EXPECT_EQ(*shown->Parameters.JumpThreshold, 2.0);
  EXPECT_FALSE(shown->Parameters.Anisotropy.has_value());
  EXPECT_EQ(shown->Parameters.EffectiveAnisotropy(), 0.25);
  // The caption under the image: the one description of the settings (vr::DescribeFilterSettings), on two lines.
  const CPRView & view = *Window().GetCPRView();
  EXPECT_EQ(view.GetCaption(false).toStdString(), "bilateral: J = 2 mm, w = 1\n200 iterations");
  EXPECT_EQ(view.GetCaption(false).toStdString(), "bilateral: " + DescribeFilterSettings(shown->Parameters, "\n"));
  EXPECT_EQ(view.GetCaption(true).toStdString(), "unfiltered (w = 0)");
  ReformationParameters quarter = TestParameters(StartAngle);
  quarter.Anisotropy = 0.25;
  const ReformationOutputs atQuarter = ReferenceOutputs(SmallPhantomInputs(), quarter);
  ExpectShows(Window(), atQuarter.CPR);
  EXPECT_NE(NodePixels(atQuarter.CPR), atHalf) << "a = 0.25 and a = 0.5 differ, so the comparison can fail";

  // Back to the paper's a: the spin box shows the same kernel (0.25), then a = 0.5 goes alone, no jump threshold.
  ui.kernelCombo->setCurrentIndex(1);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  EXPECT_DOUBLE_EQ(ui.anisotropySpin->value(), 0.25);
  ui.anisotropySpin->setValue(0.5);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  shown = Window().GetCPRView()->GetResult();
  ASSERT_TRUE(shown->Parameters.Anisotropy.has_value());
  EXPECT_EQ(*shown->Parameters.Anisotropy, 0.5);
  EXPECT_FALSE(shown->Parameters.JumpThreshold.has_value());
  EXPECT_EQ(NodePixels(shown->Outputs.CPR), atHalf);
  ExpectShows(Window(), ReferenceOutputs(SmallPhantomInputs(), TestParameters(StartAngle)).CPR);

  // The steady solver: N and w do not apply, and the image is the logic's steady one.
  ui.solverCombo->setCurrentText(QStringLiteral("steady"));
  ASSERT_TRUE(WaitUntilSettled(Window()));
  EXPECT_FALSE(ui.iterationsSpin->isEnabled());
  EXPECT_FALSE(ui.relaxationSpin->isEnabled());
  shown = Window().GetCPRView()->GetResult();
  EXPECT_EQ(shown->Parameters.Solver, itk::BilateralDepthRelaxSolver::Steady);
  ReformationParameters steady = TestParameters(StartAngle);
  steady.Solver = itk::BilateralDepthRelaxSolver::Steady;
  const ReformationOutputs steadyReference = ReferenceOutputs(SmallPhantomInputs(), steady);
  ExpectShows(Window(), steadyReference.CPR);
  EXPECT_NE(NodePixels(steadyReference.CPR), atHalf) << "200 Jacobi passes are not the fixed point";
  EXPECT_EQ(view.GetCaption(false).toStdString(), "bilateral: a = 0.5 mm^-2\nsteady solver");
  EXPECT_EQ(view.GetCaption(false).toStdString(), "bilateral: " + DescribeFilterSettings(shown->Parameters, "\n"));

  // The backend the logic chose, and why, under the backend choice.
  ASSERT_FALSE(shown->Outputs.RelaxBackendReason.empty());
  const std::string report = Window().GetPanel()->GetRelaxBackendReport().toStdString();
  EXPECT_NE(report.find(shown->Outputs.RelaxBackendReason), std::string::npos) << report;
  EXPECT_NE(report.find("cpu"), std::string::npos) << report;
}

TEST_F(WidgetsTest, TheFileMenuOpensTheThoracicPhantomAndShowsTheLogicsCPR)
{
  QAction * open = Window().findChild<QAction *>(QStringLiteral("openPhantom_thorax"));
  ASSERT_NE(open, nullptr) << "File > Open phantom > thorax";
  EXPECT_NE(open->text().toStdString().find("thoracic"), std::string::npos) << open->text().toStdString();
  const auto runoff = Controller().GetInputs();
  open->trigger();
  ASSERT_TRUE(WaitUntil([&] { return Controller().GetInputs() != runoff; }, 300.0));
  ASSERT_TRUE(WaitUntilSettled(Window(), 300.0));
  const auto inputs = Controller().GetInputs();
  EXPECT_TRUE(inputs->IsPhantom);
  EXPECT_NE(inputs->VolumeSource.find("thorax"), std::string::npos) << inputs->VolumeSource;
  EXPECT_EQ(Window().GetPanel()->GetUi().phantomCombo->currentText(), QStringLiteral("thorax"));
  bool arch = false;
  for (const auto & branch : inputs->Tree.GetBranches())
  {
    arch = arch || inputs->BranchName(branch.Id).find("subclavian") != std::string::npos;
  }
  EXPECT_TRUE(arch) << "the thoracic phantom's arteries by name";
  const auto shown = Window().GetCPRView()->GetResult();
  ASSERT_EQ(shown->Inputs, inputs);
  EXPECT_DOUBLE_EQ(shown->Outputs.View.GetAngleInDegrees(), StartAngle);
  // The reference: a logic of its own on a thoracic phantom made anew, at the same angle.
  const ReformationOutputs reference = ReferenceOutputs(MakePhantomInputs("thorax", 1.5), TestParameters(StartAngle));
  ExpectShows(Window(), reference.CPR);
  const auto runoffPixels = NodePixels(ReferenceOutputs(SmallPhantomInputs(), TestParameters(StartAngle)).CPR);
  EXPECT_NE(NodePixels(reference.CPR), runoffPixels);
}

TEST_F(WidgetsTest, SavesTheOutputsOnScreenAllOrNothing)
{
  ScopedTemporaryFolder folder;
  ASSERT_TRUE(Window().SaveOutputs(QString::fromStdString(folder.Path().string())));
  const std::vector<std::string> expected = { "cpr-unfiltered.nrrd", "cpr.nrrd",   "cpr.png",     "cut-surface.vtp",
                                              "depth-relaxed.nrrd",  "depth.nrrd", "labels.nrrd", "mask.nrrd" };
  EXPECT_EQ(folder.Entries(), expected);
  const auto saved = ReadDepthImage(folder.File("cpr.nrrd"));
  const auto shown = NodePixels(Window().GetCPRView()->GetResult()->Outputs.CPR);
  EXPECT_EQ(std::vector<float>(saved->GetBufferPointer(), saved->GetBufferPointer() + shown.size()), shown);
  // The cut surface as 3D Slicer writes models, like the module's and the demo's: LPS with "SPACE" = "LPS" in the
  // file, read here with VTK's own reader and no conversion of ours. The logic's surface is RAS: each point of the file
  // is the point on screen with x and y negated.
  const auto latest = Controller().GetLatestResult(); // the result that brought the surface (SaveOutputs)
  ASSERT_TRUE(latest && latest->Outputs.Surface);
  vtkPolyData *                surface = latest->Outputs.Surface;
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(folder.File("cut-surface.vtp").c_str());
  reader->Update();
  vtkPolyData * file = reader->GetOutput();
  auto *        space = vtkStringArray::SafeDownCast(file->GetFieldData()->GetAbstractArray("SPACE"));
  ASSERT_NE(space, nullptr) << "no SPACE marker in cut-surface.vtp";
  EXPECT_EQ(space->GetValue(0), "LPS");
  ASSERT_EQ(file->GetNumberOfPoints(), surface->GetNumberOfPoints());
  for (vtkIdType k : { vtkIdType{ 0 }, surface->GetNumberOfPoints() / 3, surface->GetNumberOfPoints() - 1 })
  {
    double ras[3];
    double lps[3];
    surface->GetPoint(k, ras);
    file->GetPoint(k, lps);
    EXPECT_FLOAT_EQ(lps[0], -ras[0]) << "point " << k;
    EXPECT_FLOAT_EQ(lps[1], -ras[1]) << "point " << k;
    EXPECT_FLOAT_EQ(lps[2], ras[2]) << "point " << k;
  }

  int errors = 0;
  QObject::connect(&Window(), &ViewerWindow::errorShown, &Window(), [&] { ++errors; });
  const std::string missing = folder.File("no-such-folder");
  EXPECT_FALSE(Window().SaveOutputs(QString::fromStdString(missing)));
  EXPECT_EQ(errors, 1);
  EXPECT_FALSE(std::filesystem::exists(missing));
  QMessageBox * dialog = ErrorDialog(Window());
  ASSERT_NE(dialog, nullptr);
  EXPECT_NE(dialog->text().toStdString().find("no-such-folder"), std::string::npos) << dialog->text().toStdString();
  dialog->close();
}

TEST_F(WidgetsTest, ExportsARotationSeriesOfTheImageOnScreen)
{
  EXPECT_NE(Window().findChild<QAction *>(QStringLiteral("exportRotationSeries")), nullptr)
    << "File > Export rotation series";
  EXPECT_TRUE(ViewerWindow::HelpText().contains(QStringLiteral("Export rotation series")));
  ScopedTemporaryFolder folder;
  const std::string     series = folder.File("series");
  const auto            shown = Window().GetCPRView()->GetResult();
  ASSERT_TRUE(shown);
  const double window = Window().GetPanel()->GetWindowSpinBox()->value();
  const double level = Window().GetPanel()->GetLevelSpinBox()->value();
  ASSERT_GT(window, 0.0);
  const double angle = shown->Outputs.View.GetAngleInDegrees();
  EXPECT_EQ(Window().ExportRotationSeries(QString::fromStdString(series), RotationAngles{ angle, 120.0, 3 }), 3);
  const std::set<std::string> expected = { "rotation-000.png",   "rotation-001.png", "rotation-002.png",
                                           "rotation-000.dcm",   "rotation-001.dcm", "rotation-002.dcm",
                                           "rotation-angles.csv" };
  std::set<std::string>       written;
  for (const auto & entry : std::filesystem::directory_iterator(series))
  {
    written.insert(entry.path().filename().string());
  }
  EXPECT_EQ(written, expected);
  // View 0 is at the angle on screen: the image on screen through the panel's window and level, computed here.
  const QImage png(QString::fromStdString(series + "/rotation-000.png"));
  const auto   pixels = NodePixels(shown->Outputs.CPR);
  ASSERT_EQ(static_cast<std::size_t>(png.width()) * static_cast<std::size_t>(png.height()), pixels.size());
  std::size_t mismatches = 0;
  for (int y = 0; y < png.height(); ++y)
  {
    for (int x = 0; x < png.width(); ++x)
    {
      const float value =
        pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(png.width()) + static_cast<std::size_t>(x)];
      const double grey =
        std::isnan(value)
          ? 0.0
          : std::min(255.0, std::max(0.0, std::floor(255.0 * (value - level + window / 2) / window + 0.5)));
      mismatches += qGray(png.pixel(x, y)) != static_cast<int>(grey);
    }
  }
  EXPECT_EQ(mismatches, 0u);

  // The same folder again: refused with a dialog naming why, the series kept.
  int errors = 0;
  QObject::connect(&Window(), &ViewerWindow::errorShown, &Window(), [&] { ++errors; });
  EXPECT_EQ(Window().ExportRotationSeries(QString::fromStdString(series), RotationAngles{}), 0);
  EXPECT_EQ(errors, 1);
  QMessageBox * dialog = ErrorDialog(Window());
  ASSERT_NE(dialog, nullptr);
  EXPECT_NE(dialog->text().toStdString().find("already holds a rotation series"), std::string::npos)
    << dialog->text().toStdString();
  dialog->close();
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(series), std::filesystem::directory_iterator()), 7);
}

TEST_F(WidgetsTest, EveryControlOfThePanelHasATooltip)
{
  int controls = 0;
  for (QWidget * control : Window().GetPanel()->findChildren<QWidget *>())
  {
    const bool isControl = qobject_cast<QAbstractSpinBox *>(control) || qobject_cast<QComboBox *>(control) ||
                           qobject_cast<QAbstractButton *>(control) || qobject_cast<QSlider *>(control);
    if (!isControl || control->parent() == nullptr || qobject_cast<QAbstractSpinBox *>(control->parentWidget()))
    {
      continue;
    }
    ++controls;
    EXPECT_FALSE(control->toolTip().isEmpty()) << control->objectName().toStdString();
  }
  EXPECT_GE(controls, 30);
}

/** A controller alone on the small phantom, keeping every result it delivers. */
struct ControllerRun
{
  ReformationController                                 Controller;
  std::vector<std::shared_ptr<const ReformationResult>> Results;

  ControllerRun()
  {
    QObject::connect(&Controller,
                     &ReformationController::resultReady,
                     &Controller,
                     [this](std::shared_ptr<const ReformationResult> result) { Results.push_back(result); });
    Controller.LoadInputs([] { return SmallPhantomInputs(); }, QStringLiteral("the small phantom"));
  }
};

TEST(ReformationControllerSurface, AFinalRequestsCutSurfaceWaitsUntilItsImagesAreShown)
{
  ControllerRun run;
  run.Controller.SetSurfaceWaitsForDisplay(true, 60.0);
  ASSERT_TRUE(WaitUntil([&] { return run.Controller.GetInputs() != nullptr; }));
  const std::uint64_t id = run.Controller.Request(TestParameters(StartAngle), RequestKind::Final);
  ASSERT_TRUE(WaitUntil([&] { return !run.Results.empty(); }));
  EXPECT_EQ(run.Results.front()->RequestId, id);
  EXPECT_FALSE(run.Results.front()->HasFullSurface());
  const unsigned int surfacesBefore = run.Controller.GetStageExecutionCounts().Surface;
  // Without ImageShown the surface does not come (the small phantom's takes a few milliseconds once started).
  EXPECT_FALSE(WaitUntil([&] { return run.Results.size() > 1; }, 1.0));
  EXPECT_EQ(run.Controller.GetStageExecutionCounts().Surface, surfacesBefore);
  run.Controller.ImageShown(id);
  ASSERT_TRUE(WaitUntil([&] { return run.Results.size() > 1; }));
  EXPECT_EQ(run.Results.back()->RequestId, id);
  EXPECT_TRUE(run.Results.back()->HasFullSurface());
  EXPECT_EQ(run.Controller.GetStageExecutionCounts().Surface, surfacesBefore + 1);
}

TEST(ReformationControllerSurface, WithoutADisplayTheCutSurfaceComesAfterTheTimeLimit)
{
  ControllerRun run;
  run.Controller.SetSurfaceWaitsForDisplay(true, 0.2);
  ASSERT_TRUE(WaitUntil([&] { return run.Controller.GetInputs() != nullptr; }));
  const std::uint64_t id = run.Controller.Request(TestParameters(StartAngle), RequestKind::Final);
  ASSERT_TRUE(WaitUntil([&] { return run.Results.size() > 1; }));
  EXPECT_EQ(run.Results.back()->RequestId, id);
  EXPECT_TRUE(run.Results.back()->HasFullSurface());
}

TEST(WidgetsAbout, TheAboutTextCitesThePaper)
{
  const std::string about = ViewerWindow::AboutText().toStdString();
  EXPECT_NE(about.find("Kretschmer"), std::string::npos);
  EXPECT_NE(about.find("Bilateral Depth Filtering for Enhanced Vessel Reformation"), std::string::npos);
  EXPECT_NE(about.find("EuroVis) 2014"), std::string::npos);
  EXPECT_NE(about.find("0.5 degrees per pixel"), std::string::npos);
}

TEST(SurfacePreview, ItsPointsLieOnTheFullCutSurface)
{
  const ReformationOutputs outputs = ReferenceOutputs(SmallPhantomInputs(), TestParameters(StartAngle));
  EXPECT_EQ(PreviewSurfaceStride(512, 1024), 4u);
  EXPECT_EQ(PreviewSurfaceStride(128, 256), 1u);
  EXPECT_EQ(PreviewSurfaceStride(256, 768), 3u);
  for (unsigned int stride : { 1u, 3u, 4u })
  {
    const auto preview = BuildPreviewSurface(outputs, stride);
    ASSERT_NE(preview, nullptr);
    const unsigned int width = (128 - 1) / stride + 1;
    const unsigned int height = (256 - 1) / stride + 1;
    ASSERT_EQ(preview->GetNumberOfPoints(), static_cast<vtkIdType>(width * height));
    double worst = 0.0;
    for (unsigned int j = 0; j < height; ++j)
    {
      for (unsigned int i = 0; i < width; ++i)
      {
        double coarse[3];
        double full[3];
        preview->GetPoint(static_cast<vtkIdType>(j * width + i), coarse);
        outputs.Surface->GetPoint(static_cast<vtkIdType>((stride * j) * 128 + stride * i), full);
        for (int axis = 0; axis < 3; ++axis)
        {
          worst = std::max(worst, std::abs(coarse[axis] - full[axis]));
        }
      }
    }
    EXPECT_LT(worst, 1e-3) << "stride " << stride;
  }
}
} // namespace
