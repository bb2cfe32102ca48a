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
  workspace.ColumnWinner.assign(count, None);
  workspace.ColumnDistance.assign(count, std::numeric_limits<double>::infinity());
  int32_t * const columnWinner = workspace.ColumnWinner.data();
  double * const  columnDistance = workspace.ColumnDistance.data();
  const double    sx = spacing[0];
  const double    sy = spacing[1];

  // Pass 1, per column: the nearest seed of the column (its row) and the squared vertical distance in mm^2.
  threader->ParallelizeArray(
    0,
    width,
    [&](SizeValueType column)
    {
      auto    at = [&](long row) { return static_cast<std::size_t>(row) * width + column; };
      int32_t upper = None;
      for (long row = 0; row < rows; ++row)
      {
        upper = owner[at(row)] != 0 ? static_cast<int32_t>(row) : upper;
        columnWinner[at(row)] = upper;
      }
      int32_t lower = None;
      for (long row = rows - 1; row >= 0; --row)
      {
        lower = owner[at(row)] != 0 ? static_cast<int32_t>(row) : lower;
        int32_t chosen = columnWinner[at(row)];
        if (chosen == None || (lower != None && Precedes((lower - row) * sy,
                                                         depth[at(lower)],
                                                         owner[at(lower)],
                                                         (row - chosen) * sy,
                                                         depth[at(chosen)],
                                                         owner[at(chosen)])))
        {
          chosen = lower;
        }
        columnWinner[at(row)] = chosen;
        if (chosen != None)
        {
          const double dy = (row - chosen) * sy;
          columnDistance[at(row)] = dy * dy;
        }
      }
    },
    nullptr);

  // Pass 2, per row: the lower envelope of g_q(x) = ((x - q) sx)^2 + f(q) over the columns q with a winner.
  threader->ParallelizeArray(
    0,
    height,
    [&](SizeValueType row)
    {
      const std::size_t   first = row * width;
      std::vector<long>   envelope(width);
      std::vector<double> boundary(width + 1);
      const auto          f = [&](long q) { return columnDistance[first + q]; };
      const auto          intersection = [&](long p, long q)
      { return ((f(q) + sx * sx * q * q) - (f(p) + sx * sx * p * p)) / (2.0 * sx * sx * (q - p)); };
      long parabolas = 0;
      for (long q = 0; q < columns; ++q)
      {
        if (columnWinner[first + q] == None)
        {
          continue;
        }
        if (parabolas == 0)
        {
          envelope[0] = q;
          boundary[0] = -std::numeric_limits<double>::infinity();
          boundary[1] = std::numeric_limits<double>::infinity();
          parabolas = 1;
          continue;
        }
        // A parabola that only ties the envelope at one point stays (strictly below pops), so that a tie at a
        // pixel finds every candidate among the envelope's neighbours there.
        double s = intersection(envelope[parabolas - 1], q);
        while (parabolas > 1 && s < boundary[parabolas - 1] - 1e-9 * (1.0 + std::abs(s)))
        {
          --parabolas;
          s = intersection(envelope[parabolas - 1], q);
        }
        envelope[parabolas] = q;
        boundary[parabolas] = s;
        boundary[parabolas + 1] = std::numeric_limits<double>::infinity();
        ++parabolas;
      }

      const auto source = [&](long q)
      { return static_cast<std::size_t>(columnWinner[first + q]) * width + static_cast<std::size_t>(q); };
      const auto distance = [&](long x, long q)
      {
        const double dx = (x - q) * sx;
        return dx * dx + f(q);
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
        // The envelope's neighbours may tie with its choice at x: the order of candidates decides.
        long   best = envelope[k];
        double bestDistance = distance(x, best);
        for (long neighbour = std::max(0L, k - 2); neighbour <= std::min(parabolas - 1, k + 2); ++neighbour)
        {
          if (neighbour == k)
          {
            continue;
          }
          const long   q = envelope[neighbour];
          const double d = distance(x, q);
          if (Precedes(d, depth[source(q)], owner[source(q)], bestDistance, depth[source(best)], owner[source(best)]))
          {
            best = q;
            bestDistance = d;
          }
        }
        depth[pixel] = depth[source(best)];
        owner[pixel] = owner[source(best)];
      }
    },
    nullptr);
}
} // namespace itk::detail
