// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkRotationMinimizingFrame.h"

#include "itkMacro.h"
#include "itkMath.h"

#include <cmath>

namespace itk
{
namespace
{
Vector<double, 3>
Cross(const Vector<double, 3> & a, const Vector<double, 3> & b)
{
  Vector<double, 3> c;
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
  return c;
}

/** \a v made normal to the unit vector \a t and normalised. */
Vector<double, 3>
NormalTo(const Vector<double, 3> & v, const Vector<double, 3> & t)
{
  Vector<double, 3> n = v - t * (v * t);
  n.Normalize();
  return n;
}
} // namespace

auto
RotationMinimizingFrame::InitialLateral(const VectorType & tangent, const CPRViewGeometry & view) -> VectorType
{
  if (std::abs(view.GetU() * tangent) <= NearlyParallelCosine)
  {
    return NormalTo(view.GetU(), tangent);
  }
  const VectorType up = NormalTo(-view.GetV(), tangent);
  VectorType       lateral = Cross(up, tangent);
  lateral.Normalize();
  return lateral;
}

void
RotationMinimizingFrame::Roll(VesselPathSectionList & sections, double rollInDegrees)
{
  if (!std::isfinite(rollInDegrees))
  {
    itkGenericExceptionMacro(<< "RotationMinimizingFrame: the roll angle " << rollInDegrees
                             << " degrees is not finite");
  }
  if (rollInDegrees == 0.0)
  {
    return;
  }
  const double c = std::cos(rollInDegrees * Math::pi / 180.0);
  const double s = std::sin(rollInDegrees * Math::pi / 180.0);
  for (VesselPathSection & section : sections)
  {
    const VectorType lateral = section.Lateral * c + section.Up * s;
    section.Up = section.Up * c - section.Lateral * s;
    section.Lateral = lateral;
  }
}

VesselPathSectionList
RotationMinimizingFrame::Compute(const VesselPath &      path,
                                 double                  step,
                                 const CPRViewGeometry & view,
                                 double                  rollInDegrees)
{
  if (!std::isfinite(rollInDegrees))
  {
    itkGenericExceptionMacro(<< "RotationMinimizingFrame: the roll angle " << rollInDegrees
                             << " degrees is not finite");
  }
  const std::vector<double> arcLengths = path.SampleArcLengths(step); // throws on a bad step or a short path
  VesselPathSectionList     sections(arcLengths.size());
  for (std::size_t k = 0; k < arcLengths.size(); ++k)
  {
    VesselPathSection & section = sections[k];
    section.ArcLength = arcLengths[k];
    section.Center = path.PointAt(arcLengths[k]);
    section.Tangent = path.TangentAt(arcLengths[k]);
    section.Radius = path.RadiusAt(arcLengths[k]);
    section.BranchId = path.BranchIdAt(arcLengths[k]);
  }
  sections[0].Lateral = InitialLateral(sections[0].Tangent, view);
  for (std::size_t k = 0; k + 1 < sections.size(); ++k)
  {
    // Double reflection: the first in the bisector plane of the two centres, the second in the plane that then maps
    // the reflected tangent onto the next tangent.
    const VesselPathSection & a = sections[k];
    VesselPathSection &       b = sections[k + 1];
    const VectorType          v1 = b.Center - a.Center;
    const double              c1 = v1 * v1;
    VectorType                lateral = a.Lateral;
    VectorType                tangent = a.Tangent;
    if (c1 > 0.0)
    {
      lateral -= v1 * (2.0 / c1 * (v1 * lateral));
      tangent -= v1 * (2.0 / c1 * (v1 * tangent));
    }
    const VectorType v2 = b.Tangent - tangent;
    const double     c2 = v2 * v2;
    if (c2 > 0.0)
    {
      lateral -= v2 * (2.0 / c2 * (v2 * lateral));
    }
    // Exact in exact arithmetic; the projection keeps rounding from accumulating over thousands of sections.
    b.Lateral = NormalTo(lateral, b.Tangent);
  }
  for (VesselPathSection & section : sections)
  {
    section.Up = Cross(section.Tangent, section.Lateral);
  }
  Roll(sections, rollInDegrees);
  return sections;
}

auto
RotationMinimizingFrame::CurvatureVectors(const VesselPathSectionList & sections) -> std::vector<VectorType>
{
  std::vector<VectorType> curvature(sections.size());
  if (sections.size() < 2)
  {
    for (auto & k : curvature)
    {
      k.Fill(0.0);
    }
    return curvature;
  }
  for (std::size_t k = 0; k < sections.size(); ++k)
  {
    const std::size_t before = k == 0 ? 0 : k - 1;
    const std::size_t after = k + 1 == sections.size() ? k : k + 1;
    const double      ds = sections[after].ArcLength - sections[before].ArcLength;
    curvature[k] = (sections[after].Tangent - sections[before].Tangent) / (ds > 0.0 ? ds : 1.0);
  }
  return curvature;
}

} // namespace itk
