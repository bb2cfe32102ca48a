// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkBilateralDepthRelaxSteadyStragglers.h"

#include "itkBilateralDepthRelaxRangeWeight.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace itk::detail::BilateralDepthRelaxSteady
{
namespace
{
/** Pixels in one window. */
constexpr std::size_t WindowPixels = (2 * StragglerRadius + 1) * (2 * StragglerRadius + 1);

/** The most window pixels: every straggler's whole window, but never more than the grid. */
std::size_t
MostWindowPixels(long width, long height)
{
  return std::min(StragglerBuffers::MostStragglers(width, height) * WindowPixels,
                  static_cast<std::size_t>(width * height));
}

/** Moves every pixel of the window, in raster order, to the mean of its neighbours weighted by the range weights at
 * the current depths (the weight as WeightRow computes it: the difference in double rounded to float; none across
 * the image border), within the input's range; returns the largest move. */
double
Sweep(Field & field, const std::vector<long> & window)
{
  double * depth = field.Depth;
  double   largest = 0.0;
  for (const long p : window)
  {
    const long   x = p % field.Stride - 1;
    const long   y = p / field.Stride - 1;
    const double own = depth[p];
    double       weights = 0.0;
    double       weighted = 0.0;
    auto         edge = [&](long q)
    {
      const double difference = depth[q] - own;
      const float  weight = field.Isotropic ? 1.0f : RangeWeight(static_cast<float>(difference), field.Scale);
      weights += weight;
      weighted += weight * difference;
    };
    if (x > 0)
    {
      edge(p - 1);
    }
    if (x + 1 < field.Width)
    {
      edge(p + 1);
    }
    if (y > 0)
    {
      edge(p - field.Stride);
    }
    if (y + 1 < field.Height)
    {
      edge(p + field.Stride);
    }
    if (weights > 0.0)
    {
      const double moved = std::clamp(own + weighted / weights, field.Lowest, field.Highest);
      largest = std::max(largest, std::abs(moved - own));
      depth[p] = moved;
    }
  }
  return largest;
}

/** The pixels above the tolerance, by the same test as the rows' maxima (RowMaximumOverDiagonal), read only on the
 * rows whose maximum is above it, in row order; false where there are more than the buffers hold. */
bool
FindStragglers(Field & field, StragglerBuffers & buffers, double tolerance)
{
  const std::vector<double> & maxima = field.RowMaxima();
  const std::size_t           most = StragglerBuffers::MostStragglers(field.Width, field.Height);
  buffers.Stragglers.clear();
  for (long y = 0; y < field.Height; ++y)
  {
    if (!(maxima[static_cast<std::size_t>(y)] > tolerance))
    {
      continue;
    }
    const long row = field.At(0, y);
    for (long x = 0; x < field.Width; ++x)
    {
      const float diagonal = field.Finest.C[row + x];
      const float quotient = std::abs(field.Residual[row + x]) / std::max(diagonal, std::numeric_limits<float>::min());
      if (diagonal > 0.0f && quotient > tolerance)
      {
        if (buffers.Stragglers.size() == most)
        {
          return false;
        }
        buffers.Stragglers.push_back({ x, y });
      }
    }
  }
  return !buffers.Stragglers.empty();
}

/** The windows' active pixels, each once, in raster order, and the runs of rows they cover: row by row, the column
 * ranges of the windows that reach the row, merged. */
void
GatherWindows(const Field & field, StragglerBuffers & buffers)
{
  buffers.Ranges.clear();
  for (const auto & straggler : buffers.Stragglers)
  {
    const long first = std::max(straggler.Y - StragglerRadius, 0L);
    const long last = std::min(straggler.Y + StragglerRadius, field.Height - 1);
    if (!buffers.Ranges.empty() && first <= buffers.Ranges.back().Last + 1)
    {
      buffers.Ranges.back().Last = std::max(buffers.Ranges.back().Last, last);
    }
    else
    {
      buffers.Ranges.push_back({ first, last });
    }
  }
  buffers.Window.clear();
  std::size_t from = 0; // the first straggler whose window may reach the row
  for (const auto & range : buffers.Ranges)
  {
    for (long y = range.First; y <= range.Last; ++y)
    {
      while (buffers.Stragglers[from].Y + StragglerRadius < y)
      {
        ++from;
      }
      buffers.Columns.clear();
      for (std::size_t k = from; k < buffers.Stragglers.size() && buffers.Stragglers[k].Y - StragglerRadius <= y; ++k)
      {
        const long x = buffers.Stragglers[k].X;
        buffers.Columns.push_back(
          { std::max(x - StragglerRadius, 0L), std::min(x + StragglerRadius, field.Width - 1) });
      }
      std::sort(buffers.Columns.begin(),
                buffers.Columns.end(),
                [](const StragglerBuffers::Span & a, const StragglerBuffers::Span & b) { return a.First < b.First; });
      long next = 0; // the first column not yet taken on this row
      for (const auto & columns : buffers.Columns)
      {
        for (long x = std::max(columns.First, next); x <= columns.Last; ++x)
        {
          if (field.Active[field.At(x, y)] > 0.0f)
          {
            buffers.Window.push_back(field.At(x, y));
          }
        }
        next = std::max(next, columns.Last + 1);
      }
    }
  }
}

/** One round of SettleStragglers; returns false, with the field as it was, where it settled nothing. */
bool
SettleOnce(Field & field, StragglerBuffers & buffers, double tolerance, bool hessian)
{
  if (!FindStragglers(field, buffers, tolerance))
  {
    return false;
  }
  GatherWindows(field, buffers);
  buffers.Saved.clear();
  for (const long p : buffers.Window)
  {
    buffers.Saved.push_back(field.Depth[p]);
  }
  for (unsigned int sweep = 0; sweep < MaximumStragglerSweeps; ++sweep)
  {
    if (!(Sweep(field, buffers.Window) > StragglerStepFraction * tolerance))
    {
      break;
    }
  }
  bool samePattern = true;
  for (const auto & range : buffers.Ranges)
  {
    samePattern = field.ReassembleRows(range.First, range.Last, hessian) && samePattern;
  }
  if (samePattern)
  {
    return true;
  }
  for (std::size_t k = 0; k < buffers.Window.size(); ++k)
  {
    field.Depth[buffers.Window[k]] = buffers.Saved[k];
  }
  for (const auto & range : buffers.Ranges)
  {
    field.ReassembleRows(range.First, range.Last, hessian);
  }
  return false;
}
} // namespace

std::size_t
StragglerBuffers::MostStragglers(long width, long height)
{
  return std::max(MinimumStragglers, static_cast<std::size_t>(width * height) / PixelsPerStraggler);
}

std::size_t
StragglerBuffers::BytesFor(long width, long height)
{
  const std::size_t stragglers = MostStragglers(width, height);
  return stragglers * (sizeof(Straggler) + 2 * sizeof(Span)) +
         MostWindowPixels(width, height) * (sizeof(long) + sizeof(double));
}

void
StragglerBuffers::Reserve(long width, long height)
{
  const std::size_t stragglers = MostStragglers(width, height);
  const std::size_t pixels = MostWindowPixels(width, height);
  // Exactly these capacities, so that BytesFor counts what is held: fresh vectors where the sizes differ.
  if (Stragglers.capacity() != stragglers || Window.capacity() != pixels)
  {
    Stragglers = std::vector<Straggler>();
    Ranges = std::vector<Span>();
    Columns = std::vector<Span>();
    Window = std::vector<long>();
    Saved = std::vector<double>();
    Stragglers.reserve(stragglers);
    Ranges.reserve(stragglers);
    Columns.reserve(stragglers);
    Window.reserve(pixels);
    Saved.reserve(pixels);
  }
}

double
SettleStragglers(Field & field, StragglerBuffers & buffers, double residual, double tolerance, bool hessian)
{
  for (unsigned int round = 0; round < MaximumStragglerRounds && residual > tolerance; ++round)
  {
    if (!SettleOnce(field, buffers, tolerance, hessian))
    {
      break;
    }
    const std::vector<double> & maxima = field.RowMaxima();
    residual = *std::max_element(maxima.begin(), maxima.end());
  }
  return residual;
}
} // namespace itk::detail::BilateralDepthRelaxSteady
