// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkCenterlineBranchGeometry.h"

#include "itkCenterlinePolylineMerge.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace itk
{
namespace detail
{
namespace
{
using Vector3 = std::array<double, 3>;

double
Distance(const Vector3 & a, const Vector3 & b)
{
  return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]));
}

std::vector<double>
ArcLengths(const std::vector<Vector3> & points)
{
  std::vector<double> arc(points.size(), 0.0);
  for (std::size_t k = 1; k < points.size(); ++k)
  {
    arc[k] = arc[k - 1] + Distance(points[k - 1], points[k]);
  }
  return arc;
}

double
MedianOf(std::vector<double> values)
{
  if (values.empty())
  {
    return 0.0;
  }
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}
} // namespace

namespace
{
/** Local linear regression of \a values against \a arc with Gaussian weights of width \a sigma. */
template<std::size_t N>
std::vector<std::array<double, N>>
SmoothAlongArc(const std::vector<double> & arc, const std::vector<std::array<double, N>> & values, double sigma)
{
  const std::size_t count = values.size();
  if (count < 3 || !(sigma > 0.0))
  {
    return values;
  }
  const double                       reach = 3.0 * sigma;
  std::vector<std::array<double, N>> smoothed(count);
  std::size_t                        low = 0;
  std::size_t                        high = 0;
  for (std::size_t i = 0; i < count; ++i)
  {
    while (arc[i] - arc[low] > reach)
    {
      ++low;
    }
    while (high + 1 < count && arc[high + 1] - arc[i] <= reach)
    {
      ++high;
    }
    double                s0 = 0.0;
    double                s1 = 0.0;
    double                s2 = 0.0;
    std::array<double, N> t0{};
    std::array<double, N> t1{};
    for (std::size_t j = low; j <= high; ++j)
    {
      const double u = arc[j] - arc[i];
      const double w = std::exp(-0.5 * u * u / (sigma * sigma));
      s0 += w;
      s1 += w * u;
      s2 += w * u * u;
      for (std::size_t axis = 0; axis < N; ++axis)
      {
        t0[axis] += w * values[j][axis];
        t1[axis] += w * u * values[j][axis];
      }
    }
    const double determinant = s0 * s2 - s1 * s1;
    for (std::size_t axis = 0; axis < N; ++axis)
    {
      smoothed[i][axis] = determinant > 1e-9 * s0 * s2 ? (s2 * t0[axis] - s1 * t1[axis]) / determinant : t0[axis] / s0;
    }
  }
  return smoothed;
}
} // namespace

std::vector<Vector3>
SmoothPolyline(const std::vector<Vector3> & points, double sigma)
{
  return SmoothAlongArc(ArcLengths(points), points, sigma);
}

std::vector<Vector3>
ResamplePolyline(const std::vector<Vector3> & points, double spacing)
{
  if (points.size() < 2)
  {
    return points;
  }
  const double         length = ArcLengths(points).back();
  const std::size_t    steps = std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(length / spacing)));
  std::vector<Vector3> resampled;
  std::vector<double>  noRadii;
  ResamplePolylineEvenly(points, {}, steps + 1, resampled, noRadii);
  return resampled;
}

namespace
{
/** The voxel size across a direction: the spacing seen in the plane normal to the unit vector \a tangent (index
 * axes). Isotropic voxels of size h give h. */
double
VoxelSizeAcross(const Vector3 & tangent, const std::array<double, 3> & spacing)
{
  double across = 0.0;
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    across += spacing[axis] * spacing[axis] * (1.0 - tangent[axis] * tangent[axis]);
  }
  return std::sqrt(0.5 * across);
}

/** Unit tangents of a polyline, by central differences. */
std::vector<Vector3>
Tangents(const std::vector<Vector3> & points)
{
  std::vector<Vector3> tangents(points.size(), Vector3{ 0.0, 0.0, 1.0 });
  for (std::size_t k = 0; k < points.size() && points.size() > 1; ++k)
  {
    const Vector3 & before = points[k == 0 ? 0 : k - 1];
    const Vector3 & after = points[std::min(k + 1, points.size() - 1)];
    const double    length = Distance(before, after);
    if (length > 0.0)
    {
      for (unsigned int axis = 0; axis < 3; ++axis)
      {
        tangents[k][axis] = (after[axis] - before[axis]) / length;
      }
    }
  }
  return tangents;
}

