// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The viewer in Visibility mode (issue 38), on the small run-off phantom under Xvfb: the panel's mode switch, the
// hidden stretches drawn dashed where the tube ray caster of the tests (PlainTubeRayCaster) says a centerline lies
// behind another vessel and solid where it says not, the occlusion strip's click, View > Best view, and the readout
// that names both vessels over an overlap.
#include "vrWidgetsTestSupport.h"
#include "vrWindowTestFixture.h"

#include "PlainTubeRayCaster.h"
#include "vrCenterlineOverlay.h"
#include "vrNodeConversion.h"
#include "vrPixelReadout.h"

#include <QAction>
#include <QComboBox>
#include <QMouseEvent>
#include <QTest>

#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
using namespace vr;
using namespace vr::test;

/** The angle where the phantom's legs overlap. */
constexpr double OverlapAngle = 124.0;

class VisibilityViewerTest : public WindowOnSmallPhantomTest
{
protected:
  /** Chooses \a mode in the panel's combo box, as a user does, and waits for its image. */
  void
  ChooseMode(const char * mode)
  {
    auto * combo = Window().GetPanel()->findChild<QComboBox *>(QStringLiteral("modeCombo"));
    ASSERT_NE(combo, nullptr);
    combo->setCurrentText(QString::fromLatin1(mode));
    ASSERT_TRUE(WaitUntil([&] { return Shown().Parameters.Mode == ParseDepthMode(mode, "mode"); }));
    ASSERT_TRUE(WaitUntilSettled(Window()));
  }

  void
  TurnTo(double angle)
  {
    Window().GetPanel()->SetAngle(angle, RequestKind::Final);
    ASSERT_TRUE(WaitUntil([&] { return !Shown().IsPreview() && Shown().Outputs.View.GetAngleInDegrees() == angle; }));
    ASSERT_TRUE(WaitUntilSettled(Window()));
  }

  const ReformationResult &
  Shown()
  {
    return *Window().GetCPRView()->GetResult();
  }

  /** The smallest distance (world units of the overlay) from (\a x, \a y) to a line cell marked \a hidden. */
  double
  DistanceToOverlay(double x, double y, bool hidden)
  {
    vtkPolyData *  overlay = Window().GetCPRView()->GetCenterlineOverlay();
    vtkDataArray * marks = overlay->GetCellData()->GetArray(HiddenStretchArrayName);
    double         best = std::numeric_limits<double>::infinity();
    if (marks == nullptr)
    {
      return best;
    }
    vtkNew<vtkIdList> ids;
    for (vtkIdType cell = 0; cell < overlay->GetNumberOfCells(); ++cell)
    {
      if ((marks->GetTuple1(cell) != 0.0) != hidden)
      {
        continue;
      }
      overlay->GetCellPoints(cell, ids);
      for (vtkIdType k = 0; k + 1 < ids->GetNumberOfIds(); ++k)
      {
        double a[3];
        double b[3];
        overlay->GetPoint(ids->GetId(k), a);
        overlay->GetPoint(ids->GetId(k + 1), b);
        const double dx = b[0] - a[0];
        const double dy = b[1] - a[1];
        const double l2 = dx * dx + dy * dy;
        const double t = l2 > 0.0 ? std::clamp(((x - a[0]) * dx + (y - a[1]) * dy) / l2, 0.0, 1.0) : 0.0;
        best = std::min(best, std::hypot(x - a[0] - t * dx, y - a[1] - t * dy));
      }
    }
    return best;
  }
};
} // namespace

TEST_F(VisibilityViewerTest, ThePanelSwitchesTheDepthModeAndTheOutputsFollow)
{
  EXPECT_EQ(Shown().Parameters.Mode, itk::CPRDepthMode::Scanline);
  EXPECT_FALSE(Shown().Outputs.HiddenLabels);
  ChooseMode("visibility");
  EXPECT_TRUE(Shown().Outputs.HiddenLabels);
  EXPECT_FALSE(Shown().Outputs.BranchOcclusions.empty());
  ChooseMode("scanline");
  EXPECT_FALSE(Shown().Outputs.HiddenLabels);
  EXPECT_TRUE(Shown().Outputs.BranchOcclusions.empty());
}

