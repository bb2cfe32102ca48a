// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkBilateralDepthRelaxKernel_h
#define itkBilateralDepthRelaxKernel_h

#include <cstddef>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace itk
{

/** \class BilateralDepthRelaxKernel
 * \brief The fast CPU relaxation of BilateralDepthRelaxFilter for float depth maps (non-template, compiled once).
 *
 * Runs N Jacobi iterations of Eq. 1 of Kretschmer, Preim, Stamminger (EuroVis 2014), written in difference form,
 * for every pixel p that is not fixed:
 *
 * \f[ D'_p = D_p + \frac{\sum_{q \in \Omega(p)} R(D_q - D_p)\,(D_q - D_p)}
 *                    {\frac{1-w}{w}|\Omega| + \sum_{q \in \Omega(p)} R(D_q - D_p)}, \qquad R(x) = e^{-a x^2}, \f]
 *
 * which is Eq. 1 divided through by w (w = 0 changes nothing and is not iterated). R is 0 when a x^2 exceeds
 * -ln(FLT_MIN) (BilateralDepthRelaxFilter::WeightUnderflowExponent); a zero denominator keeps D_p; fixed pixels
 * keep their value and still feed their neighbours.
 *
 * How it is fast: each edge weight R is computed once per iteration and shared by its two pixels (two
 * exponentials per pixel, a polynomial 2^x on whole vectors, relative error below 3e-7); one pass per row
 * computes both new edges of each pixel and its update, with no branch per pixel (image borders are edges of
 * weight 0, fixed pixels have an infinite self weight); rows are padded to whole vectors; a team of threads,
 * created once per call, relaxes fixed bands of rows and meets at a barrier only after every block of several
 * passes (temporal blocking: each thread computes again the rows near its neighbours' bands that its last pass of
 * the block needs, running the block's passes as a wavefront down its band; docs/design.md); nothing is
 * allocated inside the iteration loop. Depths are held as pairs of floats, high + low, between iterations (a
 * single float cannot take the small late steps of a 70 mm depth); differences, weights and steps are floats.
 * Depths are held multiplied by sqrt(a log2 e), so that R = 2^-(x^2) for a difference x of held values.
 *
 * On x86-64 the row sweep (itkBilateralDepthRelaxRows.hxx) is compiled for AVX-512, AVX2+FMA and baseline
 * x86-64, one translation unit each, and the widest the processor supports is chosen at run time (CPUID; CMake
 * option VR_RELAX_RUNTIME_DISPATCH, on by default). With the option off the compiler flags decide (e.g.
 * -march=native).
 *
 * Every pixel is computed by the same instructions from the same input values whatever thread runs its row and
 * whatever the block, so the result is bit-identical for any number of threads and any passes between
 * synchronizations with a given instruction set.
 *
 * \sa BilateralDepthRelaxFilter, ThreadTeamBarrier
 * \ingroup VesselReformation
 */
class BilateralDepthRelaxKernel
{
public:
  /** Called by the calling thread after each completed iteration with the number of iterations done; may throw
   * (for instance to abort), which stops the team at the end of the current block of passes (no further call) and
   * is rethrown by Relax(). */
  using ProgressCallback = std::function<void(unsigned int completedIterations)>;

  /** Memory Relax() can keep from one call to the next: the depth buffers (about 20 bytes per pixel) and each
   * thread's row buffers (a few rows per pass of a block). Reusing one spares allocating and first touching them on
   * every call (a few ms at 512 x 1024). One call at a time per workspace. */
  class Workspace
  {
  public:
    Workspace();
    ~Workspace();
    Workspace(const Workspace &) = delete;
    Workspace &
    operator=(const Workspace &) = delete;

  private:
    friend class BilateralDepthRelaxKernel;
    struct Buffers;
    std::unique_ptr<Buffers> m_Buffers;
  };

  /** Relaxes \a depth (row-major \a width x \a height, finite values, in mm; see IsWithinRange()) into
   * \a relaxed (same layout; may be the same buffer as \a depth). \a fixed (row-major, non-zero = fixed) may be
   * null. \a relaxation is w in [0, 1], \a anisotropy a >= 0 in mm^-2; the caller checks both. \a threads
   * (>= 1) is the size of the team; it never exceeds the number of rows. \a workspace (may be null) keeps the
   * buffers for the next call. \a passesBetweenSynchronizations is how many passes each thread makes on its band
   * before the team meets (AutomaticPassesBetweenSynchronizations: the kernel's choice from the band height); it
   * changes the speed only. \a progress is called after every pass, in order; one that throws stops the team at
   * the end of its current block. */
  static void
  Relax(const float *            depth,
        const unsigned char *    fixed,
        float *                  relaxed,
        std::size_t              width,
        std::size_t              height,
        double                   relaxation,
        double                   anisotropy,
        unsigned int             iterations,
        unsigned int             threads,
        const ProgressCallback & progress = ProgressCallback(),
        Workspace *              workspace = nullptr,
        unsigned int             passesBetweenSynchronizations = AutomaticPassesBetweenSynchronizations);

  /** The bytes Relax() allocates for a \a width x \a height map with \a iterations passes (none when 0), a team of
   * \a threads and \a passesBetweenSynchronizations, all of which a workspace keeps: the two depth buffers of high
   * and low parts and the pixels' own weights on rows padded to RowAlignment floats (20 bytes per padded pixel), and
   * per team member a pass's row edges and discarded row (six padded rows) for each pass of a block, with a ring of
   * three double rows for each pass but the last. The workspace's own bookkeeping (tens of bytes) is left out. */
  static std::size_t
  GetWorkspaceBytes(std::size_t  width,
                    std::size_t  height,
                    unsigned int iterations,
                    unsigned int threads,
                    unsigned int passesBetweenSynchronizations = AutomaticPassesBetweenSynchronizations);

  /** Relax()'s passesBetweenSynchronizations that leaves the choice to the kernel
   * (ChoosePassesBetweenSynchronizations). */
  static constexpr unsigned int AutomaticPassesBetweenSynchronizations = 0;

  /** The largest team that meets after every pass when the choice is the kernel's. */
  static constexpr unsigned int LargestTeamWithoutBlocks = 4;

  /** The kernel's choice of passes between synchronizations for a team of \a team threads on \a height rows
   * (docs/design.md "Relaxation"): 1 (a barrier after every pass, the plain row sweep) for teams of up to
   * LargestTeamWithoutBlocks, where the blocked row-by-row wavefront costs more than the barriers it saves (measured
   * on 2 cores); for larger teams the band height / 16, between 1 and 16. */
  static unsigned int
  ChoosePassesBetweenSynchronizations(std::size_t height, unsigned int team);

  /** Depths, multiplied by sqrt(a log2 e) when that exceeds 1, of larger magnitude (mm) could overflow a float
   * difference or flux; Relax() is only for maps within this range (any scanner's field of view is a million
   * million times smaller). */
  static constexpr double MaximumDepthMagnitude = 1e30;

  /** True when every depth suits Relax() with anisotropy a (see MaximumDepthMagnitude). */
  static bool
  IsWithinRange(const float * depth, std::size_t count, double anisotropy);

  /** The instruction set Relax() runs its row sweep with: the widest this build and processor support
   * ("AVX-512", "AVX2+FMA", "x86-64", or with runtime dispatch off the one the compiler flags chose), unless
   * SetInstructionSet() picked another. */
  static std::string
  GetInstructionSet();

  /** Every instruction set this build can run on this processor, widest first. */
  static std::vector<std::string>
  GetSupportedInstructionSets();

  /** Makes later Relax() calls (process-wide) use \a name, one of GetSupportedInstructionSets(), so that tests
   * and benchmarks can check and time each; "" restores the widest. Throws std::invalid_argument naming the
   * supported ones otherwise. Results differ between instruction sets only by rounding. */
  static void
  SetInstructionSet(const std::string & name);
};

} // namespace itk

#endif
