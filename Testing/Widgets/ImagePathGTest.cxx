// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// One image path to the screen and to files: the PNG the viewer saves and the view on screen hold the same grey for
// every pixel under the same window (vr::WindowLevelToByte), and the QPainter views draw the bytes of that mapping.
#include "vrWidgetsTestSupport.h"
#include "vrWindowTestFixture.h"

#include "vrGreyImage.h"
#include "vrStraightenedCPRView.h"
#include "vrTestFiles.h"

#include <QDir>
#include <QDoubleSpinBox>
#include <QImage>
#include <QVTKOpenGLNativeWidget.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace
{
using namespace vr;
using namespace vr::test;

using ImagePathTest = WindowOnSmallPhantomTest;

/** Where the test leaves its pictures to look at. */
QDir
PicturesFolder()
{
  QDir folder(QStringLiteral(VR_TEST_OUTPUT_DIR));
  folder.mkpath(QStringLiteral("image-path"));
  folder.cd(QStringLiteral("image-path"));
  return folder;
}

TEST_F(ImagePathTest, TheSavedPNGIsTheViewOnScreenToTheGreyLevel)
{
  // A window whose scale (255 / 333 per HU) puts many greys between two integers, where rounding and truncation part.
  Window().GetPanel()->GetWindowSpinBox()->setValue(333.0);
  Window().GetPanel()->GetLevelSpinBox()->setValue(123.0);
  ASSERT_TRUE(WaitUntilSettled(Window()));
  CPRView * view = Window().GetCPRView();
  ASSERT_DOUBLE_EQ(view->GetWindow(), 333.0);
  ASSERT_DOUBLE_EQ(view->GetLevel(), 123.0);

  ScopedTemporaryFolder folder;
  ASSERT_TRUE(Window().SaveOutputs(QString::fromStdString(folder.Path().string())))
    << Window().GetLastError().toStdString();
  // Read by Qt, not by the writer's own library.
  const QImage saved =
    QImage(QString::fromStdString(folder.File("cpr.png"))).convertToFormat(QImage::Format_Grayscale8);
  ASSERT_FALSE(saved.isNull());
  const std::vector<float> values = NodePixels(view->GetResult()->Outputs.CPR);
  int                      dimensions[3];
  view->GetResult()->Outputs.CPR->GetImageData()->GetDimensions(dimensions);
  ASSERT_EQ(saved.width(), dimensions[0]);
  ASSERT_EQ(saved.height(), dimensions[1]);

  // Each image pixel spans more than one screen pixel (nearest interpolation), so its centre is its grey.
  const QPointF origin = view->WidgetPositionOfPixel(0.0, 0.0, false);
  ASSERT_GT(view->WidgetPositionOfPixel(1.0, 1.0, false).x() - origin.x(), 1.2);
  ASSERT_GT(view->WidgetPositionOfPixel(1.0, 1.0, false).y() - origin.y(), 1.2);
  const QImage frame = view->GetRenderWidget()->grabFramebuffer();
  frame.save(PicturesFolder().filePath(QStringLiteral("cpr-view-frame.png")));
  saved.save(PicturesFolder().filePath(QStringLiteral("cpr-saved.png")));

  int               checked = 0, different = 0, worst = 0, truncatedDifferently = 0, greys = 0;
  std::vector<bool> seen(256, false);
  for (int j = 0; j < dimensions[1]; ++j)
  {
    for (int i = 0; i < dimensions[0]; ++i)
    {
      const QPointF position = view->WidgetPositionOfPixel(i, j, false);
      const QPoint  screen(static_cast<int>(std::floor(position.x())), static_cast<int>(std::floor(position.y())));
      ASSERT_TRUE(frame.rect().contains(screen)) << "pixel (" << i << ", " << j << ") is off screen";
      const int file = qGray(saved.pixel(i, j));
      const int shown = FrameGrey(frame, position);
      different += shown != file ? 1 : 0;
      worst = std::max(worst, std::abs(shown - file));
      ++checked;
      // The test could tell a truncating view from a rounding one: how many pixels the two would draw differently.
      const double value = values[static_cast<std::size_t>(j) * dimensions[0] + i];
      const double scaled = std::clamp(255.0 * (value - (123.0 - 0.5 * 333.0)) / 333.0, 0.0, 255.0);
      truncatedDifferently += std::isfinite(value) && static_cast<int>(scaled) != file ? 1 : 0;
      greys += seen[file] ? 0 : 1;
      seen[file] = true;
    }
  }
  EXPECT_EQ(checked, dimensions[0] * dimensions[1]);
  EXPECT_EQ(different, 0) << "pixels whose grey on screen is not the saved PNG's, of " << checked << " (largest "
                          << worst << " grey levels)";
  EXPECT_GT(truncatedDifferently, checked / 10) << "the window does not tell rounding from truncation";
  EXPECT_GT(greys, 50) << "the image shows too few greys to compare";
}

TEST(ImagePathQPainter, TheStraightenedViewDrawsTheRoundedGreysOfASavedPNG)
{
  // Window 400 about level 100, by hand: -100 -> 0, 0 -> 63.75 -> 64, 100 -> 127.5 -> 128, 237 -> 214.84 -> 215,
  // 300 -> 255; truncation would give 63, 127 and 214.
  const std::vector<float> values = { -100.0f, 0.0f, 100.0f, 237.0f, 300.0f, 0.0f };
  const std::vector<int>   expected = { 0, 64, 128, 215, 255, 64 };
  auto                     image = DepthImageType::New();
  image->SetRegions(itk::ImageRegion<2>({ { 0, 0 } }, { { 3, 2 } }));
  image->Allocate();
  std::copy(values.begin(), values.end(), image->GetBufferPointer());

  const QImage        grey = GreyImage(image, 400.0, 100.0);
  StraightenedCPRView view;
  view.resize(200, 300);
  view.SetImage(image, 400.0, 100.0);
  view.SetCaption(QStringLiteral("window 400, level 100"));
  EXPECT_EQ(view.GetDisplayedImage(), grey);
  const QImage drawn = view.grab().toImage();
  drawn.save(PicturesFolder().filePath(QStringLiteral("straightened-view.png")));
  const QRectF target = view.ImageRect();
  ASSERT_GT(target.width(), 30.0);
  for (int j = 0; j < 2; ++j)
  {
    for (int i = 0; i < 3; ++i)
    {
      const int     k = j * 3 + i;
      const QPointF centre(target.left() + (i + 0.5) * target.width() / 3,
                           target.top() + (j + 0.5) * target.height() / 2);
      EXPECT_EQ(qGray(grey.pixel(i, j)), expected[k]) << "pixel " << k;
      EXPECT_EQ(qGray(drawn.pixel(centre.toPoint())), expected[k]) << "pixel " << k << " on screen";
    }
  }
}
} // namespace
