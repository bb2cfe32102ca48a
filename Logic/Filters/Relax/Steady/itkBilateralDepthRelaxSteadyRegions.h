// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The steady solver's floating regions: free pixels that no fixed pixel reaches through non-zero weights, whose
// fixed point is any constant; the solver gives each its mean input depth. Internal (namespace itk::detail), not
// installed; see itkBilateralDepthRelaxSteadySolver.h for the method.
#ifndef itkBilateralDepthRelaxSteadyRegions_h
#define itkBilateralDepthRelaxSteadyRegions_h

#include "itkBilateralDepthRelaxSteadyGrid.h"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace itk::detail::BilateralDepthRelaxSteady
{
/** Union-find over row runs, for the regions of pixels connected through non-zero weights. */
class Regions
{
public:
  std::int32_t
  Find(std::int32_t a)
  {
    while (m_Parent[a] != a)
    {
      m_Parent[a] = m_Parent[m_Parent[a]];
      a = m_Parent[a];
    }
    return a;
  }
  void
  Unite(std::int32_t a, std::int32_t b)
  {
    a = Find(a);
    b = Find(b);
    if (a != b)
    {
      m_Parent[std::max(a, b)] = std::min(a, b);
    }
  }
  /** \a count regions, each its own. */
  void
  Reset(std::size_t count)
  {
    m_Parent.resize(count);
    for (std::size_t k = 0; k < count; ++k)
    {
      m_Parent[k] = static_cast<std::int32_t>(k);
    }
  }

private:
  std::vector<std::int32_t> m_Parent;
};

/** A run of pixels of one row, [Begin, End), joined by non-zero weights, and its region. */
struct RowRun
{
  long         Begin;
  long         End;
  std::int32_t Region;
};

/** What a classification allocates, kept from one solve to the next. */
struct RegionBuffers
{
  Regions             RunRegions;
  std::vector<RowRun> Runs;
  std::vector<long>   RowRunStart;
  std::vector<char>   RunJoined, RunFixed, RowChanged, RegionAnchored;
  std::vector<double> RegionSum, RegionPixels, RowFloating;
};

/** The padded finest grid a classification reads (weights to the right and to the row above, fixed pixels as 1) and
 * writes (activity, 1 or 0, and the depths of floating pixels). */
struct RegionGrid
{
  long          Width;
  long          Height;
  long          Stride;
  const float * WeightRight;
  const float * WeightDown;
  const float * Fixed;
  float *       Active;
  double *      Depth;

  /** Index of pixel (0, y). */
  long
  RowStart(long y) const
  {
    return (y + 1) * Stride + 1;
  }
};

/** Marks the free pixels of regions without a fixed pixel (regions connected through non-zero weights), gives
 * each such region its mean depth, and marks every other free pixel active. Works on runs of pixels joined
 * within their row, united with the runs they touch through a non-zero weight in the next row. The passes over
 * pixels run on bands of rows; only the union-find over runs and the means of floating regions are serial.
 * Returns the floating pixel count; \a changed tells whether any pixel's activity changed. */
std::size_t
ClassifyFloatingRegions(RegionBuffers & buffers, Bands & bands, const RegionGrid & grid, bool & changed);
} // namespace itk::detail::BilateralDepthRelaxSteady

#endif
