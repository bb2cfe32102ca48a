// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrLogicTestFixture_h
#define vrLogicTestFixture_h

// What the module logic's tests share: two vessels as a volume node and a centerline node (LPS given, RAS stored),
// quick parameters, and a fixture whose logic holds them.

#include "itkCPRVectorHelpers.h"
#include "vrCoordinateFrames.h"
#include "vrCutSurface.h"
#include "vrInputError.h"
#include "vrNodeConversion.h"
#include "vrVesselReformationLogic.h"
#include "vrCenterlineVolumeFit.h"

#include "PlainBilateralDepthRelax.h"
#include "vrTestImages.h"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDoubleArray.h>
#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <array>
#include <functional>
#include <cmath>
#include <string>
#include <vector>

namespace vr::test::logic
{
using vr::ReformationParameters;
using vr::VesselReformationLogic;

constexpr float  Lumen = 1000.0f;
constexpr float  Background = 100.0f;
constexpr double LumenRadius = 3.0;

/** A polyline given in LPS, stored in RAS as a platform would hand it over. */
struct Polyline
{
  std::vector<std::array<double, 3>> PointsLPS;
};

/** Distance from \a p to the segment a-b. */
inline double
DistanceToSegment(const std::array<double, 3> & p, const std::array<double, 3> & a, const std::array<double, 3> & b)
{
  double ab[3];
  double ap[3];
  double lengthSquared = 0.0;
  double dot = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    ab[k] = b[k] - a[k];
    ap[k] = p[k] - a[k];
    lengthSquared += ab[k] * ab[k];
    dot += ab[k] * ap[k];
  }
  const double t = lengthSquared > 0.0 ? std::clamp(dot / lengthSquared, 0.0, 1.0) : 0.0;
  double       distanceSquared = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    const double d = ap[k] - t * ab[k];
    distanceSquared += d * d;
  }
  return std::sqrt(distanceSquared);
}

/** Two vessels, a straight trunk along z and a branch leaving it, in LPS mm. */
inline std::vector<Polyline>
TwoVessels()
{
  Polyline trunk;
  for (int z = 5; z <= 45; z += 2)
  {
    trunk.PointsLPS.push_back({ 15.0, 20.0, static_cast<double>(z) });
  }
  Polyline branch;
  for (int step = 0; step <= 10; ++step)
  {
    branch.PointsLPS.push_back({ 15.0 + 1.3 * step, 20.0 + 0.6 * step, 25.0 + 2.0 * step });
  }
  return { trunk, branch };
}

/** A 40 x 40 x 50 volume with 1 mm voxels whose IJK->RAS is diag(-1, -1, 1): voxel (i, j, k) lies at LPS
 * (i, j, k). Lumen intensity within LumenRadius of the vessels, background elsewhere. */
inline vtkSmartPointer<vr::VolumeNode>
MakeVolumeNode(const std::vector<Polyline> & vessels)
{
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetExtent(0, 39, 0, 39, 0, 49);
  data->AllocateScalars(VTK_SHORT, 1);
  auto * voxels = static_cast<short *>(data->GetScalarPointer());
  for (int k = 0; k < 50; ++k)
  {
    for (int j = 0; j < 40; ++j)
    {
      for (int i = 0; i < 40; ++i)
      {
        double distance = 1e9;
        for (const auto & vessel : vessels)
        {
          for (std::size_t s = 0; s + 1 < vessel.PointsLPS.size(); ++s)
          {
            distance = std::min(
              distance,
              DistanceToSegment({ double(i), double(j), double(k) }, vessel.PointsLPS[s], vessel.PointsLPS[s + 1]));
          }
        }
        voxels[(k * 40 + j) * 40 + i] = static_cast<short>(distance <= LumenRadius ? Lumen : Background);
      }
    }
  }
  auto matrix = vtkSmartPointer<vtkMatrix4x4>::New();
  matrix->SetElement(0, 0, -1.0);
  matrix->SetElement(1, 1, -1.0);
  auto node = vtkSmartPointer<vr::VolumeNode>::New();
  node->SetName("two-vessels");
  node->SetImageData(data);
  node->SetIJKToRASMatrix(matrix);
  return node;
}

/** The vessels as a centerline node: polylines in RAS with a "Radius" array. With \a forgetRAS the LPS
 * coordinates are stored as they are, the classic mistake. */
inline vtkSmartPointer<vr::CenterlineNode>
MakeCenterlineNode(const std::vector<Polyline> & vessels, bool forgetRAS = false)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  auto radii = vtkSmartPointer<vtkDoubleArray>::New();
  radii->SetName("Radius");
  for (const auto & vessel : vessels)
  {
    lines->InsertNextCell(static_cast<vtkIdType>(vessel.PointsLPS.size()));
    for (const auto & p : vessel.PointsLPS)
    {
      const double sign = forgetRAS ? 1.0 : -1.0;
      lines->InsertCellPoint(points->InsertNextPoint(sign * p[0], sign * p[1], p[2]));
      radii->InsertNextValue(LumenRadius);
    }
  }
  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetLines(lines);
  polyData->GetPointData()->AddArray(radii);
  auto node = vtkSmartPointer<vr::CenterlineNode>::New();
  node->SetName("two-vessels-centerlines");
  node->SetPolyData(polyData);
  return node;
}

inline itk::Point<double, 3>
MakePoint(double x, double y, double z)
{
  itk::Point<double, 3> point;
  point[0] = x;
  point[1] = y;
  point[2] = z;
  return point;
}

inline ReformationParameters
QuickParameters()
{
  ReformationParameters parameters;
  parameters.Iterations = 30;
  parameters.Backend = vr::RelaxBackend::CPU;
  return parameters;
}

class VesselReformationLogicTest : public ::testing::Test
{
protected:
  void
  SetUp() override
  {
    m_Vessels = TwoVessels();
    m_Volume = MakeVolumeNode(m_Vessels);
    m_Centerlines = MakeCenterlineNode(m_Vessels);
    m_Logic.SetVolumeNode(m_Volume);
    m_Logic.SetCenterlineNode(m_Centerlines);
    m_Logic.SetParameters(QuickParameters());
  }

  std::vector<Polyline>               m_Vessels;
  vtkSmartPointer<vr::VolumeNode>     m_Volume;
  vtkSmartPointer<vr::CenterlineNode> m_Centerlines;
  VesselReformationLogic              m_Logic;
};

inline void
ExpectCounts(const vr::ReformationStageCounts & counts,
             unsigned                           depth,
             unsigned                           relax,
             unsigned                           resample,
             unsigned                           unfiltered,
             unsigned                           relaxed)
{
  EXPECT_EQ(counts.Depth, depth);
  EXPECT_EQ(counts.Relax, relax);
  EXPECT_EQ(counts.Resample, resample);
  EXPECT_EQ(counts.UnfilteredSamplings, unfiltered);
  EXPECT_EQ(counts.RelaxedSamplings, relaxed);
}

} // namespace vr::test::logic

#endif
