// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "PlainTubeRayCaster.h"

#include "itkMultiThreaderBase.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vr::test
{
namespace
{
using Vector3 = itk::Vector<double, 3>;
using Point3 = itk::Point<double, 3>;

struct Tube
{
  Point3   A;
  Point3   B;
  double   RadiusA;
  double   RadiusB;
  uint32_t Branch;
};

std::vector<Tube>
TubesOf(const itk::CenterlineTree & tree)
{
  std::vector<Tube> tubes;
  for (const auto & branch : tree.GetBranches())
  {
    const auto radius = [&](std::size_t p) { return branch.HasRadii() ? branch.Radii[p] : 0.0; };
    if (branch.Points.size() == 1)
    {
      tubes.push_back({ branch.Points[0], branch.Points[0], radius(0), radius(0), static_cast<uint32_t>(branch.Id) });
    }
    for (std::size_t p = 0; p + 1 < branch.Points.size(); ++p)
    {
      tubes.push_back(
        { branch.Points[p], branch.Points[p + 1], radius(p), radius(p + 1), static_cast<uint32_t>(branch.Id) });
    }
  }
  return tubes;
}

/** The smallest and largest s in [low, high] with a s^2 + b s + c <= 0; false when there is none. */
bool
QuadraticNotPositive(double a, double b, double c, double low, double high, double & first, double & last)
{
  if (!(high >= low))
  {
    return false;
  }
  const double scale = std::max({ std::abs(a), std::abs(b), std::abs(c), 1e-300 });
  if (std::abs(a) <= 1e-14 * scale)
  {
    if (b == 0.0)
    {
      if (c > 0.0)
      {
        return false;
      }
      first = low;
      last = high;
      return true;
    }
    const double root = -c / b;
    first = b > 0.0 ? low : std::max(low, root);
    last = b > 0.0 ? std::min(high, root) : high;
    return first <= last;
  }
  const double discriminant = b * b - 4.0 * a * c;
  if (a > 0.0)
  {
    if (discriminant < 0.0)
    {
      return false;
    }
    const double root = std::sqrt(discriminant);
    first = std::max(low, (-b - root) / (2.0 * a));
    last = std::min(high, (-b + root) / (2.0 * a));
    return first <= last;
  }
  if (discriminant < 0.0)
  {
    first = low;
    last = high;
    return true;
  }
  const double root = std::sqrt(discriminant);
  const double r1 = std::min((-b - root) / (2.0 * a), (-b + root) / (2.0 * a));
  const double r2 = std::max((-b - root) / (2.0 * a), (-b + root) / (2.0 * a));
  // Outside (r1, r2).
  const bool lowPart = low <= r1;
  const bool highPart = high >= r2;
  if (!lowPart && !highPart)
  {
    return false;
  }
  first = lowPart ? low : std::max(low, r2);
  last = highPart ? high : std::min(high, r1);
  return first <= last;
}

/** Where the ray origin + s direction (|direction| = 1) is inside the tube: false when nowhere. */
bool
Intersect(const Tube & tube, const Point3 & origin, const Vector3 & direction, double & entry, double & exit)
{
  const Vector3 w = tube.B - tube.A;
  const double  w2 = w * w;
  const Vector3 o = origin - tube.A;
  entry = std::numeric_limits<double>::infinity();
  exit = -entry;
  bool       hit = false;
  const auto sphere = [&](const Vector3 & offset, double radius, double low, double high)
  {
    double first = 0.0;
    double last = 0.0;
    if (QuadraticNotPositive(
          1.0, 2.0 * (offset * direction), offset * offset - radius * radius, low, high, first, last))
    {
      entry = std::min(entry, first);
      exit = std::max(exit, last);
      hit = true;
    }
  };
  const double infinity = std::numeric_limits<double>::infinity();
  if (!(w2 > 0.0))
  {
    sphere(o, std::max(tube.RadiusA, tube.RadiusB), -infinity, infinity);
    return hit;
  }
  // The nearest segment parameter along the ray, unclamped: t(s) = t0 + s t1.
  const double t0 = (o * w) / w2;
  const double t1 = (direction * w) / w2;
  double       breaks[4] = { -infinity, infinity, infinity, infinity };
  int          count = 1;
  if (t1 != 0.0)
  {
    breaks[count++] = (0.0 - t0) / t1;
    breaks[count++] = (1.0 - t0) / t1;
  }
  breaks[count++] = infinity;
  std::sort(breaks, breaks + count);
  for (int piece = 0; piece + 1 < count; ++piece)
  {
    const double low = breaks[piece];
    const double high = breaks[piece + 1];
    if (!(high > low))
    {
      continue;
    }
    double middle = 0.0;
    if (std::isinf(low) && std::isinf(high))
    {
      middle = 0.0;
    }
    else if (std::isinf(low))
    {
      middle = high - 1.0;
    }
    else if (std::isinf(high))
    {
      middle = low + 1.0;
    }
    else
    {
      middle = 0.5 * (low + high);
    }
    const double t = t0 + middle * t1;
    if (t <= 0.0)
    {
      sphere(o, tube.RadiusA, low, high);
    }
    else if (t >= 1.0)
    {
      sphere(origin - tube.B, tube.RadiusB, low, high);
    }
    else
    {
      // |m0 + s m1| <= rho0 + s rho1 with the nearest point interpolated.
      const Vector3 m0 = o - t0 * w;
      const Vector3 m1 = direction - t1 * w;
      const double  rho0 = tube.RadiusA + t0 * (tube.RadiusB - tube.RadiusA);
      const double  rho1 = t1 * (tube.RadiusB - tube.RadiusA);
      double        first = 0.0;
      double        last = 0.0;
      if (QuadraticNotPositive(
            m1 * m1 - rho1 * rho1, 2.0 * (m0 * m1 - rho0 * rho1), m0 * m0 - rho0 * rho0, low, high, first, last))
      {
        entry = std::min(entry, first);
        exit = std::max(exit, last);
        hit = true;
      }
    }
  }
  return hit;
}
} // namespace

std::vector<TubeCrossing>
CrossTubes(const itk::CenterlineTree & tree, const itk::CPRViewGeometry & view, double column, double row)
{
  std::vector<TubeCrossing> crossings;
  const Point3              origin = view.PlanePoint(column, row);
  for (const Tube & tube : TubesOf(tree))
  {
    double entry = 0.0;
    double exit = 0.0;
    if (Intersect(tube, origin, view.GetV(), entry, exit))
    {
      crossings.push_back({ tube.Branch, entry, exit });
    }
  }
  return crossings;
}

TubeHits
CastTubeRays(const itk::CenterlineTree & tree, const itk::CPRViewGeometry & view)
{
  const std::vector<Tube> tubes = TubesOf(tree);
  TubeHits                hits;
  hits.Width = static_cast<unsigned int>(view.GetSize()[0]);
  hits.Height = static_cast<unsigned int>(view.GetSize()[1]);
  const std::size_t count = static_cast<std::size_t>(hits.Width) * hits.Height;
  hits.FirstBranch.assign(count, 0);
  hits.EntryDepth.assign(count, std::numeric_limits<double>::quiet_NaN());

  // Tiles of 16 x 16 pixels list the tubes whose bounding box (the end spheres, projected) reaches them.
  constexpr int                 Tile = 16;
  const int                     tilesAcross = (static_cast<int>(hits.Width) + Tile - 1) / Tile;
  const int                     tilesDown = (static_cast<int>(hits.Height) + Tile - 1) / Tile;
  std::vector<std::vector<int>> tiles(static_cast<std::size_t>(tilesAcross) * tilesDown);
  const Vector3                 u = view.GetU();
  const Vector3                 up = view.GetUp();
  const double                  sx = view.GetSpacing()[0];
  const double                  sy = view.GetSpacing()[1];
  const auto column = [&](const Point3 & p) { return ((p - view.GetCenter()) * u) / sx + 0.5 * (hits.Width - 1.0); };
  const auto row = [&](const Point3 & p) { return -((p - view.GetCenter()) * up) / sy + 0.5 * (hits.Height - 1.0); };
  for (std::size_t k = 0; k < tubes.size(); ++k)
  {
    const Tube & tube = tubes[k];
    const double r = std::max(tube.RadiusA, tube.RadiusB);
    const double c0 = std::min(column(tube.A), column(tube.B)) - r / sx - 1.0;
    const double c1 = std::max(column(tube.A), column(tube.B)) + r / sx + 1.0;
    const double r0 = std::min(row(tube.A), row(tube.B)) - r / sy - 1.0;
    const double r1 = std::max(row(tube.A), row(tube.B)) + r / sy + 1.0;
    const int    tx0 = static_cast<int>(std::clamp(std::floor(c0 / Tile), 0.0, tilesAcross - 1.0));
    const int    tx1 = static_cast<int>(std::clamp(std::floor(c1 / Tile), 0.0, tilesAcross - 1.0));
    const int    ty0 = static_cast<int>(std::clamp(std::floor(r0 / Tile), 0.0, tilesDown - 1.0));
    const int    ty1 = static_cast<int>(std::clamp(std::floor(r1 / Tile), 0.0, tilesDown - 1.0));
    if (c1 < 0.0 || r1 < 0.0 || c0 > hits.Width || r0 > hits.Height)
    {
      continue;
    }
    for (int ty = ty0; ty <= ty1; ++ty)
    {
      for (int tx = tx0; tx <= tx1; ++tx)
      {
        tiles[static_cast<std::size_t>(ty) * tilesAcross + tx].push_back(static_cast<int>(k));
      }
    }
  }

  auto threader = itk::MultiThreaderBase::New();
  threader->ParallelizeArray(
    0,
    hits.Height,
    [&](itk::SizeValueType j)
    {
      for (unsigned int i = 0; i < hits.Width; ++i)
      {
        const Point3 origin = view.PlanePoint(i, static_cast<double>(j));
        double       best = std::numeric_limits<double>::infinity();
        uint32_t     branch = 0;
        for (const int k : tiles[static_cast<std::size_t>(j / Tile) * tilesAcross + i / Tile])
        {
          double entry = 0.0;
          double exit = 0.0;
          if (Intersect(tubes[k], origin, view.GetV(), entry, exit) &&
              (entry < best || (entry == best && tubes[k].Branch < branch)))
          {
            best = entry;
            branch = tubes[k].Branch;
          }
        }
        const std::size_t pixel = static_cast<std::size_t>(j) * hits.Width + i;
        hits.FirstBranch[pixel] = branch;
        hits.EntryDepth[pixel] = branch != 0 ? best : std::numeric_limits<double>::quiet_NaN();
      }
    },
    nullptr);
  return hits;
}

bool
IsInsideBranch(const itk::CenterlineTree & tree, uint32_t branchId, const itk::CenterlineTree::PointType & point)
{
  for (const auto & branch : tree.GetBranches())
  {
    if (static_cast<uint32_t>(branch.Id) != branchId)
    {
      continue;
    }
    const auto radius = [&](std::size_t p) { return branch.HasRadii() ? branch.Radii[p] : 0.0; };
    for (std::size_t p = 0; p < branch.Points.size(); ++p)
    {
      const std::size_t q = std::min(p + 1, branch.Points.size() - 1);
      const Vector3     w = branch.Points[q] - branch.Points[p];
      const double      w2 = w * w;
      const double      t = w2 > 0.0 ? std::clamp(((point - branch.Points[p]) * w) / w2, 0.0, 1.0) : 0.0;
      const Point3      nearest = branch.Points[p] + t * w;
      if (point.EuclideanDistanceTo(nearest) <= radius(p) + t * (radius(q) - radius(p)))
      {
        return true;
      }
    }
  }
  return false;
}

bool
IsCenterlinePointHidden(const itk::CenterlineTree &            tree,
                        const itk::CPRViewGeometry &           view,
                        const itk::CenterlineTree::PointType & point,
                        double                                 radius)
{
  const auto coordinates = view.ToView(point);
  for (const TubeCrossing & crossing : CrossTubes(tree, view, coordinates.Column, coordinates.Row))
  {
    if (crossing.Exit < coordinates.Depth - radius)
    {
      return true;
    }
  }
  return false;
}
} // namespace vr::test
