// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkCPRDepthAssignment.h"

#include "itkMacro.h"

#include <cmath>
#include <limits>

namespace itk
{
std::ostream &
operator<<(std::ostream & os, CPRDepthMode mode)
{
  switch (mode)
  {
    case CPRDepthMode::Nearest:
      return os << "Nearest";
    case CPRDepthMode::Visibility:
      return os << "Visibility";
    default:
      return os << "Scanline";
  }
}

namespace detail
{
namespace
{
constexpr long None = -1;

/** Candidate order: distance, then depth (nearer the viewer), then branch id. */
bool
Precedes(double distance, double depth, uint32_t owner, double otherDistance, double otherDepth, uint32_t otherOwner)
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

bool
IsWithinLumen(const CPRCenterlinePixels & pixels, std::size_t source, double distanceInMillimetres)
{
  const double radius = pixels.Radius[source];
  return !std::isnan(radius) && distanceInMillimetres <= radius;
}

void
AssignScanline(const CPRCenterlinePixels & pixels,
               double                      columnSpacing,
               bool                        fixLumen,
               MultiThreaderBase *         threader,
               CPRDepthAssignment &        result)
{
  const std::size_t          width = pixels.Width;
  const std::size_t          height = pixels.Height;
  std::vector<unsigned char> rowHasCenterline(height, 0);

  threader->ParallelizeArray(
    0,
    height,
    [&](SizeValueType row)
    {
      const std::size_t first = row * width;
      std::vector<long> nearestRight(width, None);
      long              next = None;
      for (long column = static_cast<long>(width) - 1; column >= 0; --column)
      {
        next = pixels.IsCenterline(first + column) ? column : next;
        nearestRight[column] = next;
      }
      if (nearestRight[0] == None)
      {
        return;
      }
      rowHasCenterline[row] = 1;
      long previous = None;
      for (long column = 0; column < static_cast<long>(width); ++column)
      {
        previous = pixels.IsCenterline(first + column) ? column : previous;
        const long left = previous;
        const long right = nearestRight[column];
        long       chosen = left;
        if (left == None || (right != None && Precedes(right - column,
                                                       pixels.Depth[first + right],
                                                       pixels.Owner[first + right],
                                                       column - left,
                                                       pixels.Depth[first + left],
                                                       pixels.Owner[first + left])))
        {
          chosen = right;
        }
        const std::size_t k = first + column;
        const std::size_t source = first + chosen;
        result.Depth[k] = static_cast<float>(pixels.Depth[source]);
        result.Owner[k] = pixels.Owner[source];
        const double distance = std::abs(column - chosen) * columnSpacing;
        result.Fixed[k] = (chosen == column || (fixLumen && IsWithinLumen(pixels, source, distance))) ? 1 : 0;
      }
    },
    nullptr);

  // Rows without a centerline pixel copy the nearest row that has one (the upper one on a tie).
  std::vector<long> nearestFilledRow(height, None);
  long              previous = None;
  for (std::size_t row = 0; row < height; ++row)
  {
    previous = rowHasCenterline[row] ? static_cast<long>(row) : previous;
    nearestFilledRow[row] = previous;
  }
  long next = None;
  for (long row = static_cast<long>(height) - 1; row >= 0; --row)
  {
    next = rowHasCenterline[row] ? row : next;
    const long above = nearestFilledRow[row];
    if (above == None || (next != None && next - row < row - above))
    {
      nearestFilledRow[row] = next;
    }
  }
  if (nearestFilledRow[0] == None)
  {
    itkGenericExceptionMacro(<< "CPRDepthImageFilter: no centerline point projects into the " << width << " x "
                             << height << " image; check the view centre, size and spacing");
  }
  for (std::size_t row = 0; row < height; ++row)
  {
    if (rowHasCenterline[row])
    {
      continue;
    }
    const std::size_t source = static_cast<std::size_t>(nearestFilledRow[row]) * width;
    std::copy_n(result.Depth.begin() + source, width, result.Depth.begin() + row * width);
    std::copy_n(result.Owner.begin() + source, width, result.Owner.begin() + row * width);
  }
}

void
AssignNearest(const CPRCenterlinePixels & pixels,
              const Vector<double, 2> &   spacing,
              bool                        fixLumen,
              MultiThreaderBase *         threader,
              CPRDepthAssignment &        result)
{
  const long width = static_cast<long>(pixels.Width);
  const long height = static_cast<long>(pixels.Height);
  if (pixels.CountCenterlinePixels() == 0)
  {
    itkGenericExceptionMacro(<< "CPRDepthImageFilter: no centerline point projects into the " << width << " x "
                             << height << " image; check the view centre, size and spacing");
  }

  // Pass 1, per column: the nearest centerline pixel in the column (row index), ordered like Precedes with the
  // vertical distance. Adding the same horizontal term to every candidate of a column keeps this order, so the
  // 2D nearest pixel is the best of these column winners (the separable exact Euclidean distance transform).
  std::vector<long>   columnWinner(static_cast<std::size_t>(width * height), None);
  std::vector<double> columnDistance(static_cast<std::size_t>(width * height), 0.0);
  threader->ParallelizeArray(
    0,
    width,
    [&](SizeValueType column)
    {
      auto              pixelIndex = [&](long row) { return static_cast<std::size_t>(row * width) + column; };
      std::vector<long> upper(height, None);
      long              previous = None;
      for (long row = 0; row < height; ++row)
      {
        previous = pixels.IsCenterline(pixelIndex(row)) ? row : previous;
        upper[row] = previous;
      }
      long lower = None;
      for (long row = height - 1; row >= 0; --row)
      {
        lower = pixels.IsCenterline(pixelIndex(row)) ? row : lower;
        long chosen = upper[row];
        if (chosen == None || (lower != None && Precedes((lower - row) * spacing[1],
                                                         pixels.Depth[pixelIndex(lower)],
                                                         pixels.Owner[pixelIndex(lower)],
                                                         (row - chosen) * spacing[1],
                                                         pixels.Depth[pixelIndex(chosen)],
                                                         pixels.Owner[pixelIndex(chosen)])))
        {
          chosen = lower;
        }
        columnWinner[pixelIndex(row)] = chosen;
        if (chosen != None)
        {
          const double dy = (row - chosen) * spacing[1];
          columnDistance[pixelIndex(row)] = dy * dy;
        }
      }
    },
    nullptr);

  // Pass 2, per row: scan the column winners outwards until the horizontal distance alone exceeds the best.
  threader->ParallelizeArray(
    0,
    height,
    [&](SizeValueType row)
    {
      const std::size_t first = row * width;
      for (long column = 0; column < width; ++column)
      {
        double      bestDistance = std::numeric_limits<double>::infinity();
        double      bestDepth = 0.0;
        uint32_t    bestOwner = 0;
        std::size_t bestSource = 0;
        for (long offset = 0; offset < width; ++offset)
        {
          const double dx = offset * spacing[0];
          if (dx * dx > bestDistance)
          {
            break;
          }
          for (const long candidate : { column - offset, column + offset })
          {
            if (candidate < 0 || candidate >= width || (offset == 0 && candidate != column - offset))
            {
              continue;
            }
            const long winnerRow = columnWinner[first + candidate];
            if (winnerRow == None)
            {
              continue;
            }
            const std::size_t source = static_cast<std::size_t>(winnerRow * width + candidate);
            const double      distance = dx * dx + columnDistance[first + candidate];
            if (bestOwner == 0 ||
                Precedes(distance, pixels.Depth[source], pixels.Owner[source], bestDistance, bestDepth, bestOwner))
            {
              bestDistance = distance;
              bestDepth = pixels.Depth[source];
              bestOwner = pixels.Owner[source];
              bestSource = source;
            }
          }
        }
        const std::size_t k = first + column;
        result.Depth[k] = static_cast<float>(bestDepth);
        result.Owner[k] = bestOwner;
        result.Fixed[k] =
          (bestSource == k || (fixLumen && IsWithinLumen(pixels, bestSource, std::sqrt(bestDistance)))) ? 1 : 0;
      }
    },
    nullptr);
}
} // namespace

void
AssignDepth(const CPRCenterlinePixels & pixels,
            CPRDepthMode                mode,
            const Vector<double, 2> &   spacing,
            bool                        fixLumen,
            MultiThreaderBase *         threader,
            CPRDepthAssignment &        result)
{
  const std::size_t count = static_cast<std::size_t>(pixels.Width) * pixels.Height;
  result.Depth.assign(count, 0.0f);
  result.Fixed.assign(count, 0);
  result.Owner.assign(count, 0);
  result.Hidden.clear();
  if (mode == CPRDepthMode::Scanline)
  {
    AssignScanline(pixels, spacing[0], fixLumen, threader, result);
  }
  else
  {
    AssignNearest(pixels, spacing, fixLumen, threader, result);
  }
}

} // namespace detail
} // namespace itk
