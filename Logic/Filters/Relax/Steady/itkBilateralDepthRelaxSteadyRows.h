// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The steady solver's row kernels: a table of functions, each working on one row of a padded grid (see
// itkBilateralDepthRelaxSteadyGrid.h). The table is compiled for baseline x86-64, AVX2 (x86-64-v3) and AVX-512
// (x86-64-v4), one unit each (itkBilateralDepthRelaxSteadyRows.hxx), and Rows() holds the widest the processor runs,
// chosen once by the same CPUID check as the Jacobi sweep's (itkBilateralDepthRelaxInstructionSets.h): every row of a
// solve runs the same code, so results stay independent of the thread count. Builds without runtime dispatch have the
// baseline table alone, as wide as the compiler flags allow. Internal (namespace itk::detail), not installed.
#ifndef itkBilateralDepthRelaxSteadyRows_h
#define itkBilateralDepthRelaxSteadyRows_h

#include "itkBilateralDepthRelaxInstructionSets.h"

#include <cstdint>

namespace itk::detail::BilateralDepthRelaxSteady
{
struct Level;

/** The row kernels of one instruction set. */
struct RowKernels
{
  /** Gauss-Seidel on every other point of a 5-point row from column \a first: x_p = (b_p + sum w_pq x_q) / C_p.
   * The points updated are never each other's neighbours, so the row is one vector operation. */
  void (*SmoothRow5)(float * __restrict x,
                     const float * __restrict above,
                     const float * __restrict below,
                     const float * __restrict b,
                     const float * __restrict e,
                     const float * __restrict n,
                     const float * __restrict nBelow,
                     const float * __restrict c,
                     long first,
                     long width);

  /** The first colour of a Gauss-Seidel sweep that starts from x = 0: the neighbours are all 0, so x_p = b_p / C_p. */
  void (*SmoothRowFromZero)(float * __restrict x,
                            const float * __restrict b,
                            const float * __restrict c,
                            long first,
                            long width);

  /** The same on a 9-point row; \a neBelow and \a nwBelow point at the row below's NE and NW (see Level). */
  void (*SmoothRow9)(float * __restrict x,
                     const float * __restrict above,
                     const float * __restrict below,
                     const float * __restrict b,
                     const float * __restrict e,
                     const float * __restrict n,
                     const float * __restrict nBelow,
                     const float * __restrict ne,
                     const float * __restrict neBelow,
                     const float * __restrict nw,
                     const float * __restrict nwBelow,
                     const float * __restrict c,
                     long first,
                     long width);

  /** r = b - A x on a 5-point row. */
  void (*ResidualRow5)(float * __restrict r,
                       const float * __restrict x,
                       const float * __restrict above,
                       const float * __restrict below,
                       const float * __restrict b,
                       const float * __restrict c,
                       const float * __restrict e,
                       const float * __restrict n,
                       const float * __restrict nBelow,
                       long width);

  /** r = b - A x on a 5-point row right after one red-black sweep from x = 0 whose first colour starts at column
   * \a first: at the second colour's points 0 (each has just solved its own equation), at the first colour's
   * (x_p = b_p / C_p) the couplings to the second colour, sum w_pq x_q. So b and C need not be read again. Exact
   * up to rounding; at inactive points (b = 0, no couplings) 0 either way. */
  void (*ResidualAfterSweepFromZeroRow5)(float * __restrict r,
                                         const float * __restrict x,
                                         const float * __restrict above,
                                         const float * __restrict below,
                                         const float * __restrict e,
                                         const float * __restrict n,
                                         const float * __restrict nBelow,
                                         long first,
                                         long width);

  /** r = b - A x on a 9-point row. */
  void (*ResidualRow9)(float * __restrict r,
                       const float * __restrict x,
                       const float * __restrict above,
                       const float * __restrict below,
                       const float * __restrict b,
                       const float * __restrict c,
                       const float * __restrict e,
                       const float * __restrict n,
                       const float * __restrict nBelow,
                       const float * __restrict ne,
                       const float * __restrict neBelow,
                       const float * __restrict nw,
                       const float * __restrict nwBelow,
                       long width);

  /** q = A v on a 5-point row. */
  void (*ApplyRow5)(float * __restrict q,
                    const float * __restrict v,
                    const float * __restrict above,
                    const float * __restrict below,
                    const float * __restrict c,
                    const float * __restrict e,
                    const float * __restrict n,
                    const float * __restrict nBelow,
                    long width);

  /** One coarse row of b_c = P^T r_f: \a r is the fine row 2J, \a rAbove row 2J + 1, \a rBelow row 2J - 1; the
   * weights of the coarse row (and, for those stored a row lower, of the row below). */
  void (*RestrictRow)(float * __restrict b,
                      const float * __restrict r,
                      const float * __restrict rAbove,
                      const float * __restrict rBelow,
                      const float * __restrict xa,
                      const float * __restrict xb,
                      const float * __restrict ya,
                      const float * __restrict ybBelow,
                      const float * __restrict q0,
                      const float * __restrict q1,
                      const float * __restrict q2Below,
                      const float * __restrict q3Below,
                      long width);

  /** One coarse row of x_f += P x_c: fine rows 2J (\a fine) and 2J + 1 (\a fineAbove) from coarse rows J (\a x) and
   * J + 1 (\a xAbove). */
  void (*ProlongRow)(float * __restrict fine,
                     float * __restrict fineAbove,
                     const float * __restrict x,
                     const float * __restrict xAbove,
                     const float * __restrict xa,
                     const float * __restrict xb,
                     const float * __restrict ya,
                     const float * __restrict yb,
                     const float * __restrict q0,
                     const float * __restrict q1,
                     const float * __restrict q2,
                     const float * __restrict q3,
                     long width);

