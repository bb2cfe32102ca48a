// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkBilateralDepthRelaxSteadySolver_h
#define itkBilateralDepthRelaxSteadySolver_h

#include <cstddef>
#include <functional>
#include <memory>
#include <string>

namespace itk
{

/** \class BilateralDepthRelaxSteadySolver
 * \brief The steady state of BilateralDepthRelaxFilter's relaxation: the fixed point of Eq. 1, computed directly.
 *
 * N Jacobi passes of Eq. 1 (Kretschmer, Preim, Stamminger, EuroVis 2014) spread smoothing about sqrt(N) pixels,
 * so their result depends on N and on the pixel count. This solver computes where those passes lead instead: a
 * depth map in which every free pixel p equals the R-weighted mean of its 4-neighbours, the weights taken at the
 * solution,
 *
 * \f[ D_p = \frac{\sum_{q \in \Omega(p)} R(D_p - D_q)\, D_q}{\sum_{q \in \Omega(p)} R(D_p - D_q)}, \qquad
 *     R(x) = e^{-a x^2}, \f]
 *
 * to a maximum residual |D_p - sum R D_q / sum R| below Tolerance mm. The relaxation w only damps Jacobi and does
 * not move this fixed point, so it is no parameter here. Fixed pixels keep their input value bit for bit.
 *
 * The equation is the stationary condition of the robust (Welsch) energy
 * E(D) = sum over 4-neighbour edges of (1 - R(D_p - D_q)) / (2a), and Jacobi's passes descend it. The solver
 * descends it too, and every step it takes lowers E (measured, in float). Outer iterations take lagged-weights
 * steps (iteratively reweighted least squares, a majorise-minimise step: the graph Laplacian with weights R at the
 * current depths, the fixed pixels as Dirichlet values, solved approximately by conjugate gradients preconditioned
 * with a multigrid V-cycle until the residual has fallen tenfold) while each halves the residual. From the first one
 * that does not, they try Newton steps: the energy's own curvature along an edge is R(x) (1 - 2 a x^2), so its
 * Hessian is the Laplacian with those weights (negative where |x| > J / sqrt(2), J = 1 / sqrt(a)), solved the same
 * way with the lagged-weights V-cycle as preconditioner. A Newton step is taken when it lowers E (else half of it,
 * when that does), and Newton steps go on while they are taken. Otherwise that outer iteration takes the
 * lagged-weights correction, stretched by the power of two up to 64 that lowers E most, or, where the conjugate
 * gradients met negative curvature, a step along that direction (either sense, J / 32 doubled up to 2 J) if it
 * lowers E more. Lagged weights alone creep where edges sit near or beyond the inflection J / sqrt(2), since their
 * curvature R overstates the energy's: on the thoracic phantom's arch seams at 512 x 1024 they took 617 outer
 * iterations, against 54 with them (19 against 131 at 128 x 256; 50 at 512 x 1024 since half Newton steps); the
 * run-off phantom never leaves lagged weights (5). From the same start the solver reaches the fixed
 * point Jacobi approaches (the same energy to eight digits as lagged weights alone).
 *
 * Those outer iterations settle the seams near the inflection a few at a time, so from the input they grew with the
 * image's height (the thoracic phantom: 34, 54, 124 at 256 x 512 to 1024 x 2048). So a solve starts from the input,
 * and where lagged weights slow down (the first outer iteration that turns to Newton steps) before they have brought
 * the residual below a tenth of the first, on a map whose coarser grid has 128 x 128 pixels or more, it starts again
 * from the solution on a grid of half the pixels per axis (the same view, fixed where any of a 2 x 2 block is, with J
 * times sqrt 2 and ten times the tolerance; solved the same way, recursively, down to 64 x 128 and at most three grids
 * deep), interpolated across without blurring its depth jumps: nested iteration, after which the map's own grid takes 7
 * to 11 outer iterations (the one from the input included) on the thoracic phantom at 256 x 512 to 2048 x 4096. Maps
 * that lagged weights finish (the run-off phantom, the VMTK aorta) and smaller maps are solved as before, with the same
 * bits. The energy is not convex, so a different start may end in a different fixed point: measured, always one of
 * lower energy than the start from the input. A solve stops after Settings::MaximumOuterIterations on the map's own
 * grid with Report::Converged false and its last iterate (Describe() says how far it got). docs/steady-solver.md gives
 * the reasons and the measurements.
 *
 * The last outer iterations of a solve are often spent on a handful of pixels (the VMTK aorta at 1024 x 2048: 18, then
 * 2, of two million above the tolerance). Where an outer iteration finds at most one such pixel per 2048 (and at
 * least 64), it settles them on their own: Gauss-Seidel sweeps of the lagged-weights update on 9 x 9 windows around
 * them, then the rows they touch assembled again, so that the residual compared with the tolerance is still the whole
 * grid's, exactly as a whole assembly gives it. A settling that would change which weights vanish is undone (the
 * floating regions are then the outer iteration's to classify). It saves one or two outer iterations and their
 * V-cycles on every map measured (docs/steady-solver.md, "The last few pixels").
 *
 * The multigrid is a black-box multigrid (Dendy, "Black box multigrid", J. Comput. Phys. 48, 1982): coarse points
 * on every other row and column, interpolation that follows the weights (a pixel beside a depth jump interpolates
 * from its own side only, and a pixel on a line between two depth steps, coupled along the line only, from neither
 * side: on the VMTK aorta where its iliacs cross, collapsing its stencil joined the two sides on the coarser levels,
 * and the conjugate gradients took 40 iterations where they now take a few), Galerkin coarse operators (9-point
 * stencils), red-black Gauss-Seidel smoothing on the 5-point finest level and four-colour Gauss-Seidel on the 9-point
 * coarse ones, a dense Cholesky solve on the coarsest (at most 64 points). Its cost per cycle is proportional to the
 * pixel count and its convergence rate does not depend on the image's diameter, so a whole solve costs a few tens of
 * passes over the image. The hierarchy is built from the first weights and rebuilt only when the conjugate gradients
 * slow down (the preconditioner may lag the weights; the operator never does).
 *
 * Where the Laplacian is singular, the fixed point is not unique; the solver decides:
 * - A pixel whose every weight underflows (a x^2 above -ln FLT_MIN for all its neighbours) is isolated and keeps its
 *   value, as in Jacobi.
 * - A region of free pixels that no fixed pixel reaches through non-zero weights ("floating"; for instance every
 *   region of a map without any fixed pixel) has every constant as a fixed point. The solver gives it its mean
 *   input depth: constant, and the value the relaxation preserves there. Regions are found on the input and again
 *   whenever the pattern of vanishing weights changes.
 *
 * Depths are held in double between outer iterations, corrections and weights are float. Every pixel is computed
 * by the same code whatever thread runs its row, and sums are formed per row and then added in row order, so the
 * result is bit-identical for any number of threads.
 *
 * \sa BilateralDepthRelaxFilter, BilateralDepthRelaxKernel
 * \ingroup VesselReformation
 */
class BilateralDepthRelaxSteadySolver
{
public:
  /** Called by the calling thread after each outer iteration with the fraction of the way done (from the
   * logarithm of the residual); may throw (for instance to abort), which stops the solve and is rethrown. */
  using ProgressCallback = std::function<void(double fraction)>;

