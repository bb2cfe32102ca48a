// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The range weight R(x) = exp(-a x^2) of Eq. 1 as the relax kernels compute it: one definition for the Jacobi row
// sweep and the steady solver. Internal (namespace itk::detail), not installed.
//
// Everything here has internal linkage (an unnamed namespace): the Jacobi sweep includes it into translation units
// compiled for different instruction sets, and the linker must never pick one unit's copy for a caller in another.
#ifndef itkBilateralDepthRelaxRangeWeight_h
#define itkBilateralDepthRelaxRangeWeight_h

#include <cstdint>

namespace itk::detail
{
namespace
{
/** 2^f for |f| <= 1/2: degree-5 minimax polynomial, relative error 7.5e-8 (2.3e-7 after float rounding). TFloat is
 * float or a GCC vector of floats. */
template<typename TFloat>
inline __attribute__((always_inline)) TFloat
TwoToTheFraction(TFloat f)
{
  TFloat p = f * 1.327647198e-3f + 9.675541334e-3f;
  p = p * f + 5.550713274e-2f;
  p = p * f + 2.402211972e-1f;
  p = p * f + 6.931469671e-1f;
  return p * f + 1.000000072f;
}

/** R = exp(-a x^2) of \a difference = x, 0 when a x^2 exceeds -ln(FLT_MIN) (BilateralDepthRelaxFilter's
 * WeightUnderflowExponent), as 2^u with u = -(scale x)^2, scale = sqrt(a log2(e)): 2^u = 2^n 2^f, n the nearest
 * integer, f in [-1/2, 1/2], 2^f by TwoToTheFraction, 2^n built in the exponent bits. Written without branches or
 * library calls so that whole rows become vector operations. */
inline float
RangeWeight(float difference, float scale)
{
  const float     t = scale * difference;
  const float     u = -(t * t);
  const float     clamped = u < -126.0f ? -126.0f : u; // std::max(u, -126), spelled out (see above)
  constexpr float RoundingShifter = 12582912.0f;       // 1.5 * 2^23: adding it rounds to an integer
  const float     shifted = clamped + RoundingShifter;
  const float     f = clamped - (shifted - RoundingShifter);
  const float     power = __builtin_bit_cast(float, (__builtin_bit_cast(std::uint32_t, shifted) << 23) + 0x3F800000u);
  const float     weight = TwoToTheFraction(f) * power;
  return u >= -126.0f ? weight : 0.0f;
}
} // namespace
} // namespace itk::detail

#endif
