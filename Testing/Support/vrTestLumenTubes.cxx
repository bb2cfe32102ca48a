// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrTestLumenTubes.h"

#include "vrTestSegmentations.h"

#include <algorithm>
#include <cmath>

namespace vr::test
{
LumenTube::LumenTube()
{
  Spacing[0] = 0.6;
  Spacing[1] = 0.8;
  Spacing[2] = 1.1;
  Axis[0] = 1.0;
  Axis[1] = 0.5;
  Axis[2] = 0.8;
  Start[0] = 12.0;
  Start[1] = -7.0;
  Start[2] = 30.0;
}

double
StenosisRadius(double s)
{
  const double offset = s - 40.0;
  return std::abs(offset) <= 5.0 ? 4.0 - (1.0 + std::cos(2.0 * M_PI * offset / 10.0)) : 4.0;
}

LumenTubeScene
MakeLumenTube(const LumenTube & tube)
{
  using VectorType = itk::Vector<double, 3>;
  VectorType tangent = tube.Axis;
  tangent.Normalize();
  // Lateral: perpendicular to the axis, from the LPS axis least aligned with it.
  VectorType helper;
  helper.Fill(0.0);
  unsigned int least = 0;
  for (unsigned int d = 1; d < 3; ++d)
  {
    least = std::abs(tangent[d]) < std::abs(tangent[least]) ? d : least;
  }
  helper[least] = 1.0;
  VectorType lateral = helper - tangent * (helper * tangent);
  lateral.Normalize();
  const VectorType up = itk::CrossProduct(tangent, lateral);

  // The grid: the rotated direction, an origin and size that cover the tube with 3 mm around it.
  const auto direction =
    RotationMatrix(tube.RotationAxis[0], tube.RotationAxis[1], tube.RotationAxis[2], tube.RotationDegrees);
  double       maximumRadius = 0.0;
  const double first = -10.0;
  const double last = tube.PathLength + 10.0;
  for (double s = first; s <= last; s += 0.05)
  {
    maximumRadius = std::max(maximumRadius, tube.Radius(s));
  }
  const double reach = maximumRadius * std::max(1.0, tube.LateralScale) + 3.0;
  double       lowest[3] = { 1e300, 1e300, 1e300 };
  double       highest[3] = { -1e300, -1e300, -1e300 };
  const auto   inverse = direction.GetTranspose();
  for (const double s : { first, last })
  {
    for (int corner = 0; corner < 8; ++corner)
    {
      itk::Point<double, 3> p = tube.Start + tangent * s;
      for (unsigned int d = 0; d < 3; ++d)
      {
        p[d] += ((corner >> d) & 1) ? reach : -reach;
      }
      // Continuous index about origin 0.
      for (unsigned int r = 0; r < 3; ++r)
      {
        double sum = 0.0;
        for (unsigned int c = 0; c < 3; ++c)
        {
          sum += inverse[r][c] * p[c];
        }
        const double index = sum / tube.Spacing[r];
        lowest[r] = std::min(lowest[r], std::floor(index));
        highest[r] = std::max(highest[r], std::ceil(index));
      }
    }
  }
  itk::Size<3>          size;
  itk::Point<double, 3> origin;
  origin.Fill(0.0);
  for (unsigned int r = 0; r < 3; ++r)
  {
    size[r] = static_cast<itk::SizeValueType>(highest[r] - lowest[r] + 1.0);
  }
  for (unsigned int r = 0; r < 3; ++r)
  {
    for (unsigned int c = 0; c < 3; ++c)
    {
      origin[r] += direction[r][c] * lowest[c] * tube.Spacing[c];
    }
  }
  LumenTubeScene scene;
  scene.Mask = MakeLabelMap(size, tube.Spacing, origin, direction);

  unsigned char * buffer = scene.Mask->GetBufferPointer();
  std::size_t     k = 0;
  itk::Index<3>   index;
  for (index[2] = 0; index[2] < static_cast<long>(size[2]); ++index[2])
  {
    for (index[1] = 0; index[1] < static_cast<long>(size[1]); ++index[1])
    {
      for (index[0] = 0; index[0] < static_cast<long>(size[0]); ++index[0], ++k)
      {
        itk::Point<double, 3> p;
        scene.Mask->TransformIndexToPhysicalPoint(index, p);
        const VectorType offset = p - tube.Start;
        const double     s = offset * tangent;
        if (s < first || s > last)
        {
          continue;
        }
        const double r = tube.Radius(s);
        const double x = (offset * lateral) / (r * tube.LateralScale);
        const double y = (offset * up) / r;
        buffer[k] = x * x + y * y < 1.0 ? 1 : 0;
      }
    }
  }

  const auto count = static_cast<std::size_t>(std::floor(tube.PathLength / tube.SectionStep + 1e-9)) + 1;
  for (std::size_t n = 0; n < count; ++n)
  {
    itk::VesselPathSection section;
    section.ArcLength = static_cast<double>(n) * tube.SectionStep;
    section.Center = tube.Start + tangent * section.ArcLength;
    section.Tangent = tangent;
    section.Lateral = lateral;
    section.Up = up;
    section.Radius = tube.Radius(section.ArcLength) * std::min(1.0, tube.LateralScale);
    section.BranchId = 1;
    scene.Sections.push_back(section);
  }
  return scene;
}
} // namespace vr::test
