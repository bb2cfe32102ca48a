// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrWindowTestFixture_h
#define vrWindowTestFixture_h

#include "vrReformationController.h"
#include "vrWidgetsTestSupport.h"

#include <gtest/gtest.h>

#include <memory>

namespace vr::test
{
/** The angle the window tests start at, degrees. */
constexpr double StartAngle = 30.0;

/** A fixture of the widget tests: a shown viewer window on the small phantom at StartAngle, its first CPR on
 * screen. */
class WindowOnSmallPhantomTest : public ::testing::Test
{
protected:
  void
  SetUp() override
  {
    m_Window = MakeWindowOnSmallPhantom(StartAngle);
    ASSERT_TRUE(m_Window->GetCPRView()->GetResult()) << m_Window->GetLastError().toStdString();
  }

  ViewerWindow &
  Window()
  {
    return *m_Window;
  }
  ReformationController &
  Controller()
  {
    return *m_Window->GetController();
  }

  std::unique_ptr<ViewerWindow> m_Window;
};

/** The widgets' tests on that window (VesselReformationWidgets*GTest.cxx). */
class WidgetsTest : public WindowOnSmallPhantomTest
{
};
} // namespace vr::test

#endif
