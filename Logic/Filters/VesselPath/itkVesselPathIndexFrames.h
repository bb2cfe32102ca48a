// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkVesselPathIndexFrames_h
#define itkVesselPathIndexFrames_h

#include "itkContinuousIndex.h"
#include "itkVesselPathSection.h"

#include <vector>

namespace itk
{

/** A vessel path section's frame in a volume's continuous index. The index is affine in the physical point, so the
 * sample at Center + a Lateral + b Up + c Tangent lies at Center + a Lateral + b Up + c Tangent here too: the
 * single-vessel filters step through the volume's index without a transform per sample. */
struct SectionIndexFrame
{
  Vector<double, 3> Center;
  Vector<double, 3> Lateral;
  Vector<double, 3> Up;
  Vector<double, 3> Tangent;
};

/** The index frame of every section of \a sections in \a volume. */
template<typename TVolume>
std::vector<SectionIndexFrame>
SectionIndexFrames(const TVolume * volume, const VesselPathSectionList & sections)
{
  std::vector<SectionIndexFrame> frames(sections.size());
  for (std::size_t k = 0; k < sections.size(); ++k)
  {
    const VesselPathSection &  section = sections[k];
    ContinuousIndex<double, 3> center;
    ContinuousIndex<double, 3> lateral;
    ContinuousIndex<double, 3> up;
    ContinuousIndex<double, 3> tangent;
    volume->TransformPhysicalPointToContinuousIndex(section.Center, center);
    volume->TransformPhysicalPointToContinuousIndex(section.Center + section.Lateral, lateral);
    volume->TransformPhysicalPointToContinuousIndex(section.Center + section.Up, up);
    volume->TransformPhysicalPointToContinuousIndex(section.Center + section.Tangent, tangent);
    frames[k] = { center.GetVectorFromOrigin(), lateral - center, up - center, tangent - center };
  }
  return frames;
}

} // namespace itk

#endif
