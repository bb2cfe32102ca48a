// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Progressive refinement (docs/progressive-refinement.md): the preview rule of the logic layer against the full
// resolution on the phantoms and the VMTK aorta, the choice of the preview factor, and the viewer while the user
// drags: labelled previews, the logic's full-resolution CPR after the release, and a step aborting a refinement.
#include "vrWidgetsTestSupport.h"
#include "vrWindowTestFixture.h"

#include "vrProgressiveRefinement.h"
#include "vrTestFiles.h"

#include <QImage>
#include <QTest>
#include <QVTKOpenGLNativeWidget.h>

#include <vtkImageData.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <vector>

namespace
{
using namespace vr;
using namespace vr::test;

// ---------------------------------------------------------------------------------------------------------------
// The rule, by hand.

TEST(PreviewRule, PassesScaleWithTheInverseSquareOfTheFactorRoundedUpAndAtLeastOne)
{
  EXPECT_EQ(PreviewIterations(500, 1), 500);
  EXPECT_EQ(PreviewIterations(500, 2), 125);
  EXPECT_EQ(PreviewIterations(500, 4), 32); // 31.25 rounded up
  EXPECT_EQ(PreviewIterations(3, 4), 1);
  EXPECT_EQ(PreviewIterations(1, 2), 1);
  EXPECT_EQ(PreviewIterations(0, 2), 0); // no relaxation stays none
}

TEST(PreviewRule, APreviewKeepsTheCentreTheExtentAndTheSteadySolver)
{
  ReformationParameters full;
  full.AngleInDegrees = 40.0;
  full.Iterations = 500;
  const itk::CPRViewGeometry  view(full.Up,
                                  40.0,
                                  itk::CPRViewGeometry::PointType(std::array<double, 3>{ 1.0, -2.0, 3.0 }.data()),
                                  itk::Size<2>{ { 511, 1024 } },
                                  itk::CPRViewGeometry::SpacingType(std::array<double, 2>{ 0.5, 0.75 }.data()));
  const ReformationParameters preview = PreviewParameters(full, view, 4);
  EXPECT_TRUE(preview.HasCenter);
  EXPECT_EQ(preview.Center, view.GetCenter());
  EXPECT_EQ(preview.ImageSize[0], 128u); // ceil(511 / 4)
  EXPECT_EQ(preview.ImageSize[1], 256u);
  EXPECT_DOUBLE_EQ(preview.PixelSpacing[0], 2.0);
  EXPECT_DOUBLE_EQ(preview.PixelSpacing[1], 3.0);
  EXPECT_EQ(preview.Iterations, 32);
  EXPECT_DOUBLE_EQ(preview.AngleInDegrees, 40.0);

  full.Solver = itk::BilateralDepthRelaxSolver::Steady;
  EXPECT_EQ(PreviewParameters(full, view, 2).Iterations, 500) << "the steady solver's fixed point needs no scaling";
}

TEST(PreviewRule, TheFinestFactorWhoseUpdateFitsTheBudgetIsChosen)
{
  const double unknown = -1.0;
  EXPECT_EQ(ChoosePreviewFactor({ unknown, unknown, unknown }, 0.05), 1u) << "nothing measured: full resolution";
  EXPECT_EQ(ChoosePreviewFactor({ 0.030, unknown, unknown }, 0.05), 1u) << "the full update fits: no preview";
  // 176 ms at full resolution: 44 ms expected at k = 2 (a quarter of the pixels).
  EXPECT_EQ(ChoosePreviewFactor({ 0.176, unknown, unknown }, 0.05), 2u);
  EXPECT_EQ(ChoosePreviewFactor({ 0.250, unknown, unknown }, 0.05), 4u); // 62.5 ms at 2, 15.6 ms at 4
  EXPECT_EQ(ChoosePreviewFactor({ 0.250, 0.030, unknown }, 0.05), 2u) << "a measured time decides";
  EXPECT_EQ(ChoosePreviewFactor({ 0.250, 0.070, 0.020 }, 0.05), 4u);
  EXPECT_EQ(ChoosePreviewFactor({ 2.0, 0.5, 0.2 }, 0.05), 4u) << "none fits: the coarsest";
  EXPECT_EQ(ChoosePreviewFactor({ unknown, unknown, 0.004 }, 0.05), 2u) << "from a coarser measurement: 16 ms at 2";
}

// ---------------------------------------------------------------------------------------------------------------
// The preview's relaxed depth against the full resolution's.

/** Bilinear value of \a image (row-major, \a width x \a height) at continuous pixel (\a x, \a y), clamped inside. */
double
Bilinear(const std::vector<double> & image, int width, int height, double x, double y)
{
  x = std::clamp(x, 0.0, width - 1.0);
  y = std::clamp(y, 0.0, height - 1.0);
  const int    x0 = std::min(static_cast<int>(std::floor(x)), width - 2 < 0 ? 0 : width - 2);
  const int    y0 = std::min(static_cast<int>(std::floor(y)), height - 2 < 0 ? 0 : height - 2);
  const int    x1 = std::min(x0 + 1, width - 1);
  const int    y1 = std::min(y0 + 1, height - 1);
  const double fx = x - x0;
  const double fy = y - y0;
  auto         at = [&](int i, int j) { return image[static_cast<std::size_t>(j) * width + i]; };
  return (1 - fy) * ((1 - fx) * at(x0, y0) + fx * at(x1, y0)) + fy * ((1 - fx) * at(x0, y1) + fx * at(x1, y1));
}

std::vector<double>
Values(VolumeNode * node, int & width, int & height)
{
  vtkImageData * data = node->GetImageData();
  int            dimensions[3];
  data->GetDimensions(dimensions);
  width = dimensions[0];
  height = dimensions[1];
  std::vector<double> values(static_cast<std::size_t>(width) * height);
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      values[static_cast<std::size_t>(j) * width + i] = data->GetScalarComponentAsDouble(i, j, 0, 0);
    }
  }
  return values;
}

