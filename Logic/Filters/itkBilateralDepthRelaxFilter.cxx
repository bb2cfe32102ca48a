// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkBilateralDepthRelaxFilter.h"

namespace itk
{
template class BilateralDepthRelaxFilter<Image<float, 2>>;
} // namespace itk
