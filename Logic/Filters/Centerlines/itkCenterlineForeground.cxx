// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkCenterlineForeground.h"

#include "itkMacro.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace itk
{
namespace detail
{
auto
CenterlineForeground::IndexOf(uint32_t voxel) const -> IndexType
{
  const std::size_t offset = Offset[voxel];
  const std::size_t row = BufferSize[0];
  const std::size_t slice = row * BufferSize[1];
  IndexType         index;
  index[0] = BufferStart[0] + static_cast<IndexValueType>(offset % row);
  index[1] = BufferStart[1] + static_cast<IndexValueType>((offset / row) % BufferSize[1]);
  index[2] = BufferStart[2] + static_cast<IndexValueType>(offset / slice);
  return index;
}

std::array<double, 3>
CenterlineForeground::ScaledPosition(uint32_t voxel) const
{
  const IndexType index = IndexOf(voxel);
  return { index[0] * Spacing[0], index[1] * Spacing[1], index[2] * Spacing[2] };
}

double
CenterlineForeground::DistanceBetween(uint32_t a, uint32_t b) const
{
  const auto p = ScaledPosition(a);
  const auto q = ScaledPosition(b);
  return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
}

namespace
{
/** One line of the separable distance transform: \a positions (mm, ascending) carry squared distances \a values
 * (0 for background); on return \a values holds at each position min_k (p - p_k)^2 + values_k, the lower envelope
 * of the parabolas (Felzenszwalb and Huttenlocher, "Distance transforms of sampled functions", 2012). */
void
LowerEnvelope(const std::vector<double> & positions,
              std::vector<double> &       values,
              std::vector<std::size_t> &  apex,
              std::vector<double> &       bound)
{
  const std::size_t count = positions.size();
  apex.assign(count, 0);
  bound.assign(count + 1, 0.0);
  std::size_t k = 0;
  bound[0] = -std::numeric_limits<double>::infinity();
  bound[1] = std::numeric_limits<double>::infinity();
  const auto crossing = [&](std::size_t q, std::size_t v)
  {
    return ((values[q] + positions[q] * positions[q]) - (values[v] + positions[v] * positions[v])) /
           (2.0 * (positions[q] - positions[v]));
  };
  for (std::size_t q = 1; q < count; ++q)
  {
    double s = crossing(q, apex[k]);
    while (s <= bound[k])
    {
      --k;
      s = crossing(q, apex[k]);
    }
    ++k;
    apex[k] = q;
    bound[k] = s;
    bound[k + 1] = std::numeric_limits<double>::infinity();
  }
  std::vector<double> lowest(count);
  k = 0;
  for (std::size_t q = 0; q < count; ++q)
  {
    while (bound[k + 1] < positions[q])
    {
      ++k;
    }
    const double d = positions[q] - positions[apex[k]];
    lowest[q] = d * d + values[apex[k]];
  }
  values.swap(lowest);
}

/** Passes of the exact Euclidean distance transform along \a axis, over the lines that cross the foreground only:
 * \a squared (per foreground voxel) holds the squared distance found so far; background voxels count as 0 and only
 * the two that bound each run of foreground voxels along a line can be nearest, so a line's candidates are its
 * foreground voxels and those bounds. Lines are found by a stable counting sort of the compact list by the other
 * two coordinates, which keeps each line in order along \a axis. */
void
DistancePass(const CenterlineForeground & f, unsigned int axis, std::vector<double> & squared)
{
  const std::size_t        nx = f.BufferSize[0];
  const std::size_t        ny = f.BufferSize[1];
  const std::size_t        count = f.Size();
  std::vector<std::size_t> coordinate(3);
  const auto               unravel = [&](uint32_t voxel, std::size_t & x, std::size_t & y, std::size_t & z)
  {
    const std::size_t offset = f.Offset[voxel];
    x = offset % nx;
    y = (offset / nx) % ny;
    z = offset / (nx * ny);
  };
  // The line key: the two other coordinates.
  const unsigned int       a = axis == 0 ? 1 : 0;
  const unsigned int       b = axis == 2 ? 1 : 2;
  const std::size_t        keys = f.BufferSize[a] * f.BufferSize[b];
  std::vector<uint32_t>    start(keys + 1, 0);
  std::vector<uint32_t>    key(count);
  std::vector<std::size_t> along(count);
  for (uint32_t voxel = 0; voxel < count; ++voxel)
  {
    std::size_t c[3];
    unravel(voxel, c[0], c[1], c[2]);
    key[voxel] = static_cast<uint32_t>(c[b] * f.BufferSize[a] + c[a]);
    along[voxel] = c[axis];
    ++start[key[voxel] + 1];
  }
  for (std::size_t k = 0; k < keys; ++k)
  {
    start[k + 1] += start[k];
  }
  std::vector<uint32_t> sorted(count);
  {
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (uint32_t voxel = 0; voxel < count; ++voxel)
    {
      sorted[fill[key[voxel]]++] = voxel; // buffer order: ascending along every axis within a line
    }
  }
  const double             step = f.Spacing[axis];
  std::vector<double>      positions;
  std::vector<double>      values;
  std::vector<uint32_t>    members;
  std::vector<std::size_t> apex;
  std::vector<double>      bound;
  for (std::size_t line = 0; line < keys; ++line)
  {
    if (start[line] == start[line + 1])
    {
      continue;
    }
    positions.clear();
    values.clear();
    members.clear();
    for (uint32_t k = start[line]; k < start[line + 1]; ++k)
    {
      const uint32_t voxel = sorted[k];
      const double   here = static_cast<double>(along[voxel]);
      const bool     runStarts = k == start[line] || along[sorted[k - 1]] + 1 != along[voxel];
      if (runStarts && (positions.empty() || positions.back() < (here - 1.0) * step))
      {
        positions.push_back((here - 1.0) * step); // the background voxel before the run
        values.push_back(0.0);
        members.push_back(UINT32_MAX);
      }
      positions.push_back(here * step);
      values.push_back(squared[voxel]);
      members.push_back(voxel);
      const bool runEnds = k + 1 == start[line + 1] || along[sorted[k + 1]] != along[voxel] + 1;
      if (runEnds)
      {
        positions.push_back((here + 1.0) * step); // the background voxel after it
        values.push_back(0.0);
        members.push_back(UINT32_MAX);
      }
    }
    LowerEnvelope(positions, values, apex, bound);
    for (std::size_t k = 0; k < members.size(); ++k)
    {
      if (members[k] != UINT32_MAX)
      {
        squared[members[k]] = values[k];
      }
    }
  }
}
} // namespace

CenterlineForeground
MakeCenterlineForeground(const CenterlineForeground::MaskImageType * mask)
{
  const auto        region = mask->GetBufferedRegion();
  const std::size_t total = region.GetNumberOfPixels();
  if (total >= (std::size_t{ 1 } << 31))
  {
    itkGenericExceptionMacro(<< "CenterlineForeground: " << total
                             << " voxels in the foreground's bounding box; at most 2^31 - 1 are supported");
  }
  CenterlineForeground foreground;
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    foreground.BufferSize[axis] = region.GetSize(axis);
    foreground.BufferStart[axis] = region.GetIndex(axis);
    foreground.Spacing[axis] = mask->GetSpacing()[axis];
  }
  const std::size_t nx = foreground.BufferSize[0];
  const std::size_t ny = foreground.BufferSize[1];
  const std::size_t nz = foreground.BufferSize[2];
  if (nx < 3 || ny < 3 || nz < 3)
  {
    itkGenericExceptionMacro(<< "CenterlineForeground: the mask buffer " << nx << " x " << ny << " x " << nz
                             << " has no room for a background margin");
  }
  foreground.CompactIndex.assign(total, -1);
  const unsigned char * voxels = mask->GetBufferPointer();
  for (std::size_t z = 0; z < nz; ++z)
  {
    for (std::size_t y = 0; y < ny; ++y)
    {
      const std::size_t row = (z * ny + y) * nx;
      const bool        edgeRow = z == 0 || z + 1 == nz || y == 0 || y + 1 == ny;
      for (std::size_t x = 0; x < nx; ++x)
      {
        if (voxels[row + x] == 0)
        {
          continue;
        }
        if (edgeRow || x == 0 || x + 1 == nx)
        {
          itkGenericExceptionMacro(<< "CenterlineForeground: a foreground voxel lies on the buffer's edge; the mask "
                                      "needs a background margin");
        }
        foreground.CompactIndex[row + x] = static_cast<int32_t>(foreground.Offset.size());
        foreground.Offset.push_back(static_cast<uint32_t>(row + x));
      }
    }
  }
  unsigned int n = 0;
  for (int dz = -1; dz <= 1; ++dz)
  {
    for (int dy = -1; dy <= 1; ++dy)
    {
      for (int dx = -1; dx <= 1; ++dx)
      {
        if (dx == 0 && dy == 0 && dz == 0)
        {
          continue;
        }
        foreground.NeighbourOffset[n] =
          (static_cast<std::ptrdiff_t>(dz) * static_cast<std::ptrdiff_t>(ny) + dy) * static_cast<std::ptrdiff_t>(nx) +
          dx;
        foreground.NeighbourStep[n] = std::sqrt(dx * dx * foreground.Spacing[0] * foreground.Spacing[0] +
                                                dy * dy * foreground.Spacing[1] * foreground.Spacing[1] +
                                                dz * dz * foreground.Spacing[2] * foreground.Spacing[2]);
        ++n;
      }
    }
  }
  // The exact Euclidean distance to the nearest background voxel centre, one separable pass per axis; the first
  // pass starts from farther than anything in the box, which the bounds of each run replace.
  double far = 0.0;
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    far += static_cast<double>(foreground.BufferSize[axis]) * foreground.Spacing[axis];
  }
  std::vector<double> squared(foreground.Size(), 4.0 * far * far);
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    DistancePass(foreground, axis, squared);
  }
  foreground.Distance.resize(foreground.Size());
  for (std::size_t k = 0; k < squared.size(); ++k)
  {
    foreground.Distance[k] = static_cast<float>(std::sqrt(squared[k]));
  }
  return foreground;
}

