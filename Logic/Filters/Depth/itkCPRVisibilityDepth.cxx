// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkCPRVisibilityDepth.h"

#include "itkCPROcclusionRule.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace itk::detail
{
namespace
{
constexpr float Infinity = std::numeric_limits<float>::infinity();

/** The footprint samples of one band of rows, row-major from the band's first pixel: the visible lumen (where the
 * ray meets it, its centerline depth, radius and front), the nearest lumen back (min depth + radius, copied to the
 * workspace for the hidden lengths), the front of the centerline cell the rasteriser kept, and the nearest lumen
 * wholly behind the visible one (where the ray meets it, its depth and front, its branch index + 1). One set per
 * thread, reused band after band, so that it stays in the cache (whole-image arrays were first touched, and missed, at
 * every footprint pixel). Written before they are read: Offer() starts a pixel when its Branch is 0. */
struct BandSamples
{
  std::vector<float>    Key;
  std::vector<float>    Back;
  std::vector<float>    Depth;
  std::vector<float>    Radius;
  std::vector<float>    Front;
  std::vector<float>    CellFront;
  std::vector<float>    HiddenKey;
  std::vector<float>    HiddenDepth;
  std::vector<float>    HiddenFront;
  std::vector<uint32_t> HiddenBranch;

  void
  Resize(std::size_t count)
  {
    for (std::vector<float> * values :
         { &Key, &Back, &Depth, &Radius, &Front, &CellFront, &HiddenKey, &HiddenDepth, &HiddenFront })
    {
      values->resize(count);
    }
    HiddenBranch.resize(count);
  }
};

/** Collects the footprint samples of every segment of a band of rows: the visible lumen per pixel (its branch into
 * the workspace, the rest into the band's samples), the nearest back, and the nearest lumen wholly behind the visible
 * one. */
class FootprintCollector
{
public:
  /** Collects into the rows [\a firstRow, \a endRow) of the workspace and into \a samples (those rows' samples), the
   * centerline cells into \a cells (emptied). */
  FootprintCollector(CPRVisibilityWorkspace &        workspace,
                     BandSamples &                   samples,
                     const CPRCenterlinePixels &     pixels,
                     const Vector<double, 2> &       spacing,
                     const std::vector<uint32_t> &   ids,
                     long                            firstRow,
                     long                            endRow,
                     std::vector<CPRFootprintCell> & cells)
    : m_Workspace(workspace)
    , m_Samples(samples)
    , m_Pixels(pixels)
    , m_Width(static_cast<long>(pixels.Width))
    , m_Spacing(spacing)
    , m_Ids(ids)
    , m_FirstRow(firstRow)
    , m_EndRow(endRow)
    , m_Cells(cells)
    , m_BandFirst(static_cast<std::size_t>(firstRow * m_Width))
  {
    m_Cells.clear();
  }

  /** The front of each centerline cell where the rasteriser's pixel is that very cell: it kept this branch at this
   * depth (the same sum); the last such cell in the tree's order wins. Read after the band's segments, not at each
   * cell, where the rasteriser's pixels, not otherwise in the cache, stalled the footprints. */
  void
  SetCellFronts() const
  {
    for (const CPRFootprintCell & cell : m_Cells)
    {
      if (m_Pixels.Owner[cell.Index] == cell.Owner && m_Pixels.Depth[cell.Index] == cell.Depth)
      {
        m_Samples.CellFront[cell.Index - m_BandFirst] = cell.Front;
      }
    }
  }

  /** Whether the segment from \a a to \a b, with its lumen reach \a reach (mm), can touch the band's rows. */
  bool
  Reaches(const CPRProjectedPoint & a, const CPRProjectedPoint & b, double reach) const
  {
    const double rows = reach / m_Spacing[1] + 1.0;
    return std::max(a.Row, b.Row) + rows >= static_cast<double>(m_FirstRow) &&
           std::min(a.Row, b.Row) - rows <= static_cast<double>(m_EndRow - 1);
  }

  /** The footprint of the segment from \a a to \a b of branch \a branch: lumen (radii \a ra, \a rb in mm, 0 without)
   * and centerline cells; \a tolerance is the segment's self-occlusion tolerance (itkCPROcclusionRule.h). */
  void
  AddSegment(const CPRProjectedPoint & a,
             const CPRProjectedPoint & b,
             double                    ra,
             double                    rb,
             uint32_t                  branch,
             double                    tolerance)
  {
    AddLumen(a, b, ra, rb, branch, tolerance);
    const auto cell = [&](long column, long row, double t)
    {
      if (row < m_FirstRow || row >= m_EndRow)
      {
        return;
      }
      const double depth = a.Depth + t * (b.Depth - a.Depth);
      const double radius = ra + t * (rb - ra);
      const auto   k = static_cast<std::size_t>(row * m_Width + column);
      const double front = depth - radius - tolerance;
      Offer(k, branch, depth, radius, depth, front);
      m_Cells.push_back({ k, m_Ids[branch], depth, static_cast<float>(front) });
    };
    if (IsDegenerateSegment(a, b))
    {
      for (const auto & [end, t] : { std::pair<const CPRProjectedPoint *, double>{ &a, 0.0 }, { &b, 1.0 } })
      {
        const long column = CellOf(end->Column);
        const long row = CellOf(end->Row);
        if (column >= 0 && row >= m_FirstRow && column < m_Width && row < m_EndRow)
        {
          // The ends' own values, as the rasteriser deposits them.
          const auto   k = static_cast<std::size_t>(row * m_Width + column);
          const double radius = t == 0.0 ? ra : rb;
          const double front = end->Depth - radius - tolerance;
          Offer(k, branch, end->Depth, radius, end->Depth, front);
          m_Cells.push_back({ k, m_Ids[branch], end->Depth, static_cast<float>(front) });
        }
      }
      return;
    }
    if (std::max(a.Row, b.Row) + 1.0 >= static_cast<double>(m_FirstRow) &&
        std::min(a.Row, b.Row) - 1.0 <= static_cast<double>(m_EndRow - 1))
    {
      TraverseSegmentCells(a, b, m_Pixels.Width, m_Pixels.Height, cell);
    }
  }

private:
  /** The pixels within the interpolated radius of the segment (in mm), row by row over the rows and columns the
   * capsule can reach. */
  void
  AddLumen(const CPRProjectedPoint & a,
           const CPRProjectedPoint & b,
           double                    ra,
           double                    rb,
           uint32_t                  branch,
           double                    tolerance)
  {
    const double reach = std::max(ra, rb);
    if (!(reach > 0.0))
    {
      return;
    }
    const double sx = m_Spacing[0];
    const double sy = m_Spacing[1];
    const double ax = a.Column * sx;
    const double ay = a.Row * sy;
    const double dx = (b.Column - a.Column) * sx;
    const double dy = (b.Row - a.Row) * sy;
    const double lengthSquared = dx * dx + dy * dy;
    const double firstRow = static_cast<double>(m_FirstRow);
    const double lastRow = static_cast<double>(m_EndRow - 1);
    const double lastColumn = static_cast<double>(m_Width - 1);
    const double rowLow = std::clamp(std::ceil((std::min(ay, ay + dy) - reach) / sy), firstRow, lastRow + 1.0);
    const double rowHigh = std::clamp(std::floor((std::max(ay, ay + dy) + reach) / sy), firstRow - 1.0, lastRow);
    for (long row = static_cast<long>(rowLow); row <= static_cast<long>(rowHigh); ++row)
    {
      const double y = row * sy;
      // The part of the segment within reach of this row, and the columns within reach of that part.
      double tLow = 0.0;
      double tHigh = 1.0;
      if (dy != 0.0)
      {
        double t1 = (y - reach - ay) / dy;
        double t2 = (y + reach - ay) / dy;
        if (t1 > t2)
        {
          std::swap(t1, t2);
        }
        tLow = std::max(tLow, t1);
        tHigh = std::min(tHigh, t2);
        if (tLow > tHigh)
        {
          continue;
        }
      }
      else if (std::abs(ay - y) > reach)
      {
        continue;
      }
      const double xLow = std::min(ax + tLow * dx, ax + tHigh * dx) - reach;
      const double xHigh = std::max(ax + tLow * dx, ax + tHigh * dx) + reach;
      const double columnLow = std::clamp(std::ceil(xLow / sx), 0.0, lastColumn + 1.0);
      const double columnHigh = std::clamp(std::floor(xHigh / sx), -1.0, lastColumn);
      const double py = y - ay;
      for (long column = static_cast<long>(columnLow); column <= static_cast<long>(columnHigh); ++column)
      {
        const double px = column * sx - ax;
        double       t = lengthSquared > 0.0 ? (px * dx + py * dy) / lengthSquared : 0.0;
        t = std::min(1.0, std::max(0.0, t));
        const double qx = px - t * dx;
        const double qy = py - t * dy;
        const double distanceSquared = qx * qx + qy * qy;
        const double radius = ra + t * (rb - ra);
        if (distanceSquared > radius * radius)
        {
          continue;
        }
        const double depth = a.Depth + t * (b.Depth - a.Depth);
        const double halfChord = std::sqrt(radius * radius - distanceSquared);
        Offer(static_cast<std::size_t>(row * m_Width + column),
              branch,
              depth,
              radius,
              depth - halfChord,
              depth - radius - tolerance);
      }
    }
  }

  void
  Offer(std::size_t k, uint32_t branch, double depth, double radius, double key, double front)
  {
    CPRVisibilityWorkspace & w = m_Workspace;
    BandSamples &            band = m_Samples;
    const std::size_t        i = k - m_BandFirst;
    const auto               back = static_cast<float>(depth + radius);
    const auto               keyValue = static_cast<float>(key);
    const auto               depthValue = static_cast<float>(depth);
    const auto               frontValue = static_cast<float>(front);
    const uint32_t           current = w.Branch[k];
    if (current == 0)
    {
      band.Back[i] = back;
      band.Key[i] = keyValue;
      band.Depth[i] = depthValue;
      band.Radius[i] = static_cast<float>(radius);
      band.Front[i] = frontValue;
      w.Branch[k] = branch + 1;
      band.HiddenBranch[i] = 0;
      return;
    }
    band.Back[i] = std::min(band.Back[i], back);
    // Where the ray meets the lumen first; then the nearer centerline; then the smaller id (as the rasteriser).
    if (keyValue < band.Key[i] ||
        (keyValue == band.Key[i] &&
         (depthValue < band.Depth[i] || (depthValue == band.Depth[i] && m_Ids[branch] < m_Ids[current - 1]))))
    {
      // The new visible lumen: the one it replaces is the nearest behind it if it lies wholly behind it (it had the
      // best key so far); else the lumen behind stays if it is still wholly behind.
      if (IsBehind(band.Front[i], back))
      {
        band.HiddenKey[i] = band.Key[i];
        band.HiddenDepth[i] = band.Depth[i];
        band.HiddenFront[i] = band.Front[i];
        band.HiddenBranch[i] = current;
      }
      else if (band.HiddenBranch[i] != 0 && !IsBehind(band.HiddenFront[i], back))
      {
        band.HiddenBranch[i] = 0;
      }
      band.Key[i] = keyValue;
      band.Depth[i] = depthValue;
      band.Radius[i] = static_cast<float>(radius);
      band.Front[i] = frontValue;
      w.Branch[k] = branch + 1;
      return;
    }
    if (!IsBehind(frontValue, band.Depth[i] + band.Radius[i]))
    {
      return;
    }
    const uint32_t hidden = band.HiddenBranch[i];
    if (hidden == 0 || keyValue < band.HiddenKey[i] ||
        (keyValue == band.HiddenKey[i] && (depthValue < band.HiddenDepth[i] ||
                                           (depthValue == band.HiddenDepth[i] && m_Ids[branch] < m_Ids[hidden - 1]))))
    {
      band.HiddenKey[i] = keyValue;
      band.HiddenDepth[i] = depthValue;
      band.HiddenFront[i] = frontValue;
      band.HiddenBranch[i] = branch + 1;
    }
  }

  CPRVisibilityWorkspace &        m_Workspace;
  BandSamples &                   m_Samples;
  const CPRCenterlinePixels &     m_Pixels;
  long                            m_Width;
  Vector<double, 2>               m_Spacing;
  const std::vector<uint32_t> &   m_Ids;
  long                            m_FirstRow;
  long                            m_EndRow;
  std::vector<CPRFootprintCell> & m_Cells;
  std::size_t                     m_BandFirst;
};

/** Rows per band of the footprint pass: each band's pixels are written by one task, in the tree's order of
 * segments, so the result does not depend on the number of threads. */
constexpr long RowsPerBand = 32;

double
Distance3D(const CenterlineBranch::PointType & a, const CenterlineBranch::PointType & b)
{
  return a.EuclideanDistanceTo(b);
}
} // namespace

void
AssignVisibility(const CenterlineTree &            tree,
                 const CPRViewGeometry &           view,
                 const CPRCenterlinePixels &       pixels,
                 bool                              fixLumen,
                 MultiThreaderBase *               threader,
                 CPRVisibilityWorkspace &          workspace,
                 CPRDepthAssignment &              result,
                 std::vector<CPRBranchOcclusion> & occlusion)
{
  const SizeValueType      width = pixels.Width;
  const SizeValueType      height = pixels.Height;
  const std::size_t        count = static_cast<std::size_t>(width) * height;
  const Vector<double, 2>  spacing = view.GetSpacing();
  const double             pixelSize = std::max(spacing[0], spacing[1]);
  CPRVisibilityWorkspace & w = workspace;
  // Back is written on every footprint pixel (Branch not 0), the only ones whose Back is read: only Branch is cleared,
  // by each band for its rows.
  w.Back.resize(count);
  w.Branch.resize(count);

  std::vector<uint32_t>      ids;
  std::vector<unsigned char> hasRadii;
  for (const auto & branch : tree.GetBranches())
  {
    ids.push_back(static_cast<uint32_t>(branch.Id));
    hasRadii.push_back(branch.HasRadii() ? 1 : 0);
  }
  // Every branch projected once, one after another.
  w.Projected.clear();
  w.FirstPoint.assign(1, 0);
  std::vector<CPRProjectedPoint> projected;
  for (const auto & branch : tree.GetBranches())
  {
    ProjectBranch(branch, view, projected);
    w.Projected.insert(w.Projected.end(), projected.begin(), projected.end());
    w.FirstPoint.push_back(w.Projected.size());
  }
  const auto radiusOf = [&](std::size_t branch, const CPRProjectedPoint & p)
  { return hasRadii[branch] ? p.Radius : 0.0; };
  const auto tolerance = [&](std::size_t branch, const CPRProjectedPoint & a, const CPRProjectedPoint & b)
  {
    const double dx = (b.Column - a.Column) * spacing[0];
    const double dy = (b.Row - a.Row) * spacing[1];
    return SelfOcclusionTolerance(
      b.Depth - a.Depth, std::sqrt(dx * dx + dy * dy), pixelSize + std::max(radiusOf(branch, a), radiusOf(branch, b)));
  };

  // Every segment's footprint, band by band of rows (in parallel), branch by branch within a band; then the band's
  // outputs.
  const long bands = (static_cast<long>(height) + RowsPerBand - 1) / RowsPerBand;
  result.Depth.resize(count);
  result.Fixed.resize(count);
  result.Owner.resize(count);
  result.Hidden.resize(count);
  w.BandCells.resize(static_cast<std::size_t>(bands));
  threader->ParallelizeArray(
    0,
    static_cast<SizeValueType>(bands),
    [&](SizeValueType band)
    {
      const long firstRow = static_cast<long>(band) * RowsPerBand;
      const long endRow = std::min(static_cast<long>(height), firstRow + RowsPerBand);
      std::fill(w.Branch.begin() + firstRow * static_cast<long>(width),
                w.Branch.begin() + endRow * static_cast<long>(width),
                0);
      thread_local BandSamples samples;
      samples.Resize(static_cast<std::size_t>(RowsPerBand) * width);
      FootprintCollector collector(w, samples, pixels, spacing, ids, firstRow, endRow, w.BandCells[band]);
      for (std::size_t b = 0; b < ids.size(); ++b)
      {
        const CPRProjectedPoint * p = w.Projected.data() + w.FirstPoint[b];
        const std::size_t         n = w.FirstPoint[b + 1] - w.FirstPoint[b];
        const auto                branch = static_cast<uint32_t>(b);
        if (n == 1 && collector.Reaches(p[0], p[0], radiusOf(b, p[0])))
        {
          collector.AddSegment(p[0], p[0], radiusOf(b, p[0]), radiusOf(b, p[0]), branch, 0.0);
        }
        for (std::size_t i = 0; i + 1 < n; ++i)
        {
          const double ra = radiusOf(b, p[i]);
          const double rb = radiusOf(b, p[i + 1]);
          if (collector.Reaches(p[i], p[i + 1], std::max(ra, rb)))
          {
            collector.AddSegment(p[i], p[i + 1], ra, rb, branch, tolerance(b, p[i], p[i + 1]));
          }
        }
      }
      collector.SetCellFronts();
      // The band's depth, owner, fixed flag and hidden label while its rows are in the cache; the pixels outside every
      // footprint (most of them: cleared as a block first) are free and wait for the fill.
      const std::size_t bandFirst = static_cast<std::size_t>(firstRow) * width;
      const std::size_t bandEnd = static_cast<std::size_t>(endRow) * width;
      std::fill(result.Owner.begin() + bandFirst, result.Owner.begin() + bandEnd, 0);
      std::fill(result.Fixed.begin() + bandFirst, result.Fixed.begin() + bandEnd, 0);
      std::fill(result.Hidden.begin() + bandFirst, result.Hidden.begin() + bandEnd, 0);
      for (std::size_t k = bandFirst; k < bandEnd; ++k)
      {
        if (w.Branch[k] == 0)
        {
          continue;
        }
        const uint32_t branch = w.Branch[k] - 1;
        const uint32_t owner = ids[branch];
        // The vessel's own centerline pixel keeps the rasteriser's depth (as in every mode), unless it is a stretch
        // of the same vessel lying behind the visible one (a loop seen end-on).
        const std::size_t i = k - bandFirst;
        const bool        centerline =
          pixels.Owner[k] == owner && !IsBehind(samples.CellFront[i], samples.Depth[i] + samples.Radius[i]);
        result.Owner[k] = owner;
        w.Back[k] = samples.Back[i];
        result.Depth[k] = centerline ? static_cast<float>(pixels.Depth[k]) : samples.Depth[i];
        result.Fixed[k] = (centerline || (fixLumen && hasRadii[branch])) ? 1 : 0;
        result.Hidden[k] = samples.HiddenBranch[i] != 0 ? ids[samples.HiddenBranch[i] - 1] : 0;
      }
    },
    nullptr);

  FillFromNearestSeeds(width, height, spacing, result.Depth, result.Owner, threader, w.Fill);

  // How much of each branch lies behind another lumen: its centerline sampled every half pixel of projected length.
  occlusion.assign(tree.GetNumberOfBranches(), CPRBranchOcclusion());
  threader->ParallelizeArray(
    0,
    tree.GetNumberOfBranches(),
    [&](SizeValueType b)
    {
      const CenterlineBranch &  branch = tree.GetBranches()[b];
      const CPRProjectedPoint * p = w.Projected.data() + w.FirstPoint[b];
      const std::size_t         points = w.FirstPoint[b + 1] - w.FirstPoint[b];
      CPRBranchOcclusion        entry;
      entry.BranchId = branch.Id;
      for (std::size_t i = 0; i + 1 < points; ++i)
      {
        const double length = Distance3D(branch.Points[i], branch.Points[i + 1]);
        entry.Length += length;
        const double columns = p[i + 1].Column - p[i].Column;
        const double rows = p[i + 1].Row - p[i].Row;
        const double steps = std::min(std::ceil(2.0 * std::hypot(columns, rows)), 8.0 * (width + height));
        const auto   n = static_cast<long>(std::max(1.0, steps));
        const double eps = tolerance(b, p[i], p[i + 1]);
        const double ra = radiusOf(b, p[i]);
        const double rb = radiusOf(b, p[i + 1]);
        long         hidden = 0;
        for (long m = 0; m < n; ++m)
        {
          const double t = (m + 0.5) / n;
          const long   column = CellOf(p[i].Column + t * columns);
          const long   row = CellOf(p[i].Row + t * rows);
          if (column < 0 || row < 0 || column >= static_cast<long>(width) || row >= static_cast<long>(height))
          {
            continue;
          }
          const double      depth = p[i].Depth + t * (p[i + 1].Depth - p[i].Depth);
          const double      front = depth - (ra + t * (rb - ra)) - eps;
          const std::size_t k = static_cast<std::size_t>(row) * width + column;
          if (w.Branch[k] == 0 || !IsBehind(front, w.Back[k]))
          {
            continue;
          }
          ++hidden;
          // The sample's share of the polyline, joined to the stretch it continues.
          const double first = static_cast<double>(i) + static_cast<double>(m) / n;
          const double last = static_cast<double>(i) + static_cast<double>(m + 1) / n;
          if (!entry.HiddenStretches.empty() && entry.HiddenStretches.back().Last >= first - 1e-9)
          {
            entry.HiddenStretches.back().Last = last;
          }
          else
          {
            entry.HiddenStretches.push_back({ first, last });
          }
        }
        entry.HiddenLength += length * static_cast<double>(hidden) / static_cast<double>(n);
      }
      occlusion[b] = std::move(entry);
    },
    nullptr);
}
} // namespace itk::detail