struct DepthComparison
{
  double      Median{ 0.0 };
  double      P90{ 0.0 };
  std::size_t Compared{ 0 };
  std::size_t Free{ 0 };
};

/** The preview's relaxed depth at factor \a factor, brought up to the full grid bilinearly, against the full
 * resolution's, over the free pixels (not fixed in the full result) with no jump larger than J between 4-neighbours
 * of the full relaxed depth within \a factor pixels. */
DepthComparison
ComparePreview(const ReformationInputs & inputs, const ReformationParameters & full, unsigned int factor)
{
  VesselReformationLogic logic;
  logic.SetVolumeNode(inputs.Volume);
  logic.SetCenterlineNode(inputs.Centerlines);
  logic.SetSurfaceEnabled(false);
  logic.SetParameters(full);
  const ReformationOutputs fullOutputs = logic.Update();
  std::cout << "full view " << fullOutputs.View.GetSize() << " px of " << fullOutputs.View.GetSpacing() << " mm"
            << std::endl;
  logic.SetParameters(PreviewParameters(full, fullOutputs.View, factor));
  const ReformationOutputs previewOutputs = logic.Update();
  EXPECT_EQ(previewOutputs.View.GetCenter(), fullOutputs.View.GetCenter());
  EXPECT_DOUBLE_EQ(previewOutputs.View.GetSpacing()[0], factor * fullOutputs.View.GetSpacing()[0]);

  int          width = 0, height = 0, previewWidth = 0, previewHeight = 0, maskWidth = 0, maskHeight = 0;
  const auto   depth = Values(fullOutputs.RelaxedDepth, width, height);
  const auto   mask = Values(fullOutputs.FixedMask, maskWidth, maskHeight);
  const auto   preview = Values(previewOutputs.RelaxedDepth, previewWidth, previewHeight);
  const double jump = 1.0 / std::sqrt(full.EffectiveAnisotropy());
  const int    radius = static_cast<int>(factor);

  // Pixels next to a jump larger than J: every pixel within the radius of a 4-neighbour pair that differs by more.
  std::vector<unsigned char> nearJump(depth.size(), 0);
  auto                       index = [&](int i, int j) { return static_cast<std::size_t>(j) * width + i; };
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      const bool right = i + 1 < width && !(std::abs(depth[index(i, j)] - depth[index(i + 1, j)]) <= jump);
      const bool down = j + 1 < height && !(std::abs(depth[index(i, j)] - depth[index(i, j + 1)]) <= jump);
      if (!right && !down)
      {
        continue;
      }
      for (int y = std::max(0, j - radius); y <= std::min(height - 1, j + 1 + radius); ++y)
      {
        for (int x = std::max(0, i - radius); x <= std::min(width - 1, i + 1 + radius); ++x)
        {
          nearJump[index(x, y)] = 1;
        }
      }
    }
  }
  DepthComparison     result;
  std::vector<double> differences;
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      if (mask[index(i, j)] != 0.0)
      {
        continue;
      }
      ++result.Free;
      if (nearJump[index(i, j)] != 0 || !std::isfinite(depth[index(i, j)]))
      {
        continue;
      }
      // Both grids are centred on C: full column c lies at (c - (W - 1) / 2) s mm, preview column c' at
      // (c' - (W' - 1) / 2) k s mm.
      const double x = (i - 0.5 * (width - 1)) / factor + 0.5 * (previewWidth - 1);
      const double y = (j - 0.5 * (height - 1)) / factor + 0.5 * (previewHeight - 1);
      differences.push_back(std::abs(Bilinear(preview, previewWidth, previewHeight, x, y) - depth[index(i, j)]));
    }
  }
  result.Compared = differences.size();
  if (!differences.empty())
  {
    std::sort(differences.begin(), differences.end());
    result.Median = differences[differences.size() / 2];
    result.P90 = differences[differences.size() * 9 / 10];
  }
  return result;
}

