// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkStraightenedCPRImageFilter.h"

namespace itk
{
std::ostream &
operator<<(std::ostream & os, VesselPathCPRMode mode)
{
  return os << (mode == VesselPathCPRMode::Stretched ? "Stretched" : "Straightened");
}

template class StraightenedCPRImageFilter<Image<float, 3>, Image<float, 2>>;
template class StraightenedCPRImageFilter<ImageBase<3>, Image<float, 2>>;
} // namespace itk
