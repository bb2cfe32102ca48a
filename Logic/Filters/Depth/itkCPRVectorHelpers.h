// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCPRVectorHelpers_h
#define itkCPRVectorHelpers_h

#include "itkVector.h"

namespace itk::detail
{
// ITK 5.2 has no itk::MakeVector (it arrived in 5.3); these keep literals readable.
inline Vector<double, 3>
MakeVector3(double x, double y, double z)
{
  Vector<double, 3> v;
  v[0] = x;
  v[1] = y;
  v[2] = z;
  return v;
}

inline Vector<double, 2>
MakeVector2(double x, double y)
{
  Vector<double, 2> v;
  v[0] = x;
  v[1] = y;
  return v;
}
} // namespace itk::detail

#endif
