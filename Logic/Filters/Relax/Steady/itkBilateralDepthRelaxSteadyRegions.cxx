// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkBilateralDepthRelaxSteadyRegions.h"

#include <algorithm>

namespace itk::detail::BilateralDepthRelaxSteady
{
std::size_t
ClassifyFloatingRegions(RegionBuffers & buffers, Bands & bands, const RegionGrid & grid, bool & changed)
{
  Regions &             regions = buffers.RunRegions;
  std::vector<RowRun> & runs = buffers.Runs;
  std::vector<long> &   rowStart = buffers.RowRunStart;
  const std::size_t     rowCount = static_cast<std::size_t>(grid.Height);
  // The runs of each row (a run ends at a vanishing weight to its right or at the row's end), then their places.
  rowStart.assign(rowCount + 1, 0);
  bands.ForRows(grid.Height,
                true,
                [&](long y0, long y1)
                {
                  for (long y = y0; y < y1; ++y)
                  {
                    const float * right = grid.WeightRight + grid.RowStart(y);
                    long          count = 1;
                    for (long x = 0; x + 1 < grid.Width; ++x)
                    {
                      count += right[x] == 0.0f ? 1 : 0;
                    }
                    rowStart[static_cast<std::size_t>(y) + 1] = count;
                  }
                });
  for (std::size_t y = 0; y < rowCount; ++y)
  {
    rowStart[y + 1] += rowStart[y];
  }
  const std::size_t   count = static_cast<std::size_t>(rowStart[rowCount]);
  std::vector<char> & fixedRun = buffers.RunFixed;
  runs.resize(count);
  fixedRun.assign(count, 0);
  bands.ForRows(grid.Height,
                true,
                [&](long y0, long y1)
                {
                  for (long y = y0; y < y1; ++y)
                  {
                    const float * right = grid.WeightRight + grid.RowStart(y);
                    const float * fixed = grid.Fixed + grid.RowStart(y);
                    long          k = rowStart[static_cast<std::size_t>(y)];
                    long          begin = 0;
                    for (long x = 0; x < grid.Width; ++x)
                    {
                      if (x + 1 == grid.Width || right[x] == 0.0f)
                      {
                        runs[static_cast<std::size_t>(k)] = { begin, x + 1, static_cast<std::int32_t>(k) };
                        fixedRun[static_cast<std::size_t>(k)] =
                          std::any_of(fixed + begin, fixed + x + 1, [](float value) { return value != 0.0f; });
                        ++k;
                        begin = x + 1;
                      }
                    }
                  }
                });
  // Walks the overlapping runs of rows y and y + 1 in order. Row pair y's walk takes fewer than
  // rowStart[y + 2] - rowStart[y] steps, so its steps can be numbered from rowStart[y] + rowStart[y + 1].
  auto walk = [&](long y, const auto & step)
  {
    const std::size_t row = static_cast<std::size_t>(y);
    std::size_t       a = static_cast<std::size_t>(rowStart[row]);
    std::size_t       b = static_cast<std::size_t>(rowStart[row + 1]);
    const std::size_t aEnd = b;
    const std::size_t bEnd = static_cast<std::size_t>(rowStart[row + 2]);
    std::size_t       number = static_cast<std::size_t>(rowStart[row] + rowStart[row + 1]);
    while (a < aEnd && b < bEnd)
    {
      step(a, b, number++);
      runs[a].End < runs[b].End ? ++a : ++b;
    }
  };
  // Whether each such pair is joined by a non-zero weight, in parallel; then the unions, in order.
  std::vector<char> & joined = buffers.RunJoined;
  joined.assign(2 * count, 0);
  bands.ForRows(grid.Height - 1,
                true,
                [&](long y0, long y1)
                {
                  for (long y = y0; y < y1; ++y)
                  {
                    const float * down = grid.WeightDown + grid.RowStart(y);
                    walk(y,
                         [&](std::size_t a, std::size_t b, std::size_t number)
                         {
                           const long begin = std::max(runs[a].Begin, runs[b].Begin);
                           const long end = std::min(runs[a].End, runs[b].End);
                           joined[number] =
                             std::any_of(down + begin, down + end, [](float weight) { return weight > 0.0f; });
                         });
                  }
                });
  regions.Reset(count);
  for (long y = 0; y + 1 < grid.Height; ++y)
  {
    walk(y,
         [&](std::size_t a, std::size_t b, std::size_t number)
         {
           if (joined[number])
           {
             regions.Unite(runs[a].Region, runs[b].Region);
           }
         });
  }
  std::vector<char> & anchored = buffers.RegionAnchored;
  anchored.assign(count, 0);
  for (std::size_t k = 0; k < count; ++k)
  {
    runs[k].Region = regions.Find(runs[k].Region);
    anchored[static_cast<std::size_t>(runs[k].Region)] |= fixedRun[k];
  }
  // The mean depth of each floating region, over its free pixels (a floating region has no fixed ones).
  std::vector<double> & sum = buffers.RegionSum;
  std::vector<double> & pixels = buffers.RegionPixels;
  sum.assign(count, 0.0);
  pixels.assign(count, 0.0);
  for (long y = 0; y < grid.Height; ++y)
  {
    const double * depth = grid.Depth + grid.RowStart(y);
    for (long k = rowStart[static_cast<std::size_t>(y)]; k < rowStart[static_cast<std::size_t>(y + 1)]; ++k)
    {
      const RowRun & run = runs[static_cast<std::size_t>(k)];
      if (!anchored[static_cast<std::size_t>(run.Region)])
      {
        for (long x = run.Begin; x < run.End; ++x)
        {
          sum[static_cast<std::size_t>(run.Region)] += depth[x];
        }
        pixels[static_cast<std::size_t>(run.Region)] += static_cast<double>(run.End - run.Begin);
      }
    }
  }
  // Activity and the floating regions' means, per row; the counts per row are added in order.
  std::vector<double> & rowCounts = buffers.RowFloating;
  rowCounts.assign(rowCount, 0.0);
  std::vector<char> & rowChanged = buffers.RowChanged;
  rowChanged.assign(rowCount, 0);
  bands.ForRows(grid.Height,
                true,
                [&](long y0, long y1)
                {
                  for (long y = y0; y < y1; ++y)
                  {
                    const long    row = grid.RowStart(y);
                    const float * fixed = grid.Fixed + row;
                    float *       active = grid.Active + row;
                    double *      depth = grid.Depth + row;
                    long          floating = 0;
                    long          changes = 0;
                    for (long k = rowStart[static_cast<std::size_t>(y)]; k < rowStart[static_cast<std::size_t>(y + 1)];
                         ++k)
                    {
                      const RowRun &    run = runs[static_cast<std::size_t>(k)];
                      const std::size_t region = static_cast<std::size_t>(run.Region);
                      if (anchored[region])
                      {
                        for (long x = run.Begin; x < run.End; ++x)
                        {
                          const float now = 1.0f - fixed[x];
                          changes += now != active[x];
                          active[x] = now;
                        }
                      }
                      else
                      {
                        const double mean = sum[region] / pixels[region];
                        for (long x = run.Begin; x < run.End; ++x)
                        {
                          changes += active[x] != 0.0f;
                          active[x] = 0.0f;
                          depth[x] = mean;
                        }
                        floating += run.End - run.Begin;
                      }
                    }
                    rowCounts[static_cast<std::size_t>(y)] = static_cast<double>(floating);
                    rowChanged[static_cast<std::size_t>(y)] = changes > 0 ? 1 : 0;
                  }
                });
  std::size_t floating = 0;
  changed = false;
  for (std::size_t y = 0; y < rowCount; ++y)
  {
    floating += static_cast<std::size_t>(rowCounts[y]);
    changed = changed || rowChanged[y] != 0;
  }
  return floating;
}

} // namespace itk::detail::BilateralDepthRelaxSteady
