// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkCrossSectionStackImageFilter.h"

namespace itk
{
template class CrossSectionStackImageFilter<Image<float, 3>, Image<float, 3>>;
template class CrossSectionStackImageFilter<ImageBase<3>, Image<float, 3>>;
} // namespace itk