/** \param spacing the full view's pixel spacing in mm, 0 for the default (the volume's smallest spacing). */
void
ExpectPreviewsCloseToTheFullResolution(const ReformationInputs & inputs, const char * name, double spacing = 0.0)
{
  ReformationParameters full; // the defaults: a view that fits the tree, scanline depth, 500 Jacobi passes, J = 3 mm
  full.AngleInDegrees = StartAngle;
  full.Backend = RelaxBackend::CPU;
  full.PixelSpacing.Fill(spacing);
  for (const unsigned int factor : { 2U, 4U })
  {
    const DepthComparison comparison = ComparePreview(inputs, full, factor);
    EXPECT_GT(comparison.Compared, comparison.Free / 3) << name << ", k = " << factor << ": too few pixels compared";
    EXPECT_LE(comparison.Median, 1.0) << name << ", k = " << factor << ": median |preview - full| in mm";
    std::cout << name << ", k = " << factor << ": median " << comparison.Median << " mm, p90 " << comparison.P90
              << " mm over " << comparison.Compared << " of " << comparison.Free << " free pixels" << std::endl;
  }
}

TEST(PreviewDepth, TheRunOffPhantomsPreviewLiesWithinAMillimetreOfTheFullResolution)
{
  ExpectPreviewsCloseToTheFullResolution(MakePhantomInputs("runoff", 1.5), "run-off phantom");
}

TEST(PreviewDepth, TheThoracicPhantomsPreviewLiesWithinAMillimetreOfTheFullResolution)
{
  ExpectPreviewsCloseToTheFullResolution(MakePhantomInputs("thorax", 1.5), "thoracic phantom");
}

TEST(PreviewDepth, TheVMTKAortasPreviewLiesWithinAMillimetreOfTheFullResolution)
{
  const std::string data = AortaDataFolder();
  ASSERT_FALSE(data.empty()) << "the VMTK aorta data beside the checkout";
  const ReformationInputs inputs =
    MakeInputs(ReadVolumeNode(data + "/aorta.mha"), ReadCenterlineNode(data + "/aorta-centerline-branches.vtp"));
  // At the size where the viewer previews at all (516 x 206 pixels of 0.22 mm: previews at 0.44 and 0.88 mm, the
  // volume's own spacing). At the default view (130 x 52 pixels of 0.88 mm) a full update fits the frame budget, so
  // no preview is made; its previews at 1.76 and 3.5 mm would differ by more (docs/progressive-refinement.md).
  ExpectPreviewsCloseToTheFullResolution(inputs, "VMTK aorta", 0.22);
}

// ---------------------------------------------------------------------------------------------------------------
// The viewer.

class PreviewWidgetsTest : public WindowOnSmallPhantomTest
{
};

/** Amber pixels (the preview label's colour) in the lower right corner of the CPR view's frame. */
int
AmberPixelsInTheLowerRightCorner(CPRView & view)
{
  const QImage frame = view.GetRenderWidget()->grabFramebuffer();
  int          count = 0;
  for (int y = std::max(0, frame.height() - 40); y < frame.height(); ++y)
  {
    for (int x = std::max(0, frame.width() - 320); x < frame.width(); ++x)
    {
      const QColor color = frame.pixelColor(x, y);
      count += color.red() > 200 && color.green() > 140 && color.green() < 230 && color.blue() < 120 ? 1 : 0;
    }
  }
  return count;
}

