// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkPhantomRendering.h"

namespace itk::detail
{
CenterlineBranch
SampleCatmullRomBranch(int id, const std::vector<PhantomPoint> & knots, const std::vector<double> & radii, double step)
{
  CenterlineBranch branch;
  branch.Id = id;
  const std::size_t spans = knots.size() - 1;
  for (std::size_t s = 0; s < spans; ++s)
  {
    const PhantomPoint & p0 = knots[s == 0 ? 0 : s - 1];
    const PhantomPoint & p1 = knots[s];
    const PhantomPoint & p2 = knots[s + 1];
    const PhantomPoint & p3 = knots[std::min(s + 2, spans)];
    const int            samples = std::max(2, static_cast<int>(std::ceil(p1.EuclideanDistanceTo(p2) / step)));
    for (int k = 0; k < samples; ++k)
    {
      const double t = static_cast<double>(k) / samples;
      const double t2 = t * t;
      const double t3 = t2 * t;
      PhantomPoint point;
      for (unsigned int axis = 0; axis < 3; ++axis)
      {
        point[axis] = 0.5 * (2.0 * p1[axis] + (-p0[axis] + p2[axis]) * t +
                             (2.0 * p0[axis] - 5.0 * p1[axis] + 4.0 * p2[axis] - p3[axis]) * t2 +
                             (-p0[axis] + 3.0 * p1[axis] - 3.0 * p2[axis] + p3[axis]) * t3);
      }
      branch.Points.push_back(point);
      branch.Radii.push_back(radii[s] + t * (radii[s + 1] - radii[s]));
    }
  }
  branch.Points.push_back(knots.back());
  branch.Radii.push_back(radii.back());
  return branch;
}

Capsule
MakeCapsule(const PhantomPoint & a,
            const PhantomPoint & b,
            double               outerA,
            double               outerB,
            double               innerA,
            double               innerB,
            float                innerHU)
{
  const double reach = std::max(outerA, outerB);
  return { a, b, outerA, outerB, innerA, innerB, innerHU, std::min(a[2], b[2]) - reach, std::max(a[2], b[2]) + reach };
}

double
DistanceToSegment(const PhantomPoint & p, const PhantomPoint & a, const PhantomPoint & b, double & t)
{
  const Vector<double, 3> ab = b - a;
  const double            lengthSquared = ab.GetSquaredNorm();
  t = lengthSquared > 0.0 ? std::min(1.0, std::max(0.0, ((p - a) * ab) / lengthSquared)) : 0.0;
  return (p - (a + ab * t)).GetNorm();
}

double
NoiseSample(std::uint64_t i, std::uint64_t j, std::uint64_t k, std::uint64_t seed)
{
  std::uint64_t state = (i * 0x9E3779B97F4A7C15ull) ^ (j * 0xC2B2AE3D27D4EB4Full) ^ (k * 0x165667B19E3779F9ull) ^
                        (seed * 0xD6E8FEB86659FD93ull);
  double sum = 0.0;
  for (int n = 0; n < 3; ++n)
  {
    state ^= state >> 33;
    state *= 0xFF51AFD7ED558CCDull;
    state ^= state >> 33;
    state *= 0xC4CEB9FE1A85EC53ull;
    state ^= state >> 33;
    sum += static_cast<double>(state >> 11) * (1.0 / 9007199254740992.0) - 0.5;
    state += 0x9E3779B97F4A7C15ull;
  }
  return sum * 2.0; // variance of the sum of three U(-0.5, 0.5) is 1/4
}
} // namespace itk::detail
