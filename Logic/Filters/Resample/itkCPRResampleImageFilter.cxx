// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkCPRResampleImageFilter.h"

namespace itk
{
std::ostream &
operator<<(std::ostream & os, CPRInterpolationMode mode)
{
  switch (mode)
  {
    case CPRInterpolationMode::Nearest:
      return os << "Nearest";
    case CPRInterpolationMode::Cubic:
      return os << "Cubic";
    default:
      return os << "Linear";
  }
}

std::ostream &
operator<<(std::ostream & os, CPRSlabMode mode)
{
  switch (mode)
  {
    case CPRSlabMode::MinIP:
      return os << "MinIP";
    case CPRSlabMode::Mean:
      return os << "Mean";
    default:
      return os << "MIP";
  }
}

template class CPRResampleImageFilter<Image<float, 3>, Image<float, 2>, Image<float, 2>>;
template class CPRResampleImageFilter<ImageBase<3>, Image<float, 2>, Image<float, 2>>;
} // namespace itk
