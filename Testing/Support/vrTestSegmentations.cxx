// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrTestSegmentations.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace vr::test
{
LabelMap::Pointer
MakeLabelMap(const itk::Size<3> &              size,
             const itk::Vector<double, 3> &    spacing,
             const PointType &                 origin,
             const itk::Matrix<double, 3, 3> & direction)
{
  auto image = LabelMap::New();
  image->SetRegions(LabelMap::RegionType(size));
  image->SetSpacing(spacing);
  image->SetOrigin(origin);
  image->SetDirection(direction);
  image->Allocate(true);
  return image;
}

itk::Matrix<double, 3, 3>
RotationMatrix(double x, double y, double z, double degrees)
{
  const double norm = std::sqrt(x * x + y * y + z * z);
  x /= norm;
  y /= norm;
  z /= norm;
  const double              c = std::cos(degrees * M_PI / 180.0);
  const double              s = std::sin(degrees * M_PI / 180.0);
  const double              t = 1.0 - c;
  itk::Matrix<double, 3, 3> r;
  r(0, 0) = t * x * x + c;
  r(0, 1) = t * x * y - s * z;
  r(0, 2) = t * x * z + s * y;
  r(1, 0) = t * x * y + s * z;
  r(1, 1) = t * y * y + c;
  r(1, 2) = t * y * z - s * x;
  r(2, 0) = t * x * z - s * y;
  r(2, 1) = t * y * z + s * x;
  r(2, 2) = t * z * z + c;
  return r;
}

namespace
{
PointType
P3(double x, double y, double z)
{
  PointType p;
  p[0] = x;
  p[1] = y;
  p[2] = z;
  return p;
}

/** Distance from p to segment ab and the segment parameter of the nearest point. */
double
DistanceToSegment(const PointType & p, const PointType & a, const PointType & b, double & t)
{
  const itk::Vector<double, 3> ab = b - a;
  const double                 lengthSquared = ab.GetSquaredNorm();
  t = lengthSquared > 0.0 ? std::min(1.0, std::max(0.0, ((p - a) * ab) / lengthSquared)) : 0.0;
  return (p - (a + ab * t)).GetNorm();
}
} // namespace

void
DrawTubes(LabelMap * image, const itk::CenterlineTree & tree, unsigned char label)
{
  const auto region = image->GetLargestPossibleRegion();
  for (const auto & branch : tree.GetBranches())
  {
    if (!branch.HasRadii())
    {
      throw std::invalid_argument("DrawTubes: a branch without radii");
    }
    for (std::size_t k = 0; k + 1 < branch.Points.size(); ++k)
    {
      const PointType & a = branch.Points[k];
      const PointType & b = branch.Points[k + 1];
      const double      ra = branch.Radii[k];
      const double      rb = branch.Radii[k + 1];
      const double      reach = std::max(ra, rb);
      // The capsule's bounding box in index space: the continuous indices of its box's eight corners.
      itk::ContinuousIndex<double, 3> low;
      itk::ContinuousIndex<double, 3> high;
      low.Fill(std::numeric_limits<double>::infinity());
      high.Fill(-std::numeric_limits<double>::infinity());
      for (int corner = 0; corner < 8; ++corner)
      {
        PointType p;
        for (unsigned int axis = 0; axis < 3; ++axis)
        {
          const double lo = std::min(a[axis], b[axis]) - reach;
          const double hi = std::max(a[axis], b[axis]) + reach;
          p[axis] = (corner >> axis) & 1 ? hi : lo;
        }
        itk::ContinuousIndex<double, 3> index;
        image->TransformPhysicalPointToContinuousIndex(p, index);
        for (unsigned int axis = 0; axis < 3; ++axis)
        {
          low[axis] = std::min(low[axis], index[axis]);
          high[axis] = std::max(high[axis], index[axis]);
        }
      }
      LabelMap::IndexType first;
      LabelMap::IndexType last;
      for (unsigned int axis = 0; axis < 3; ++axis)
      {
        first[axis] = std::max<itk::IndexValueType>(region.GetIndex(axis), static_cast<long>(std::floor(low[axis])));
        last[axis] = std::min<itk::IndexValueType>(region.GetIndex(axis) + static_cast<long>(region.GetSize(axis)) - 1,
                                                   static_cast<long>(std::ceil(high[axis])));
      }
      LabelMap::IndexType index;
      for (index[2] = first[2]; index[2] <= last[2]; ++index[2])
      {
        for (index[1] = first[1]; index[1] <= last[1]; ++index[1])
        {
          for (index[0] = first[0]; index[0] <= last[0]; ++index[0])
          {
            PointType p;
            image->TransformIndexToPhysicalPoint(index, p);
            double       t = 0.0;
            const double distance = DistanceToSegment(p, a, b, t);
            if (distance <= ra + t * (rb - ra))
            {
              image->SetPixel(index, label);
            }
          }
        }
      }
    }
  }
}

std::vector<PointType>
ArcPoints(const PointType &              center,
          double                         radius,
          const itk::Vector<double, 3> & u,
          const itk::Vector<double, 3> & v,
          double                         from,
          double                         to,
          double                         step)
{
  const double           span = std::abs(to - from) * M_PI / 180.0 * radius;
  const int              count = std::max(1, static_cast<int>(std::ceil(span / step)));
  std::vector<PointType> points;
  for (int k = 0; k <= count; ++k)
  {
    const double angle = (from + (to - from) * k / count) * M_PI / 180.0;
    points.push_back(center + u * (radius * std::cos(angle)) + v * (radius * std::sin(angle)));
  }
  return points;
}

std::vector<PointType>
SegmentPoints(const PointType & a, const PointType & b, double step)
{
  const int              count = std::max(1, static_cast<int>(std::ceil(a.EuclideanDistanceTo(b) / step)));
  std::vector<PointType> points;
  for (int k = 0; k <= count; ++k)
  {
    points.push_back(a + (b - a) * (static_cast<double>(k) / count));
  }
  return points;
}

itk::CenterlineTree
MakeBranchingTree(unsigned int size, unsigned int generations)
{
  struct Sprout
  {
    PointType              Start;
    itk::Vector<double, 3> Direction;
    double                 Length;
    double                 Radius;
    unsigned int           Generation;
  };
  itk::CenterlineTree    tree;
  const double           s = static_cast<double>(size);
  itk::Vector<double, 3> up;
  up[0] = 0.0;
  up[1] = 0.0;
  up[2] = 1.0;
  std::vector<Sprout> sprouts{ { P3(0.5 * s, 0.5 * s, 0.04 * s), up, 0.3 * s, s / 25.0, 0 } };
  int                 id = 1;
  for (std::size_t next = 0; next < sprouts.size(); ++next)
  {
    const Sprout    sprout = sprouts[next];
    const PointType end = sprout.Start + sprout.Direction * sprout.Length;
    tree.AddBranch(TubeBranch(id++, SegmentPoints(sprout.Start, end, 0.5), sprout.Radius));
    if (sprout.Generation == generations)
    {
      continue;
    }
    // Turn about an axis across the parent, alternating between two such axes.
    itk::Vector<double, 3> across = sprout.Generation % 2 == 0
                                      ? itk::CrossProduct(sprout.Direction, up)
                                      : itk::CrossProduct(sprout.Direction, itk::CrossProduct(sprout.Direction, up));
    if (across.GetNorm() < 1e-6)
    {
      across[0] = 1.0;
      across[1] = 0.0;
      across[2] = 0.0;
    }
    across.Normalize();
    for (const double sign : { -1.0, 1.0 })
    {
      const auto             rotation = RotationMatrix(across[0], across[1], across[2], sign * 32.0);
      itk::Vector<double, 3> direction = rotation * sprout.Direction;
      direction.Normalize();
      sprouts.push_back({ end, direction, 0.75 * sprout.Length, 0.72 * sprout.Radius, sprout.Generation + 1 });
    }
  }
  return tree;
}

itk::CenterlineBranch
TubeBranch(int id, const std::vector<PointType> & points, double radius)
{
  itk::CenterlineBranch branch;
  branch.Id = id;
  branch.Points = points;
  branch.Radii.assign(points.size(), radius);
  return branch;
}

NearestOnPolyline
NearestPointOnPolyline(const PointType &              point,
                       const std::vector<PointType> & polyline,
                       const std::vector<double> &    radii)
{
  NearestOnPolyline nearest{ std::numeric_limits<double>::infinity(), 0.0, 0.0 };
  double            arc = 0.0;
  if (polyline.size() == 1)
  {
    return { point.EuclideanDistanceTo(polyline[0]), radii.empty() ? 0.0 : radii[0], 0.0 };
  }
  for (std::size_t k = 0; k + 1 < polyline.size(); ++k)
  {
    double       t = 0.0;
    const double distance = DistanceToSegment(point, polyline[k], polyline[k + 1], t);
    const double length = polyline[k].EuclideanDistanceTo(polyline[k + 1]);
    if (distance < nearest.Distance)
    {
      nearest.Distance = distance;
      nearest.Radius = radii.empty() ? 0.0 : radii[k] + t * (radii[k + 1] - radii[k]);
      nearest.ArcLength = arc + t * length;
    }
    arc += length;
  }
  return nearest;
}

NearestOnTree
NearestPointOnTree(const PointType & point, const itk::CenterlineTree & tree)
{
  NearestOnTree best{ { std::numeric_limits<double>::infinity(), 0.0, 0.0 }, 0 };
  for (std::size_t b = 0; b < tree.GetNumberOfBranches(); ++b)
  {
    const auto & branch = tree.GetBranches()[b];
    const auto   nearest = NearestPointOnPolyline(point, branch.Points, branch.Radii);
    if (nearest.Distance < best.Nearest.Distance)
    {
      best = { nearest, b };
    }
  }
  return best;
}

double
PolylineLength(const std::vector<PointType> & polyline)
{
  double length = 0.0;
  for (std::size_t k = 1; k < polyline.size(); ++k)
  {
    length += polyline[k - 1].EuclideanDistanceTo(polyline[k]);
  }
  return length;
}

double
Quantile(std::vector<double> values, double q)
{
  if (values.empty())
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  std::sort(values.begin(), values.end());
  const std::size_t index = std::min(
    values.size() - 1, static_cast<std::size_t>(std::ceil(q * static_cast<double>(values.size()))) - (q > 0 ? 1 : 0));
  return values[index];
}
} // namespace vr::test