  /** The default residual tolerance, in mm: a tenth of the 1e-3 mm the filter promises, as a margin for the
   * float arithmetic of the solver. */
  static constexpr double DefaultTolerance = 1e-4;

  /** What a solve did. */
  struct Report
  {
    /** Outer (reweighting) iterations on the image's own grid, each with its own weights, those from the input
     * before a nested start included: the iterations whose cost grows with the pixel count (the coarser grids' are
     * CoarseOuterIterations). */
    unsigned int OuterIterations{ 0 };
    /** Outer iterations on the coarser grids of the nested iteration, all of them together. */
    unsigned int CoarseOuterIterations{ 0 };
    /** Grids solved: the image's own and the coarser ones whose solutions were the starts (1 without any). */
    unsigned int Grids{ 1 };
    /** Multigrid V-cycles, over all outer iterations on all grids. */
    unsigned int Cycles{ 0 };
    /** Times a multigrid hierarchy was built, on all grids. */
    unsigned int HierarchyBuilds{ 0 };
    /** Pixels that no fixed pixel reaches and that took their region's mean (isolated pixels included). */
    std::size_t FloatingPixels{ 0 };
    /** max |D_p - sum R D_q / sum R| over free pixels with non-zero weights at the end, in mm (float weights). */
    double Residual{ 0.0 };
    /** For a solve that stopped short (Converged false): the energy sum over 4-neighbour edges of
     * (1 - R(D_p - D_q)) / (2a) at the end, in mm^2 (a = 0: sum of (D_p - D_q)^2 / 2); 0 after a converged one. */
    double Energy{ 0.0 };
    /** False when the residual was still above the tolerance after the most outer iterations allowed: the result is
     * the last iterate, and Describe() says how far it got. */
    bool Converged{ true };
  };

