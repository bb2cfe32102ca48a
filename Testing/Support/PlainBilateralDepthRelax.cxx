// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "PlainBilateralDepthRelax.h"

#include <cfloat>
#include <cmath>
#include <stdexcept>

namespace vr::test
{
std::vector<double>
PlainBilateralDepthRelax(const std::vector<float> &         depth,
                         const std::vector<unsigned char> & fixed,
                         std::size_t                        width,
                         std::size_t                        height,
                         double                             relaxation,
                         double                             anisotropy,
                         unsigned int                       iterations)
{
  if (depth.size() != width * height || (!fixed.empty() && fixed.size() != depth.size()))
  {
    throw std::invalid_argument("PlainBilateralDepthRelax: depth or mask size does not match width x height");
  }
  const double underflowExponent = -std::log(static_cast<double>(FLT_MIN));
  auto         R = [&](double x)
  {
    const double exponent = anisotropy * x * x;
    return exponent > underflowExponent ? 0.0 : std::exp(-exponent);
  };

  std::vector<double> current(depth.begin(), depth.end());
  std::vector<double> next(current.size());
  const long          columns = static_cast<long>(width);
  const long          rows = static_cast<long>(height);
  const long          neighbourOffsets[4][2] = { { -1, 0 }, { 1, 0 }, { 0, -1 }, { 0, 1 } };
  for (unsigned int iteration = 0; iteration < iterations; ++iteration)
  {
    for (long y = 0; y < rows; ++y)
    {
      for (long x = 0; x < columns; ++x)
      {
        const std::size_t p = static_cast<std::size_t>(y * columns + x);
        const double      Dp = current[p];
        if (!fixed.empty() && fixed[p] != 0)
        {
          next[p] = Dp;
          continue;
        }
        double omega = 0.0;
        double weightedNeighbours = 0.0;
        double weights = 0.0;
        for (const auto & offset : neighbourOffsets)
        {
          const long qx = x + offset[0];
          const long qy = y + offset[1];
          if (qx < 0 || qy < 0 || qx >= columns || qy >= rows)
          {
            continue;
          }
          const double Dq = current[static_cast<std::size_t>(qy * columns + qx)];
          const double weight = R(Dp - Dq);
          omega += 1.0;
          weightedNeighbours += weight * Dq;
          weights += weight;
        }
        const double numerator = (1.0 - relaxation) * omega * Dp + relaxation * weightedNeighbours;
        const double denominator = (1.0 - relaxation) * omega + relaxation * weights;
        next[p] = denominator > 0.0 ? numerator / denominator : Dp;
      }
    }
    current.swap(next);
  }
  return current;
}
} // namespace vr::test
