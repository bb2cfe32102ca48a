// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrCenterlineIOTestSupport_h
#define vrCenterlineIOTestSupport_h

// What the centerline IO tests share: distances between trees, a small Y-shaped tree, polylines as vtkPolyData.

#include "vrCenterlineIO.h"
#include "vrCenterlinePolyData.h"
#include "vrInputError.h"
#include "vrTestFiles.h"
#include "vrVolumeIO.h"

#include "vrTestImages.h"

#include <gtest/gtest.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkIntArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkPolyDataWriter.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iostream>
#include <limits>

namespace vr::test::centerlineio
{
using vr::CoordinateSpace;
using PointType = itk::CenterlineBranch::PointType;

using vr::test::P;

using vr::test::InputErrorOf;

using vr::test::InputErrorAndPrintedTextOf;

#define EXPECT_MESSAGE_HAS(message, part)                                                                              \
  EXPECT_NE((message).find(part), std::string::npos) << "message: " << (message) << "\nmissing: " << (part)

/** Distance from \a point to the polyline \a line. */
inline double
DistanceToPolyline(const PointType & point, const std::vector<PointType> & line)
{
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k + 1 < line.size(); ++k)
  {
    const auto   segment = line[k + 1] - line[k];
    const double length2 = segment.GetSquaredNorm();
    double       t = length2 > 0.0 ? ((point - line[k]) * segment) / length2 : 0.0;
    t = std::min(1.0, std::max(0.0, t));
    best = std::min(best, point.EuclideanDistanceTo(line[k] + segment * t));
  }
  if (line.size() == 1)
  {
    best = point.EuclideanDistanceTo(line[0]);
  }
  return best;
}

/** The largest distance from a point of \a from to the nearest branch of \a to. */
inline double
OneSidedDistance(const itk::CenterlineTree & from, const itk::CenterlineTree & to)
{
  double worst = 0.0;
  for (const auto & branch : from.GetBranches())
  {
    for (const auto & point : branch.Points)
    {
      double nearest = std::numeric_limits<double>::infinity();
      for (const auto & other : to.GetBranches())
      {
        nearest = std::min(nearest, DistanceToPolyline(point, other.Points));
      }
      worst = std::max(worst, nearest);
    }
  }
  return worst;
}

/** A Y-shaped tree (trunk and two children starting at its end) with radii, ids 4, 7, 9. */
inline itk::CenterlineTree
MakeYTree()
{
  itk::CenterlineTree   tree;
  itk::CenterlineBranch trunk;
  trunk.Id = 4;
  trunk.Points = { P(10.25, -20.5, 30.125), P(10.5, -20.0, 25.0), P(11.0, -19.75, 20.0) };
  trunk.Radii = { 6.5, 6.25, 6.0 };
  itk::CenterlineBranch left;
  left.Id = 7;
  left.Points = { P(11.0, -19.75, 20.0), P(15.0, -19.0, 15.0), P(19.125, -18.5, 10.0) };
  left.Radii = { 4.0, 3.5, 3.0 };
  itk::CenterlineBranch right;
  right.Id = 9;
  right.Points = { P(11.0, -19.75, 20.0), P(7.0, -20.0, 15.5), P(3.0, -20.25, 11.0), P(-1.0, -20.5, 7.0) };
  right.Radii = { 4.0, 3.75, 3.25, 2.75 };
  tree.AddBranch(trunk);
  tree.AddBranch(left);
  tree.AddBranch(right);
  return tree;
}

inline void
ExpectSameTree(const itk::CenterlineTree & expected,
               const itk::CenterlineTree & actual,
               double                      tolerance,
               bool                        sameIds = true)
{
  ASSERT_EQ(actual.GetNumberOfBranches(), expected.GetNumberOfBranches());
  for (std::size_t b = 0; b < expected.GetNumberOfBranches(); ++b)
  {
    const auto & want = expected.GetBranches()[b];
    const auto & got = actual.GetBranches()[b];
    if (sameIds)
    {
      EXPECT_EQ(got.Id, want.Id) << "branch " << b;
    }
    ASSERT_EQ(got.Points.size(), want.Points.size()) << "branch " << b;
    ASSERT_EQ(got.Radii.size(), want.Radii.size()) << "branch " << b;
    for (std::size_t k = 0; k < want.Points.size(); ++k)
    {
      EXPECT_LE(got.Points[k].EuclideanDistanceTo(want.Points[k]), tolerance) << "branch " << b << " point " << k;
      if (!want.Radii.empty())
      {
        EXPECT_NEAR(got.Radii[k], want.Radii[k], tolerance) << "branch " << b << " point " << k;
      }
    }
  }
}

/** Polylines (RAS) from point lists, one cell each, with a Radius array of \a radius everywhere. */
inline vtkSmartPointer<vtkPolyData>
MakePolyData(const std::vector<std::vector<PointType>> & polylines, double radius = 1.0)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  auto radii = vtkSmartPointer<vtkDoubleArray>::New();
  radii->SetName("Radius");
  for (const auto & polyline : polylines)
  {
    lines->InsertNextCell(static_cast<vtkIdType>(polyline.size()));
    for (const auto & point : polyline)
    {
      lines->InsertCellPoint(points->InsertNextPoint(point.GetDataPointer()));
      radii->InsertNextValue(radius);
    }
  }
  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetLines(lines);
  polyData->GetPointData()->AddArray(radii);
  return polyData;
}

inline std::vector<PointType>
Line(const PointType & from, const PointType & to, int steps)
{
  std::vector<PointType> points;
  for (int k = 0; k <= steps; ++k)
  {
    points.push_back(from + (to - from) * (static_cast<double>(k) / steps));
  }
  return points;
}

inline std::vector<PointType>
Concatenate(std::vector<PointType> a, const std::vector<PointType> & b)
{
  a.insert(a.end(), b.begin() + 1, b.end());
  return a;
}

} // namespace vr::test::centerlineio

#endif
