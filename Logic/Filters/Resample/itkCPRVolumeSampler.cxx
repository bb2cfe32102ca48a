// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkCPRVolumeSampler.h"

namespace itk
{
// The typed samplers of every stored pixel type (their interpolators among them) are compiled here once; the filters
// that share them inline only the per-sample code.
template class CPRVolumeSampler<Image<short, 3>>;
template class CPRVolumeSampler<Image<float, 3>>;
template class CPRVolumeSampler<Image<unsigned short, 3>>;
template class CPRVolumeSampler<Image<unsigned char, 3>>;
template class CPRVolumeSampler<Image<signed char, 3>>;
template class CPRVolumeSampler<Image<double, 3>>;
} // namespace itk
