// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkCPRCenterlineRasterizer.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace itk::detail
{
namespace
{
using ProjectedPoint = CPRProjectedPoint;

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

template<typename TWriter>
void
RasterizeSegment(const ProjectedPoint & a,
                 const ProjectedPoint & b,
                 uint32_t               owner,
                 TWriter &              writer,
                 SizeValueType          width,
                 SizeValueType          height)
{
  if (IsDegenerateSegment(a, b))
  {
    writer.Deposit(CellOf(a.Column), CellOf(a.Row), a.Depth, a.Radius, owner);
    writer.Deposit(CellOf(b.Column), CellOf(b.Row), b.Depth, b.Radius, owner);
    return;
  }
  // Depth and radius at the segment point nearest the pixel centre.
  TraverseSegmentCells(
    a,
    b,
    width,
    height,
    [&](long column, long row, double t)
    { writer.Deposit(column, row, a.Depth + t * (b.Depth - a.Depth), a.Radius + t * (b.Radius - a.Radius), owner); });
}

/** Projects every branch of \a tree into \a view and hands each pixel its segments pass through to \a writer. */
template<typename TWriter>
void
RasterizeTree(const CenterlineTree & tree, const CPRViewGeometry & view, TWriter & writer)
{
  const SizeValueType         width = view.GetSize()[0];
  const SizeValueType         height = view.GetSize()[1];
  std::vector<ProjectedPoint> projected;
  for (const auto & branch : tree.GetBranches())
  {
    ProjectBranch(branch, view, projected);
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

void
ProjectBranch(const CenterlineBranch & branch, const CPRViewGeometry & view, std::vector<CPRProjectedPoint> & projected)
{
  projected.clear();
  projected.reserve(branch.Points.size());
  for (std::size_t p = 0; p < branch.Points.size(); ++p)
  {
    const auto   coordinates = view.ToView(branch.Points[p]);
    const double radius = branch.HasRadii() ? branch.Radii[p] : std::numeric_limits<double>::quiet_NaN();
    projected.push_back({ coordinates.Column, coordinates.Row, coordinates.Depth, radius });
  }
}

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