TEST_F(PreviewWidgetsTest, ADragShowsLabelledPreviewsOverTheSameMillimetresAndLeavesTheLogicsFullResolutionCPR)
{
  Controller().SetPreviewFactor(2);
  CPRView *         view = Window().GetCPRView();
  const QPointF     fullCorner = view->WidgetPositionOfPixel(0.5, 0.5, false);
  std::vector<bool> labelled;
  int               previews = 0;
  int               amber = -1;
  QPointF           previewCorner;
  QObject::connect(view,
                   &CPRView::imageDisplayed,
                   view,
                   [&](std::uint64_t)
                   {
                     const auto result = view->GetResult();
                     labelled.push_back(view->GetPreviewLabel() == QStringLiteral("preview (1/2 resolution)"));
                     EXPECT_EQ(labelled.back(), result->IsPreview())
                       << "label '" << view->GetPreviewLabel().toStdString() << "' on a result at 1/"
                       << result->PreviewFactor;
                     if (result->IsPreview())
                     {
                       ++previews;
                       EXPECT_EQ(result->PreviewFactor, 2u);
                       EXPECT_EQ(result->Outputs.View.GetSize()[0], 64u); // 128 x 256 at twice the spacing
                       EXPECT_EQ(result->Outputs.View.GetSize()[1], 128u);
                       EXPECT_EQ(result->Parameters.Iterations, 50); // 200 / 2^2
                       EXPECT_EQ(result->FullView.GetSize()[0], 128u);
                       previewCorner = view->WidgetPositionOfPixel(0.0, 0.0, false);
                       amber = std::max(amber, AmberPixelsInTheLowerRightCorner(*view));
                     }
                   });
  QWidget *     target = view->GetRenderWidget();
  const QPointF start(300.0, 400.0);
  constexpr int N = 40;
  SendMouse(target, QEvent::MouseButtonPress, start, Qt::LeftButton, Qt::LeftButton);
  for (int step = 1; step <= 4; ++step)
  {
    SendMouse(target, QEvent::MouseMove, start + QPointF(N * step / 4.0, 0.0), Qt::NoButton, Qt::LeftButton);
    QTest::qWait(5);
  }
  ASSERT_TRUE(WaitUntil([&] { return previews > 0; }, 60.0));
  SendMouse(target, QEvent::MouseButtonRelease, start + QPointF(N, 0.0), Qt::LeftButton, Qt::NoButton);
  ASSERT_TRUE(WaitUntilSettled(Window()));

  // The preview lay over the full image's millimetres: its pixel (0, 0) covers full pixels 0 and 1 of either axis.
  EXPECT_NEAR(previewCorner.x(), fullCorner.x(), 1e-6);
  EXPECT_NEAR(previewCorner.y(), fullCorner.y(), 1e-6);
  EXPECT_GT(amber, 20) << "the preview label is drawn on the frame";
  EXPECT_GT(Controller().GetStatistics().Previews, 0u);

  // After the release: the logic's full-resolution CPR at the final angle, bit for bit, and no label.
  const double expected = StartAngle + CPRView::DegreesPerPixel * N;
  const auto   shown = view->GetResult();
  EXPECT_EQ(shown->Kind, RequestKind::Final);
  EXPECT_FALSE(shown->IsPreview());
  EXPECT_DOUBLE_EQ(shown->Outputs.View.GetAngleInDegrees(), expected);
  EXPECT_TRUE(view->GetPreviewLabel().isEmpty());
  EXPECT_EQ(AmberPixelsInTheLowerRightCorner(*view), 0);
  ExpectSameImage(*view, ReferenceOutputs(SmallPhantomInputs(), TestParameters(expected)).CPR);
  EXPECT_NEAR(view->WidgetPositionOfPixel(0.5, 0.5, false).x(), fullCorner.x(), 1e-6) << "the camera stayed";
}