  /** The range weights of a row's edges to the right (the last column has none) and, when \a below is not null, to
   * the row below; returns a signature of the vanishing ones (their count and the sum of their columns). */
  std::uint64_t (*WeightRow)(float * __restrict right,
                             float * __restrict down,
                             const double * __restrict d,
                             const double * __restrict below,
                             float scale,
                             bool  isotropic,
                             long  width);

  /** The finest level's operator and residual in a row (see Field::Assemble), without and with the energy's Hessian. */
  void (*AssembleOperatorRow)(float * __restrict c,
                              float * __restrict e,
                              float * __restrict n,
                              float * __restrict hc,
                              float * __restrict he,
                              float * __restrict hn,
                              float * __restrict residual,
                              const double * __restrict d,
                              const double * __restrict dAbove,
                              const double * __restrict dBelow,
                              const float * __restrict active,
                              const float * __restrict activeAbove,
                              const float * __restrict right,
                              const float * __restrict down,
                              const float * __restrict up,
                              float twiceAnisotropy,
                              long  width);

  void (*AssembleOperatorAndHessianRow)(float * __restrict c,
                                        float * __restrict e,
                                        float * __restrict n,
                                        float * __restrict hc,
                                        float * __restrict he,
                                        float * __restrict hn,
                                        float * __restrict residual,
                                        const double * __restrict d,
                                        const double * __restrict dAbove,
                                        const double * __restrict dBelow,
                                        const float * __restrict active,
                                        const float * __restrict activeAbove,
                                        const float * __restrict right,
                                        const float * __restrict down,
                                        const float * __restrict up,
                                        float twiceAnisotropy,
                                        long  width);

  /** delta += alpha v, r -= alpha q on a row. */
  void (*UpdateRow)(float * __restrict delta,
                    float * __restrict r,
                    const float * __restrict v,
                    const float * __restrict q,
                    float alpha,
                    long  width);

  /** v = z + beta v on a row. */
  void (*DirectionRow)(float * __restrict v, const float * __restrict z, float beta, long width);

  /** The change of the energy sum (1 - R(D_p - D_q)) over a row's edges to the right and to the row below (\a below
   * null for the last row) when the depths move by \a step times \a delta, times 2a, summed in Lanes partial sums;
   * \a right and \a down are the edges' weights at the current depths (WeightRow's). */
  double (*EnergyChangeRow)(const double * __restrict d,
                            const double * __restrict below,
                            const float * __restrict right,
                            const float * __restrict down,
                            const float * __restrict delta,
                            const float * __restrict deltaBelow,
                            float step,
                            float anisotropy,
                            float scale,
                            float * __restrict scratch,
                            long width);

  /** One fine row of a coarser grid's solution interpolated as a start (ProlongStart,
   * itkBilateralDepthRelaxSteadyNested.h): at every active pixel x (\a active nonzero), the bilinear mean of coarse
   * pixel x / 2 of \a own (the coarse row of the pixel's centre) and its neighbours towards the pixel in \a own and \a
   * other (the coarse row on the pixel's side), each neighbour weighted by the range weight of its difference to x / 2
   * (\a scale as in RangeWeight; 0: plain bilinear). Other pixels keep their depth. */
  void (*ProlongStartRow)(double * __restrict depth,
                          const float * __restrict active,
                          const float * __restrict own,
                          const float * __restrict other,
                          long  coarseWidth,
                          float scale,
                          long  width);

  /** depth += delta on a row, kept within [low, high]: the fixed point lies within the range of the input (each free
   * pixel a weighted mean of its neighbours), so a correction that leaves it, as one can in a mode the weights all
   * but decouple, is cut back to it. */
  void (*AddRow)(double * __restrict depth,
                 const float * __restrict delta,
                 float  step,
                 double low,
                 double high,
                 long   width);

  /** sum of a[i] b[i] over a row, in Lanes partial sums added in a fixed order: the same bits on any machine. */
  double (*RowDot)(const float * __restrict a, const float * __restrict b, long count);

  /** max |r[i]| s[i] over a row, in Lanes partial maxima. */
  float (*RowMaximum)(const float * __restrict r, const float * __restrict s, long count);

  /** max |r[i]| / c[i] over a row's active points (see DividedByDiagonal), in Lanes partial maxima. */
  float (*RowMaximumOverDiagonal)(const float * __restrict r, const float * __restrict c, long count);

  /** Coarse row J of the Galerkin operator P^T A P of a finer 5-point (the finest) or 9-point level. */
  void (*BuildGalerkinRowFrom5)(const Level & f, Level & c, long J);
  void (*BuildGalerkinRowFrom9)(const Level & f, Level & c, long J);
};

/** The row kernels compiled for each instruction set (the AVX ones exist only in builds with runtime dispatch). */
extern const RowKernels RowKernelsBaseline;
extern const RowKernels RowKernelsAVX2;
extern const RowKernels RowKernelsAVX512;

/** The row kernels compiled for \a set, one of RunnableInstructionSets(). */
const RowKernels &
RowsFor(InstructionSet set);

/** The row kernels the solver uses: those of the widest instruction set this processor runs. */
const RowKernels &
Rows();
} // namespace itk::detail::BilateralDepthRelaxSteady

#endif
