// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The steady solver's floating-region classification alone, on small grids worked by hand: which free pixels no fixed
// pixel reaches through non-zero weights, the mean depth each such region takes, the activity of the others, and
// whether anything changed; the same for any number of threads.
#include "itkBilateralDepthRelaxSteadyRegions.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace
{
namespace Steady = itk::detail::BilateralDepthRelaxSteady;

/** A padded grid of \a rows (one string per row, bottom row first): 'F' a fixed pixel, '.' a free one; every
 * weight 1 except those named 0 by \a cutRight (x, y: the edge from (x, y) to (x + 1, y)) and \a cutUp (to
 * (x, y + 1)). Depth of (x, y) = 10 y + x. */
struct Grid
{
  long                Width;
  long                Height;
  long                Stride;
  std::vector<float>  Right, Up, Fixed, Active;
  std::vector<double> Depth;

  Grid(const std::vector<std::string> & rows)
    : Width(static_cast<long>(rows[0].size()))
    , Height(static_cast<long>(rows.size()))
    , Stride(Steady::PaddedStride(Width))
    , Right(Steady::PaddedSize(Width, Height), 0.0f)
    , Up(Right.size(), 0.0f)
    , Fixed(Right.size(), 0.0f)
    , Active(Right.size(), 0.0f)
    , Depth(Right.size(), 0.0)
  {
    for (long y = 0; y < Height; ++y)
    {
      for (long x = 0; x < Width; ++x)
      {
        const long p = At(x, y);
        Right[p] = x + 1 < Width ? 1.0f : 0.0f;
        Up[p] = y + 1 < Height ? 1.0f : 0.0f;
        Fixed[p] = rows[static_cast<std::size_t>(y)][static_cast<std::size_t>(x)] == 'F' ? 1.0f : 0.0f;
        Depth[p] = 10.0 * y + x;
      }
    }
  }
  long
  At(long x, long y) const
  {
    return (y + 1) * Stride + x + 1;
  }
  void
  CutRight(long x, long y)
  {
    Right[At(x, y)] = 0.0f;
  }
  void
  CutUp(long x, long y)
  {
    Up[At(x, y)] = 0.0f;
  }
  std::size_t
  Classify(bool & changed, unsigned int threads = 1)
  {
    Steady::BandBuffers      bandBuffers;
    Steady::Bands            bands(bandBuffers, threads, Height, Stride);
    Steady::RegionBuffers    buffers;
    const Steady::RegionGrid grid{ Width,     Height,       Stride,        Right.data(),
                                   Up.data(), Fixed.data(), Active.data(), Depth.data() };
    return Steady::ClassifyFloatingRegions(buffers, bands, grid, changed);
  }
};
} // namespace

// A wall of cut weights between columns 2 and 3: the left part holds the fixed pixel, the right part none. The right
// part floats and takes its mean depth: columns 3 to 5 of rows 0 to 2, mean x 4, mean y 1, so 10 + 4 = 14.
TEST(BilateralDepthRelaxSteadyRegions, ARegionWithoutAFixedPixelFloatsAtItsMean)
{
  Grid grid({ "F.....", "......", "......" });
  for (long y = 0; y < 3; ++y)
  {
    grid.CutRight(2, y);
  }
  bool changed = false;
  EXPECT_EQ(grid.Classify(changed), 9u);
  EXPECT_TRUE(changed);
  for (long y = 0; y < 3; ++y)
  {
    for (long x = 0; x < 6; ++x)
    {
      const long p = grid.At(x, y);
      if (x >= 3)
      {
        EXPECT_EQ(grid.Active[p], 0.0f) << x << ", " << y;
        EXPECT_DOUBLE_EQ(grid.Depth[p], 14.0) << x << ", " << y;
      }
      else
      {
        EXPECT_EQ(grid.Active[p], x == 0 && y == 0 ? 0.0f : 1.0f) << x << ", " << y;
        EXPECT_DOUBLE_EQ(grid.Depth[p], 10.0 * y + x) << x << ", " << y;
      }
    }
  }
  // The same weights again: nothing changes.
  grid.Active.assign(grid.Active.size(), 0.0f);
  EXPECT_EQ(grid.Classify(changed), 9u);
  EXPECT_TRUE(changed) << "activity written afresh after it was cleared";
  EXPECT_EQ(grid.Classify(changed), 9u);
  EXPECT_FALSE(changed);
}