double
CenterlineForeground::InterpolatedDistance(const std::array<double, 3> & position) const
{
  // Trilinear interpolation over the buffer; background voxels are 0, so is anything outside.
  std::array<double, 3>      fraction{};
  std::array<std::size_t, 3> base{};
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    const double index = position[axis] / Spacing[axis] - static_cast<double>(BufferStart[axis]);
    if (!(index >= 0.0 && index <= static_cast<double>(BufferSize[axis] - 1)))
    {
      return 0.0;
    }
    base[axis] = std::min(static_cast<std::size_t>(index), static_cast<std::size_t>(BufferSize[axis] - 2));
    fraction[axis] = index - static_cast<double>(base[axis]);
  }
  double value = 0.0;
  for (unsigned int corner = 0; corner < 8; ++corner)
  {
    double      weight = 1.0;
    std::size_t offset = 0;
    std::size_t stride = 1;
    for (unsigned int axis = 0; axis < 3; ++axis)
    {
      const std::size_t bit = (corner >> axis) & 1;
      weight *= bit ? fraction[axis] : 1.0 - fraction[axis];
      offset += (base[axis] + bit) * stride;
      stride *= BufferSize[axis];
    }
    const int32_t voxel = CompactIndex[offset];
    if (voxel >= 0 && weight > 0.0)
    {
      value += weight * Distance[static_cast<std::size_t>(voxel)];
    }
  }
  return value;
}

std::vector<std::vector<uint32_t>>
FindForegroundComponents(const CenterlineForeground & foreground)
{
  std::vector<std::vector<uint32_t>> components;
  std::vector<uint8_t>               seen(foreground.Size(), 0);
  for (uint32_t seed = 0; seed < foreground.Size(); ++seed)
  {
    if (seen[seed])
    {
      continue;
    }
    std::vector<uint32_t> members{ seed };
    seen[seed] = 1;
    for (std::size_t next = 0; next < members.size(); ++next)
    {
      foreground.ForEachNeighbour(members[next],
                                  [&](uint32_t neighbour, double)
                                  {
                                    if (!seen[neighbour])
                                    {
                                      seen[neighbour] = 1;
                                      members.push_back(neighbour);
                                    }
                                  });
    }
    components.push_back(std::move(members));
  }
  std::stable_sort(components.begin(),
                   components.end(),
                   [](const std::vector<uint32_t> & a, const std::vector<uint32_t> & b)
                   { return a.size() > b.size(); });
  return components;
}

} // namespace detail
} // namespace itk
