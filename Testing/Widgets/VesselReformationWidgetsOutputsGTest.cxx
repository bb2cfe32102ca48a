// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The viewer window's panel and outputs, driven as a user would under a virtual X server: parameters and filter
// settings reaching the logic, the file menu, saving and exporting, tooltips, the cut surface and its preview.
#include "vrBurnedInLabels.h"
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
  // At the CPR's own size (0), so that the pixels compare one for one.
  EXPECT_EQ(Window().ExportRotationSeries(QString::fromStdString(series), RotationAngles{ angle, 120.0, 3 }, 0), 3);
  const std::set<std::string> expected = { "rotation-000.png",   "rotation-001.png", "rotation-002.png",
                                           "rotation-000.dcm",   "rotation-001.dcm", "rotation-002.dcm",
                                           "rotation-angles.csv" };
  std::set<std::string>       written;
  for (const auto & entry : std::filesystem::directory_iterator(series))
  {
    written.insert(entry.path().filename().string());
  }
  EXPECT_EQ(written, expected);
  // View 0 is at the angle on screen: the image on screen through the panel's window and level, computed here, with
  // the view's labels burned in (vr::BurnInViewLabels at the view's own axes).
  const QImage png(QString::fromStdString(series + "/rotation-000.png"));
  const auto   pixels = NodePixels(shown->Outputs.CPR);
  ASSERT_EQ(static_cast<std::size_t>(png.width()) * static_cast<std::size_t>(png.height()), pixels.size());
  auto labelled = MaskImageType::New();
  labelled->SetRegions(MaskImageType::SizeType{
    { static_cast<itk::SizeValueType>(png.width()), static_cast<itk::SizeValueType>(png.height()) } });
  labelled->Allocate();
  for (std::size_t p = 0; p < pixels.size(); ++p)
  {
    const float  value = pixels[p];
    const double grey =
      std::isnan(value)
        ? 0.0
        : std::min(255.0, std::max(0.0, std::floor(255.0 * (value - level + window / 2) / window + 0.5)));
    labelled->GetBufferPointer()[p] = static_cast<unsigned char>(grey);
  }
  BurnInViewLabels(labelled, shown->Outputs.View.GetU(), shown->Outputs.View.GetUp(), angle);
  std::size_t mismatches = 0;
  for (int y = 0; y < png.height(); ++y)
  {
    for (int x = 0; x < png.width(); ++x)
    {
      mismatches += qGray(png.pixel(x, y)) != labelled->GetPixel({ { x, y } });
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
  const unsigned int surfacesBefore = run.Controller.GetStageCounts().Surface;
  // Without ImageShown the surface does not come (the small phantom's takes a few milliseconds once started).
  EXPECT_FALSE(WaitUntil([&] { return run.Results.size() > 1; }, 1.0));
  EXPECT_EQ(run.Controller.GetStageCounts().Surface, surfacesBefore);
  run.Controller.ImageShown(id);
  ASSERT_TRUE(WaitUntil([&] { return run.Results.size() > 1; }));
  EXPECT_EQ(run.Results.back()->RequestId, id);
  EXPECT_TRUE(run.Results.back()->HasFullSurface());
  EXPECT_EQ(run.Controller.GetStageCounts().Surface, surfacesBefore + 1);
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
