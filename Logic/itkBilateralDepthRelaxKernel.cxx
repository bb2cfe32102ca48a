#include "itkBilateralDepthRelaxKernel.h"

#include "itkThreadTeamBarrier.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <future>
#include <limits>
#include <memory>
#include <new>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

#if defined(VR_RELAX_RUNTIME_DISPATCH) && defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#  define VR_RELAX_DISPATCH_AT_RUN_TIME
#  define VR_AVX512_TARGET __attribute__((target("arch=x86-64-v4")))
#  define VR_AVX2_TARGET __attribute__((target("arch=x86-64-v3")))
#endif
#define VR_ALWAYS_INLINE inline __attribute__((always_inline))

namespace itk
{
namespace
{
/** Rows are padded to a multiple of the widest vector, so every instruction set sees the same grid. */
constexpr std::size_t RowAlignment = 16;

/** 2^f for |f| <= 1/2: degree-5 minimax polynomial, relative error 7.5e-8 (2.3e-7 after float rounding). */
template <typename TFloat>
VR_ALWAYS_INLINE TFloat
TwoToTheFraction(TFloat f)
{
  TFloat p = f * 1.327647198e-3f + 9.675541334e-3f;
  p = p * f + 5.550713274e-2f;
  p = p * f + 2.402211972e-1f;
  p = p * f + 6.931469671e-1f;
  return p * f + 1.000000072f;
}

/** 2^u for u = -a log2(e) x^2, that is R = exp(-a x^2), and 0 for u < -126, that is a x^2 > -ln(FLT_MIN) (the
 * filter's underflow rule; -log2(FLT_MIN) is exactly 126). u = n + f with n an integer and |f| <= 1/2 (f exact);
 * 2^f by a degree-5 minimax polynomial (relative error 7.5e-8, 2.3e-7 after float rounding); 2^n built in the
 * exponent bits, a normal float since n >= -126 on the kept range. */
template <typename TFloat, typename TBits>
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

/** The vector types of one instruction set: N float lanes fill one register (SSE2 4, AVX2 8, AVX-512 16).
 * FloatInMemory is an unaligned view of memory that may alias anything. */
template <std::size_t N>
struct VectorsOf;

template <>
struct VectorsOf<4>
{
  static constexpr std::size_t Lanes = 4;
  using Float = float __attribute__((vector_size(16)));
  using Bits = std::uint32_t __attribute__((vector_size(16)));
  using FloatInMemory = float __attribute__((vector_size(16), aligned(4), may_alias));
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

template <>
struct VectorsOf<8>
{
  static constexpr std::size_t Lanes = 8;
  using Float = float __attribute__((vector_size(32)));
  using Bits = std::uint32_t __attribute__((vector_size(32)));
  using FloatInMemory = float __attribute__((vector_size(32), aligned(4), may_alias));
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

template <>
struct VectorsOf<16>
{
  static constexpr std::size_t Lanes = 16;
  using Float = float __attribute__((vector_size(64)));
  using Bits = std::uint32_t __attribute__((vector_size(64)));
  using FloatInMemory = float __attribute__((vector_size(64), aligned(4), may_alias));
  static VR_ALWAYS_INLINE Float
  PowerOfTwo(Float u)
  {
    return PowerOfTwoFromBits<Float, Bits>(u);
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
#  define VR_RELAX_ROUNDING_BARRIER(x) __asm__("" : "+v"(x))
constexpr bool RelaxRowsInPairs = true;
#elif defined(__aarch64__)
#  define VR_RELAX_ROUNDING_BARRIER(x) __asm__("" : "+w"(x))
constexpr bool RelaxRowsInPairs = true;
#else
#  define VR_RELAX_ROUNDING_BARRIER(x)
constexpr bool RelaxRowsInPairs = false;
#endif
template <typename TFloat>
VR_ALWAYS_INLINE TFloat
Rounded(TFloat x)
{
  VR_RELAX_ROUNDING_BARRIER(x);
  return x;
}

template <typename V>
VR_ALWAYS_INLINE typename V::Float
LoadFloats(const float * from)
{
  return *reinterpret_cast<const typename V::FloatInMemory *>(from);
}

template <typename V>
VR_ALWAYS_INLINE void
StoreFloats(float * to, typename V::Float lanes)
{
  *reinterpret_cast<typename V::FloatInMemory *>(to) = lanes;
}

/** Isotropic (a = 0) edges all weigh 1: no exponential needed. */
template <typename V>
struct IsotropicWeight
{
  VR_ALWAYS_INLINE typename V::Float operator()(typename V::Float) const { return typename V::Float{} + 1.0f; }
};

/** R(x) = exp(-a x^2) with the underflow rule, for differences of depths scaled by sqrt(a log2(e)): 2^-(x^2). */
template <typename V>
struct RangeWeight
{
  VR_ALWAYS_INLINE typename V::Float
  operator()(typename V::Float scaledDifference) const
  {
    return V::PowerOfTwo(typename V::Float{} - scaledDifference * scaledDifference);
  }
};

/** The grid the team works on: rows padded to whole vectors, plus what stays constant over the iterations.
 *
 * Each depth is held as a pair of floats, high + low (about 48 bits, like a double): a single float depth of
 * 70 mm cannot take a step below 4e-6 mm, and over hundreds of iterations such lost steps add up to more than
 * 1e-4 mm. A padded row of the depth buffers is Stride high parts followed by Stride low parts. Differences,
 * weights and steps are small and computed in plain float. */
struct RelaxGrid
{
  std::size_t Width;
  std::size_t Height;
  /** Values per padded row: a multiple of RowAlignment, >= Width. */
  std::size_t Stride;
  /** a = 0: every weight is 1. Otherwise depths are held multiplied by sqrt(a log2(e)) (see DepthScale()), so
   * that R = 2^-(x^2) for a difference x of held values. */
  bool Isotropic;
  /** Per padded pixel ((1 - w) / w) |Omega|; infinite for fixed pixels and padding, which so never move. */
  const float * SelfWeight;
};

/** One thread's buffers: the vertical edges above and below the row being relaxed (Weight R and Flux
 * R (D_below - D_above) of each column), and a row that takes the discarded output of the band's first edge row. */
struct RowScratch
{
  float * UpWeight;
  float * UpFlux;
  float * DownWeight;
  float * DownFlux;
  float * DiscardedRow;
};

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
template <typename V, bool HasRowBelow, bool IsLastVector, typename TWeight>
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
template <typename V, bool HasRowBelowPair, bool IsLastVector, typename TWeight>
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
template <typename V>
VR_ALWAYS_INLINE std::size_t
                 LastVectorOfRow(const RelaxGrid & grid)
{
  return (grid.Width - 1) / V::Lanes * V::Lanes;
}

/** One Jacobi step of row y into \a out; leaves the edges below the row in scratch.Down*. */
template <typename V, bool HasRowBelow, typename TWeight>
VR_ALWAYS_INLINE void
RelaxRow(const RelaxGrid &  grid,
         const TWeight &    weight,
         typename V::Float  lastVectorRightEdges,
         const float *      current,
         std::size_t        y,
         float *            out,
         const RowScratch & scratch)
{
  const std::size_t stride = grid.Stride;
  const RowPointers rows{ current + 2 * y * stride,
                          current + 2 * (y + 1) * stride,
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

/** One Jacobi step of rows y and y + 1 into \a out (two padded rows); uses the edges above row y from
 * scratch.Up* and leaves those below row y + 1 in scratch.Down*. Bit for bit the same as two RelaxRow calls. */
template <typename V, bool HasRowBelowPair, typename TWeight>
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

/** One Jacobi iteration of rows [rowBegin, rowEnd): reads \a current (all rows), writes those rows of \a next.
 * The edges above the band come from relaxing the row above into a discarded row with the very same code, so
 * a band boundary changes no bit. */
template <typename V, typename TWeight>
VR_ALWAYS_INLINE void
SweepRows(const RelaxGrid & grid,
          const float *     current,
          float *           next,
          std::size_t       rowBegin,
          std::size_t       rowEnd,
          RowScratch &      scratch)
{
  const TWeight     weight{};
  typename V::Float lastVectorRightEdges;
  for (std::size_t lane = 0; lane < V::Lanes; ++lane)
  {
    // Only columns left of the last one have a right neighbour.
    lastVectorRightEdges[lane] = (LastVectorOfRow<V>(grid) + lane + 1 < grid.Width) ? 1.0f : 0.0f;
  }
  std::fill_n(scratch.UpWeight, grid.Stride, 0.0f);
  std::fill_n(scratch.UpFlux, grid.Stride, 0.0f);
  if (rowBegin > 0)
  {
    RelaxRow<V, true>(grid, weight, lastVectorRightEdges, current, rowBegin - 1, scratch.DiscardedRow, scratch);
    std::swap(scratch.UpWeight, scratch.DownWeight);
    std::swap(scratch.UpFlux, scratch.DownFlux);
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
    std::swap(scratch.UpWeight, scratch.DownWeight);
    std::swap(scratch.UpFlux, scratch.DownFlux);
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
    std::swap(scratch.UpWeight, scratch.DownWeight);
    std::swap(scratch.UpFlux, scratch.DownFlux);
  }
}

template <typename V>
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

using SweepFunction = void (*)(const RelaxGrid &, const float *, float *, std::size_t, std::size_t, RowScratch &);

/** The row sweep for one instruction set, and its name. */
struct RowSweep
{
  SweepFunction Sweep;
  const char *  InstructionSet;
};

#if defined(VR_RELAX_DISPATCH_AT_RUN_TIME)
VR_AVX512_TARGET void
SweepRowsAVX512(const RelaxGrid & grid,
                const float *     current,
                float *           next,
                std::size_t       rowBegin,
                std::size_t       rowEnd,
                RowScratch &      scratch)
{
  SweepRowsWith<VectorsOf<16>>(grid, current, next, rowBegin, rowEnd, scratch);
}

VR_AVX2_TARGET void
SweepRowsAVX2(const RelaxGrid & grid,
              const float *     current,
              float *           next,
              std::size_t       rowBegin,
              std::size_t       rowEnd,
              RowScratch &      scratch)
{
  SweepRowsWith<VectorsOf<8>>(grid, current, next, rowBegin, rowEnd, scratch);
}

void
SweepRowsBaseline(const RelaxGrid & grid,
                  const float *     current,
                  float *           next,
                  std::size_t       rowBegin,
                  std::size_t       rowEnd,
                  RowScratch &      scratch)
{
  SweepRowsWith<VectorsOf<4>>(grid, current, next, rowBegin, rowEnd, scratch);
}

/** The instruction sets this processor runs (CPUID), widest first. */
std::vector<RowSweep>
FindRowSweeps()
{
  std::vector<RowSweep> sweeps;
  __builtin_cpu_init();
  if (__builtin_cpu_supports("x86-64-v4"))
  {
    sweeps.push_back({ SweepRowsAVX512, "AVX-512" });
  }
  if (__builtin_cpu_supports("x86-64-v3"))
  {
    sweeps.push_back({ SweepRowsAVX2, "AVX2+FMA" });
  }
  sweeps.push_back({ SweepRowsBaseline, "x86-64" });
  return sweeps;
}
#else
/** Without runtime dispatch the compiler's target flags (e.g. -march=native) decide the vector width. */
#  if defined(__AVX512F__)
using CompiledVectors = VectorsOf<16>;
constexpr const char * CompiledInstructionSet = "AVX-512 (compile time)";
#  elif defined(__AVX2__)
using CompiledVectors = VectorsOf<8>;
constexpr const char * CompiledInstructionSet = "AVX2 (compile time)";
#  else
using CompiledVectors = VectorsOf<4>;
constexpr const char * CompiledInstructionSet = "128-bit vectors (compile time)";
#  endif

void
SweepRowsCompiled(const RelaxGrid & grid,
                  const float *     current,
                  float *           next,
                  std::size_t       rowBegin,
                  std::size_t       rowEnd,
                  RowScratch &      scratch)
{
  SweepRowsWith<CompiledVectors>(grid, current, next, rowBegin, rowEnd, scratch);
}

std::vector<RowSweep>
FindRowSweeps()
{
  return { { SweepRowsCompiled, CompiledInstructionSet } };
}
#endif

const std::vector<RowSweep> &
RowSweeps()
{
  static const std::vector<RowSweep> sweeps = FindRowSweeps();
  return sweeps;
}

/** Index into RowSweeps() of the one Relax() uses: the widest unless SetInstructionSet() said otherwise. */
std::atomic<std::size_t> ChosenRowSweep{ 0 };

const RowSweep &
TheRowSweep()
{
  return RowSweeps()[ChosenRowSweep.load(std::memory_order_relaxed)];
}

/** sqrt(a log2(e)) for a > 0, 1 for a = 0: the factor the kernel holds depths multiplied by. */
double
DepthScale(double anisotropy)
{
  return anisotropy > 0.0 ? std::sqrt(anisotropy / std::log(2.0)) : 1.0;
}

/** Values aligned to a cache line, zero-filled. */
template <typename TValue>
class AlignedBuffer
{
public:
  explicit AlignedBuffer(std::size_t count)
    : m_Data(Allocate(count))
  {
  }
  TValue *
  Get() const
  {
    return m_Data.get();
  }

private:
  static constexpr std::align_val_t Alignment{ 64 };
  static TValue *
  Allocate(std::size_t count)
  {
    if (count > std::numeric_limits<std::size_t>::max() / sizeof(TValue) - RowAlignment)
    {
      throw std::bad_alloc();
    }
    const std::size_t rounded = (count + RowAlignment - 1) / RowAlignment * RowAlignment;
    auto *            data = static_cast<TValue *>(::operator new[](rounded * sizeof(TValue), Alignment));
    std::fill_n(data, rounded, TValue{});
    return data;
  }
  struct Deleter
  {
    void
    operator()(TValue * data) const
    {
      ::operator delete[](data, Alignment);
    }
  };
  std::unique_ptr<TValue[], Deleter> m_Data;
};

/** A thread's row buffers, in two allocations. */
class ThreadScratch
{
public:
  explicit ThreadScratch(std::size_t stride)
    : m_Edges(4 * stride)
    , m_DiscardedRow(2 * stride)
  {
    m_Rows.UpWeight = m_Edges.Get();
    m_Rows.UpFlux = m_Edges.Get() + stride;
    m_Rows.DownWeight = m_Edges.Get() + 2 * stride;
    m_Rows.DownFlux = m_Edges.Get() + 3 * stride;
    m_Rows.DiscardedRow = m_DiscardedRow.Get();
  }
  RowScratch &
  Rows()
  {
    return m_Rows;
  }

private:
  AlignedBuffer<float> m_Edges;
  AlignedBuffer<float> m_DiscardedRow;
  RowScratch           m_Rows{};
};
} // namespace

void
BilateralDepthRelaxKernel::Relax(const float *            depth,
                                 const unsigned char *    fixed,
                                 float *                  relaxed,
                                 std::size_t              width,
                                 std::size_t              height,
                                 double                   relaxation,
                                 double                   anisotropy,
                                 unsigned int             iterations,
                                 unsigned int             threads,
                                 const ProgressCallback & progress)
{
  const std::size_t count = width * height;
  if (count == 0)
  {
    return;
  }
  if (iterations == 0 || relaxation == 0.0)
  {
    // w = 0 gives every pixel all the weight: nothing moves.
    std::memmove(relaxed, depth, count * sizeof(float));
    if (progress && iterations > 0)
    {
      progress(iterations);
    }
    return;
  }

  RelaxGrid grid{};
  grid.Width = width;
  grid.Height = height;
  grid.Stride = (width + RowAlignment - 1) / RowAlignment * RowAlignment;
  grid.Isotropic = anisotropy == 0.0;
  const double      scale = DepthScale(anisotropy);
  const std::size_t paddedCount = height * grid.Stride;

  // The right neighbour of the last vector of the last row reads one vector past the image.
  AlignedBuffer<float> first(2 * paddedCount + RowAlignment);
  AlignedBuffer<float> second(2 * paddedCount + RowAlignment);
  // Eq. 1 divided by w: the pixel's own weight becomes ((1 - w) / w) |Omega|.
  AlignedBuffer<float> selfWeight(paddedCount);
  const double         selfPerNeighbour = (1.0 - relaxation) / relaxation;
  const float          immovable = std::numeric_limits<float>::infinity();
  for (std::size_t y = 0; y < height; ++y)
  {
    // Padding columns repeat the last column.
    float * high = first.Get() + 2 * y * grid.Stride;
    float * low = high + grid.Stride;
    for (std::size_t x = 0; x < grid.Stride; ++x)
    {
      const double scaled = scale * depth[y * width + std::min(x, width - 1)];
      high[x] = static_cast<float>(scaled);
      low[x] = static_cast<float>(scaled - high[x]);
    }
    float *           self = selfWeight.Get() + y * grid.Stride;
    const std::size_t verticalNeighbours = (y > 0) + (y + 1 < height);
    for (std::size_t x = 0; x < width; ++x)
    {
      const std::size_t neighbours = verticalNeighbours + (x > 0) + (x + 1 < width);
      self[x] = (fixed && fixed[y * width + x])
                  ? immovable
                  : static_cast<float>(selfPerNeighbour * static_cast<double>(neighbours));
    }
    std::fill(self + width, self + grid.Stride, immovable);
  }
  std::copy_n(first.Get(), 2 * paddedCount + RowAlignment, second.Get());
  grid.SelfWeight = selfWeight.Get();

  const unsigned int team = static_cast<unsigned int>(std::max<std::size_t>(1, std::min<std::size_t>(threads, height)));
  std::vector<ThreadScratch> scratch;
  scratch.reserve(team);
  for (unsigned int member = 0; member < team; ++member)
  {
    scratch.emplace_back(grid.Stride);
  }

  // Each member sweeps a fixed band of rows; after the barrier every member sees the whole new image. Member 0
  // is the calling thread and reports progress; a progress callback that throws stops every member after the
  // same barrier. The iteration after whose barrier the team stops is set by member 0 while others may still
  // be leaving the previous barrier, so each member compares it with the iteration it has just finished.
  ThreadTeamBarrier         barrier(team);
  std::atomic<unsigned int> stopAfterIteration{ iterations };
  std::exception_ptr        failure;
  auto                      work = [&](unsigned int member)
  {
    const std::size_t   rowBegin = height * member / team;
    const std::size_t   rowEnd = height * (member + 1) / team;
    const SweepFunction sweep = TheRowSweep().Sweep;
    float *             current = first.Get();
    float *             next = second.Get();
    for (unsigned int iteration = 0; iteration < iterations; ++iteration)
    {
      sweep(grid, current, next, rowBegin, rowEnd, scratch[member].Rows());
      if (member == 0 && progress && iteration > 0)
      {
        try
        {
          progress(iteration);
        }
        catch (...)
        {
          failure = std::current_exception();
          stopAfterIteration.store(iteration, std::memory_order_relaxed);
        }
      }
      barrier.Wait();
      if (stopAfterIteration.load(std::memory_order_relaxed) <= iteration)
      {
        return;
      }
      std::swap(current, next);
    }
  };

  // Helpers wait for the word to start, so that a helper the system refuses to create leaves nobody waiting.
  std::promise<bool>       start;
  std::shared_future<bool> started = start.get_future().share();
  std::vector<std::thread> helpers;
  helpers.reserve(team - 1);
  try
  {
    for (unsigned int member = 1; member < team; ++member)
    {
      helpers.emplace_back(
        [&work, started, member]
        {
          if (started.get())
          {
            work(member);
          }
        });
    }
  }
  catch (const std::system_error &)
  {
    start.set_value(false);
    for (auto & helper : helpers)
    {
      helper.join();
    }
    // The result does not depend on the team size: do it all on this thread.
    Relax(depth, fixed, relaxed, width, height, relaxation, anisotropy, iterations, 1, progress);
    return;
  }
  start.set_value(true);
  work(0);
  for (auto & helper : helpers)
  {
    helper.join();
  }
  if (failure)
  {
    std::rethrow_exception(failure);
  }
  if (progress)
  {
    progress(iterations);
  }

  const float * result = (iterations % 2 == 0) ? first.Get() : second.Get();
  for (std::size_t y = 0; y < height; ++y)
  {
    // Exact for fixed pixels: (x scale) / scale comes within 1e-14 of the float x, which rounding gives back.
    const float * high = result + 2 * y * grid.Stride;
    const float * low = high + grid.Stride;
    for (std::size_t x = 0; x < width; ++x)
    {
      relaxed[y * width + x] = static_cast<float>((static_cast<double>(high[x]) + low[x]) / scale);
    }
  }
}

bool
BilateralDepthRelaxKernel::IsWithinRange(const float * depth, std::size_t count, double anisotropy)
{
  const double limit = MaximumDepthMagnitude / std::max(1.0, DepthScale(anisotropy));
  return std::all_of(depth, depth + count, [limit](float value) { return std::abs(value) <= limit; });
}

std::string
BilateralDepthRelaxKernel::GetInstructionSet()
{
  return TheRowSweep().InstructionSet;
}

std::vector<std::string>
BilateralDepthRelaxKernel::GetSupportedInstructionSets()
{
  std::vector<std::string> names;
  for (const auto & sweep : RowSweeps())
  {
    names.emplace_back(sweep.InstructionSet);
  }
  return names;
}

void
BilateralDepthRelaxKernel::SetInstructionSet(const std::string & name)
{
  const auto & sweeps = RowSweeps();
  if (name.empty())
  {
    ChosenRowSweep.store(0);
    return;
  }
  for (std::size_t k = 0; k < sweeps.size(); ++k)
  {
    if (name == sweeps[k].InstructionSet)
    {
      ChosenRowSweep.store(k);
      return;
    }
  }
  std::string supported;
  for (const auto & sweep : sweeps)
  {
    supported += std::string(supported.empty() ? "" : ", ") + sweep.InstructionSet;
  }
  throw std::invalid_argument("BilateralDepthRelaxKernel: instruction set \"" + name +
                              "\" is not supported here; supported: " + supported);
}

} // namespace itk
