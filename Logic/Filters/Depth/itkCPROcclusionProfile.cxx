// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkCPROcclusionProfile.h"

#include "itkCPROcclusionRule.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace itk
{
namespace
{
/** A segment of the tree: its end points (indices into the point list), radii (mm, 0 without), its footprint radii
 * (at least half a pixel), its extent along up (angle-independent) and its 3D length. */
struct Segment
{
  std::size_t A;
  std::size_t B;
  double      RadiusA;
  double      RadiusB;
  double      ReachA;
  double      ReachB;
  double      RowLow;
  double      RowHigh;
  double      Length;
};

struct Interval
{
  double Low;
  double High;
};

/** Narrows [low, high] to the t where p + q t <= 0. */
void
KeepWhereNotPositive(double p, double q, double & low, double & high)
{
  if (q == 0.0)
  {
    if (p > 0.0)
    {
      high = low - 1.0;
    }
    return;
  }
  const double root = -p / q;
  if (q > 0.0)
  {
    high = std::min(high, root);
  }
  else
  {
    low = std::max(low, root);
  }
}

/** One segment's point P(t) = A + t D (2D, mm) and lumen front f(t) = frontA + t (frontB - frontA), against another
 * segment Q0 -> Q1 with footprint radii R0, R1 and lumen back b0, b1: appends the t in [0, 1] where P(t) lies in the
 * footprint and its front behind the back, both at the closest point of Q0 Q1 (itkCPROcclusionRule.h). */
class HiddenIntervals
{
public:
  double Ax, Ay, Dx, Dy, FrontA, FrontB;

  void
  Against(double                  q0x,
          double                  q0y,
          double                  q1x,
          double                  q1y,
          double                  reach0,
          double                  reach1,
          double                  back0,
          double                  back1,
          std::vector<Interval> & out) const
  {
    const double ex = q1x - q0x;
    const double ey = q1y - q0y;
    const double e2 = ex * ex + ey * ey;
    if (!(e2 > 1e-18))
    {
      Clamped(q0x, q0y, std::max(reach0, reach1), std::min(back0, back1), 0.0, 1.0, out);
      return;
    }
    // The closest point's parameter on Q0 Q1, before clamping: u(t) = u0 + u1 t.
    const double u0 = ((Ax - q0x) * ex + (Ay - q0y) * ey) / e2;
    const double u1 = (Dx * ex + Dy * ey) / e2;
    double       breaks[4] = { 0.0, 1.0, 1.0, 1.0 };
    int          count = 1;
    if (u1 != 0.0)
    {
      for (const double u : { 0.0, 1.0 })
      {
        const double t = (u - u0) / u1;
        if (t > 0.0 && t < 1.0)
        {
          breaks[count++] = t;
        }
      }
    }
    breaks[count++] = 1.0;
    std::sort(breaks, breaks + count);
    for (int piece = 0; piece + 1 < count; ++piece)
    {
      const double low = breaks[piece];
      const double high = breaks[piece + 1];
      if (!(high > low))
      {
        continue;
      }
      const double u = u0 + u1 * 0.5 * (low + high);
      if (u <= 0.0)
      {
        Clamped(q0x, q0y, reach0, back0, low, high, out);
      }
      else if (u >= 1.0)
      {
        Clamped(q1x, q1y, reach1, back1, low, high, out);
      }
      else
      {
        Interior(q0x, q0y, ex, ey, std::sqrt(e2), u0, u1, reach0, reach1, back0, back1, low, high, out);
      }
    }
  }

private:
  void
  KeepBehind(double back, double backSlope, double & low, double & high) const
  {
    // front(t) > back(t)  <=>  (back - frontA) + (backSlope - (frontB - frontA)) t < 0
    KeepWhereNotPositive(back - FrontA, backSlope - (FrontB - FrontA), low, high);
  }

  /** The closest point is the end Q: |A - Q + t D| <= R, and the front behind a constant back. */
  void
  Clamped(double qx, double qy, double reach, double back, double low, double high, std::vector<Interval> & out) const
  {
    const double px = Ax - qx;
    const double py = Ay - qy;
    const double a = Dx * Dx + Dy * Dy;
    const double b = 2.0 * (px * Dx + py * Dy);
    const double c = px * px + py * py - reach * reach;
    if (a > 0.0)
    {
      const double discriminant = b * b - 4.0 * a * c;
      if (discriminant < 0.0)
      {
        return;
      }
      const double root = std::sqrt(discriminant);
      low = std::max(low, (-b - root) / (2.0 * a));
      high = std::min(high, (-b + root) / (2.0 * a));
    }
    else if (c > 0.0)
    {
      return;
    }
    KeepBehind(back, 0.0, low, high);
    if (high > low)
    {
      out.push_back({ low, high });
    }
  }

  /** The closest point lies inside Q0 Q1: the signed distance to its line and the radius there are linear in t. */
  void
  Interior(double                  q0x,
           double                  q0y,
           double                  ex,
           double                  ey,
           double                  length,
           double                  u0,
           double                  u1,
           double                  reach0,
           double                  reach1,
           double                  back0,
           double                  back1,
           double                  low,
           double                  high,
           std::vector<Interval> & out) const
  {
    const double nx = -ey / length;
    const double ny = ex / length;
    const double alpha = nx * (Ax - q0x) + ny * (Ay - q0y);
    const double beta = nx * Dx + ny * Dy;
    const double gamma = reach0 + u0 * (reach1 - reach0);
    const double delta = u1 * (reach1 - reach0);
    KeepWhereNotPositive(alpha - gamma, beta - delta, low, high);
    KeepWhereNotPositive(-alpha - gamma, -beta - delta, low, high);
    KeepBehind(back0 + u0 * (back1 - back0), u1 * (back1 - back0), low, high);
    if (high > low)
    {
      out.push_back({ low, high });
    }
  }
};

/** The measure of the union of \a intervals (sorted in place). */
double
UnionLength(std::vector<Interval> & intervals)
{
  std::sort(intervals.begin(), intervals.end(), [](const Interval & a, const Interval & b) { return a.Low < b.Low; });
  double total = 0.0;
  double low = 0.0;
  double high = -1.0;
  for (const Interval & interval : intervals)
  {
    if (interval.Low > high)
    {
      total += std::max(0.0, high - low);
      low = interval.Low;
      high = interval.High;
    }
    else
    {
      high = std::max(high, interval.High);
    }
  }
  return total + std::max(0.0, high - low);
}
} // namespace

double
CPROcclusionProfile::HiddenFraction(unsigned int angle) const
{
  return TreeLength > 0.0 && angle < HiddenLength.size() ? HiddenLength[angle] / TreeLength : 0.0;
}

unsigned int
CPROcclusionProfile::LeastOccludedAngle() const
{
  return static_cast<unsigned int>(std::min_element(HiddenLength.begin(), HiddenLength.end()) - HiddenLength.begin());
}

unsigned int
CPROcclusionProfile::MostOccludedAngle() const
{
  return static_cast<unsigned int>(std::max_element(HiddenLength.begin(), HiddenLength.end()) - HiddenLength.begin());
}

CPROcclusionProfile
ComputeCPROcclusionProfile(const CenterlineTree & tree, const CPRViewGeometry & view, MultiThreaderBase * threader)
{
  tree.Validate();
  MultiThreaderBase::Pointer ownThreader;
  if (threader == nullptr)
  {
    ownThreader = MultiThreaderBase::New();
    threader = ownThreader;
  }
  const double pixelSize = std::max(view.GetSpacing()[0], view.GetSpacing()[1]);
  const double halfPixel = 0.5 * pixelSize;

  // Points relative to the centre; their height along up never changes with the angle.
  std::vector<CPRViewGeometry::VectorType> offsets;
  std::vector<double>                      heights;
  std::vector<Segment>                     segments;
  CPROcclusionProfile                      profile;
  for (const CenterlineBranch & branch : tree.GetBranches())
  {
    const std::size_t first = offsets.size();
    for (const auto & point : branch.Points)
    {
      offsets.push_back(point - view.GetCenter());
      heights.push_back(-(offsets.back() * view.GetUp()));
    }
    const auto        radius = [&](std::size_t p) { return branch.HasRadii() ? branch.Radii[p] : 0.0; };
    const std::size_t last = branch.Points.size() > 1 ? branch.Points.size() - 1 : 1;
    for (std::size_t p = 0; p < last; ++p)
    {
      const std::size_t q = std::min(p + 1, branch.Points.size() - 1);
      Segment           segment{ first + p,
                       first + q,
                       radius(p),
                       radius(q),
                       std::max(radius(p), halfPixel),
                       std::max(radius(q), halfPixel),
                       std::min(heights[first + p], heights[first + q]),
                       std::max(heights[first + p], heights[first + q]),
                       branch.Points[p].EuclideanDistanceTo(branch.Points[q]) };
      profile.TreeLength += segment.Length;
      segments.push_back(segment);
    }
  }

  // Which segments can cover which, by their extents along up (the same at every angle): buckets of that height.
  double low = std::numeric_limits<double>::infinity();
  double high = -low;
  double reach = 0.0;
  for (const Segment & s : segments)
  {
    low = std::min(low, s.RowLow);
    high = std::max(high, s.RowHigh);
    reach = std::max({ reach, s.ReachA, s.ReachB });
  }
  const double bucketHeight = std::max({ 4.0 * pixelSize, reach, (high - low) / 4096.0 });
  const auto   bucketOf = [&](double y)
  { return static_cast<std::size_t>(std::clamp(std::floor((y - low) / bucketHeight), 0.0, 4095.0)); };
  // Every index a segment reaches, up to its reach above the highest point (bucketOf clamps, so this bounds them).
  std::vector<std::vector<std::size_t>> buckets(bucketOf(high + reach) + 1);
  for (std::size_t i = 0; i < segments.size(); ++i)
  {
    const Segment & s = segments[i];
    const double    r = std::max(s.ReachA, s.ReachB);
    for (std::size_t b = bucketOf(s.RowLow - r); b <= bucketOf(s.RowHigh + r); ++b)
    {
      buckets[b].push_back(i);
    }
  }
  std::vector<std::size_t> offsetsOfCandidates(segments.size() + 1, 0);
  std::vector<std::size_t> candidates;
  std::vector<std::size_t> seen(segments.size(), segments.size());
  for (std::size_t i = 0; i < segments.size(); ++i)
  {
    const Segment & s = segments[i];
    for (std::size_t b = bucketOf(s.RowLow); b <= bucketOf(s.RowHigh); ++b)
    {
      for (const std::size_t j : buckets[b])
      {
        const Segment & o = segments[j];
        const double    r = std::max(o.ReachA, o.ReachB);
        if (j == i || seen[j] == i || o.RowLow - r > s.RowHigh || o.RowHigh + r < s.RowLow)
        {
          continue;
        }
        seen[j] = i;
        candidates.push_back(j);
      }
    }
    offsetsOfCandidates[i + 1] = candidates.size();
  }

  profile.HiddenLength.assign(CPROcclusionProfile::NumberOfAngles, 0.0);
  threader->ParallelizeArray(
    0,
    CPROcclusionProfile::NumberOfAngles,
    [&](SizeValueType angle)
    {
      const CPRViewGeometry angled(
        view.GetUp(), static_cast<double>(angle), view.GetCenter(), view.GetSize(), view.GetSpacing());
      std::vector<double> across(offsets.size());
      std::vector<double> depth(offsets.size());
      for (std::size_t p = 0; p < offsets.size(); ++p)
      {
        across[p] = offsets[p] * angled.GetU();
        depth[p] = offsets[p] * angled.GetV();
      }
      std::vector<Interval> intervals;
      double                hidden = 0.0;
      for (std::size_t i = 0; i < segments.size(); ++i)
      {
        const Segment & s = segments[i];
        if (!(s.Length > 0.0))
        {
          continue;
        }
        HiddenIntervals solver;
        solver.Ax = across[s.A];
        solver.Ay = heights[s.A];
        solver.Dx = across[s.B] - across[s.A];
        solver.Dy = heights[s.B] - heights[s.A];
        const double tolerance =
          detail::SelfOcclusionTolerance(depth[s.B] - depth[s.A],
                                         std::sqrt(solver.Dx * solver.Dx + solver.Dy * solver.Dy),
                                         pixelSize + std::max(s.RadiusA, s.RadiusB));
        solver.FrontA = depth[s.A] - s.RadiusA - tolerance;
        solver.FrontB = depth[s.B] - s.RadiusB - tolerance;
        const double frontMost = std::max(solver.FrontA, solver.FrontB);
        const double left = std::min(across[s.A], across[s.B]);
        const double right = std::max(across[s.A], across[s.B]);
        intervals.clear();
        for (std::size_t c = offsetsOfCandidates[i]; c < offsetsOfCandidates[i + 1]; ++c)
        {
          const Segment & o = segments[candidates[c]];
          const double    back0 = depth[o.A] + o.RadiusA;
          const double    back1 = depth[o.B] + o.RadiusB;
          const double    r = std::max(o.ReachA, o.ReachB);
          if (!detail::IsBehind(frontMost, std::min(back0, back1)) || std::min(across[o.A], across[o.B]) - r > right ||
              std::max(across[o.A], across[o.B]) + r < left)
          {
            continue;
          }
          solver.Against(
            across[o.A], heights[o.A], across[o.B], heights[o.B], o.ReachA, o.ReachB, back0, back1, intervals);
        }
        if (!intervals.empty())
        {
          hidden += s.Length * UnionLength(intervals);
        }
      }
      profile.HiddenLength[angle] = hidden;
    },
    nullptr);
  return profile;
}
} // namespace itk
