// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkCPRCenterlineRasterizer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace itk::detail
{
namespace
{
struct ProjectedPoint
{
  double Column;
  double Row;
  double Depth;
  double Radius;
};

/** Whether a deposit of \a depth by \a owner replaces the pixel's \a current owner and \a currentDepth: the nearer
 * wins, then the smaller branch id; on a tie the first deposit stays. */
bool
Replaces(double depth, uint32_t owner, double currentDepth, uint32_t current)
{
  return current == 0 || depth < currentDepth || (depth == currentDepth && owner < current);
}

class PixelWriter
{
public:
  explicit PixelWriter(CPRCenterlinePixels & pixels)
    : m_Pixels(pixels)
  {
  }

  void
  Deposit(long column, long row, double depth, double radius, uint32_t owner)
  {
    if (column < 0 || row < 0 || column >= static_cast<long>(m_Pixels.Width) ||
        row >= static_cast<long>(m_Pixels.Height))
    {
      return;
    }
    const std::size_t k = static_cast<std::size_t>(row) * m_Pixels.Width + static_cast<std::size_t>(column);
    if (Replaces(depth, owner, m_Pixels.Depth[k], m_Pixels.Owner[k]))
    {
      m_Pixels.Owner[k] = owner;
      m_Pixels.Depth[k] = depth;
      m_Pixels.Radius[k] = radius;
    }
  }

private:
  CPRCenterlinePixels & m_Pixels;
};

/** Collects the deposits in order; Resolve() then keeps per pixel what PixelWriter would have kept. */
class PixelListWriter
{
public:
  PixelListWriter(std::vector<CPRCenterlinePixel> & pixels, SizeValueType width, SizeValueType height)
    : m_Pixels(pixels)
    , m_Width(width)
    , m_Height(height)
  {
    m_Pixels.clear();
  }

  void
  Deposit(long column, long row, double depth, double radius, uint32_t owner)
  {
    if (column < 0 || row < 0 || column >= static_cast<long>(m_Width) || row >= static_cast<long>(m_Height))
    {
      return;
    }
    m_Pixels.push_back(
      { static_cast<std::size_t>(row) * m_Width + static_cast<std::size_t>(column), depth, radius, owner });
  }

  /** Sorts by pixel (stable: a pixel's deposits stay in their order) and keeps the winner of each. */
  void
  Resolve()
  {
    std::stable_sort(m_Pixels.begin(),
                     m_Pixels.end(),
                     [](const CPRCenterlinePixel & a, const CPRCenterlinePixel & b) { return a.Index < b.Index; });
    std::size_t kept = 0;
    for (std::size_t k = 0; k < m_Pixels.size(); ++k)
    {
      if (kept > 0 && m_Pixels[kept - 1].Index == m_Pixels[k].Index)
      {
        CPRCenterlinePixel & winner = m_Pixels[kept - 1];
        if (Replaces(m_Pixels[k].Depth, m_Pixels[k].Owner, winner.Depth, winner.Owner))
        {
          winner = m_Pixels[k];
        }
      }
      else
      {
        m_Pixels[kept++] = m_Pixels[k];
      }
    }
    m_Pixels.resize(kept);
  }

private:
  std::vector<CPRCenterlinePixel> & m_Pixels;
  SizeValueType                     m_Width;
  SizeValueType                     m_Height;
};

/** The pixel cell holding a view coordinate; -1 (outside every image) for one beyond what a long holds. */
long
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
bool
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

template<typename TWriter>
void
RasterizeSegment(const ProjectedPoint & a,
                 const ProjectedPoint & b,
                 uint32_t               owner,
                 TWriter &              writer,
                 SizeValueType          width,
                 SizeValueType          height)
{
  const double dx = b.Column - a.Column;
  const double dy = b.Row - a.Row;
  const double lengthSquared = dx * dx + dy * dy;
  if (lengthSquared < 1e-18)
  {
    writer.Deposit(CellOf(a.Column), CellOf(a.Row), a.Depth, a.Radius, owner);
    writer.Deposit(CellOf(b.Column), CellOf(b.Row), b.Depth, b.Radius, owner);
    return;
  }
  double t0 = 0.0;
  double t1 = 1.0;
  if (!ClipAxis(a.Column, dx, -0.5, width - 0.5, t0, t1) || !ClipAxis(a.Row, dy, -0.5, height - 0.5, t0, t1))
  {
    return;
  }
  auto depositCell = [&](long column, long row)
  {
    // Depth and radius at the segment point nearest the pixel centre.
    double t = ((column - a.Column) * dx + (row - a.Row) * dy) / lengthSquared;
    t = std::min(1.0, std::max(0.0, t));
    writer.Deposit(column, row, a.Depth + t * (b.Depth - a.Depth), a.Radius + t * (b.Radius - a.Radius), owner);
  };

  // Amanatides-Woo traversal of the pixel cells [i - 0.5, i + 0.5) x [j - 0.5, j + 0.5).
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
    depositCell(column, row);
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

/** Projects every branch of \a tree into \a view and hands each pixel its segments pass through to \a writer. */
template<typename TWriter>
void
RasterizeTree(const CenterlineTree & tree, const CPRViewGeometry & view, TWriter & writer)
{
  const SizeValueType width = view.GetSize()[0];
  const SizeValueType height = view.GetSize()[1];
  for (const auto & branch : tree.GetBranches())
  {
    std::vector<ProjectedPoint> projected;
    projected.reserve(branch.Points.size());
    for (std::size_t p = 0; p < branch.Points.size(); ++p)
    {
      const auto   coordinates = view.ToView(branch.Points[p]);
      const double radius = branch.HasRadii() ? branch.Radii[p] : std::numeric_limits<double>::quiet_NaN();
      projected.push_back({ coordinates.Column, coordinates.Row, coordinates.Depth, radius });
    }
    const auto owner = static_cast<uint32_t>(branch.Id);
    if (projected.size() == 1)
    {
      writer.Deposit(
        CellOf(projected[0].Column), CellOf(projected[0].Row), projected[0].Depth, projected[0].Radius, owner);
    }
    for (std::size_t p = 0; p + 1 < projected.size(); ++p)
    {
      RasterizeSegment(projected[p], projected[p + 1], owner, writer, width, height);
    }
  }
}
} // namespace

std::size_t
CPRCenterlinePixels::CountCenterlinePixels() const
{
  return static_cast<std::size_t>(std::count_if(Owner.begin(), Owner.end(), [](uint32_t o) { return o != 0; }));
}

CPRCenterlinePixels
RasterizeCenterlines(const CenterlineTree & tree, const CPRViewGeometry & view)
{
  CPRCenterlinePixels pixels;
  RasterizeCenterlines(tree, view, pixels);
  return pixels;
}

void
RasterizeCenterlines(const CenterlineTree & tree, const CPRViewGeometry & view, CPRCenterlinePixels & pixels)
{
  pixels.Width = view.GetSize()[0];
  pixels.Height = view.GetSize()[1];
  const std::size_t count = static_cast<std::size_t>(pixels.Width) * pixels.Height;
  pixels.Depth.assign(count, std::numeric_limits<double>::infinity());
  pixels.Radius.assign(count, std::numeric_limits<double>::quiet_NaN());
  pixels.Owner.assign(count, 0);
  PixelWriter writer(pixels);
  RasterizeTree(tree, view, writer);
}

void
RasterizeCenterlines(const CenterlineTree &            tree,
                     const CPRViewGeometry &           view,
                     std::vector<CPRCenterlinePixel> & pixels)
{
  PixelListWriter writer(pixels, view.GetSize()[0], view.GetSize()[1]);
  RasterizeTree(tree, view, writer);
  writer.Resolve();
}

} // namespace itk::detail