// A region joined to the anchored one only through a single weight to the row above, far from its own row's joins,
// is anchored; cut that weight and it floats.
TEST(BilateralDepthRelaxSteadyRegions, OneWeightToTheNextRowAnchorsARegion)
{
  Grid grid({ "F....", "....." });
  for (long x = 0; x < 5; ++x)
  {
    if (x != 4)
    {
      grid.CutUp(x, 0);
    }
  }
  bool changed = false;
  EXPECT_EQ(grid.Classify(changed), 0u);
  grid.CutUp(4, 0);
  EXPECT_EQ(grid.Classify(changed), 5u);
  EXPECT_TRUE(changed);
  // Row 1 floats at its mean: 10 + 2.
  for (long x = 0; x < 5; ++x)
  {
    EXPECT_DOUBLE_EQ(grid.Depth[grid.At(x, 1)], 12.0);
    EXPECT_EQ(grid.Active[grid.At(x, 1)], 0.0f);
  }
}

// A free pixel whose four weights all vanish is a region of its own: it floats, keeping its value; a fixed pixel
// cut off the same way is no floating pixel. Regions joined through a U-shaped path (the union-find must merge runs
// met in either order) share their anchor.
TEST(BilateralDepthRelaxSteadyRegions, IsolatedPixelsAndWindingRegions)
{
  Grid grid({ "F......", ".......", ".......", "......F" });
  // Isolate (3, 1); isolate the fixed (6, 3).
  grid.CutRight(2, 1);
  grid.CutRight(3, 1);
  grid.CutUp(3, 0);
  grid.CutUp(3, 1);
  grid.CutRight(5, 3);
  grid.CutUp(6, 2);
  bool changed = false;
  EXPECT_EQ(grid.Classify(changed), 1u);
  EXPECT_EQ(grid.Active[grid.At(3, 1)], 0.0f);
  EXPECT_DOUBLE_EQ(grid.Depth[grid.At(3, 1)], 13.0);
  EXPECT_EQ(grid.Active[grid.At(6, 3)], 0.0f);
  EXPECT_EQ(grid.Active[grid.At(5, 3)], 1.0f);
  // A U: column 6 of rows 0 to 2 joins the rest only along row 0 (cut from column 5 in rows 1 and 2).
  grid.CutRight(5, 1);
  grid.CutRight(5, 2);
  EXPECT_EQ(grid.Classify(changed), 1u) << "the U is anchored through row 0";
  EXPECT_EQ(grid.Active[grid.At(6, 2)], 1.0f);
}

// Threads share out the passes over pixels; the union-find and means are serial: the same result for any count.
TEST(BilateralDepthRelaxSteadyRegions, AnyNumberOfThreadsGivesTheSameRegions)
{
  std::vector<std::string> rows(64, std::string(40, '.'));
  rows[3][5] = 'F';
  rows[50][30] = 'F';
  Grid reference(rows);
  for (long y = 0; y < reference.Height; ++y)
  {
    for (long x = 0; x < reference.Width; ++x)
    {
      if ((x * 7 + y * 3) % 5 == 0)
      {
        reference.CutRight(x, y);
      }
      if ((x * 5 + y * 11) % 4 == 0)
      {
        reference.CutUp(x, y);
      }
    }
  }
  Grid       one = reference;
  bool       changed = false;
  const auto floating = one.Classify(changed, 1);
  EXPECT_GT(floating, 0u);
  EXPECT_LT(floating, static_cast<std::size_t>(40 * 64));
  for (const unsigned int threads : { 2u, 3u, 7u })
  {
    Grid many = reference;
    EXPECT_EQ(many.Classify(changed, threads), floating) << threads << " threads";
    EXPECT_EQ(many.Active, one.Active) << threads << " threads";
    EXPECT_EQ(many.Depth, one.Depth) << threads << " threads";
  }
}
