// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The steady solver's problem on the image's own grid: the depths, the range weights at them, the lagged-weights
// operator and the energy's Hessian, the energy change along a correction. Internal (namespace itk::detail), not
// installed; see itkBilateralDepthRelaxSteadySolver.h for the method.
#ifndef itkBilateralDepthRelaxSteadyField_h
#define itkBilateralDepthRelaxSteadyField_h

#include "itkBilateralDepthRelaxSteadyGrid.h"
#include "itkBilateralDepthRelaxSteadyRegions.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace itk::detail::BilateralDepthRelaxSteady
{
/** The finest grid's arrays, kept from one solve to the next: one double and FloatArrays floats per padded pixel. */
struct FieldBuffers
{
  static constexpr std::size_t FloatArrays = 12;

  Array<double>              Depth;
  Array<float>               WeightRight, WeightDown, Fixed, Active;
  Array<float>               Residual, Z, Delta, Direction;
  Array<float>               HessianC, HessianE, HessianN, Saved;
  std::vector<double>        RowLowest, RowHighest, RowMaxima;
  std::vector<std::uint64_t> RowSignatures;
  RegionBuffers              Regions;
};

/** The depth map being solved on padded arrays of one layout (see Level), and what the outer iterations compute on
 * it. Depths are double, everything else float. The operator of the finest level (\a finest's C, E, N) is
 * assembled here; its right-hand side B is Residual and its correction X is Z. */
class Field
{
public:
  /** With \a lender, the arrays are spans of its memory (a coarser grid of the nested iteration). */
  Field(FieldBuffers & buffers,
        Bands &        bands,
        Level &        finest,
        long           width,
        long           height,
        double         anisotropy,
        Lender *       lender = nullptr);

  /** Lends the scratch arrays, whose values no outer iteration keeps for the next (residual, corrections, search
   * directions, Hessian), to \a lender. */
  void
  LendScratchTo(Lender & lender);

  /** Index of pixel (x, y). */
  long
  At(long x, long y) const
  {
    return (y + 1) * Stride + x + 1;
  }

  /** The input depths (row-major, Width x Height) and fixed pixels (non-zero, or none when null) and their range. */
  void
  Load(const float * depth, const unsigned char * fixed);

  /** The coarser grid's solution (row-major \a coarseWidth x \a coarseHeight, see CoarsenMap) interpolated onto the
   * active pixels as the start (ProlongStart); fixed and floating pixels keep their depths. */
  void
  StartFrom(const float * coarse, long coarseWidth, long coarseHeight);

  /** The energy sum over 4-neighbour edges of (1 - R(D_p - D_q)) / (2a) at the current depths, in mm^2 (a = 0: the
   * Dirichlet energy, sum of (D_p - D_q)^2 / 2), in double (one exponential per edge: for reports, not the loop). */
  double
  Energy();

  /** The solved depths into \a relaxed; fixed pixels take their input \a depth bit for bit. */
  void
  Store(const float * depth, const unsigned char * fixed, float * relaxed) const;

  /** The weight of every edge at the current depths (0 across the image border), and a signature of the pattern
   * of vanishing weights, to notice when regions may have changed. */
  std::uint64_t
  ComputeWeights();

  /** Activity and the floating regions' means at the current weights (see ClassifyFloatingRegions). */
  std::size_t
  ClassifyRegions(bool & changed);

  /** The finest level's operator from the weights (C = the pixel's weight sum, couplings between active pixels)
   * and the residual sum R (D_q - D_p) as the conjugate gradients' right-hand side, and with \a hessian the energy's
   * Hessian for Newton steps (a third of the work, left out while lagged weights suffice). Returns max |residual| / C
   * over active pixels: the fixed-point residual |D_p - sum R D_q / sum R| in mm. */
  double
  Assemble(bool hessian);

  /** ComputeWeights and Assemble(\a hessian) again where only the depths of rows [\a first, \a last] changed: the
   * weights of rows first - 1 to last, the operator and residual of rows first - 1 to last + 1 (an edge reaches one
   * row further), the same values as both on the whole grid. Returns whether the pattern of vanishing weights of those
   * rows is the one ComputeWeights last signed (the floating regions are then those classified). */
  bool
  ReassembleRows(long first, long last, bool hessian);

  /** The energy change, times 2a, when the depths move by \a step times the correction Delta. Reads the weights
   * ComputeWeights last stored: they must be those of the current depths (as in every outer iteration's step). */
  double
  EnergyChange(float step);

  /** to = from on every row. */
  void
  CopyRows(const float * from, float * to);

  /** depth += step times the correction Delta, kept within the input's range. */
  void
  ApplyCorrection(float step);

  /** One value per row, for maxima over rows. */
  std::vector<double> &
  RowMaxima()
  {
    return m_Buffers.RowMaxima;
  }

  const long Width;
  const long Height;
  const long Stride;
  /** sqrt(a log2(e)): the range weight's scale (see RangeWeight). */
  const float Scale;
  const bool  Isotropic;
  const float TwiceAnisotropy;
  Level &     Finest;
  double      Lowest{ 0.0 };
  double      Highest{ 0.0 };
  double *    Depth;
  float *     WeightRight;
  float *     WeightDown;
  float *     Fixed;
  float *     Active;
  float *     Residual;
  float *     Z;
  float *     Delta;
  float *     Direction;
  float *     HessianC;
  float *     HessianE;
  float *     HessianN;
  float *     Saved;

private:
  /** Row \a y's weights (WeightRow) and their vanishing-weight signature. */
  std::uint64_t
  WeightRowSignature(long y);
  /** Row \a y of Assemble, with its maximum into RowMaxima. */
  void
  AssembleRow(long y, bool hessian);

  FieldBuffers & m_Buffers;
  Bands &        m_Bands;
};
} // namespace itk::detail::BilateralDepthRelaxSteady

#endif