/** Moves \a point, in the plane normal to \a tangent, to the centre of the ridge of the distance map: the centroid
 * of the part of a small square of that plane (two voxels each way) where the interpolated distance lies within one
 * voxel of its highest value there. Near the ridge the distance is a cone around the true axis, so that part is a
 * disc centred on it; the interpolation between voxel centres leaves the disc's centre in place even when the axis
 * runs between them, where a voxel path cannot follow it. */
Vector3
CentreOnRidge(const Vector3 & point, const Vector3 & tangent, const CenterlineForeground & foreground)
{
  const auto & spacing = foreground.Spacing;
  // Two unit vectors spanning the normal plane.
  Vector3 helper{ 1.0, 0.0, 0.0 };
  if (std::abs(tangent[0]) > 0.9)
  {
    helper = { 0.0, 1.0, 0.0 };
  }
  Vector3      n1{ tangent[1] * helper[2] - tangent[2] * helper[1],
              tangent[2] * helper[0] - tangent[0] * helper[2],
              tangent[0] * helper[1] - tangent[1] * helper[0] };
  const double n1Length = std::sqrt(n1[0] * n1[0] + n1[1] * n1[1] + n1[2] * n1[2]);
  for (auto & value : n1)
  {
    value /= n1Length;
  }
  const Vector3 n2{ tangent[1] * n1[2] - tangent[2] * n1[1],
                    tangent[2] * n1[0] - tangent[0] * n1[2],
                    tangent[0] * n1[1] - tangent[1] * n1[0] };

  const double        voxel = VoxelSizeAcross(tangent, spacing);
  constexpr int       steps = 8; // samples each way, a quarter voxel apart
  const double        step = 0.25 * voxel;
  std::vector<double> samples((2 * steps + 1) * (2 * steps + 1));
  double              top = 0.0;
  for (int a = -steps; a <= steps; ++a)
  {
    for (int b = -steps; b <= steps; ++b)
    {
      Vector3 sample;
      for (unsigned int axis = 0; axis < 3; ++axis)
      {
        sample[axis] = point[axis] + a * step * n1[axis] + b * step * n2[axis];
      }
      const double value = foreground.InterpolatedDistance(sample);
      samples[(a + steps) * (2 * steps + 1) + (b + steps)] = value;
      top = std::max(top, value);
    }
  }
  double sumA = 0.0;
  double sumB = 0.0;
  double count = 0.0;
  for (int a = -steps; a <= steps; ++a)
  {
    for (int b = -steps; b <= steps; ++b)
    {
      if (samples[(a + steps) * (2 * steps + 1) + (b + steps)] >= top - voxel)
      {
        sumA += a * step;
        sumB += b * step;
        count += 1.0;
      }
    }
  }
  Vector3 centred = point;
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    centred[axis] += (sumA * n1[axis] + sumB * n2[axis]) / count;
  }
  return centred;
}
} // namespace