  /** Limits and choices of a solve. */
  struct Settings
  {
    /** Outer iterations on the image's own grid at most; a solve that has not converged then stops with Converged
     * false. Each costs a few passes over the image. */
    unsigned int MaximumOuterIterations;
    /** Where lagged weights slow down, start again from the solution on a grid of half the pixels per axis, itself
     * solved the same way (nested iteration); false goes on from the input depths, as the solver did before (kept
     * for comparisons). */
    bool NestedIteration;
  };

  /** The default settings: at most DefaultMaximumOuterIterations, nested iteration. */
  static Settings
  DefaultSettings()
  {
    return { DefaultMaximumOuterIterations, true };
  }

  /** A sentence for a solve that stopped short: iterations, residual against \a tolerance, energy. */
  static std::string
  Describe(const Report & report, double tolerance);

  /** Buffers kept from one solve to the next (about 95.5 bytes per pixel at 512 x 1024, whether a solve started from
   * the coarser grids or not; GetWorkspaceBytes says how many for a size): reusing one spares allocating and first
   * touching them. One solve at a time per workspace. */
  class Workspace
  {
  public:
    Workspace();
    ~Workspace();
    Workspace(const Workspace &) = delete;
    Workspace &
    operator=(const Workspace &) = delete;

    /** What it holds (defined where the solver is). */
    struct Buffers;

  private:
    friend class BilateralDepthRelaxSteadySolver;
    std::unique_ptr<Buffers> m_Buffers;
  };

  /** Solves for the fixed point of \a depth (row-major \a width x \a height, finite values, in mm) into
   * \a relaxed (same layout; may be the same buffer). \a fixed (row-major, non-zero = fixed) may be null.
   * \a anisotropy is a >= 0 in mm^-2 (0: the harmonic interpolation of the fixed pixels). \a tolerance is the
   * residual to reach, in mm (> 0). \a threads (>= 1) work on bands of rows. A solve whose residual has not fallen
   * below \a tolerance after \a settings' MaximumOuterIterations stops there (Report::Converged false).
   * Throws std::invalid_argument for a bad tolerance. */
  static Report
  Solve(const float *            depth,
        const unsigned char *    fixed,
        float *                  relaxed,
        std::size_t              width,
        std::size_t              height,
        double                   anisotropy,
        double                   tolerance = DefaultTolerance,
        unsigned int             threads = 1,
        const ProgressCallback & progress = ProgressCallback(),
        Workspace *              workspace = nullptr,
        const Settings &         settings = DefaultSettings());

  /** The bytes a solve of a \a width x \a height map with \a threads threads allocates at most (its workspace keeps
   * them): 56 per padded pixel for the depths and the finest grid's vectors, 12 for its operator, 64 per point of
   * each coarser level (about a third as many points in all), and rows. The floating regions add 48 bytes for each
   * run of pixels beyond one per row that vanishing weights split a row into. The coarser grids of the nested
   * iteration, which a solve takes once lagged weights slow down, add only their rows: their maps, arrays and
   * solutions are spans of the finer grid's scratch arrays (residual, corrections, search directions, Hessian, first
   * coarse level), whose values that grid computes again once it has read its start, so the figure is the same
   * whichever path a solve takes (the most either allocates, within 0.2 %). */
  static std::size_t
  GetWorkspaceBytes(std::size_t width, std::size_t height, unsigned int threads = 1);

  /** The most outer iterations on the image's own grid a solve takes by default: with the coarser grids' start the
   * thoracic phantom takes at most 13 at any size measured (256 x 512 to 2048 x 4096; 124 from the input at
   * 1024 x 2048), about 30 passes over the image each. */
  static constexpr unsigned int DefaultMaximumOuterIterations = 100;
};

} // namespace itk

#endif
