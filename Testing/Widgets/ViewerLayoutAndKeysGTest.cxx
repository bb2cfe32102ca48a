// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// A viewer that never loses its image and keys that always work (issue 39, items 2-5; docs/viewer.md): a saved split
// that hid the views is reset; at 800 x 500 the CPR view keeps its width and no text lies over an image; Home puts the
// 3D camera along the view direction at several angles; each window key works with the focus in a spin box, the tree
// view and the straightened CPR view, and a text field keeps its own keys while the user types in it; status messages
// and timings have their own fields; file dialogs start in the data's folder; the fold warning offers its width
// through the width setting. Screenshots at 800 x 500 and 1920 x 1080 go to viewer-output/ for a person to look at.
#include "vrWidgetsTestSupport.h"
#include "vrWindowTestFixture.h"

#include "vrCenterlineIO.h"
#include "vrCrossSectionView.h"
#include "vrLumenProfilePlot.h"
#include "vrNodeConversion.h"
#include "vrStraightenedCPRView.h"
#include "vrTestFiles.h"
#include "vrVesselPathPanel.h"
#include "vrVesselPathReport.h"
#include "vrVesselPathSettings.h"
#include "vrViewerLayout.h"
#include "vrViewerStatusBar.h"
#include "vrVolumeIO.h"
#include "vrWindowKeyPolicy.h"

#include <QAction>
#include <QApplication>
#include <QCheckBox>
#include <QDataStream>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QRegularExpression>
#include <QSplitter>
#include <QStatusBar>
#include <QTabWidget>
#include <QTest>
#include <QTextBrowser>
#include <QVTKOpenGLNativeWidget.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>