TEST_F(VisibilityViewerTest, HiddenStretchesAreDashedWhereTheRayCasterSaysHiddenAndSolidWhereNot)
{
  // Pixels of about a millimetre (the fixture's 4 mm pixels are as wide as the vessels), in visibility mode.
  ReformationParameters parameters = Window().GetPanel()->GetParameters();
  parameters.ImageSize[0] = 384;
  parameters.ImageSize[1] = 768;
  parameters.Mode = itk::CPRDepthMode::Visibility;
  parameters.AngleInDegrees = OverlapAngle;
  Window().GetPanel()->SetParameters(parameters);
  Window().RequestReformation(RequestKind::Final);
  ASSERT_TRUE(WaitUntil([&] { return Shown().Outputs.View.GetSize()[0] == 384 && !Shown().IsPreview(); }));
  ASSERT_TRUE(WaitUntilSettled(Window()));
  const ReformationResult &    result = Shown();
  const itk::CenterlineTree &  tree = result.Inputs->Tree;
  const itk::CPRViewGeometry & view = result.Outputs.View;
  const double                 pixel = std::max(view.GetSpacing()[0], view.GetSpacing()[1]);
  // Whether the ray caster calls a centerline point hidden, and calls it so a pixel to each side as well (away from a
  // footprint's edge, where pixel centres decide).
  const auto robustlyHidden = [&](const itk::CenterlineTree::PointType & point, double radius, bool & hidden)
  {
    hidden = IsCenterlinePointHidden(tree, view, point, radius);
    for (const auto & shift : { view.GetU(), -view.GetU(), view.GetUp(), -view.GetUp() })
    {
      if (IsCenterlinePointHidden(tree, view, point + pixel * shift, radius) != hidden)
      {
        return false;
      }
    }
    return true;
  };
  // Every centerline point whose neighbours along the vessel (two points each way) the ray caster calls the same,
  // robustly: hidden ones lie on a dashed stretch (within a dash's gap), visible ones on a solid line.
  int hiddenChecked = 0;
  int hiddenDashed = 0;
  int visibleChecked = 0;
  int visibleSolid = 0;
  for (const auto & branch : tree.GetBranches())
  {
    for (std::size_t p = 2; p + 2 < branch.Points.size(); ++p)
    {
      bool same = true;
      bool hidden = false;
      for (std::size_t q = p - 2; same && q <= p + 2; ++q)
      {
        bool h = false;
        same = robustlyHidden(branch.Points[q], branch.Radii[q], h);
        hidden = q == p - 2 ? h : hidden;
        same = same && h == hidden;
      }
      if (!same)
      {
        continue;
      }
      const auto   at = view.ToView(branch.Points[p]);
      const auto   world = Window().GetCPRView()->WorldPositionOfPixel(at.Column, at.Row);
      const double dashed = DistanceToOverlay(world[0], world[1], true);
      const double solid = DistanceToOverlay(world[0], world[1], false);
      if (hidden)
      {
        ++hiddenChecked;
        hiddenDashed += dashed <= (HiddenDashPixels + 0.5) * pixel && solid > 1e-3 * pixel ? 1 : 0;
      }
      else
      {
        ++visibleChecked;
        visibleSolid += solid <= 1e-3 * pixel ? 1 : 0; // on the line (the overlay's points are floats)
      }
    }
  }
  std::cout << "hidden points: " << hiddenDashed << " of " << hiddenChecked
            << " on dashes; visible points: " << visibleSolid << " of " << visibleChecked << " on solid lines\n";
  ASSERT_GT(hiddenChecked, 20) << "the legs overlap at " << OverlapAngle << " degrees";
  EXPECT_GE(hiddenDashed, 0.95 * hiddenChecked);
  EXPECT_GE(visibleSolid, 0.98 * visibleChecked);
}

