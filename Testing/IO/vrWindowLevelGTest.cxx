// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The one window/level -> grey mapping of the views and the PNG writers (vrWindowLevel.h), against values computed by
// hand: grey = round(255 (v - level + window/2) / window), clamped to [0, 255].
#include "vrWindowLevel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace
{
using vr::WindowLevelToByte;

TEST(WindowLevel, TheWindowsEdgesMapToBlackAndWhite)
{
  // Window 400 about level 100: -100 is black, 300 white, and beyond them the grey is clamped.
  EXPECT_EQ(WindowLevelToByte(-100.0, 400.0, 100.0), 0);
  EXPECT_EQ(WindowLevelToByte(300.0, 400.0, 100.0), 255);
  EXPECT_EQ(WindowLevelToByte(-1000.0, 400.0, 100.0), 0);
  EXPECT_EQ(WindowLevelToByte(5000.0, 400.0, 100.0), 255);
  // The CTA window (W 900, L 200): -250 and 650 HU.
  EXPECT_EQ(WindowLevelToByte(-250.0, 900.0, 200.0), 0);
  EXPECT_EQ(WindowLevelToByte(650.0, 900.0, 200.0), 255);
}

TEST(WindowLevel, RoundsToTheNearestGreyWhereTruncationWouldNot)
{
  // The level itself: 127.5 rounds up to 128 (truncation: 127).
  EXPECT_EQ(WindowLevelToByte(100.0, 400.0, 100.0), 128);
  // 0 HU in the CTA window: 255 * 250 / 900 = 70.83 -> 71 (truncation: 70).
  EXPECT_EQ(WindowLevelToByte(0.0, 900.0, 200.0), 71);
  // Window 255 about 127.5 is the identity before rounding: 10.6 -> 11, 10.4 -> 10, 254.6 -> 255.
  EXPECT_EQ(WindowLevelToByte(10.6, 255.0, 127.5), 11);
  EXPECT_EQ(WindowLevelToByte(10.4, 255.0, 127.5), 10);
  EXPECT_EQ(WindowLevelToByte(254.6, 255.0, 127.5), 255);
  // Just inside the edges: 0.4 of a grey above black stays black, 0.6 becomes 1; 0.6 below white becomes 254.
  EXPECT_EQ(WindowLevelToByte(0.4, 255.0, 127.5), 0);
  EXPECT_EQ(WindowLevelToByte(0.6, 255.0, 127.5), 1);
  EXPECT_EQ(WindowLevelToByte(254.4, 255.0, 127.5), 254);
}

TEST(WindowLevel, NotANumberIsBlackAndInfinitiesAreClamped)
{
  EXPECT_EQ(WindowLevelToByte(std::nan(""), 400.0, 100.0), 0);
  EXPECT_EQ(WindowLevelToByte(-std::numeric_limits<double>::infinity(), 400.0, 100.0), 0);
  EXPECT_EQ(WindowLevelToByte(std::numeric_limits<double>::infinity(), 400.0, 100.0), 255);
}

TEST(WindowLevel, TheBufferFormMapsEachValueAsTheSingleOne)
{
  const std::vector<float>         values = { -100.0f, 100.0f, 0.0f, 300.0f, std::nanf(""), 237.0f };
  const std::vector<unsigned char> expected = { 0, 128, 64 /* 63.75 */, 255, 0, 215 /* 214.84 */ };
  std::vector<unsigned char>       grey(values.size(), 7);
  vr::WindowLevelToBytes(values.data(), values.size(), 400.0, 100.0, grey.data());
  EXPECT_EQ(grey, expected);
}
} // namespace