namespace vr::test
{
namespace
{
namespace fs = std::filesystem;

QSplitter *
MainSplitter(ViewerWindow & window)
{
  // The splitter that holds the CPR view's part of the window (the view sits in a column with the occlusion strip).
  QWidget * widget = window.GetCPRView();
  while (widget != nullptr && qobject_cast<QSplitter *>(widget->parentWidget()) == nullptr)
  {
    widget = widget->parentWidget();
  }
  return widget != nullptr ? qobject_cast<QSplitter *>(widget->parentWidget()) : nullptr;
}

/** A split as QSplitter::saveState writes it, with \a sizes. */
QByteArray
SplitterState(const QList<int> & sizes)
{
  QByteArray  state;
  QDataStream stream(&state, QIODevice::WriteOnly);
  stream << qint32(0xff) << qint32(0) << sizes << true << qint32(5) << true << qint32(Qt::Horizontal) << false;
  return state;
}

/** The rectangle of \a widget in \a window's coordinates. */
QRect
InWindow(const QWidget * widget, const QWidget * window)
{
  return QRect(widget->mapTo(window, QPoint(0, 0)), widget->size());
}

double
DegreesBetween(const std::array<double, 3> & a, const std::array<double, 3> & b)
{
  const double dot = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  const double norms = std::sqrt((a[0] * a[0] + a[1] * a[1] + a[2] * a[2]) * (b[0] * b[0] + b[1] * b[1] + b[2] * b[2]));
  return std::acos(std::clamp(dot / norms, -1.0, 1.0)) * 180.0 / M_PI;
}

std::string
OutputFolder()
{
  const fs::path folder = fs::path(VR_TEST_OUTPUT_DIR) / "layout";
  fs::create_directories(folder);
  return folder.string();
}

/** Presses \a key with \a modifiers as a user does: to the focused widget of the active window (shortcuts first). */
void
Press(QWidget * focus, int key, Qt::KeyboardModifiers modifiers = Qt::NoModifier)
{
  QApplication::setActiveWindow(focus->window());
  focus->setFocus();
  QTest::keyClick(focus, static_cast<Qt::Key>(key), modifiers);
}

class ViewerLayoutTest : public WindowOnSmallPhantomTest
{
protected:
  /** Opens the longest path and waits for the panel. */
  void
  OpenPath()
  {
    ASSERT_TRUE(Window().OpenVesselPath(0)) << Window().GetLastError().toStdString();
    ASSERT_TRUE(WaitUntilSettled(Window()));
  }
};

TEST(ViewerLayout, FitGivesWayInTheStatedOrder)
{
  const QList<int> minimum = {
    340, ViewerLayout::MinimumCPRWidth, ViewerLayout::MinimumThreeDWidth, ViewerLayout::MinimumPathPanelWidth
  };
  const QList<bool> all = { true, true, true, true };
  const auto        sum = [](const QList<int> & sizes) { return std::accumulate(sizes.begin(), sizes.end(), 0); };
  // Wide: everything at least its minimum, the room used.
  const QList<int> wide = ViewerLayout::Fit({ 340, 600, 400, 600 }, minimum, all, 1900);
  EXPECT_EQ(sum(wide), 1900);
  EXPECT_GE(wide[ViewerLayout::ThreeD], ViewerLayout::MinimumThreeDWidth);
  // 800 pixels with the path panel: the 3D view goes first, then the module panel; the CPR view and the path
  // panel keep their minimums.
  const QList<int> narrow = ViewerLayout::Fit({ 340, 600, 400, 600 }, minimum, all, 785);
  EXPECT_EQ(sum(narrow), 785);
  EXPECT_EQ(narrow[ViewerLayout::ThreeD], 0);
  EXPECT_EQ(narrow[ViewerLayout::Panel], 0);
  EXPECT_GE(narrow[ViewerLayout::CPR], ViewerLayout::MinimumCPRWidth);
  EXPECT_GE(narrow[ViewerLayout::Path], ViewerLayout::MinimumPathPanelWidth);
  // 1000 pixels: the 3D view is gone, the module panel stays.
  const QList<int> middle = ViewerLayout::Fit({ 340, 600, 400, 600 }, minimum, all, 985);
  EXPECT_EQ(middle[ViewerLayout::ThreeD], 0);
  EXPECT_EQ(middle[ViewerLayout::Panel], 340);
  EXPECT_EQ(sum(middle), 985);
  // Without the path panel, 800 pixels hold the panel, the CPR view and the 3D view.
  const QList<int> three = ViewerLayout::Fit({ 340, 600, 400, 0 }, minimum, { true, true, true, false }, 790);
  EXPECT_EQ(three[ViewerLayout::Path], 0);
  EXPECT_EQ(sum(three), 790);
  EXPECT_GE(three[ViewerLayout::CPR], ViewerLayout::MinimumCPRWidth);
  EXPECT_GE(three[ViewerLayout::ThreeD], ViewerLayout::MinimumThreeDWidth);
  // QSplitter's own state is what the layout reads back.
  QSplitter splitter;
  for (int k = 0; k < 4; ++k)
  {
    splitter.addWidget(new QWidget);
  }
  splitter.resize(1000, 300);
  splitter.setSizes({ 100, 400, 200, 285 });
  EXPECT_EQ(ViewerLayout::SavedSizes(splitter.saveState()), (QList<int>{ 100, 400, 200, 285 }));
  EXPECT_TRUE(ViewerLayout::SavedSizes(QByteArray("not a splitter")).isEmpty());
}

TEST(ViewerLayoutRestart, ASavedSplitThatHidTheViewsIsResetAndAGoodOneKept)
{
  ScopedTemporaryFolder folder;
  const QString         ini = QString::fromStdString(folder.File("viewer.ini"));
  {
    ViewerSettings settings(ini);
    settings.SetValue(QStringLiteral("window/splitter"), SplitterState({ 323, 0, 0, -1 }));
    settings.Sync();
  }
  QList<int> closed;
  for (const bool second : { false, true })
  {
    ViewerWindow window;
    window.UseSettings(std::make_shared<ViewerSettings>(ini));
    window.resize(1280, 800);
    window.show();
    window.GetController()->LoadInputs([] { return SmallPhantomInputs(); }, QStringLiteral("the small phantom"));
    ASSERT_TRUE(WaitUntil([&] { return window.GetCPRView()->GetResult() != nullptr; }));
    ASSERT_TRUE(WaitUntilSettled(window));
    const QList<int> sizes = MainSplitter(window)->sizes();
    SCOPED_TRACE(second ? "the second start, on the first one's saved split" : "the first start, on [323, 0, 0, -1]");
    EXPECT_GE(sizes[ViewerLayout::CPR], ViewerLayout::MinimumCPRWidth);
    EXPECT_GE(sizes[ViewerLayout::ThreeD], ViewerLayout::MinimumThreeDWidth);
    EXPECT_TRUE(window.GetCPRView()->isVisible());
    EXPECT_TRUE(window.GetThreeDView()->isVisible());
    EXPECT_GE(window.GetCPRView()->width(), ViewerLayout::MinimumCPRWidth);
    if (second)
    {
      // The first start's split, saved at its close, is kept (same window size).
      for (int k = 0; k < 3; ++k)
      {
        EXPECT_NEAR(sizes[k], closed[k], 2) << "part " << k;
      }
    }
    // View > Reset layout brings a collapsed 3D view back.
    MainSplitter(window)->setSizes({ sizes[0], sizes[1] + sizes[2], 0, 0 });
    window.findChild<QAction *>(QStringLiteral("resetLayout"))->trigger();
    EXPECT_GE(MainSplitter(window)->sizes()[ViewerLayout::ThreeD], ViewerLayout::MinimumThreeDWidth);
    if (!second)
    {
      // A split of the user's own (the module panel wider), which the second start must keep.
      const QList<int> now = MainSplitter(window)->sizes();
      MainSplitter(window)->setSizes({ now[0] + 60, now[1] - 60, now[2], now[3] });
    }
    closed = MainSplitter(window)->sizes();
    window.close(); // saves the split for the second start
  }
}

TEST_F(ViewerLayoutTest, At800x500TheCPRViewKeepsItsWidthAndNoTextLiesOverAnImage)
{
  for (const QSize size : { QSize(800, 500), QSize(1920, 1080) })
  {
    SCOPED_TRACE(std::to_string(size.width()) + " x " + std::to_string(size.height()));
    Window().resize(size);
    OpenPath();
    // The window really is that size once laid out (a minimum width beyond it would have widened it).
    ASSERT_TRUE(WaitUntil(
      [&]
      {
        QApplication::processEvents();
        return Window().size() == size;
      },
      10.0))
      << Window().width() << " x " << Window().height();
    EXPECT_LE(Window().minimumSizeHint().width(), size.width());
    EXPECT_GE(Window().GetCPRView()->width(), ViewerLayout::MinimumCPRWidth);
    EXPECT_GE(Window().GetCPRView()->height(), 150);
    // The CPR view's upper annotations (angle, up, window; size, spacing) side by side, neither over the other.
    ASSERT_TRUE(WaitUntilSettled(Window()));
    const auto corners = Window().GetCPRView()->GetCornerTextBoxes();
    EXPECT_LT(corners[0][1], corners[1][0]) << "the upper left text ends at x = " << corners[0][1]
                                            << " px, the upper right one starts at x = " << corners[1][0] << " px";
    EXPECT_GT(corners[1][1] - corners[1][0], 40.0) << "the upper right text is drawn";
    VesselPathPanel * panel = Window().GetPathPanel();
    ASSERT_TRUE(panel->isVisible());
    // The panel gets at least what its parts need, so its layout never stacks them over each other.
    EXPECT_GE(panel->width(), panel->minimumSizeHint().width());
    EXPECT_GE(panel->height(), panel->minimumSizeHint().height());
    // The images and the report (and the settings) each in a rectangle of their own.
    const QWidget * parts[] = { panel->GetStraightenedView(),
                                panel->GetCrossSectionView(),
                                panel->GetProfilePlot(),
                                panel->GetTabs(),
                                Window().GetCPRView() };
    for (const QWidget * a : parts)
    {
      EXPECT_TRUE(a->isVisible()) << a->metaObject()->className();
      EXPECT_GE(a->width(), a->minimumWidth()) << a->metaObject()->className();
      EXPECT_GE(a->height(), a->minimumHeight()) << a->metaObject()->className();
      for (const QWidget * b : parts)
      {
        if (a != b)
        {
          EXPECT_FALSE(InWindow(a, &Window()).intersects(InWindow(b, &Window())))
            << a->metaObject()->className() << " over " << b->metaObject()->className();
        }
      }
    }
    // The report's text is drawn in its own scrolling area: its document fits its width (no text beyond the area).
    QTextBrowser * report = panel->GetReportView();
    EXPECT_LE(report->document()->idealWidth(), report->viewport()->width() + 1.0);
    EXPECT_FALSE(report->toPlainText().isEmpty());
    // The status bar's fields side by side.
    auto * status = qobject_cast<ViewerStatusBar *>(Window().statusBar());
    ASSERT_NE(status, nullptr);
    EXPECT_FALSE(
      InWindow(status->GetMessageField(), &Window()).intersects(InWindow(status->GetTimesField(), &Window())));
    const QString name = QStringLiteral("%1/viewer-%2x%3.png")
                           .arg(QString::fromStdString(OutputFolder()))
                           .arg(size.width())
                           .arg(size.height());
    EXPECT_TRUE(WriteWidgetPNG(&Window(), name).isEmpty());
  }
}

// A fresh start at 800 x 500 gives the CPR view its minimum width (240 px): the upper left annotation's widest line
// and the upper right block no longer fit side by side at 14 points, and the font shrinks until they do.
TEST_F(ViewerLayoutTest, TheCPRViewsUpperAnnotationsStayApartAtItsNarrowest)
{
  Window().resize(QSize(800, 500));
  QSplitter * splitter = MainSplitter(Window());
  ASSERT_NE(splitter, nullptr);
  QList<int> sizes = splitter->sizes();
  const int  spare = sizes[ViewerLayout::CPR] - ViewerLayout::MinimumCPRWidth;
  sizes[ViewerLayout::CPR] -= spare;
  sizes[ViewerLayout::Panel] += spare;
  splitter->setSizes(sizes);
  ASSERT_TRUE(WaitUntil(
    [&]
    {
      QApplication::processEvents();
      return Window().GetCPRView()->width() == ViewerLayout::MinimumCPRWidth;
    },
    10.0))
    << "the CPR view is " << Window().GetCPRView()->width() << " px wide";
  Window().GetPanel()->SetAngle(30.0, RequestKind::Final); // a new annotation at that width
  ASSERT_TRUE(WaitUntilSettled(Window()));
  const auto corners = Window().GetCPRView()->GetCornerTextBoxes();
  EXPECT_LT(corners[0][1], corners[1][0]) << "the upper left text ends at x = " << corners[0][1]
                                          << " px, the upper right one starts at x = " << corners[1][0] << " px";
  EXPECT_GT(corners[1][1] - corners[1][0], 40.0) << "the upper right text is drawn";
  EXPECT_GT(corners[0][3] - corners[0][2], 30.0) << "three lines of the upper left text, still readable";
  // The captions under the images (two or three lines of filter settings) stay inside the view, apart, and readable,
  // in each comparison.
  CPRView *    cpr = Window().GetCPRView();
  QWidget *    view = cpr->GetRenderWidget();
  const double viewWidth = view->width() * view->devicePixelRatioF();
  for (const auto comparison : { CPRComparison::Filtered, CPRComparison::Split, CPRComparison::SideBySide })
  {
    SCOPED_TRACE("comparison " + std::to_string(static_cast<int>(comparison)));
    cpr->SetComparison(comparison);
    QApplication::processEvents();
    const auto caption = cpr->GetCaptionBox(false);
    EXPECT_LE(caption[1], viewWidth) << "the caption runs from x = " << caption[0] << " to " << caption[1]
                                     << " px in a view " << viewWidth << " px wide";
    EXPECT_GE(caption[0], 0.0) << "the caption starts left of the view";
    // Two lines at MinimumCaptionFontSize (10 points) are 19 px high, one line 9 or 10.
    EXPECT_GT(caption[3] - caption[2], 17.0) << "two lines of the caption or more";
    EXPECT_GE(caption[2], 0.0) << "the caption's last line is below the view";
    if (comparison == CPRComparison::SideBySide)
    {
      const auto unfiltered = cpr->GetCaptionBox(true);
      EXPECT_GE(unfiltered[0], 0.0) << "the unfiltered caption starts left of the view";
      EXPECT_LT(unfiltered[1], caption[0]) << "the unfiltered caption ends at x = " << unfiltered[1]
                                           << " px, the filtered one starts at x = " << caption[0] << " px";
    }
  }
}

// Maximising the window refits the image, and the captions with it, at the new size: the caption is where and as large
// as a fresh fit at that size puts it. (The render window takes the widget's new size after the view sees the resize;
// fitted at that moment, the caption kept the small window's font, 10 points, away from the image's left edge.)
TEST_F(ViewerLayoutTest, AfterTheWindowGrowsTheCaptionIsWhereAFreshFitPutsIt)
{
  Window().resize(QSize(800, 500));
  ASSERT_TRUE(WaitUntilSettled(Window()));
  CPRView * cpr = Window().GetCPRView();
  QWidget * view = cpr->GetRenderWidget();
  const int narrow = view->width();
  Window().resize(QSize(1800, 1000));
  ASSERT_TRUE(WaitUntil(
    [&]
    {
      QApplication::processEvents();
      return view->width() > narrow + 400;
    },
    10.0));
  for (int k = 0; k < 10; ++k)
  {
    QApplication::processEvents();
  }
  const auto afterResize = cpr->GetCaptionBox(false);
  cpr->FitImage();
  const auto fresh = cpr->GetCaptionBox(false);
  for (std::size_t k = 0; k < 4; ++k)
  {
    EXPECT_NEAR(afterResize[k], fresh[k], 1.0)
      << "caption box [x0, x1, y0, y1] coordinate " << k << ": " << afterResize[k] << " after the resize, " << fresh[k]
      << " when fitted afresh";
  }
}

TEST_F(ViewerLayoutTest, HomePutsThe3DCameraAlongTheViewDirectionAtAnyAngle)
{
  // ResetCamera looks along v from 30 degrees aside and 10 above: cos(angle) = cos 30 cos 10.
  const double aside = std::acos(std::cos(30.0 * M_PI / 180.0) * std::cos(10.0 * M_PI / 180.0)) * 180.0 / M_PI;
  for (const double angle : { 45.0, 135.0, -135.0, 300.0 })
  {
    SCOPED_TRACE("from " + std::to_string(angle) + " degrees");
    Window().GetPanel()->SetAngle(angle, RequestKind::Final);
    ASSERT_TRUE(WaitUntilSettled(Window()));
    Press(Window().GetCPRView()->GetRenderWidget(), Qt::Key_Home);
    // At once, before the new image: the camera already looks along the view at 0 degrees.
    const auto early = Window().GetThreeDView()->GetCameraDirection();
    ASSERT_TRUE(WaitUntilSettled(Window()));
    EXPECT_EQ(Window().GetPanel()->GetAngle(), 0.0);
    const auto & view = Window().GetCPRView()->GetResult()->Outputs.View;
    ASSERT_EQ(view.GetAngleInDegrees(), 0.0);
    const auto                  v = view.GetV();
    const std::array<double, 3> vRAS = { -v[0], -v[1], v[2] };
    const auto                  camera = Window().GetThreeDView()->GetCameraDirection();
    EXPECT_NEAR(DegreesBetween(camera, vRAS), aside, 1.0);
    EXPECT_NEAR(DegreesBetween(early, vRAS), aside, 1.0);
  }
}

TEST_F(ViewerLayoutTest, EachWindowKeyWorksWithTheFocusInASpinBoxTheTreeViewAndTheCPRView)
{
  OpenPath();
  VesselPathPanel * panel = Window().GetPathPanel();
  const int         sections = static_cast<int>(panel->GetOutputs().Sections.size());
  ASSERT_GT(sections, 30);
  QWidget *    targets[] = { Window().GetPanel()->GetAngleSpinBox(),
                             Window().GetCPRView()->GetRenderWidget(),
                             panel->GetStraightenedView(),
                             panel->GetSettings()->GetWidthSpinBox() };
  const char * names[] = { "the angle spin box", "the tree view", "the straightened CPR", "the width spin box" };
  for (int t = 0; t < 4; ++t)
  {
    SCOPED_TRACE(names[t]);
    QWidget * target = targets[t];
    // Turn: Right 1 degree, Shift+Left 10 back.
    const double angle = Window().GetPanel()->GetAngle();
    Press(target, Qt::Key_Right);
    ASSERT_TRUE(WaitUntilSettled(Window()));
    EXPECT_DOUBLE_EQ(Window().GetPanel()->GetAngle(), WrapAngle(angle + 1.0));
    Press(target, Qt::Key_Left, Qt::ShiftModifier);
    ASSERT_TRUE(WaitUntilSettled(Window()));
    EXPECT_DOUBLE_EQ(Window().GetPanel()->GetAngle(), WrapAngle(angle - 9.0));
    // Sections: Down one, Page Down ten, Up one, Page Up ten.
    panel->SetSectionIndex(sections / 2);
    Press(target, Qt::Key_Down);
    EXPECT_EQ(panel->GetSectionIndex(), sections / 2 + 1);
    Press(target, Qt::Key_PageDown);
    EXPECT_EQ(panel->GetSectionIndex(), sections / 2 + 11);
    Press(target, Qt::Key_Up);
    Press(target, Qt::Key_PageUp);
    EXPECT_EQ(panel->GetSectionIndex(), sections / 2);
    // Presets: Ctrl+2 bone, Ctrl+1 CTA.
    Press(target, Qt::Key_2, Qt::ControlModifier);
    EXPECT_EQ(Window().GetPanel()->GetPresetName(), QStringLiteral("Bone"));
    Press(target, Qt::Key_1, Qt::ControlModifier);
    EXPECT_EQ(Window().GetPanel()->GetPresetName(), QStringLiteral("CTA"));
    ASSERT_TRUE(WaitUntilSettled(Window()));
  }

  // Undo: Ctrl+Z goes to the window's Undo open from the spin box, the tree view and the straightened CPR.
  ScopedTemporaryFolder folder;
  const std::string     volume = folder.File("phantom.nrrd");
  const std::string     centerlines = folder.File("phantom.vtp");
  WriteVolume(ConvertVolumeNodeToItkImage(SmallPhantomInputs().Volume), volume);
  WriteCenterlines(SmallPhantomInputs().Tree, centerlines);
  for (int t = 0; t < 3; ++t)
  {
    SCOPED_TRACE(names[t]);
    const auto before = Controller().GetInputs();
    Window().OpenFiles(QString::fromStdString(volume), QString::fromStdString(centerlines));
    ASSERT_TRUE(WaitUntil([&] { return Controller().GetInputs() != before; }));
    ASSERT_TRUE(WaitUntilSettled(Window()));
    ASSERT_TRUE(Window().CanUndoOpen());
    if (targets[t] == panel->GetStraightenedView())
    {
      OpenPath(); // new inputs closed the path: the straightened CPR shows again
    }
    const auto opened = Controller().GetInputs();
    Press(targets[t], Qt::Key_Z, Qt::ControlModifier);
    // Undo loads a copy of the earlier inputs: the same volume node again.
    ASSERT_TRUE(WaitUntil([&] { return Controller().GetInputs() != opened; }));
    EXPECT_EQ(Controller().GetInputs()->Volume, before->Volume);
    ASSERT_TRUE(WaitUntilSettled(Window()));
  }
}

TEST_F(ViewerLayoutTest, ATextFieldKeepsItsKeysWhileTheUserTypesInIt)
{
  QDoubleSpinBox * box = Window().GetPanel()->GetAngleSpinBox();
  auto *           policy = Window().findChild<WindowKeyPolicy *>();
  ASSERT_NE(policy, nullptr);
  const double angle = Window().GetPanel()->GetAngle();
  Press(box, Qt::Key_End);
  QTest::keyClick(box, Qt::Key_Backspace);
  EXPECT_EQ(policy->GetTypingField(), box);
  // Left moves the cursor in the text, Ctrl+Z undoes the typing: neither turns the view nor undoes an open.
  const auto inputs = Controller().GetInputs();
  QTest::keyClick(box, Qt::Key_Left);
  QTest::keyClick(box, Qt::Key_Z, Qt::ControlModifier);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  EXPECT_DOUBLE_EQ(Window().GetPanel()->GetAngle(), angle);
  EXPECT_EQ(Controller().GetInputs(), inputs);
  // Enter ends the typing: the keys are the window's again.
  QTest::keyClick(box, Qt::Key_Return);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  EXPECT_EQ(policy->GetTypingField(), nullptr);
  const double typed = Window().GetPanel()->GetAngle();
  QTest::keyClick(box, Qt::Key_Right);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  EXPECT_DOUBLE_EQ(Window().GetPanel()->GetAngle(), WrapAngle(typed + 1.0));
}

TEST_F(ViewerLayoutTest, StatusMessagesAndTimesHaveTheirOwnFields)
{
  auto * status = qobject_cast<ViewerStatusBar *>(Window().statusBar());
  ASSERT_NE(status, nullptr);
  const QString times = status->GetTimesField()->text();
  ASSERT_FALSE(times.isEmpty());
  const QString message = QStringLiteral("Relaxation on cpu: a message long enough to run into the timing text if it "
                                         "were drawn across the status bar, as QStatusBar draws its messages");
  status->showMessage(message, 60000);
  QApplication::processEvents();
  EXPECT_EQ(status->GetMessageField()->text(), message);
  EXPECT_EQ(status->GetMessageField()->toolTip(), message);
  EXPECT_EQ(status->GetTimesField()->text(), times);
  EXPECT_TRUE(status->GetTimesField()->isVisible());
  EXPECT_TRUE(status->GetReadoutField()->isVisible()) << "a message hides no field";
  const QRect messageField = InWindow(status->GetMessageField(), &Window());
  EXPECT_FALSE(messageField.intersects(InWindow(status->GetTimesField(), &Window())));
  EXPECT_FALSE(messageField.intersects(InWindow(status->GetReadoutField(), &Window())));
  status->clearMessage();
  EXPECT_TRUE(status->GetMessageField()->text().isEmpty());
}

TEST_F(ViewerLayoutTest, FileDialogsStartInTheDataFolder)
{
  ScopedTemporaryFolder folder;
  const std::string     volume = folder.File("ct.nrrd");
  const std::string     centerlines = folder.File("ct.vtp");
  WriteVolume(ConvertVolumeNodeToItkImage(SmallPhantomInputs().Volume), volume);
  WriteCenterlines(SmallPhantomInputs().Tree, centerlines);
  const auto before = Controller().GetInputs();
  Window().OpenFiles(QString::fromStdString(volume), QString::fromStdString(centerlines));
  ASSERT_TRUE(WaitUntil([&] { return Controller().GetInputs() != before; }));
  EXPECT_EQ(fs::canonical(Window().StartFolder().toStdString()), fs::canonical(fs::path(volume).parent_path()));
}

TEST_F(ViewerLayoutTest, TheFoldWarningOffersItsWidthThroughTheWidthSetting)
{
  OpenPath();
  VesselPathPanel * panel = Window().GetPathPanel();
  // A width far beyond the path's radius of curvature: it folds.
  panel->SetWidth(200.0);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  const VesselPathOutputs folded = panel->GetOutputs();
  ASSERT_GT(folded.FoldedPixels, 0u);
  const QString                 html = panel->GetReportView()->toHtml();
  const QRegularExpressionMatch link = QRegularExpression(QStringLiteral("href=\"(vr:width=([0-9.]+))\"")).match(html);
  ASSERT_TRUE(link.hasMatch()) << html.toStdString();
  const double offered = link.captured(2).toDouble();
  EXPECT_LE(offered, 2.0 * folded.FoldFreeHalfWidth + 1e-9);
  emit panel->GetReportView()->anchorClicked(QUrl(link.captured(1)));
  ASSERT_TRUE(WaitUntilSettled(Window()));
  EXPECT_DOUBLE_EQ(panel->GetSettings()->GetWidthSpinBox()->value(), offered);
  EXPECT_DOUBLE_EQ(panel->GetParameters().Width, offered);
  EXPECT_EQ(panel->GetOutputs().FoldedPixels, 0u);
  // The settings reach the logic: a range cuts the path, and a bad one is refused with the path kept.
  panel->GetSettings()->GetRangeCheckBox()->setChecked(true);
  panel->GetSettings()->GetRangeStartSpinBox()->setValue(10.0);
  panel->GetSettings()->GetRangeEndSpinBox()->setValue(60.0);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  EXPECT_NEAR(panel->GetOutputs().Path.GetLength(), 50.0, 1e-6);
  QLineEdit * points = panel->GetSettings()->GetReferencePointsField();
  points->setText(QStringLiteral("5, x"));
  points->setModified(true);
  emit points->editingFinished();
  EXPECT_TRUE(panel->GetLastError().contains(QStringLiteral("not a number"))) << panel->GetLastError().toStdString();
  EXPECT_TRUE(panel->GetParameters().ReferencePoints.empty());
}
} // namespace
} // namespace vr::test
