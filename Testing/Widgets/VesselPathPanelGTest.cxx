// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The viewer's single-vessel reading (docs/viewer.md, issue 21 item 6): Ctrl+click on a vessel opens the path of
// that branch; moving the cross-section moves the markers of the straightened CPR, the tree CPR and the 3D view to
// the point an independent VesselPathLogic gives; the plot's MLD is the exported table's; a left-drag rolls the
// straightened CPR. And the picture of the panel on VMTK's aorta (docs/images/vessel-path-aorta.png).
#include "vrWidgetsTestSupport.h"
#include "vrWindowTestFixture.h"

#include "vrCrossSectionView.h"
#include "vrGreyImage.h"
#include "vrLumenProfilePlot.h"
#include "vrNodeConversion.h"
#include "vrSegmentationIO.h"
#include "vrStraightenedCPRView.h"
#include "vrTestFiles.h"
#include "vrVesselPathLogic.h"
#include "vrVesselPathPanel.h"
#include "vrVolumeIO.h"

#include <QApplication>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QMouseEvent>
#include <QTest>
#include <QVTKOpenGLNativeWidget.h>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <sstream>

namespace vr::test
{
namespace
{
namespace fs = std::filesystem;

/** An independent reading of the panel's path: a VesselPathLogic of its own on the inputs' nodes. */
struct ReferencePath
{
  VesselPathLogic Logic;

