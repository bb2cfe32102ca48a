// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The viewer window's inputs, driven as a user would under a virtual X server: long names, corrupt and hostile files
// refused with a dialog while the data stays, centerlines outside the volume, units, a segmentation.
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
    GTEST_FAIL() << "VMTK's aorta (vmtk-aorta-mra) is missing from VR_SHARED_DATA_DIR (Testing/Data by default)";
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

} // namespace
