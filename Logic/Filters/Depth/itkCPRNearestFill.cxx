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

/** One parabola of a row's lower envelope: its column, h(q), the squared vertical distance f(q) and its seed (row,
 * depth, owner). */
struct EnvelopeParabola
{
  long     Column;
  double   Height;
  double   VerticalSquared;
  int32_t  SeedRow;
  float    Depth;
  uint32_t Owner;
};
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
      const long n = std::min(columns, first + static_cast<long>(ColumnsPerTask)) - first;
      // The nearest seed row at or above, then at or below, the current row of each column. The loops over the
      // task's columns carry nothing from column to column and branch nowhere, so the compiler vectorises them; the
      // rare ties go to a second loop.
      int32_t upper[ColumnsPerTask];
      int32_t lower[ColumnsPerTask];
      std::fill_n(upper, n, None);
      for (long row = 0; row < rows; ++row)
      {
        const uint32_t * seeds = owner.data() + static_cast<std::size_t>(row) * width + first;
        int32_t *        winners = winner + static_cast<std::size_t>(row) * width + first;
        for (long c = 0; c < n; ++c)
        {
          upper[c] = seeds[c] != 0 ? static_cast<int32_t>(row) : upper[c];
          winners[c] = upper[c];
        }
      }
      std::fill_n(lower, n, None);
      for (long row = rows - 1; row >= 0; --row)
      {
        const uint32_t * seeds = owner.data() + static_cast<std::size_t>(row) * width + first;
        int32_t *        winners = winner + static_cast<std::size_t>(row) * width + first;
        const auto       here = static_cast<int32_t>(row);
        int32_t          ties = 0;
        for (long c = 0; c < n; ++c)
        {
          const int32_t below = seeds[c] != 0 ? here : lower[c];
          lower[c] = below;
          const int32_t above = winners[c];
          // Whole rows apart on one spacing: the distances compare as integers; only a tie reads the seeds.
          const int32_t toBelow = below - here;
          const int32_t toAbove = here - above;
          const bool    differ = below != None && below != above;
          const bool    closer = above == None || toBelow < toAbove;
          ties |= static_cast<int32_t>(differ && above != None && toBelow == toAbove);
          winners[c] = differ && closer ? below : above;
        }
        if (ties == 0)
        {
          continue;
        }
        for (long c = 0; c < n; ++c)
        {
          const int32_t below = lower[c];
          const int32_t above = winners[c];
          if (below == None || above == None || below == above || below - here != here - above)
          {
            continue;
          }
          const std::size_t a = static_cast<std::size_t>(above) * width + static_cast<std::size_t>(first + c);
          const std::size_t b = static_cast<std::size_t>(below) * width + static_cast<std::size_t>(first + c);
          if (Precedes(0.0, depth[b], owner[b], 0.0, depth[a], owner[a]))
          {
            winners[c] = below;
          }
        }
      }
    },
    nullptr);

  // Pass 2, per row: the lower envelope of g_q(x) = sx^2 (x - q)^2 + f(q) over the columns q with a winner, f(q) the
  // squared vertical distance to it; intersections from h(q) = f(q) + sx^2 q^2. Each parabola of the envelope reads
  // its seed's depth and owner once, not once for every pixel it fills (the seeds lie in other rows: cache misses).
  const double sx2 = sx * sx;
  threader->ParallelizeArray(
    0,
    height,
    [&](SizeValueType rowIndex)
    {
      thread_local std::vector<EnvelopeParabola> envelope;
      thread_local std::vector<double>           boundary;
      envelope.resize(width);
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
        const double dy2 = dy * dy;
        const double hq = dy2 + sx2 * q * q;
        if (parabolas == 0)
        {
          envelope[0] = { q, hq, dy2, seedRow, 0.0f, 0 };
          boundary[0] = -std::numeric_limits<double>::infinity();
          boundary[1] = std::numeric_limits<double>::infinity();
          parabolas = 1;
          continue;
        }
        // A parabola that only ties the envelope at one point stays (strictly below pops), so that a tie at a
        // pixel finds every candidate among the envelope's neighbours there.
        double s = (hq - envelope[parabolas - 1].Height) / (2.0 * sx2 * (q - envelope[parabolas - 1].Column));
        while (parabolas > 1 && s < boundary[parabolas - 1] - 1e-9 * (1.0 + std::abs(s)))
        {
          --parabolas;
          s = (hq - envelope[parabolas - 1].Height) / (2.0 * sx2 * (q - envelope[parabolas - 1].Column));
        }
        envelope[parabolas] = { q, hq, dy2, seedRow, 0.0f, 0 };
        boundary[parabolas] = s;
        boundary[parabolas + 1] = std::numeric_limits<double>::infinity();
        ++parabolas;
      }
      for (long k = 0; k < parabolas; ++k)
      {
        EnvelopeParabola & parabola = envelope[k];
        const std::size_t  from =
          static_cast<std::size_t>(parabola.SeedRow) * width + static_cast<std::size_t>(parabola.Column);
        parabola.Depth = depth[from];
        parabola.Owner = owner[from];
      }

      const auto distance = [&](long x, long k)
      {
        const double dx = (x - envelope[k].Column) * sx;
        return dx * dx + envelope[k].VerticalSquared;
      };
      // Within a pixel of the ends of the envelope's interval, its neighbours may tie with its choice: Precedes
      // decides, as Nearest mode orders candidates.
      const auto isNearAnEnd = [&](long x, long k) { return x - boundary[k] < 1.0 || boundary[k + 1] - x < 1.0; };
      const auto fillNearAnEnd = [&](long x, long k)
      {
        const std::size_t pixel = first + x;
        if (owner[pixel] != 0)
        {
          return;
        }
        long   best = k;
        double bestDistance = distance(x, k);
        for (long neighbour = std::max(0L, k - 2); neighbour <= std::min(parabolas - 1, k + 2); ++neighbour)
        {
          if (neighbour == k)
          {
            continue;
          }
          const double d = distance(x, neighbour);
          if (d < bestDistance || (d == bestDistance && Precedes(d,
                                                                 envelope[neighbour].Depth,
                                                                 envelope[neighbour].Owner,
                                                                 bestDistance,
                                                                 envelope[best].Depth,
                                                                 envelope[best].Owner)))
          {
            best = neighbour;
            bestDistance = d;
          }
        }
        depth[pixel] = envelope[best].Depth;
        owner[pixel] = envelope[best].Owner;
      };
      // Parabola k fills the pixels x with boundary[k] < x <= boundary[k + 1] (the first k whose interval reaches x),
      // run by run: the pixels near its ends one by one (the test is monotone in x), those between from its seed.
      long k = 0;
      for (long x = 0; x < columns;)
      {
        while (k + 1 < parabolas && boundary[k + 1] < x)
        {
          ++k;
        }
        const long end = boundary[k + 1] >= static_cast<double>(columns - 1)
                           ? columns
                           : static_cast<long>(std::floor(boundary[k + 1])) + 1;
        long       low = x;
        for (; low < end && isNearAnEnd(low, k); ++low)
        {
          fillNearAnEnd(low, k);
        }
        long high = end;
        for (; high > low && isNearAnEnd(high - 1, k); --high)
        {
          fillNearAnEnd(high - 1, k);
        }
        const float    seedDepth = envelope[k].Depth;
        const uint32_t seedOwner = envelope[k].Owner;
        for (std::size_t pixel = first + low; pixel < first + high; ++pixel)
        {
          if (owner[pixel] == 0)
          {
            depth[pixel] = seedDepth;
            owner[pixel] = seedOwner;
          }
        }
        x = end;
      }
    },
    nullptr);
}
} // namespace itk::detail