  ReferencePath(const ReformationInputs & inputs, const VesselPathParameters & parameters, bool crossSections = false)
  {
    Logic.SetVolumeNode(inputs.Volume);
    Logic.SetCenterlineNode(inputs.Centerlines);
    Logic.SetCrossSectionsEnabled(crossSections);
    Logic.SetParameters(parameters);
    Logic.Update();
  }
};

/** The CPR pixel (column, row) owned by the branch with the most pixels among the tree's leaves, and its id. */
struct PickedPixel
{
  int Column{ -1 };
  int Row{ -1 };
  int Branch{ 0 };
};

PickedPixel
PixelOfALeafBranch(const ReformationResult & result)
{
  const auto &                                    tree = result.Inputs->Tree;
  std::map<int, std::vector<std::pair<int, int>>> pixels;
  const auto                                      size = result.Outputs.View.GetSize();
  for (int row = 0; row < static_cast<int>(size[1]); ++row)
  {
    for (int column = 0; column < static_cast<int>(size[0]); ++column)
    {
      const PixelReadout readout = ReadPixel(result, false, column, row);
      if (readout.Inside && readout.Branch > 0)
      {
        pixels[readout.Branch].emplace_back(column, row);
      }
    }
  }
  // The tree's topology as the path reads it: a leaf is no branch's parent.
  const std::vector<int> parents = itk::VesselPath::FindParents(tree);
  PickedPixel            best;
  std::size_t            most = 0;
  for (std::size_t i = 0; i < tree.GetBranches().size(); ++i)
  {
    const auto & branch = tree.GetBranches()[i];
    const bool   leaf = std::find(parents.begin(), parents.end(), static_cast<int>(i)) == parents.end();
    const auto & owned = pixels[branch.Id];
    if (leaf && owned.size() > most)
    {
      most = owned.size();
      // The middle one of its pixels in scan order: inside the vessel's run, away from its ends.
      const auto & middle = owned[owned.size() / 2];
      best = { middle.first, middle.second, branch.Id };
    }
  }
  return best;
}

void
SendCtrlClick(QWidget * widget, const QPointF & position)
{
  for (const auto type : { QEvent::MouseButtonPress, QEvent::MouseButtonRelease })
  {
    QMouseEvent event(type,
                      position,
                      widget->mapTo(widget->window(), position.toPoint()),
                      widget->mapToGlobal(position.toPoint()),
                      Qt::LeftButton,
                      type == QEvent::MouseButtonPress ? Qt::LeftButton : Qt::NoButton,
                      Qt::ControlModifier);
    QApplication::sendEvent(widget, &event);
  }
}

void
SendWheel(QWidget * widget, int notches)
{
  const QPointF center(0.5 * widget->width(), 0.5 * widget->height());
  QWheelEvent   event(center,
                    widget->mapToGlobal(center.toPoint()),
                    QPoint(),
                    QPoint(0, 120 * notches),
                    Qt::NoButton,
                    Qt::NoModifier,
                    Qt::NoScrollPhase,
                    false);
  QApplication::sendEvent(widget, &event);
}

itk::Point<double, 3>
RASToLPSPoint(const std::array<double, 3> & ras)
{
  itk::Point<double, 3> lps;
  lps[0] = -ras[0];
  lps[1] = -ras[1];
  lps[2] = ras[2];
  return lps;
}

/** The lumen table's rows: the values of columns \a names, NaN for empty cells. */
std::vector<std::vector<double>>
ReadTableColumns(const std::string & path, const std::vector<std::string> & names)
{
  std::ifstream                    in(path);
  std::string                      line;
  std::vector<int>                 indices;
  std::vector<std::vector<double>> rows;
  auto                             split = [](const std::string & text)
  {
    std::vector<std::string> cells;
    std::stringstream        stream(text);
    std::string              cell;
    while (std::getline(stream, cell, ','))
    {
      cells.push_back(cell);
    }
    if (!text.empty() && text.back() == ',')
    {
      cells.emplace_back();
    }
    return cells;
  };
  // The comment lines stating the grading come first (docs/lumen-measurement.md, "The table").
  while (std::getline(in, line) && line.rfind('#', 0) == 0)
  {
  }
  if (line.empty())
  {
    return rows;
  }
  const auto header = split(line);
  for (const auto & name : names)
  {
    indices.push_back(static_cast<int>(std::find(header.begin(), header.end(), name) - header.begin()));
  }
  while (std::getline(in, line))
  {
    const auto          cells = split(line);
    std::vector<double> values;
    for (const int index : indices)
    {
      const bool has = index < static_cast<int>(cells.size()) && !cells[index].empty();
      values.push_back(has ? std::stod(cells[index]) : std::numeric_limits<double>::quiet_NaN());
    }
    rows.push_back(values);
  }
  return rows;
}

class VesselPathPanelTest : public WindowOnSmallPhantomTest
{
protected:
  /** Opens the path of the leaf branch with the most CPR pixels through the window. */
  int
  OpenALeafPath()
  {
    const PickedPixel picked = PixelOfALeafBranch(*Window().GetCPRView()->GetResult());
    EXPECT_GT(picked.Branch, 0);
    EXPECT_TRUE(Window().OpenVesselPath(picked.Branch)) << Window().GetLastError().toStdString();
    // Computed on the worker: the panel shows it when it comes.
    EXPECT_TRUE(WaitUntilSettled(Window()));
    QTest::qWait(50);
    return picked.Branch;
  }

