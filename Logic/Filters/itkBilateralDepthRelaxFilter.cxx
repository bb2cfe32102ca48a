#include "itkBilateralDepthRelaxFilter.h"

namespace itk
{
template class BilateralDepthRelaxFilter<Image<float, 2>>;
} // namespace itk
