// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkCPRNearestFill.h"

#include "itkMacro.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace itk::detail
{
namespace
{
constexpr int32_t None = -1;
/** Columns per task of the column pass: its rows are read and written as contiguous runs of this many pixels. */
constexpr SizeValueType ColumnsPerTask = 64;

/** Candidate order: distance, then depth (nearer the viewer), then owner. */
bool
Precedes(double distance, float depth, uint32_t owner, double otherDistance, float otherDepth, uint32_t otherOwner)
{
  if (distance != otherDistance)
  {
    return distance < otherDistance;
  }
  if (depth != otherDepth)
  {
    return depth < otherDepth;
  }
  return owner < otherOwner;
}
} // namespace

void
FillFromNearestSeeds(SizeValueType             width,
                     SizeValueType             height,
                     const Vector<double, 2> & spacing,
                     std::vector<float> &      depth,
                     std::vector<uint32_t> &   owner,
                     MultiThreaderBase *       threader,
                     CPRNearestFillWorkspace & workspace)
{
  const long        columns = static_cast<long>(width);
  const long        rows = static_cast<long>(height);
  const std::size_t count = static_cast<std::size_t>(width) * height;
  if (std::none_of(owner.begin(), owner.end(), [](uint32_t o) { return o != 0; }))
  {
    itkGenericExceptionMacro(<< "CPRDepthImageFilter: no centerline point projects into the " << width << " x "
                             << height
                             << " image (no vessel footprint reaches it); check the view centre, size and "
                                "spacing");
  }
  workspace.ColumnWinner.resize(count);
  int32_t * const winner = workspace.ColumnWinner.data();
  const double    sx = spacing[0];
  const double    sy = spacing[1];

  // Pass 1, per column (in runs of ColumnsPerTask, row by row): the nearest seed of the column, by the order of
  // Precedes with the vertical distance. Adding one horizontal term to every candidate of a column keeps this order,
  // so the 2D nearest seed is the best of the column winners.
  const SizeValueType tasks = (width + ColumnsPerTask - 1) / ColumnsPerTask;
  threader->ParallelizeArray(
    0,
    tasks,
    [&](SizeValueType task)
    {
      const long first = static_cast<long>(task * ColumnsPerTask);
      const long last = std::min(columns, first + static_cast<long>(ColumnsPerTask));
      int32_t    lower[ColumnsPerTask];
      for (long column = first; column < last; ++column)
      {
        const std::size_t k = static_cast<std::size_t>(column);
        winner[k] = owner[k] != 0 ? 0 : None;
      }
      for (long row = 1; row < rows; ++row)
      {
        const std::size_t line = static_cast<std::size_t>(row) * width;
        for (long column = first; column < last; ++column)
        {
          const std::size_t k = line + column;
          winner[k] = owner[k] != 0 ? static_cast<int32_t>(row) : winner[k - width];
        }
      }
      std::fill_n(lower, last - first, None);
      for (long row = rows - 1; row >= 0; --row)
      {
        const std::size_t line = static_cast<std::size_t>(row) * width;
        for (long column = first; column < last; ++column)
        {
          const std::size_t k = line + column;
          int32_t &         below = lower[column - first];
          below = owner[k] != 0 ? static_cast<int32_t>(row) : below;
          const int32_t above = winner[k];
          if (below == None || below == above)
          {
            continue;
          }
          // Whole rows apart on one spacing: the distances compare as integers; only a tie reads the seeds.
          const long toBelow = below - row;
          const long toAbove = row - above;
          if (above == None || toBelow < toAbove)
          {
            winner[k] = below;
          }
          else if (toBelow == toAbove)
          {
            const std::size_t a = static_cast<std::size_t>(above) * width + column;
            const std::size_t b = static_cast<std::size_t>(below) * width + column;
            if (Precedes(0.0, depth[b], owner[b], 0.0, depth[a], owner[a]))
            {
              winner[k] = below;
            }
          }
        }
      }
    },
    nullptr);

  // Pass 2, per row: the lower envelope of g_q(x) = sx^2 (x - q)^2 + f(q) over the columns q with a winner, f(q) the
  // squared vertical distance to it; intersections from h(q) = f(q) + sx^2 q^2.
  const double sx2 = sx * sx;
  threader->ParallelizeArray(
    0,
    height,
    [&](SizeValueType rowIndex)
    {
      thread_local std::vector<long>   envelope;
      thread_local std::vector<double> heights;
      thread_local std::vector<double> boundary;
      envelope.resize(width);
      heights.resize(width);
      boundary.resize(width + 1);
      const long        row = static_cast<long>(rowIndex);
      const std::size_t first = rowIndex * width;
      long              parabolas = 0;
      for (long q = 0; q < columns; ++q)
      {
        const int32_t seedRow = winner[first + q];
        if (seedRow == None)
        {
          continue;
        }
        const double dy = (row - seedRow) * sy;
        const double hq = dy * dy + sx2 * q * q;
        if (parabolas == 0)
        {
          envelope[0] = q;
          heights[0] = hq;
          boundary[0] = -std::numeric_limits<double>::infinity();
          boundary[1] = std::numeric_limits<double>::infinity();
          parabolas = 1;
          continue;
        }
        // A parabola that only ties the envelope at one point stays (strictly below pops), so that a tie at a
        // pixel finds every candidate among the envelope's neighbours there.
        double s = (hq - heights[parabolas - 1]) / (2.0 * sx2 * (q - envelope[parabolas - 1]));
        while (parabolas > 1 && s < boundary[parabolas - 1] - 1e-9 * (1.0 + std::abs(s)))
        {
          --parabolas;
          s = (hq - heights[parabolas - 1]) / (2.0 * sx2 * (q - envelope[parabolas - 1]));
        }
        envelope[parabolas] = q;
        heights[parabolas] = hq;
        boundary[parabolas] = s;
        boundary[parabolas + 1] = std::numeric_limits<double>::infinity();
        ++parabolas;
      }

      const auto source = [&](long q)
      { return static_cast<std::size_t>(winner[first + q]) * width + static_cast<std::size_t>(q); };
      const auto distance = [&](long x, long k)
      {
        const double dx = (x - envelope[k]) * sx;
        const double dy = (row - winner[first + envelope[k]]) * sy;
        return dx * dx + dy * dy;
      };
      long k = 0;
      for (long x = 0; x < columns; ++x)
      {
        while (k + 1 < parabolas && boundary[k + 1] < x)
        {
          ++k;
        }
        const std::size_t pixel = first + x;
        if (owner[pixel] != 0)
        {
          continue;
        }
        long best = k;
        // Within a pixel of the ends of the envelope's interval, its neighbours may tie with its choice: Precedes
        // decides, as Nearest mode orders candidates.
        if (x - boundary[k] < 1.0 || boundary[k + 1] - x < 1.0)
        {
          double bestDistance = distance(x, k);
          for (long neighbour = std::max(0L, k - 2); neighbour <= std::min(parabolas - 1, k + 2); ++neighbour)
          {
            if (neighbour == k)
            {
              continue;
            }
            const double d = distance(x, neighbour);
            if (d < bestDistance || (d == bestDistance && Precedes(d,
                                                                   depth[source(envelope[neighbour])],
                                                                   owner[source(envelope[neighbour])],
                                                                   bestDistance,
                                                                   depth[source(envelope[best])],
                                                                   owner[source(envelope[best])])))
            {
              best = neighbour;
              bestDistance = d;
            }
          }
        }
        const std::size_t from = source(envelope[best]);
        depth[pixel] = depth[from];
        owner[pixel] = owner[from];
      }
    },
    nullptr);
}
} // namespace itk::detail
