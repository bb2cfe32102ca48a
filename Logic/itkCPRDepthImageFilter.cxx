#include "itkCPRDepthImageFilter.h"

namespace itk
{
template class CPRDepthImageFilter<Image<float, 2>>;
} // namespace itk