TEST_F(PreviewWidgetsTest, APauseInADragBringsTheFullResolutionAndAStepDuringItAbortsIt)
{
  Controller().SetPreviewFactor(4);
  // A long full-resolution relaxation (the preview's is 16 times shorter).
  ReformationParameters slow = TestParameters(StartAngle);
  slow.Iterations = 20000;
  Window().GetPanel()->SetParameters(slow);
  Window().GetPanel()->SetAngle(StartAngle, RequestKind::Final);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  ASSERT_EQ(Window().GetCPRView()->GetResult()->Parameters.Iterations, 20000);

  std::vector<std::shared_ptr<const ReformationResult>> displayed;
  QObject::connect(Window().GetCPRView(),
                   &CPRView::imageDisplayed,
                   Window().GetCPRView(),
                   [&](std::uint64_t) { displayed.push_back(Window().GetCPRView()->GetResult()); });
  bool relaxing = false;
  QObject::connect(Window().GetController(),
                   &ReformationController::progressChanged,
                   Window().GetController(),
                   [&](double fraction, const QString & stage)
                   { relaxing = relaxing || (stage == QLatin1String("relax") && fraction > 0.2); });
  QWidget *               target = Window().GetCPRView()->GetRenderWidget();
  const QPointF           start(300.0, 400.0);
  const RequestStatistics before = Controller().GetStatistics();
  SendMouse(target, QEvent::MouseButtonPress, start, Qt::LeftButton, Qt::LeftButton);
  SendMouse(target, QEvent::MouseMove, start + QPointF(20.0, 0.0), Qt::NoButton, Qt::LeftButton);
  // The preview of the first step, then, the mouse held still, the full-resolution update of that angle.
  ASSERT_TRUE(WaitUntil([&] { return Controller().GetStatistics().Refinements > before.Refinements; }, 60.0));
  QTest::qWait(30); // the preview's own progress reports have been handled
  relaxing = false;
  ASSERT_TRUE(WaitUntil([&] { return relaxing; }, 60.0));
  ASSERT_FALSE(displayed.empty());
  EXPECT_TRUE(displayed.back()->IsPreview());
  EXPECT_EQ(displayed.back()->Parameters.Iterations, 1250); // 20000 / 4^2
  // Saving or exporting a preview would write a coarse stand-in: refused, nothing written.
  {
    vr::test::ScopedTemporaryFolder folder;
    QString                         refused;
    Window().SetErrorHandler([&](const QString & title, const QString &) { refused = title; });
    EXPECT_FALSE(Window().SaveOutputs(QString::fromStdString(folder.File(""))));
    EXPECT_EQ(refused, QStringLiteral("Cannot save outputs"));
    EXPECT_TRUE(folder.Entries().empty());
    Window().SetErrorHandler({});
  }
  const std::size_t shownBeforeStep = displayed.size();

  // A step while it relaxes: aborted through the logic, and the new angle's preview follows.
  SendMouse(target, QEvent::MouseMove, start + QPointF(40.0, 0.0), Qt::NoButton, Qt::LeftButton);
  ASSERT_TRUE(WaitUntil([&] { return Controller().GetStatistics().Aborted > before.Aborted; }, 60.0));
  ASSERT_TRUE(WaitUntil([&] { return displayed.size() > shownBeforeStep; }, 60.0));
  EXPECT_TRUE(displayed[shownBeforeStep]->IsPreview());
  EXPECT_DOUBLE_EQ(displayed[shownBeforeStep]->Outputs.View.GetAngleInDegrees(), StartAngle - 20.0);
  for (std::size_t index = 0; index < shownBeforeStep; ++index)
  {
    EXPECT_TRUE(displayed[index]->IsPreview()) << "the aborted full-resolution image was never shown";
  }

  SendMouse(target, QEvent::MouseButtonRelease, start + QPointF(40.0, 0.0), Qt::LeftButton, Qt::NoButton);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  const auto shown = Window().GetCPRView()->GetResult();
  EXPECT_FALSE(shown->IsPreview());
  EXPECT_EQ(shown->Parameters.Iterations, 20000);
  EXPECT_DOUBLE_EQ(shown->Outputs.View.GetAngleInDegrees(), StartAngle - 20.0);
}

TEST_F(PreviewWidgetsTest, WithPreviewsOffADragShowsOnlyFullResolutionImages)
{
  Controller().SetPreviewFactor(1);
  const RequestStatistics before = Controller().GetStatistics();
  QWidget *               target = Window().GetCPRView()->GetRenderWidget();
  const QPointF           start(300.0, 400.0);
  SendMouse(target, QEvent::MouseButtonPress, start, Qt::LeftButton, Qt::LeftButton);
  for (int step = 1; step <= 4; ++step)
  {
    SendMouse(target, QEvent::MouseMove, start + QPointF(10.0 * step, 0.0), Qt::NoButton, Qt::LeftButton);
    QTest::qWait(5);
  }
  ASSERT_TRUE(WaitUntil([&] { return Controller().IsIdle(); }));
  QTest::qWait(2 * ReformationController::RefinementDelayMilliseconds);
  SendMouse(target, QEvent::MouseButtonRelease, start + QPointF(40.0, 0.0), Qt::LeftButton, Qt::NoButton);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  const RequestStatistics after = Controller().GetStatistics();
  EXPECT_EQ(after.Previews, before.Previews);
  EXPECT_EQ(after.Refinements, before.Refinements);
  EXPECT_GT(after.Displayed, before.Displayed);
}
} // namespace