  VesselPathPanel &
  Panel()
  {
    return *Window().GetPathPanel();
  }
};
} // namespace

TEST_F(VesselPathPanelTest, CtrlClickOnAVesselOpensThePathOfThatBranch)
{
  CPRView &         view = *Window().GetCPRView();
  const auto        result = view.GetResult();
  const PickedPixel picked = PixelOfALeafBranch(*result);
  ASSERT_GT(picked.Branch, 0) << "no leaf branch owns a pixel of the CPR";
  // The owner label read independently of the view: the logic's own output at that pixel.
  ASSERT_EQ(ReadPixel(*result, false, picked.Column, picked.Row).Branch, picked.Branch);
  EXPECT_FALSE(Panel().isVisible());
  const double angleBefore = Window().GetPanel()->GetAngle();

  SendCtrlClick(view.GetRenderWidget(), view.WidgetPositionOfPixel(picked.Column, picked.Row, false));
  ASSERT_TRUE(WaitUntil([&] { return Panel().HasPath(); }, 30.0)) << Window().GetLastError().toStdString();

  const auto & chain = Panel().GetOutputs().Path.GetBranchChain();
  ASSERT_FALSE(chain.empty());
  EXPECT_EQ(chain.back(), picked.Branch) << "the path must end at the clicked branch";
  // From the tree's root: the first branch has no parent (the topology as itk::VesselPath finds it).
  const auto &           branches = result->Inputs->Tree.GetBranches();
  const std::vector<int> parents = itk::VesselPath::FindParents(result->Inputs->Tree);
  const auto             first =
    std::find_if(branches.begin(), branches.end(), [&](const auto & b) { return b.Id == chain.front(); });
  ASSERT_NE(first, branches.end());
  EXPECT_EQ(parents[static_cast<std::size_t>(first - branches.begin())], -1)
    << "the path starts at branch " << chain.front() << ", which has a parent";
  EXPECT_GE(chain.size(), 2u) << "a leaf of the run-off tree lies beyond the root";
  EXPECT_EQ(Panel().GetParameters().BranchId, picked.Branch);
  EXPECT_TRUE(Panel().isVisible());
  EXPECT_EQ(Panel().GetBranchList()->currentData().toInt(), picked.Branch);
  // A Ctrl+click is no rotation.
  EXPECT_EQ(Window().GetPanel()->GetAngle(), angleBefore);

  // A Ctrl+click off the vessels opens nothing new.
  SendCtrlClick(view.GetRenderWidget(), QPointF(2.0, 2.0));
  QTest::qWait(20);
  EXPECT_EQ(Panel().GetParameters().BranchId, picked.Branch);
}

TEST_F(VesselPathPanelTest, MovingTheCrossSectionMovesTheMarkersOfAllThreeViewsToTheSamePatientPoint)
{
  OpenALeafPath();
  ASSERT_TRUE(Panel().HasPath());
  const ReferencePath reference(*Window().GetCPRView()->GetResult()->Inputs, Panel().GetParameters());
  const auto &        view = Window().GetCPRView()->GetResult()->Outputs.View;

  std::vector<double> visited;
  auto                check = [&](const std::string & how)
  {
    SCOPED_TRACE(how);
    QTest::qWait(10);
    const double s = Panel().GetArcLength();
    visited.push_back(s);
    const itk::Point<double, 3> expected = reference.Logic.SectionAt(s).Center;

    // The 3D view's sphere (drawn in RAS).
    const auto marker3D = Window().GetThreeDView()->GetPathMarkerPosition();
    ASSERT_TRUE(marker3D.has_value());
    EXPECT_LT(RASToLPSPoint(*marker3D).EuclideanDistanceTo(expected), 1e-6);

    // The tree CPR's cross: it lies on the sampling line of the expected point (along the view direction v).
    const auto marker2D = Window().GetCPRView()->GetPathMarkerWorldPosition();
    ASSERT_TRUE(marker2D.has_value());
    const auto spacing = view.GetSpacing();
    const auto plane = view.PlanePoint((*marker2D)[0] / spacing[0], (*marker2D)[1] / spacing[1]);
    auto       offset = expected - plane;
    offset -= (offset * view.GetV()) * view.GetV();
    EXPECT_LT(offset.GetNorm(), 1e-6) << "the marker is drawn off the point's sampling line";

    // The straightened CPR's line: at the reference's row of s, whose middle column is the point.
    const double row = reference.Logic.RowOfArcLength(s);
    EXPECT_NEAR(Panel().GetStraightenedView()->GetPositionRow(), row, 1e-9);
    const auto size = reference.Logic.GetOutputs().CPR->GetLargestPossibleRegion().GetSize();
    const auto middle = reference.Logic.ComputePoint(0.5 * (size[0] - 1.0), row);
    EXPECT_LT(middle.EuclideanDistanceTo(expected), 1e-3);
    // And the cross-section view shows the section of s.
    EXPECT_EQ(static_cast<int>(Panel().GetCrossSectionView()->GetSliceIndex()), Panel().GetSectionIndex());
  };
  check("opened");
  Panel().SetSectionIndex(static_cast<int>(Panel().GetOutputs().Sections.size() / 2));
  check("the middle section");
  Panel().GetStraightenedView()->setFocus();
  for (int i = 0; i < 5; ++i)
  {
    QTest::keyClick(Panel().GetStraightenedView(), Qt::Key_Down);
  }
  check("five Down keys");
  SendWheel(Panel().GetStraightenedView(), -3);
  check("the wheel, three notches down");
  QTest::keyClick(Panel().GetStraightenedView(), Qt::Key_PageUp);
  check("Page Up");
  LumenProfilePlot * plot = Panel().GetProfilePlot();
  const double       target = 0.25 * Panel().GetOutputs().Path.GetLength();
  QTest::mouseClick(plot, Qt::LeftButton, Qt::NoModifier, plot->WidgetPoint(target, 1.0).toPoint());
  check("a click on the plot");
  EXPECT_NEAR(visited.back(), target, 2.0 * Panel().GetOutputs().SectionSpacing + 1.0);
  const double rowTarget = 0.75 * (Panel().GetOutputs().CPR->GetLargestPossibleRegion().GetSize()[1] - 1);
  const auto   at =
    QPointF(Panel().GetStraightenedView()->width() * 0.5, Panel().GetStraightenedView()->WidgetYOfRow(rowTarget));
  QTest::mouseClick(Panel().GetStraightenedView(), Qt::RightButton, Qt::NoModifier, at.toPoint());
  check("a right-click on the straightened CPR");
  // Every step moved the position: the checks above are of different points.
  for (std::size_t i = 1; i < visited.size(); ++i)
  {
    EXPECT_NE(visited[i], visited[i - 1]) << "step " << i << " did not move the cross-section";
  }
  EXPECT_NEAR(visited[2] - visited[1], 5.0 * Panel().GetOutputs().SectionSpacing, 1e-6);
}

// Every view that moves the cross-section takes the same keys and wheel (docs/viewer.md): Up/Down one section, Page
// Up/Down ten, a wheel notch one (down: towards the path's end); the cross-section view shows the section reached.
TEST_F(VesselPathPanelTest, EveryViewMovesTheCrossSectionByTheSameKeysAndWheel)
{
  OpenALeafPath();
  ASSERT_TRUE(Panel().HasPath());
  const int count = static_cast<int>(Panel().GetOutputs().Sections.size());
  ASSERT_GE(count, 30) << "the path is too short to step ten sections either way";
  const int       middle = count / 2;
  QWidget * const views[] = { Panel().GetCrossSectionView(), Panel().GetStraightenedView() };
  for (QWidget * view : views)
  {
    SCOPED_TRACE(view->metaObject()->className());
    view->setFocus();
    Panel().SetSectionIndex(middle);
    int        expected = middle;
    const auto moved = [&](const char * how, int sections)
    {
      SCOPED_TRACE(how);
      expected += sections;
      EXPECT_EQ(Panel().GetSectionIndex(), expected);
      EXPECT_EQ(static_cast<int>(Panel().GetCrossSectionView()->GetSliceIndex()), expected);
    };
    QTest::keyClick(view, Qt::Key_PageDown);
    moved("Page Down", 10);
    QTest::keyClick(view, Qt::Key_Down);
    moved("Down", 1);
    QTest::keyClick(view, Qt::Key_PageUp);
    moved("Page Up", -10);
    QTest::keyClick(view, Qt::Key_Up);
    moved("Up", -1);
    SendWheel(view, -2);
    moved("two wheel notches down", 2);
    SendWheel(view, 1);
    moved("a wheel notch up", -1);
    QTest::keyClick(view, Qt::Key_A);
    moved("a key that moves nothing", 0);
  }
  // Near the path's end, Page Down stops at the last section.
  Panel().SetSectionIndex(count - 3);
  QTest::keyClick(Panel().GetCrossSectionView(), Qt::Key_PageDown);
  EXPECT_EQ(Panel().GetSectionIndex(), count - 1);
}

TEST_F(VesselPathPanelTest, ThePlotsMinimalLumenDiameterIsTheExportedTables)
{
  OpenALeafPath();
  ASSERT_TRUE(Panel().HasPath());
  const auto & results = Panel().GetOutputs();
  ASSERT_TRUE(results.HasLumen) << "the phantom's centerlines carry radii";
  const auto marked = Panel().GetProfilePlot()->GetMarkedMinimum();
  ASSERT_TRUE(marked.has_value());

  const fs::path folder = FreshFolderForThisTest(fs::temp_directory_path(), "vr-");
  const fs::path table = folder / "lumen.csv";
  ASSERT_TRUE(Window().ExportLumenTable(QString::fromStdString(table.string())));
  const auto rows = ReadTableColumns(table.string(), { "arc_length_mm", "diameter_mm", "segment", "mld_candidate" });
  ASSERT_EQ(rows.size(), results.Lumen.Sections.size());
  // The MLD is the narrowest candidate of the headline segment (docs/lumen-measurement.md).
  ASSERT_GE(results.Stenosis.HeadlineSegment, 0);
  double minimum = std::numeric_limits<double>::infinity();
  double where = std::numeric_limits<double>::quiet_NaN();
  for (const auto & row : rows)
  {
    if (std::isfinite(row[1]) && row[1] < minimum && row[2] == results.Stenosis.HeadlineSegment + 1 && row[3] == 1.0)
    {
      minimum = row[1];
      where = row[0];
    }
  }
  // The table is written with a few decimals.
  EXPECT_NEAR(marked->y(), minimum, 1e-3);
  EXPECT_NEAR(marked->x(), where, 1e-3);
  EXPECT_DOUBLE_EQ(marked->y(), results.Stenosis.MinimalLumenDiameter);
  EXPECT_DOUBLE_EQ(marked->x(), results.Stenosis.MinimalLumenDiameterArcLength);
  EXPECT_TRUE(Panel().GetMeasurementText().contains(QString::number(results.Stenosis.MinimalLumenDiameter, 'f', 2)));

  const int images = Window().ExportVesselPathImages(QString::fromStdString(folder.string()));
  EXPECT_EQ(images, ViewerWindow::VesselPathImageNames().size());
  for (const QString & name : ViewerWindow::VesselPathImageNames())
  {
    EXPECT_FALSE(QImage(QString::fromStdString((folder / name.toStdString()).string())).isNull()) << name.toStdString();
  }
  fs::remove_all(folder);
}

TEST_F(VesselPathPanelTest, ALeftDragOnTheStraightenedCPRRollsIt)
{
  OpenALeafPath();
  ASSERT_TRUE(Panel().HasPath());
  StraightenedCPRView * view = Panel().GetStraightenedView();
  const QImage          before = view->GetDisplayedImage().copy();
  EXPECT_EQ(Panel().GetRoll(), 0.0);
  const QPoint start(view->width() / 2 - 40, view->height() / 2);
  QTest::mousePress(view, Qt::LeftButton, Qt::NoModifier, start);
  SendMouse(view, QEvent::MouseMove, start + QPointF(20.0, 3.0), Qt::NoButton, Qt::LeftButton);
  EXPECT_NEAR(Panel().GetRoll(), 20.0 * StraightenedCPRView::DegreesPerPixel, 1e-9);
  SendMouse(view, QEvent::MouseMove, start + QPointF(80.0, -5.0), Qt::NoButton, Qt::LeftButton);
  QTest::mouseRelease(view, Qt::LeftButton, Qt::NoModifier, start + QPoint(80, -5));
  const double expected = 80.0 * StraightenedCPRView::DegreesPerPixel;
  EXPECT_NEAR(Panel().GetRoll(), expected, 1e-9);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  EXPECT_NEAR(Panel().GetResult()->Parameters.RollInDegrees, expected, 1e-9);

  // The picture is the logic's CPR at that roll, computed apart, and not the one at roll 0.
  const ReferencePath reference(*Window().GetCPRView()->GetResult()->Inputs, Panel().GetParameters(), true);
  ASSERT_EQ(reference.Logic.GetParameters().RollInDegrees, expected);
  const QImage rolled = view->GetDisplayedImage();
  EXPECT_NE(rolled, before);
  const double window = Window().GetPanel()->GetWindowSpinBox()->value();
  const double level = Window().GetPanel()->GetLevelSpinBox()->value();
  EXPECT_EQ(rolled, GreyImage(reference.Logic.GetOutputs().CPR.GetPointer(), window, level));
  // The drag resamples the CPR alone; at the release the cross-section follows the roll too (v drawn upwards).
  const QImage section = Panel().GetCrossSectionView()->GetDisplayedImage();
  EXPECT_EQ(section,
            GreySlice(reference.Logic.GetOutputs().CrossSections.GetPointer(),
                      static_cast<unsigned int>(Panel().GetSectionIndex()),
                      window,
                      level)
              .mirrored(false, true));
}

TEST_F(VesselPathPanelTest, BadInputShowsAMessageNamingItAndKeepsThePathShown)
{
  QStringList errors;
  Window().SetErrorHandler([&](const QString & title, const QString & message) { errors << title + ": " + message; });
  const int branch = OpenALeafPath();
  ASSERT_TRUE(Panel().HasPath());
  const double length = Panel().GetOutputs().Path.GetLength();

  // An unknown branch: the logic's message names it; the path shown stays.
  EXPECT_TRUE(Window().OpenVesselPath(9999)) << "asked of the worker";
  ASSERT_TRUE(WaitUntilSettled(Window()));
  ASSERT_EQ(errors.size(), 1);
  std::cout << errors.back().toStdString() << "\n";
  EXPECT_TRUE(errors.back().contains(QStringLiteral("9999")));
  EXPECT_EQ(Panel().GetParameters().BranchId, branch);
  EXPECT_EQ(Panel().GetOutputs().Path.GetBranchChain().back(), branch);
  EXPECT_EQ(Panel().GetOutputs().Path.GetLength(), length);

  // A segmentation file that is not there.
  const fs::path folder = FreshFolderForThisTest(fs::temp_directory_path(), "vr-");
  const QString  missing = QString::fromStdString((folder / "missing.nii.gz").string());
  EXPECT_FALSE(Window().OpenLumenSegmentation({ missing }));
  ASSERT_EQ(errors.size(), 2);
  std::cout << errors.back().toStdString() << "\n";
  EXPECT_TRUE(errors.back().contains(missing));

  // A segmentation that misses the path (vessel voxels in one corner of the volume alone): the logic refuses it,
  // the lumen stays the radii's.
  VolumeImageType::Pointer corner = ConvertVolumeNodeToItkImage(Window().GetCPRView()->GetResult()->Inputs->Volume);
  corner->FillBuffer(0.0f);
  for (itk::IndexValueType k = 0; k < 3; ++k)
  {
    for (itk::IndexValueType j = 0; j < 3; ++j)
    {
      for (itk::IndexValueType i = 0; i < 3; ++i)
      {
        corner->SetPixel({ { i, j, k } }, 1.0f);
      }
    }
  }
  const std::string cornerPath = (folder / "corner.nii.gz").string();
  WriteVolume(corner, cornerPath);
  EXPECT_TRUE(Window().OpenLumenSegmentation({ QString::fromStdString(cornerPath) })) << "read, asked of the worker";
  ASSERT_TRUE(WaitUntilSettled(Window()));
  ASSERT_EQ(errors.size(), 3);
  std::cout << errors.back().toStdString() << "\n";
  EXPECT_TRUE(errors.back().contains(QStringLiteral("corner.nii.gz")));
  ASSERT_TRUE(Panel().HasPath());
  EXPECT_EQ(Panel().GetOutputs().Lumen.Source, itk::VesselLumenSource::CenterlineRadius);
  EXPECT_TRUE(Panel().GetOutputs().HasLumen);

  // A table of an unknown kind: nothing written.
  const fs::path table = folder / "lumen.xlsx";
  EXPECT_FALSE(Window().ExportLumenTable(QString::fromStdString(table.string())));
  ASSERT_EQ(errors.size(), 4);
  std::cout << errors.back().toStdString() << "\n";
  EXPECT_TRUE(errors.back().contains(QStringLiteral("lumen.xlsx")));
  EXPECT_FALSE(fs::exists(table));
  fs::remove_all(folder);
}

/** The panel on VMTK's aorta, its lumen measured on VMTK's level set: the picture for the docs. Written into the
 * build's folder, and into $VR_DOCS_IMAGES_DIR when set (docs/viewer.md says how). */
TEST(VesselPathPanelOnTheAorta, OpensTheLongestPathMeasuredOnTheLevelSetAndTakesItsPicture)
{
  const std::string data = AortaDataFolder();
  ASSERT_FALSE(data.empty()) << "the VMTK aorta data beside the checkout";
  ViewerWindow window;
  window.resize(1600, 1000);
  // As the viewer's own picture of the aorta (docs/viewer.md): its tree lies across S, so the up axis is automatic.
  ReformationParameters parameters = window.GetPanel()->GetParameters();
  parameters.AutomaticUp = true;
  window.GetPanel()->SetParameters(parameters);
  window.show();
  window.OpenFiles(QString::fromStdString(data + "/aorta.mha"), QString::fromStdString(data + "/aorta-centerline.vtp"));
  ASSERT_TRUE(WaitUntil([&] { return window.GetCPRView()->GetResult() != nullptr; }));
  ASSERT_TRUE(WaitUntilSettled(window));
  ASSERT_TRUE(window.OpenVesselPath(0)) << window.GetLastError().toStdString();
  ASSERT_TRUE(WaitUntilSettled(window));
  ASSERT_TRUE(window.OpenLumenSegmentation({ QString::fromStdString(data + "/aorta-final-levelset.mha") }))
    << window.GetLastError().toStdString();
  ASSERT_TRUE(WaitUntilSettled(window));
  VesselPathPanel & panel = *window.GetPathPanel();
  const auto &      results = panel.GetOutputs();
  ASSERT_TRUE(results.HasLumen);
  EXPECT_EQ(results.Lumen.Source, itk::VesselLumenSource::Segmentation);
  EXPECT_TRUE(std::isfinite(results.Stenosis.MinimalLumenDiameter));
  panel.SetArcLength(results.Stenosis.MinimalLumenDiameterArcLength);
  ASSERT_TRUE(WaitUntilSettled(window));
  QTest::qWait(300);
  std::cout << "aorta path " << results.Path.GetLength() << " mm, MLD " << results.Stenosis.MinimalLumenDiameter
            << " mm at " << results.Stenosis.MinimalLumenDiameterArcLength << " mm, reference "
            << results.Stenosis.ReferenceDiameter << " mm, " << results.Stenosis.DiameterStenosisPercent
            << " % diameter stenosis, CPR " << results.CPR->GetLargestPossibleRegion().GetSize() << ", "
            << results.Sections.size() << " sections\n";
  const fs::path output = fs::path(VR_TEST_OUTPUT_DIR) / "vessel-path-aorta.png";
  fs::create_directories(output.parent_path());
  ASSERT_EQ(window.WriteScreenshot(QString::fromStdString(output.string())), QString());
  EXPECT_FALSE(QImage(QString::fromStdString(output.string())).isNull());
  if (const char * docs = std::getenv("VR_DOCS_IMAGES_DIR"))
  {
    ASSERT_EQ(window.WriteScreenshot(QString::fromStdString((fs::path(docs) / "vessel-path-aorta.png").string())),
              QString());
  }
}
} // namespace vr::test
