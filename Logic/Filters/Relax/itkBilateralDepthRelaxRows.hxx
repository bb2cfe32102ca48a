// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The row sweep's templates, included only by the itkBilateralDepthRelaxRows*.cxx translation units, each
// compiled for one instruction set. Everything here has internal linkage and uses no standard-library templates:
// code compiled for AVX-512 must never be picked by the linker for a caller on another processor.
#ifndef itkBilateralDepthRelaxRows_hxx
#define itkBilateralDepthRelaxRows_hxx

#include "itkBilateralDepthRelaxRangeWeight.h"
#include "itkBilateralDepthRelaxRows.h"

#include <cstddef>
#include <cstdint>

#if defined(__AVX512F__)
#include <immintrin.h>
#endif

#define VR_ALWAYS_INLINE inline __attribute__((always_inline))

namespace itk
{
namespace detail::BilateralDepthRelaxRows
{
namespace
{
/** 2^u for u = -a log2(e) x^2, that is R = exp(-a x^2), and 0 for u < -126, that is a x^2 > -ln(FLT_MIN) (the
 * filter's underflow rule; -log2(FLT_MIN) is exactly 126). u = n + f with n an integer and |f| <= 1/2 (f exact);
 * 2^f by TwoToTheFraction (itkBilateralDepthRelaxRangeWeight.h, the steady solver's too); 2^n built in the exponent
 * bits, a normal float since n >= -126 on the kept range. */
template<typename TFloat, typename TBits>
VR_ALWAYS_INLINE TFloat
PowerOfTwoFromBits(TFloat u)
{
  // Adding 1.5 * 2^23 rounds to an integer, which then sits in the low mantissa bits.
  constexpr float RoundingShifter = 12582912.0f;
  const TFloat    shifted = u + RoundingShifter;
  const TFloat    f = u - (shifted - RoundingShifter);
  const TBits     twoToTheNBits = ((TBits)shifted << 23) + 0x3F800000u;
  const TFloat    weight = TwoToTheFraction(f) * (TFloat)twoToTheNBits;
  return u >= -126.0f ? weight : TFloat{};
}

/** The vector types of one instruction set: N float lanes fill one register (SSE2 4, AVX2 8, AVX-512 16). They
 * are read from and written to memory only through LoadFloats/StoreFloats, which make no alignment assumption. */
template<std::size_t N>
struct VectorsOf;

template<>
struct VectorsOf<4>
{
  static constexpr std::size_t Lanes = 4;
  using Float = float __attribute__((vector_size(16)));
  using Bits = std::uint32_t __attribute__((vector_size(16)));
  static VR_ALWAYS_INLINE Float
  PowerOfTwo(Float u)
  {
    return PowerOfTwoFromBits<Float, Bits>(u);
  }
  static VR_ALWAYS_INLINE Float
  ShiftInFromLeft(Float previous, Float current)
  {
    return __builtin_shufflevector(previous, current, 3, 4, 5, 6);
  }
};

template<>
struct VectorsOf<8>
{
  static constexpr std::size_t Lanes = 8;
  using Float = float __attribute__((vector_size(32)));
  using Bits = std::uint32_t __attribute__((vector_size(32)));
  static VR_ALWAYS_INLINE Float
  PowerOfTwo(Float u)
  {
    return PowerOfTwoFromBits<Float, Bits>(u);
  }
  static VR_ALWAYS_INLINE Float
  ShiftInFromLeft(Float previous, Float current)
  {
    return __builtin_shufflevector(previous, current, 7, 8, 9, 10, 11, 12, 13, 14);
  }
};

template<>
struct VectorsOf<16>
{
  static constexpr std::size_t Lanes = 16;
  using Float = float __attribute__((vector_size(64)));
  using Bits = std::uint32_t __attribute__((vector_size(64)));
  static VR_ALWAYS_INLINE Float
  PowerOfTwo(Float u)
  {
#if defined(__AVX512F__)
    // As PowerOfTwoFromBits, with AVX-512's round-to-integer and multiply-by-2^n: three operations fewer. The
    // zero-masked forms (all lanes, or those kept by the underflow rule) avoid GCC 12's undefined-source warning.
    const __mmask16 kept = _mm512_cmp_ps_mask(u, _mm512_set1_ps(-126.0f), _CMP_GE_OQ);
    const Float     n = _mm512_maskz_roundscale_ps(0xFFFF, u, _MM_FROUND_TO_NEAREST_INT | _MM_FROUND_NO_EXC);
    return _mm512_maskz_scalef_ps(kept, TwoToTheFraction(u - n), n);
#else
    return PowerOfTwoFromBits<Float, Bits>(u);
#endif
  }
  static VR_ALWAYS_INLINE Float
  ShiftInFromLeft(Float previous, Float current)
  {
    return __builtin_shufflevector(previous, current, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30);
  }
};

/** \a x as computed, never fused into a later addition (an empty asm hides it from the compiler's FMA
 * contraction): a flux is rounded once, whichever sums it enters, so that a pixel's result does not depend on
 * whether its row was relaxed alone or together with the next one. Where no such barrier is known, rows are
 * relaxed one at a time (RelaxRowsInPairs). */
#if defined(__x86_64__) || defined(__i386__)
#define VR_RELAX_ROUNDING_BARRIER(x) __asm__("" : "+v"(x))
constexpr bool RelaxRowsInPairs = true;
#elif defined(__aarch64__)
#define VR_RELAX_ROUNDING_BARRIER(x) __asm__("" : "+w"(x))
constexpr bool RelaxRowsInPairs = true;
#else
#define VR_RELAX_ROUNDING_BARRIER(x)
constexpr bool RelaxRowsInPairs = false;
#endif
template<typename TFloat>
VR_ALWAYS_INLINE TFloat
Rounded(TFloat x)
{
  VR_RELAX_ROUNDING_BARRIER(x);
  return x;
}

/** Lanes floats from \a from, which need only a float's alignment: a copy of bytes, which both GCC and Clang turn
 * into one unaligned vector load (vmovups). (A vector type declared with aligned(4) would say the same to GCC,
 * but Clang ignores an alignment below the vector's own and emits aligned loads that fault.) */
template<typename V>
VR_ALWAYS_INLINE typename V::Float
LoadFloats(const float * from)
{
  typename V::Float lanes;
  __builtin_memcpy(&lanes, from, sizeof(lanes));
  return lanes;
}

/** Stores Lanes floats at \a to, which needs only a float's alignment (see LoadFloats). */
template<typename V>
VR_ALWAYS_INLINE void
StoreFloats(float * to, typename V::Float lanes)
{
  __builtin_memcpy(to, &lanes, sizeof(lanes));
}

/** Isotropic (a = 0) edges all weigh 1: no exponential needed. */
template<typename V>
struct IsotropicWeight
{
  VR_ALWAYS_INLINE typename V::Float operator()(typename V::Float) const { return typename V::Float{} + 1.0f; }
};

/** R(x) = exp(-a x^2) with the underflow rule, for differences of depths scaled by sqrt(a log2(e)): 2^-(x^2). */
template<typename V>
struct RangeWeight
{
  VR_ALWAYS_INLINE typename V::Float
  operator()(typename V::Float scaledDifference) const
  {
    return V::PowerOfTwo(typename V::Float{} - scaledDifference * scaledDifference);
  }
};

VR_ALWAYS_INLINE void
SwapUpAndDown(RowScratch & scratch)
{
  float * weight = scratch.UpWeight;
  float * flux = scratch.UpFlux;
  scratch.UpWeight = scratch.DownWeight;
  scratch.UpFlux = scratch.DownFlux;
  scratch.DownWeight = weight;
  scratch.DownFlux = flux;
}

/** The rows of one Jacobi step of row y, held in locals so that the compiler need not reload them after stores.
 * Row, Below and Out point at high parts; the low parts are Stride further on. */
struct RowPointers
{
  const float * Row;
  const float * Below;
  std::size_t   Stride;
  const float * SelfWeight;
  const float * UpWeight;
  const float * UpFlux;
  float *       DownWeight;
  float *       DownFlux;
  float *       Out;
};

/** Relaxes one vector of row y: both new edges of each pixel (right and down) are computed here once and
 * handed on, the right one to the next vector (as its left edge), the down one to the next row (as its up edge). */
template<typename V, bool HasRowBelow, bool IsLastVector, typename TWeight>
VR_ALWAYS_INLINE void
RelaxVector(const TWeight &     weight,
            const RowPointers & rows,
            typename V::Float   lastVectorRightEdges,
            std::size_t         x,
            typename V::Float & leftWeight,
            typename V::Float & leftFlux)
{
  using Float = typename V::Float;
  const Float high = LoadFloats<V>(rows.Row + x);
  const Float low = LoadFloats<V>(rows.Row + rows.Stride + x);
  // (high_q - high_p) is exact for nearby depths, so the pair difference keeps the float's full precision.
  const Float right = (LoadFloats<V>(rows.Row + x + 1) - high) + (LoadFloats<V>(rows.Row + rows.Stride + x + 1) - low);
  Float       rightWeight = weight(right);
  if (IsLastVector)
  {
    rightWeight *= lastVectorRightEdges;
  }
  const Float rightFlux = Rounded(rightWeight * right);
  Float       downWeight{};
  Float       downFlux{};
  if (HasRowBelow)
  {
    const Float down = (LoadFloats<V>(rows.Below + x) - high) + (LoadFloats<V>(rows.Below + rows.Stride + x) - low);
    downWeight = weight(down);
    downFlux = Rounded(downWeight * down);
    StoreFloats<V>(rows.DownWeight + x, downWeight);
    StoreFloats<V>(rows.DownFlux + x, downFlux);
  }
  const Float previousWeight = V::ShiftInFromLeft(leftWeight, rightWeight);
  const Float previousFlux = V::ShiftInFromLeft(leftFlux, rightFlux);
  leftWeight = rightWeight;
  leftFlux = rightFlux;

  const Float weightSum = (previousWeight + rightWeight) + (LoadFloats<V>(rows.UpWeight + x) + downWeight);
  const Float fluxSum = (rightFlux - previousFlux) + (downFlux - LoadFloats<V>(rows.UpFlux + x));
  const Float denominator = LoadFloats<V>(rows.SelfWeight + x) + weightSum;
  const Float step = denominator > 0.0f ? fluxSum / denominator : Float{};
  // D + step as a new pair (Fast2Sum: the low part keeps what the high part's rounding dropped).
  const Float lowAndStep = low + step;
  const Float newHigh = high + lowAndStep;
  StoreFloats<V>(rows.Out + x, newHigh);
  StoreFloats<V>(rows.Out + rows.Stride + x, lowAndStep - (newHigh - high));
}

/** RelaxVector for rows y and y + 1 together: the edge between them is used by both straight from registers,
 * and row y + 1 is loaded once. The same operations in the same order as RelaxVector on each row. */
template<typename V, bool HasRowBelowPair, bool IsLastVector, typename TWeight>
VR_ALWAYS_INLINE void
RelaxVectorPair(const TWeight &     weight,
                const RowPointers & upper,
                const RowPointers & lower,
                typename V::Float   lastVectorRightEdges,
                std::size_t         x,
                typename V::Float & upperLeftWeight,
                typename V::Float & upperLeftFlux,
                typename V::Float & lowerLeftWeight,
                typename V::Float & lowerLeftFlux)
{
  using Float = typename V::Float;
  const std::size_t stride = upper.Stride;
  const Float       highUpper = LoadFloats<V>(upper.Row + x);
  const Float       lowUpper = LoadFloats<V>(upper.Row + stride + x);
  const Float       highLower = LoadFloats<V>(lower.Row + x);
  const Float       lowLower = LoadFloats<V>(lower.Row + stride + x);
  const Float       rightUpper =
    (LoadFloats<V>(upper.Row + x + 1) - highUpper) + (LoadFloats<V>(upper.Row + stride + x + 1) - lowUpper);
  const Float rightLower =
    (LoadFloats<V>(lower.Row + x + 1) - highLower) + (LoadFloats<V>(lower.Row + stride + x + 1) - lowLower);
  const Float between = (highLower - highUpper) + (lowLower - lowUpper);
  Float       rightUpperWeight = weight(rightUpper);
  Float       rightLowerWeight = weight(rightLower);
  if (IsLastVector)
  {
    rightUpperWeight *= lastVectorRightEdges;
    rightLowerWeight *= lastVectorRightEdges;
  }
  const Float rightUpperFlux = Rounded(rightUpperWeight * rightUpper);
  const Float rightLowerFlux = Rounded(rightLowerWeight * rightLower);
  const Float betweenWeight = weight(between);
  const Float betweenFlux = Rounded(betweenWeight * between);
  Float       downWeight{};
  Float       downFlux{};
  if (HasRowBelowPair)
  {
    const Float down =
      (LoadFloats<V>(lower.Below + x) - highLower) + (LoadFloats<V>(lower.Below + stride + x) - lowLower);
    downWeight = weight(down);
    downFlux = Rounded(downWeight * down);
    StoreFloats<V>(lower.DownWeight + x, downWeight);
    StoreFloats<V>(lower.DownFlux + x, downFlux);
  }
  const Float upperPreviousWeight = V::ShiftInFromLeft(upperLeftWeight, rightUpperWeight);
  const Float upperPreviousFlux = V::ShiftInFromLeft(upperLeftFlux, rightUpperFlux);
  const Float lowerPreviousWeight = V::ShiftInFromLeft(lowerLeftWeight, rightLowerWeight);
  const Float lowerPreviousFlux = V::ShiftInFromLeft(lowerLeftFlux, rightLowerFlux);
  upperLeftWeight = rightUpperWeight;
  upperLeftFlux = rightUpperFlux;
  lowerLeftWeight = rightLowerWeight;
  lowerLeftFlux = rightLowerFlux;

  {
    const Float weightSum =
      (upperPreviousWeight + rightUpperWeight) + (LoadFloats<V>(upper.UpWeight + x) + betweenWeight);
    const Float fluxSum = (rightUpperFlux - upperPreviousFlux) + (betweenFlux - LoadFloats<V>(upper.UpFlux + x));
    const Float denominator = LoadFloats<V>(upper.SelfWeight + x) + weightSum;
    const Float step = denominator > 0.0f ? fluxSum / denominator : Float{};
    const Float lowAndStep = lowUpper + step;
    const Float newHigh = highUpper + lowAndStep;
    StoreFloats<V>(upper.Out + x, newHigh);
    StoreFloats<V>(upper.Out + stride + x, lowAndStep - (newHigh - highUpper));
  }
  {
    const Float weightSum = (lowerPreviousWeight + rightLowerWeight) + (betweenWeight + downWeight);
    const Float fluxSum = (rightLowerFlux - lowerPreviousFlux) + (downFlux - betweenFlux);
    const Float denominator = LoadFloats<V>(lower.SelfWeight + x) + weightSum;
    const Float step = denominator > 0.0f ? fluxSum / denominator : Float{};
    const Float lowAndStep = lowLower + step;
    const Float newHigh = highLower + lowAndStep;
    StoreFloats<V>(lower.Out + x, newHigh);
    StoreFloats<V>(lower.Out + stride + x, lowAndStep - (newHigh - highLower));
  }
}

/** The first column of the vector that holds a row's last column. */
template<typename V>
VR_ALWAYS_INLINE std::size_t
                 LastVectorOfRow(const RelaxGrid & grid)
{
  return (grid.Width - 1) / V::Lanes * V::Lanes;
}

/** One Jacobi step of row y (input rows \a row and \a below) into \a out; leaves the edges below the row in
 * scratch.Down*. The blocked passes' rows live in rings, so the two rows are given apart. */
template<typename V, bool HasRowBelow, typename TWeight>
VR_ALWAYS_INLINE void
RelaxRowFrom(const RelaxGrid &  grid,
             const TWeight &    weight,
             typename V::Float  lastVectorRightEdges,
             const float *      row,
             const float *      below,
             std::size_t        y,
             float *            out,
             const RowScratch & scratch)
{
  const std::size_t stride = grid.Stride;
  const RowPointers rows{ row,
                          below,
                          stride,
                          grid.SelfWeight + y * stride,
                          scratch.UpWeight,
                          scratch.UpFlux,
                          scratch.DownWeight,
                          scratch.DownFlux,
                          out };
  typename V::Float leftWeight{};
  typename V::Float leftFlux{};
  // Vectors right of the one holding the last column hold only padding, which never moves and feeds nobody.
  const std::size_t lastVector = LastVectorOfRow<V>(grid);
  for (std::size_t x = 0; x < lastVector; x += V::Lanes)
  {
    RelaxVector<V, HasRowBelow, false>(weight, rows, lastVectorRightEdges, x, leftWeight, leftFlux);
  }
  RelaxVector<V, HasRowBelow, true>(weight, rows, lastVectorRightEdges, lastVector, leftWeight, leftFlux);
}

/** One Jacobi step of row y of \a current (the whole padded image) into \a out; leaves the edges below the row in
 * scratch.Down*. */
template<typename V, bool HasRowBelow, typename TWeight>
VR_ALWAYS_INLINE void
RelaxRow(const RelaxGrid &  grid,
         const TWeight &    weight,
         typename V::Float  lastVectorRightEdges,
         const float *      current,
         std::size_t        y,
         float *            out,
         const RowScratch & scratch)
{
  RelaxRowFrom<V, HasRowBelow>(grid,
                               weight,
                               lastVectorRightEdges,
                               current + 2 * y * grid.Stride,
                               current + 2 * (y + 1) * grid.Stride,
                               y,
                               out,
                               scratch);
}

/** One Jacobi step of rows y and y + 1 into \a out (two padded rows); uses the edges above row y from
 * scratch.Up* and leaves those below row y + 1 in scratch.Down*. Bit for bit the same as two RelaxRow calls. */
template<typename V, bool HasRowBelowPair, typename TWeight>
VR_ALWAYS_INLINE void
RelaxRowPair(const RelaxGrid &  grid,
             const TWeight &    weight,
             typename V::Float  lastVectorRightEdges,
             const float *      current,
             std::size_t        y,
             float *            out,
             const RowScratch & scratch)
{
  const std::size_t stride = grid.Stride;
  const RowPointers upper{ current + 2 * y * stride,
                           current + 2 * (y + 1) * stride,
                           stride,
                           grid.SelfWeight + y * stride,
                           scratch.UpWeight,
                           scratch.UpFlux,
                           nullptr,
                           nullptr,
                           out };
  const RowPointers lower{ current + 2 * (y + 1) * stride,
                           current + 2 * (y + 2) * stride,
                           stride,
                           grid.SelfWeight + (y + 1) * stride,
                           nullptr,
                           nullptr,
                           scratch.DownWeight,
                           scratch.DownFlux,
                           out + 2 * stride };
  typename V::Float upperLeftWeight{};
  typename V::Float upperLeftFlux{};
  typename V::Float lowerLeftWeight{};
  typename V::Float lowerLeftFlux{};
  const std::size_t lastVector = LastVectorOfRow<V>(grid);
  for (std::size_t x = 0; x < lastVector; x += V::Lanes)
  {
    RelaxVectorPair<V, HasRowBelowPair, false>(
      weight, upper, lower, lastVectorRightEdges, x, upperLeftWeight, upperLeftFlux, lowerLeftWeight, lowerLeftFlux);
  }
  RelaxVectorPair<V, HasRowBelowPair, true>(weight,
                                            upper,
                                            lower,
                                            lastVectorRightEdges,
                                            lastVector,
                                            upperLeftWeight,
                                            upperLeftFlux,
                                            lowerLeftWeight,
                                            lowerLeftFlux);
}

/** 1 in the lanes of a row's last vector whose column has a right neighbour, 0 elsewhere. */
template<typename V>
VR_ALWAYS_INLINE typename V::Float
LastVectorRightEdges(const RelaxGrid & grid)
{
  typename V::Float edges;
  for (std::size_t lane = 0; lane < V::Lanes; ++lane)
  {
    // Only columns left of the last one have a right neighbour.
    edges[lane] = (LastVectorOfRow<V>(grid) + lane + 1 < grid.Width) ? 1.0f : 0.0f;
  }
  return edges;
}

/** The image's first row has no edges above it: weight and flux 0. */
VR_ALWAYS_INLINE void
ClearUpEdges(const RelaxGrid & grid, const RowScratch & scratch)
{
  for (std::size_t x = 0; x < grid.Stride; ++x)
  {
    scratch.UpWeight[x] = 0.0f;
    scratch.UpFlux[x] = 0.0f;
  }
}

/** One Jacobi iteration of rows [rowBegin, rowEnd): reads \a current (all rows), writes those rows of \a next.
 * The edges above the band come from relaxing the row above into a discarded row with the very same code, so
 * a band boundary changes no bit. */
template<typename V, typename TWeight>
VR_ALWAYS_INLINE void
SweepRows(const RelaxGrid & grid,
          const float *     current,
          float *           next,
          std::size_t       rowBegin,
          std::size_t       rowEnd,
          RowScratch &      scratch)
{
  const TWeight           weight{};
  const typename V::Float lastVectorRightEdges = LastVectorRightEdges<V>(grid);
  ClearUpEdges(grid, scratch);
  if (rowBegin > 0)
  {
    RelaxRow<V, true>(grid, weight, lastVectorRightEdges, current, rowBegin - 1, scratch.DiscardedRow, scratch);
    SwapUpAndDown(scratch);
  }
  // Two rows at a time save loads and stores; a band's rows split into pairs and singles differently for
  // different bands, which the bitwise sameness of the two makes harmless.
  std::size_t y = rowBegin;
  for (; RelaxRowsInPairs && y + 1 < rowEnd; y += 2)
  {
    if (y + 2 < grid.Height)
    {
      RelaxRowPair<V, true>(grid, weight, lastVectorRightEdges, current, y, next + 2 * y * grid.Stride, scratch);
    }
    else
    {
      RelaxRowPair<V, false>(grid, weight, lastVectorRightEdges, current, y, next + 2 * y * grid.Stride, scratch);
    }
    SwapUpAndDown(scratch);
  }
  for (; y < rowEnd; ++y)
  {
    if (y + 1 < grid.Height)
    {
      RelaxRow<V, true>(grid, weight, lastVectorRightEdges, current, y, next + 2 * y * grid.Stride, scratch);
    }
    else
    {
      RelaxRow<V, false>(grid, weight, lastVectorRightEdges, current, y, next + 2 * y * grid.Stride, scratch);
    }
    SwapUpAndDown(scratch);
  }
}

template<typename V>
VR_ALWAYS_INLINE void
SweepRowsWith(const RelaxGrid & grid,
              const float *     current,
              float *           next,
              std::size_t       rowBegin,
              std::size_t       rowEnd,
              RowScratch &      scratch)
{
  if (grid.Isotropic)
  {
    SweepRows<V, IsotropicWeight<V>>(grid, current, next, rowBegin, rowEnd, scratch);
  }
  else
  {
    SweepRows<V, RangeWeight<V>>(grid, current, next, rowBegin, rowEnd, scratch);
  }
}

// Blocks of passes (temporal blocking, itkBilateralDepthRelaxKernel.cxx) relax single rows held anywhere; one
// pass a block uses SweepRows above.

/** StartFunction: the edges above row \a first, as SweepRows computes them for a band starting there. */
template<typename V, typename TWeight>
VR_ALWAYS_INLINE void
StartRows(const RelaxGrid & grid, const float * above, const float * row, std::size_t first, RowScratch & scratch)
{
  ClearUpEdges(grid, scratch);
  if (first > 0)
  {
    RelaxRowFrom<V, true>(
      grid, TWeight{}, LastVectorRightEdges<V>(grid), above, row, first - 1, scratch.DiscardedRow, scratch);
    SwapUpAndDown(scratch);
  }
}

/** RowFunction: one row, as SweepRows relaxes it. */
template<typename V, typename TWeight>
VR_ALWAYS_INLINE void
RelaxOneRow(const RelaxGrid & grid,
            const float *     row,
            const float *     below,
            std::size_t       y,
            float *           out,
            RowScratch &      scratch)
{
  if (below)
  {
    RelaxRowFrom<V, true>(grid, TWeight{}, LastVectorRightEdges<V>(grid), row, below, y, out, scratch);
  }
  else
  {
    RelaxRowFrom<V, false>(grid, TWeight{}, LastVectorRightEdges<V>(grid), row, nullptr, y, out, scratch);
  }
  SwapUpAndDown(scratch);
}

template<typename V>
VR_ALWAYS_INLINE void
StartRowsWith(const RelaxGrid & grid, const float * above, const float * row, std::size_t first, RowScratch & scratch)
{
  if (grid.Isotropic)
  {
    StartRows<V, IsotropicWeight<V>>(grid, above, row, first, scratch);
  }
  else
  {
    StartRows<V, RangeWeight<V>>(grid, above, row, first, scratch);
  }
}

template<typename V>
VR_ALWAYS_INLINE void
RelaxOneRowWith(const RelaxGrid & grid,
                const float *     row,
                const float *     below,
                std::size_t       y,
                float *           out,
                RowScratch &      scratch)
{
  if (grid.Isotropic)
  {
    RelaxOneRow<V, IsotropicWeight<V>>(grid, row, below, y, out, scratch);
  }
  else
  {
    RelaxOneRow<V, RangeWeight<V>>(grid, row, below, y, out, scratch);
  }
}

} // namespace
} // namespace detail::BilateralDepthRelaxRows
} // namespace itk

#endif
