// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// GoogleTest main for the widget tests: a QApplication with VTK's OpenGL format, needing a display (CTest runs them
// under xvfb-run).
#include <QApplication>
#include <QSurfaceFormat>
#include <QVTKOpenGLNativeWidget.h>

#include <gtest/gtest.h>

int
main(int argc, char ** argv)
{
  ::testing::InitGoogleTest(&argc, argv);
  QSurfaceFormat::setDefaultFormat(QVTKOpenGLNativeWidget::defaultFormat());
  QApplication application(argc, argv);
  return RUN_ALL_TESTS();
}