TEST_F(VisibilityViewerTest, TheStripShowsTheProfileAndAClickGoesToItsAngle)
{
  OcclusionStrip * strip = Window().GetOcclusionStrip();
  ASSERT_TRUE(strip->isVisible());
  ASSERT_TRUE(WaitUntil([&] { return strip->GetProfile() != nullptr; }));
  EXPECT_EQ(strip->GetProfile(), Shown().Outputs.OcclusionProfile);
  EXPECT_EQ(strip->GetCurrentAngle(), StartAngle);
  const double target = 100.0;
  const QPoint click(static_cast<int>(std::lround(strip->XOfAngle(target))), strip->height() / 2);
  EXPECT_EQ(strip->AngleAt(click.x()), 100);
  QTest::mouseClick(strip, Qt::LeftButton, Qt::NoModifier, click);
  ASSERT_TRUE(WaitUntil([&] { return Shown().Outputs.View.GetAngleInDegrees() == target && !Shown().IsPreview(); }));
  EXPECT_EQ(Window().GetPanel()->GetAngle(), target);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  EXPECT_EQ(strip->GetCurrentAngle(), target);
}

TEST_F(VisibilityViewerTest, BestViewGoesToTheProfilesMinimum)
{
  ASSERT_TRUE(WaitUntil([&] { return Window().GetOcclusionStrip()->GetProfile() != nullptr; }));
  TurnTo(OverlapAngle);
  const auto profile = Window().GetOcclusionStrip()->GetProfile();
  auto *     action = Window().findChild<QAction *>(QStringLiteral("bestView"));
  ASSERT_NE(action, nullptr);
  action->trigger();
  const double best = profile->LeastOccludedAngle();
  ASSERT_TRUE(WaitUntil([&] { return Shown().Outputs.View.GetAngleInDegrees() == best && !Shown().IsPreview(); }));
  EXPECT_EQ(Window().GetPanel()->GetAngle(), best);
  for (unsigned int angle = 0; angle < 180; ++angle)
  {
    EXPECT_GE(profile->HiddenLength[angle], profile->HiddenLength[static_cast<unsigned int>(best)]);
  }
}

TEST_F(VisibilityViewerTest, TheReadoutNamesTheVesselInFrontAndTheOneBehind)
{
  ChooseMode("visibility");
  TurnTo(OverlapAngle);
  const ReformationResult & result = Shown();
  const auto                owners = ConvertVolumeNodeToLabelImage(result.Outputs.OwnerLabels);
  const auto                hidden = ConvertVolumeNodeToLabelImage(result.Outputs.HiddenLabels);
  const auto                size = owners->GetLargestPossibleRegion().GetSize();
  int                       read = 0;
  for (unsigned int row = 0; row < size[1] && read < 5; ++row)
  {
    for (unsigned int column = 0; column < size[0] && read < 5; ++column)
    {
      const uint32_t behind = hidden->GetPixel({ { column, row } });
      const uint32_t front = owners->GetPixel({ { column, row } });
      if (behind == 0 || behind == front)
      {
        continue;
      }
      // Through the view, as hovering reads it.
      const QPointF      position = Window().GetCPRView()->WidgetPositionOfPixel(column, row, false);
      const PixelReadout readout = Window().GetCPRView()->ReadoutAt(position);
      ASSERT_EQ(readout.Column, static_cast<int>(column));
      ASSERT_EQ(readout.Row, static_cast<int>(row));
      const std::string expected = result.Inputs->BranchName(static_cast<int>(front)) + ", in front of the " +
                                   result.Inputs->BranchName(static_cast<int>(behind));
      EXPECT_NE(readout.ToText().toStdString().find(expected), std::string::npos)
        << readout.ToText().toStdString() << " should say " << expected;
      ++read;
    }
  }
  EXPECT_EQ(read, 5) << "pixels with a vessel hidden behind another";
}
