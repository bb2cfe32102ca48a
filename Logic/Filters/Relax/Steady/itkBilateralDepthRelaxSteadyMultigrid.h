// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The steady solver's preconditioner: a black-box multigrid (Dendy, "Black box multigrid", J. Comput. Phys. 48,
// 1982) over the 5-point operator of a padded grid. Internal (namespace itk::detail), not installed; see
// itkBilateralDepthRelaxSteadySolver.h for the method.
#ifndef itkBilateralDepthRelaxSteadyMultigrid_h
#define itkBilateralDepthRelaxSteadyMultigrid_h

#include "itkBilateralDepthRelaxSteadyGrid.h"

#include <cstddef>
#include <vector>

namespace itk::detail::BilateralDepthRelaxSteady
{
/** What a hierarchy allocates, kept from one solve to the next. */
struct MultigridBuffers
{
  /** Levels[0] is the finest; the coarser ones follow. */
  std::vector<Level>  Levels;
  std::vector<float>  ResidualRows;
  std::vector<double> CoarseFactor;
  std::vector<long>   CoarseIndex;
  std::vector<char>   CoarseDropped;
  std::vector<double> CoarseVector;
};

/** A black-box multigrid: coarse points on every other row and column, interpolation that follows the weights (a
 * point beside a depth jump interpolates from its own side only, a point on a line coupled along it only from
 * neither, a diagonal coupling counts towards a coarse point only where that point is coupled to its end), Galerkin
 * coarse operators (9-point stencils),
 * red-black Gauss-Seidel smoothing on the 5-point finest level and four-colour Gauss-Seidel on the 9-point coarse
 * ones, a dense Cholesky solve on the coarsest (at most CoarsestPoints points). Build() makes the hierarchy from the
 * finest level's operator; Cycle() applies one V(1,1)-cycle, a symmetric approximate inverse of it. Every sweep
 * gives the same bits for any split of the rows among the team. */
class Multigrid
{
public:
  /** Grids of this many points or fewer are solved directly. */
  static constexpr long CoarsestPoints = 64;

  /** A fine point between two coarse points interpolates nothing from them when its couplings towards them are below
   * this fraction of its couplings across (see docs/steady-solver.md, "Lines of pixels coupled along themselves
   * only"). */
  static constexpr float WeakInterpolation = 0.01f;

  /** On a 9-point level, a fine point's diagonal coupling counts towards a coarse point only where that coarse point's
   * coupling to the diagonal neighbour is at least this fraction of its diagonal (see docs/steady-solver.md). */
  static constexpr float DiagonalLink = 0.01f;

  /** A hierarchy over a \a width x \a height finest level, whose operator C, E, N the caller fills and whose right-hand
   * side B and correction X the caller points at arrays of the level's layout. With \a lender, the levels' arrays are
   * spans of its memory (a coarser grid of the nested iteration). */
  Multigrid(MultigridBuffers & buffers, Bands & bands, long width, long height, Lender * lender = nullptr);

  /** The levels a hierarchy over a \a width x \a height finest level has. */
  static std::size_t
  LevelCountFor(long width, long height);

  /** The finest level; the reference stays valid for the multigrid's life. */
  Level &
  Finest()
  {
    return m_Buffers.Levels[0];
  }

  /** The coarse levels, interpolation and coarsest factor from the finest level's operator. */
  void
  Build();

  /** X = M^-1 B on the finest level: one V(1,1)-cycle from X = 0. */
  void
  Cycle()
  {
    CycleFrom(0);
  }

  /** Cycle(), and B . X of the finest level, summed row by row in row order (the same bits for any team), each row's
   * formed as the row's X is final, so that neither array is read again for it. */
  double
  CycleAndDot();

  /** Lends the first coarse level's arrays (when built) to \a lender; the next Build computes them again. */
  void
  LendTo(Lender & lender)
  {
    if (m_LevelCount > 1)
    {
      m_Buffers.Levels[1].LendTo(lender);
    }
  }

  /** Levels in the hierarchy (1 before the first Build). */
  std::size_t
  GetLevelCount() const
  {
    return m_LevelCount;
  }
  const Level &
  GetLevel(std::size_t k) const
  {
    return m_Buffers.Levels[k];
  }

  /** B_{k+1} = P^T (B_k - A_k X_k): the residual of level \a k restricted to level k + 1. */
  void
  Restrict(std::size_t k)
  {
    ResidualAndRestrict(m_Buffers.Levels[k], m_Buffers.Levels[k + 1]);
  }

  /** X_k += P X_{k+1}: level k + 1's correction interpolated to level \a k. */
  void
  Prolong(std::size_t k);

private:
  void
  FactorCoarsest();
  void
  SolveCoarsest();
  void
  Smooth(const Level & l, bool forward);
  void
  SmoothFourColour(const Level & l, bool forward);
  void
  SmoothRedBlack(const Level & l, int first, bool fromZero, double * rowDots = nullptr);
  void
  ResidualAndRestrict(const Level & f, const Level & c, bool afterSweepFromZero = false);
  void
  CycleFrom(std::size_t k, double * rowDots = nullptr);

  MultigridBuffers & m_Buffers;
  Bands &            m_Bands;
  std::size_t        m_LevelCount{ 1 };
  Lender *           m_Lender;
};
} // namespace itk::detail::BilateralDepthRelaxSteady

#endif
