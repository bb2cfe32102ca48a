// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrWindowLevel.h"

#include <algorithm>
#include <cmath>

namespace vr
{
unsigned char
WindowLevelToByte(double value, double window, double level)
{
  const double t = (value - (level - 0.5 * window)) / window;
  if (std::isnan(t))
  {
    return 0;
  }
  return static_cast<unsigned char>(std::lround(255.0 * std::min(1.0, std::max(0.0, t))));
}

void
WindowLevelToBytes(const float * values, std::size_t count, double window, double level, unsigned char * grey)
{
  for (std::size_t k = 0; k < count; ++k)
  {
    grey[k] = WindowLevelToByte(values[k], window, level);
  }
}
} // namespace vr
