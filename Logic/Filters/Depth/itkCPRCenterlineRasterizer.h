// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCPRCenterlineRasterizer_h
#define itkCPRCenterlineRasterizer_h

#include "itkCPRViewGeometry.h"
#include "itkCenterlineTree.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace itk::detail
{

/** A centerline point in view coordinates: column and row (pixels), depth along v and lumen radius (mm; NaN when the
 * branch has none). */
struct CPRProjectedPoint
{
  double Column;
  double Row;
  double Depth;
  double Radius;
};

/** \a branch projected into \a view, point by point, into \a projected (its memory reused). */
void
ProjectBranch(const CenterlineBranch &         branch,
              const CPRViewGeometry &          view,
              std::vector<CPRProjectedPoint> & projected);

/** The pixel cell holding a view coordinate; -1 (outside every image) for one beyond what a long holds. */
inline long
CellOf(double coordinate)
{
  constexpr double Limit = 1e15;
  if (!(coordinate > -Limit && coordinate < Limit))
  {
    return -1;
  }
  return static_cast<long>(std::floor(coordinate + 0.5));
}

/** Liang-Barsky: narrows [t0, t1] to the part of a + t (b - a) with low <= coordinate <= high. */
inline bool
ClipAxis(double a, double delta, double low, double high, double & t0, double & t1)
{
  if (delta == 0.0)
  {
    return a >= low && a <= high;
  }
  double enter = (low - a) / delta;
  double leave = (high - a) / delta;
  if (enter > leave)
  {
    std::swap(enter, leave);
  }
  t0 = std::max(t0, enter);
  t1 = std::min(t1, leave);
  return t0 <= t1;
}

/** True for a projected segment shorter than 1e-9 pixels, which TraverseSegmentCells leaves to its caller. */
inline bool
IsDegenerateSegment(const CPRProjectedPoint & a, const CPRProjectedPoint & b)
{
  const double dx = b.Column - a.Column;
  const double dy = b.Row - a.Row;
  return dx * dx + dy * dy < 1e-18;
}

/** Calls \a visit(column, row, t) for every pixel cell [i - 0.5, i + 0.5) x [j - 0.5, j + 0.5) of a \a width x
 * \a height image that the projected segment from \a a to \a b passes through (an exact Amanatides-Woo traversal,
 * 8-connected through exact corners), with t in [0, 1] the segment parameter nearest the pixel centre in pixel units.
 * A segment shorter than 1e-9 pixels visits nothing: the caller deposits its ends (IsDegenerateSegment). Every
 * centerline pixel of the view is visited this way (RasterizeCenterlines, and the footprints of Visibility mode). */
template<typename TVisit>
void
TraverseSegmentCells(const CPRProjectedPoint & a,
                     const CPRProjectedPoint & b,
                     SizeValueType             width,
                     SizeValueType             height,
                     TVisit &&                 visit)
{
  const auto inside = [width, height](long column, long row)
  { return column >= 0 && row >= 0 && column < static_cast<long>(width) && row < static_cast<long>(height); };
  const double dx = b.Column - a.Column;
  const double dy = b.Row - a.Row;
  const double lengthSquared = dx * dx + dy * dy;
  if (lengthSquared < 1e-18)
  {
    return;
  }
  double t0 = 0.0;
  double t1 = 1.0;
  if (!ClipAxis(a.Column, dx, -0.5, width - 0.5, t0, t1) || !ClipAxis(a.Row, dy, -0.5, height - 0.5, t0, t1))
  {
    return;
  }
  const auto visitCell = [&](long column, long row)
  {
    double t = ((column - a.Column) * dx + (row - a.Row) * dy) / lengthSquared;
    visit(column, row, std::min(1.0, std::max(0.0, t)));
  };

  const double startColumn = a.Column + t0 * dx;
  const double startRow = a.Row + t0 * dy;
  long         column = std::min<long>(std::max<long>(CellOf(startColumn), 0), static_cast<long>(width) - 1);
  long         row = std::min<long>(std::max<long>(CellOf(startRow), 0), static_cast<long>(height) - 1);
  const long   stepColumn = dx > 0.0 ? 1 : -1;
  const long   stepRow = dy > 0.0 ? 1 : -1;
  const double infinity = std::numeric_limits<double>::infinity();
  const double deltaColumn = dx != 0.0 ? 1.0 / std::abs(dx) : infinity;
  const double deltaRow = dy != 0.0 ? 1.0 / std::abs(dy) : infinity;
  double       nextColumn = dx != 0.0 ? (column + 0.5 * stepColumn - a.Column) / dx : infinity;
  double       nextRow = dy != 0.0 ? (row + 0.5 * stepRow - a.Row) / dy : infinity;

  const long maximumSteps = static_cast<long>(width + height) + 4;
  for (long step = 0; step < maximumSteps; ++step)
  {
    if (inside(column, row))
    {
      visitCell(column, row);
    }
    const double nextBoundary = std::min(nextColumn, nextRow);
    if (nextBoundary > t1)
    {
      break;
    }
    if (nextColumn < nextRow)
    {
      column += stepColumn;
      nextColumn += deltaColumn;
    }
    else if (nextRow < nextColumn)
    {
      row += stepRow;
      nextRow += deltaRow;
    }
    else
    {
      column += stepColumn;
      row += stepRow;
      nextColumn += deltaColumn;
      nextRow += deltaRow;
    }
  }
}

/** \class CPRCenterlinePixels
 * \brief The centerline pixels of a view (docs/design.md "Depth", step 1), row-major W x H.
 *
 * Owner is the branch id (0 where no centerline passes), Depth the depth along v in mm and Radius the lumen
 * radius in mm (NaN when the tree has no radii), both interpolated along the projected segment.
 * \ingroup VesselReformation
 */
struct CPRCenterlinePixels
{
  SizeValueType         Width{ 0 };
  SizeValueType         Height{ 0 };
  std::vector<double>   Depth;
  std::vector<double>   Radius;
  std::vector<uint32_t> Owner;

  bool
  IsCenterline(std::size_t k) const
  {
    return Owner[k] != 0;
  }
  std::size_t
  CountCenterlinePixels() const;
};

/** One centerline pixel of a view: its row-major index k = row * W + column and what CPRCenterlinePixels holds
 * there. */
struct CPRCenterlinePixel
{
  std::size_t Index{ 0 };
  double      Depth{ 0.0 };
  double      Radius{ 0.0 };
  uint32_t    Owner{ 0 };
};

/** Projects every centerline point into \a view and marks each pixel that a projected segment passes through
 * (an exact cell traversal, 8-connected through exact corners). A pixel's depth and radius are interpolated at
 * the segment point nearest the pixel centre. Where segments of two vessels meet in a pixel, the smaller depth
 * (nearer the viewer) wins, then the smaller branch id. */
CPRCenterlinePixels
RasterizeCenterlines(const CenterlineTree & tree, const CPRViewGeometry & view);
/** As above, into \a pixels, reusing its memory (a view that rotates needs no new allocation). */
void
RasterizeCenterlines(const CenterlineTree & tree, const CPRViewGeometry & view, CPRCenterlinePixels & pixels);
/** The same centerline pixels as a list in increasing Index, without the W x H arrays: what a device computes the
 * depth map from (the OpenCL depth filter uploads this list, a few KB, per view). \a pixels is reused. */
void
RasterizeCenterlines(const CenterlineTree &            tree,
                     const CPRViewGeometry &           view,
                     std::vector<CPRCenterlinePixel> & pixels);

} // namespace itk::detail

#endif
