// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCenterlineOverlay.h"

#include "vrBranchColors.h"

#include <vtkCellArray.h>
#include <vtkNew.h>
#include <vtkCellData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace vr
{
namespace
{
using WorldPoint = std::array<double, 2>;

/** The overlay under construction: points, line cells, their colours and hidden marks. */
class OverlayBuilder
{
public:
  OverlayBuilder()
  {
    m_Colors->SetNumberOfComponents(3);
    m_Colors->SetName("BranchColors");
    m_Hidden->SetName(HiddenStretchArrayName);
  }

  void
  AddLine(const std::vector<WorldPoint> & line, const std::array<double, 3> & rgb, bool hidden)
  {
    if (line.size() < 2)
    {
      return;
    }
    std::vector<vtkIdType> ids;
    for (const WorldPoint & p : line)
    {
      ids.push_back(m_Points->InsertNextPoint(p[0], p[1], 0.0));
    }
    m_Lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
    m_Colors->InsertNextTuple3(255.0 * rgb[0], 255.0 * rgb[1], 255.0 * rgb[2]);
    m_Hidden->InsertNextValue(hidden ? 1 : 0);
  }

  vtkSmartPointer<vtkPolyData>
  Build()
  {
    auto overlay = vtkSmartPointer<vtkPolyData>::New();
    overlay->SetPoints(m_Points);
    overlay->SetLines(m_Lines);
    overlay->GetCellData()->SetScalars(m_Colors);
    overlay->GetCellData()->AddArray(m_Hidden);
    return overlay;
  }

private:
  vtkNew<vtkPoints>            m_Points;
  vtkNew<vtkCellArray>         m_Lines;
  vtkNew<vtkUnsignedCharArray> m_Colors;
  vtkNew<vtkUnsignedCharArray> m_Hidden;
};

/** The polyline through \a points between polyline parameters \a first and \a last (point floor(p), fraction). */
std::vector<WorldPoint>
Piece(const std::vector<WorldPoint> & points, double first, double last)
{
  const auto at = [&](double p)
  {
    const auto   i = std::min(static_cast<std::size_t>(std::floor(p)), points.size() - 2);
    const double t = p - static_cast<double>(i);
    return WorldPoint{ points[i][0] + t * (points[i + 1][0] - points[i][0]),
                       points[i][1] + t * (points[i + 1][1] - points[i][1]) };
  };
  std::vector<WorldPoint> piece{ at(first) };
  for (auto k = static_cast<std::size_t>(std::floor(first)) + 1; static_cast<double>(k) < last; ++k)
  {
    piece.push_back(points[k]);
  }
  piece.push_back(at(last));
  return piece;
}

/** \a line cut into dashes of \a dash (world units) with gaps as long. */
std::vector<std::vector<WorldPoint>>
Dashes(const std::vector<WorldPoint> & line, double dash)
{
  std::vector<std::vector<WorldPoint>> dashes;
  double                               along = 0.0; // distance from the line's start
  std::vector<WorldPoint>              current{ line.front() };
  bool                                 drawing = true;
  double                               next = dash;
  for (std::size_t k = 0; k + 1 < line.size(); ++k)
  {
    const double dx = line[k + 1][0] - line[k][0];
    const double dy = line[k + 1][1] - line[k][1];
    const double length = std::hypot(dx, dy);
    double       start = along;
    while (length > 0.0 && next <= start + length)
    {
      const double     t = (next - start) / length;
      const WorldPoint cut{ line[k][0] + t * dx, line[k][1] + t * dy };
      if (drawing)
      {
        current.push_back(cut);
        dashes.push_back(current);
      }
      current = { cut };
      drawing = !drawing;
      next += dash;
    }
    along += length;
    if (drawing)
    {
      current.push_back(line[k + 1]);
    }
  }
  if (drawing && current.size() > 1)
  {
    dashes.push_back(current);
  }
  return dashes;
}
} // namespace

vtkSmartPointer<vtkPolyData>
BuildCenterlineOverlay(const itk::CenterlineTree &             tree,
                       const itk::CPRViewGeometry &            view,
                       const std::vector<BranchOcclusionRow> & occlusions,
                       const double                            origin[2],
                       const double                            spacing[2])
{
  OverlayBuilder builder;
  const double   dash = HiddenDashPixels * std::max(spacing[0], spacing[1]);
  for (const auto & branch : tree.GetBranches())
  {
    if (branch.Points.size() < 2)
    {
      continue;
    }
    std::vector<WorldPoint> points;
    for (const auto & point : branch.Points)
    {
      const auto coordinates = view.ToView(point);
      points.push_back({ origin[0] + coordinates.Column * spacing[0], origin[1] + coordinates.Row * spacing[1] });
    }
    const auto rgb = BranchColor(branch.Id);
    const auto row = std::find_if(
      occlusions.begin(), occlusions.end(), [&](const BranchOcclusionRow & r) { return r.BranchId == branch.Id; });
    const double end = static_cast<double>(points.size() - 1);
    double       solidFrom = 0.0;
    if (row != occlusions.end())
    {
      for (const itk::CPRCenterlineStretch & stretch : row->HiddenStretches)
      {
        const double first = std::clamp(stretch.First, 0.0, end);
        const double last = std::clamp(stretch.Last, first, end);
        if (first > solidFrom)
        {
          builder.AddLine(Piece(points, solidFrom, first), rgb, false);
        }
        for (const auto & piece : Dashes(Piece(points, first, last), dash))
        {
          builder.AddLine(piece, rgb, true);
        }
        solidFrom = std::max(solidFrom, last);
      }
    }
    if (solidFrom < end)
    {
      builder.AddLine(Piece(points, solidFrom, end), rgb, false);
    }
  }
  return builder.Build();
}
} // namespace vr