std::vector<CenterlineBranch>
MakeCenterlineBranches(const SkeletonTree &                        skeleton,
                       const CenterlineForeground &                foreground,
                       const CenterlineForeground::MaskImageType * grid,
                       const BranchGeometryParameters &            parameters,
                       int                                         firstId)
{
  const auto &      spacing = foreground.Spacing;
  const double      diagonal = std::sqrt(spacing[0] * spacing[0] + spacing[1] * spacing[1] + spacing[2] * spacing[2]);
  const std::size_t branchCount = skeleton.Branches.size();

  // Positions (mm, the index frame scaled by the spacing): the voxel path smoothed, then centred on the ridge of
  // the distance map. Also each branch's median radius and smoothing width.
  std::vector<std::vector<Vector3>>     positions(branchCount);
  std::vector<double>                   medianRadius(branchCount);
  std::vector<double>                   sigma(branchCount);
  std::vector<std::vector<std::size_t>> children(branchCount);
  std::vector<std::size_t>              rootBranches;
  for (std::size_t b = 0; b < branchCount; ++b)
  {
    const auto &         branch = skeleton.Branches[b];
    std::vector<double>  radii;
    std::vector<Vector3> voxels;
    for (const uint32_t voxel : branch.Voxels)
    {
      voxels.push_back(foreground.ScaledPosition(voxel));
      radii.push_back(foreground.Distance[voxel]);
    }
    medianRadius[b] = MedianOf(radii);
    sigma[b] = std::max(diagonal, parameters.SmoothingRadiusRatio * medianRadius[b]);
    // Twice: the tangents of the first centring come from the voxel path (a staircase), of the second from the
    // centred points.
    positions[b] = voxels;
    for (int pass = 0; pass < 2; ++pass)
    {
      const std::vector<Vector3> smoothed = SmoothPolyline(positions[b], sigma[b]);
      const std::vector<Vector3> tangents = Tangents(smoothed);
      for (std::size_t k = 0; k < smoothed.size(); ++k)
      {
        positions[b][k] = CentreOnRidge(smoothed[k], tangents[k], foreground);
      }
    }
    if (branch.Parent >= 0)
    {
      children[static_cast<std::size_t>(branch.Parent)].push_back(b);
    }
    else
    {
      rootBranches.push_back(b);
    }
  }
  const auto widest = [&](const std::vector<std::size_t> & candidates)
  {
    return *std::max_element(candidates.begin(),
                             candidates.end(),
                             [&](std::size_t a, std::size_t c) { return medianRadius[a] < medianRadius[c]; });
  };

  // Junctions: where a branch ends and its children start (or where two root branches leave a root in the middle
  // of a vessel), on the smoothed path through the junction along the widest continuation.
  std::map<uint32_t, Vector3> junctions;
  for (std::size_t b = 0; b < branchCount; ++b)
  {
    if (children[b].empty())
    {
      continue;
    }
    const std::size_t    child = widest(children[b]);
    std::vector<Vector3> through = positions[b];
    through.insert(through.end(), positions[child].begin() + 1, positions[child].end());
    junctions[skeleton.Branches[b].Voxels.back()] = SmoothPolyline(through, sigma[b])[positions[b].size() - 1];
  }
  if (rootBranches.size() >= 2)
  {
    std::vector<std::size_t> sorted(rootBranches);
    std::sort(
      sorted.begin(), sorted.end(), [&](std::size_t a, std::size_t c) { return medianRadius[a] > medianRadius[c]; });
    std::vector<Vector3> through(positions[sorted[0]].rbegin(), positions[sorted[0]].rend());
    through.insert(through.end(), positions[sorted[1]].begin() + 1, positions[sorted[1]].end());
    junctions[skeleton.Root] = SmoothPolyline(through, sigma[sorted[0]])[positions[sorted[0]].size() - 1];
  }

  std::vector<CenterlineBranch> branches;
  for (std::size_t b = 0; b < branchCount; ++b)
  {
    const auto &         voxels = skeleton.Branches[b].Voxels;
    std::vector<Vector3> smoothed = SmoothPolyline(positions[b], sigma[b]);
    const auto           front = junctions.find(voxels.front());
    if (front != junctions.end())
    {
      smoothed.front() = front->second;
    }
    const auto back = junctions.find(voxels.back());
    if (back != junctions.end())
    {
      smoothed.back() = back->second;
    }
    const std::vector<Vector3> resampled = ResamplePolyline(smoothed, parameters.PointSpacing);
    const std::vector<Vector3> tangents = Tangents(resampled);

    // Radii: the interpolated distance plus the correction across the branch, smoothed like the points.
    std::vector<std::array<double, 1>> radii(resampled.size());
    for (std::size_t k = 0; k < resampled.size(); ++k)
    {
      radii[k][0] = foreground.InterpolatedDistance(resampled[k]) +
                    parameters.RadiusCorrection * VoxelSizeAcross(tangents[k], spacing);
    }
    radii = SmoothAlongArc(ArcLengths(resampled), radii, sigma[b]);

    CenterlineBranch branch;
    branch.Id = firstId + static_cast<int>(b);
    for (std::size_t k = 0; k < resampled.size(); ++k)
    {
      ContinuousIndex<double, 3> index;
      for (unsigned int axis = 0; axis < 3; ++axis)
      {
        index[axis] = resampled[k][axis] / spacing[axis];
      }
      CenterlineBranch::PointType point;
      grid->TransformContinuousIndexToPhysicalPoint(index, point);
      branch.Points.push_back(point);
      branch.Radii.push_back(std::max(0.0, radii[k][0]));
    }
    branches.push_back(std::move(branch));
  }
  return branches;
}
} // namespace detail
} // namespace itk
