// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "PlainBilateralDepthRelax.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <stdexcept>
#include <string>

namespace vr::test
{
namespace
{
/** R(x) = exp(-a x^2), 0 when a x^2 exceeds -ln(FLT_MIN). */
double
RangeWeight(double anisotropy, double x)
{
  static const double underflowExponent = -std::log(static_cast<double>(FLT_MIN));
  const double        exponent = anisotropy * x * x;
  return exponent > underflowExponent ? 0.0 : std::exp(-exponent);
}

/** One Jacobi pass of Eq. 1 from \a current into \a next. */
void
JacobiPass(const std::vector<double> &        current,
           std::vector<double> &              next,
           const std::vector<unsigned char> & fixed,
           std::size_t                        width,
           std::size_t                        height,
           double                             relaxation,
           double                             anisotropy)
{
  const long columns = static_cast<long>(width);
  const long rows = static_cast<long>(height);
  const long neighbourOffsets[4][2] = { { -1, 0 }, { 1, 0 }, { 0, -1 }, { 0, 1 } };
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
        const double weight = RangeWeight(anisotropy, Dp - Dq);
        omega += 1.0;
        weightedNeighbours += weight * Dq;
        weights += weight;
      }
      const double numerator = (1.0 - relaxation) * omega * Dp + relaxation * weightedNeighbours;
      const double denominator = (1.0 - relaxation) * omega + relaxation * weights;
      next[p] = denominator > 0.0 ? numerator / denominator : Dp;
    }
  }
}

void
CheckSizes(std::size_t depth, std::size_t fixed, std::size_t width, std::size_t height, const char * who)
{
  if (depth != width * height || (fixed != 0 && fixed != depth))
  {
    throw std::invalid_argument(std::string(who) + ": depth or mask size does not match width x height");
  }
}
} // namespace

std::vector<double>
PlainBilateralDepthRelax(const std::vector<float> &         depth,
                         const std::vector<unsigned char> & fixed,
                         std::size_t                        width,
                         std::size_t                        height,
                         double                             relaxation,
                         double                             anisotropy,
                         unsigned int                       iterations)
{
  CheckSizes(depth.size(), fixed.size(), width, height, "PlainBilateralDepthRelax");
  std::vector<double> current(depth.begin(), depth.end());
  std::vector<double> next(current.size());
  for (unsigned int iteration = 0; iteration < iterations; ++iteration)
  {
    JacobiPass(current, next, fixed, width, height, relaxation, anisotropy);
    current.swap(next);
  }
  return current;
}

double
PlainFixedPointResidual(const std::vector<double> &        depth,
                        const std::vector<unsigned char> & fixed,
                        std::size_t                        width,
                        std::size_t                        height,
                        double                             anisotropy)
{
  CheckSizes(depth.size(), fixed.size(), width, height, "PlainFixedPointResidual");
  // D_p - (one Jacobi pass at w = 1)_p is exactly D_p - sum R D_q / sum R, and 0 where every weight vanishes.
  std::vector<double> next(depth.size());
  JacobiPass(depth, next, fixed, width, height, 1.0, anisotropy);
  double largest = 0.0;
  for (std::size_t k = 0; k < depth.size(); ++k)
  {
    largest = std::max(largest, std::abs(depth[k] - next[k]));
  }
  return largest;
}

double
PlainRelaxEnergy(const std::vector<double> & depth, std::size_t width, std::size_t height, double anisotropy)
{
  CheckSizes(depth.size(), depth.size(), width, height, "PlainRelaxEnergy");
  auto edge = [anisotropy](double difference)
  {
    return anisotropy > 0.0 ? -std::expm1(-anisotropy * difference * difference) / (2.0 * anisotropy)
                            : 0.5 * difference * difference;
  };
  double energy = 0.0;
  for (std::size_t y = 0; y < height; ++y)
  {
    for (std::size_t x = 0; x < width; ++x)
    {
      const std::size_t k = y * width + x;
      energy += (x + 1 < width ? edge(depth[k + 1] - depth[k]) : 0.0) +
                (y + 1 < height ? edge(depth[k + width] - depth[k]) : 0.0);
    }
  }
  return energy;
}

std::vector<double>
PlainJacobiToResidual(const std::vector<float> &         depth,
                      const std::vector<unsigned char> & fixed,
                      std::size_t                        width,
                      std::size_t                        height,
                      double                             anisotropy,
                      double                             residual,
                      unsigned int                       maximumIterations,
                      unsigned int &                     iterations,
                      unsigned int                       checkEvery)
{
  CheckSizes(depth.size(), fixed.size(), width, height, "PlainJacobiToResidual");
  std::vector<double> current(depth.begin(), depth.end());
  std::vector<double> next(current.size());
  iterations = 0;
  while (iterations < maximumIterations)
  {
    if (iterations % std::max(1u, checkEvery) == 0 &&
        PlainFixedPointResidual(current, fixed, width, height, anisotropy) <= residual)
    {
      break;
    }
    JacobiPass(current, next, fixed, width, height, 1.0, anisotropy);
    current.swap(next);
    ++iterations;
  }
  return current;
}

double
ThreePixelMiddleAfterOnePass(double x, double J)
{
  const double near = std::exp(-(x / J) * (x / J));
  const double far = std::exp(-((3.0 - x) / J) * ((3.0 - x) / J));
  return 3.0 * far / (near + far);
}

double
ThreePixelMiddleFixedPoint(double J)
{
  double x = 1.0;
  for (int pass = 0; pass < 100000; ++pass)
  {
    x = ThreePixelMiddleAfterOnePass(x, J);
  }
  return x;
}
} // namespace vr::test
