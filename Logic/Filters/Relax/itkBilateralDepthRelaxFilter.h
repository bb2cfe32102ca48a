// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkBilateralDepthRelaxFilter_h
#define itkBilateralDepthRelaxFilter_h

#include "itkBilateralDepthRelaxKernel.h"
#include "itkBilateralDepthRelaxSolver.h"
#include "itkBilateralDepthRelaxSteadySolver.h"
#include "itkImage.h"
#include "itkImageToImageFilter.h"

namespace itk
{

/** \class BilateralDepthRelaxFilter
 * \brief Relaxes a CPR depth map with an iterated 4-neighbour bilateral filter, holding fixed pixels.
 *
 * Implements Eq. 1 and 2 of Kretschmer, Preim, Stamminger, "Bilateral Depth Filtering for Enhanced Vessel
 * Reformation", EuroVis 2014 (short paper). Each of N Jacobi iterations computes, for every pixel p that is not
 * fixed, from the previous iteration's values only,
 *
 * \f[ D'_p = \frac{(1-w)|\Omega| D_p + w \sum_{q \in \Omega(p)} R(D_p - D_q) D_q}
 *                 {(1-w)|\Omega| + w \sum_{q \in \Omega(p)} R(D_p - D_q)}, \qquad R(x) = e^{-(x/J)^2} = e^{-a x^2} \f]
 *
 * where Omega(p) are the 4-neighbours inside the image (2 at corners, 3 on borders). Fixed pixels (mask != 0)
 * keep their value and still feed their neighbours. w = 0 changes nothing; a = 0 is linear Laplacian
 * smoothing; a larger a stops smoothing across smaller depth jumps.
 *
 * The range kernel is set by its meaning, the jump threshold J in mm (SetJumpThreshold(); depth steps well below J
 * are smoothed away, steps of several J stay), or by the paper's anisotropy a = 1/J^2 in mm^-2 (SetAnisotropy());
 * either setter sets both. The default, J = 3 mm (a = 1/9 mm^-2), removes the 2-10 mm scan-line seams of real CT
 * angiography and keeps jumps from 20 mm; the paper's a = 0.5 mm^-2 (J = 1.41 mm) leaves most seams above 2 mm.
 *
 * Two solvers (SetSolver()): Jacobi, the paper's N passes, whose result depends on N and on the pixel count (N passes
 * spread smoothing about sqrt(N) pixels); and Steady, the fixed point those passes approach, computed directly to a
 * residual below SteadyTolerance mm by BilateralDepthRelaxSteadySolver (w and N do not apply).
 *
 * A weight R underflows to 0 when a x^2 exceeds WeightUnderflowExponent (the exponent of float's smallest
 * normal number), identically on every backend. When w = 1 and every weight of a pixel underflows, the pixel
 * keeps its value: never 0/0, never NaN.
 *
 * The output does not depend on the number of threads (bit-identical), and carries the input's metadata
 * dictionary (the CPR view) along. Float images are relaxed by BilateralDepthRelaxKernel (shared edge weights, a
 * vectorised exponential, a team of GetNumberOfHostThreads() threads: one per core unless the work units are set);
 * other pixel types by a plain loop in double (Jacobi) or through a float copy (Steady).
 *
 * AbortGenerateData() is honoured after every iteration (Jacobi; the threads stop together at the end of their
 * current block of PassesBetweenSynchronizations passes, within about one pass of work) or outer iteration
 * (Steady): the update ends with itk::ProcessAborted.
 *
 * Bad parameters or inputs (w outside [0, 1], a < 0, J <= 0, a non-finite parameter, a mask of another size, a
 * non-finite depth) raise an itk::ExceptionObject naming the parameter and its value.
 *
 * \sa CPRDepthImageFilter, CPRResampleImageFilter, OpenCLBilateralDepthRelaxFilter, BilateralDepthRelaxKernel,
 * BilateralDepthRelaxSteadySolver
 * \ingroup VesselReformation
 */
template<typename TImage, typename TMaskImage = Image<unsigned char, TImage::ImageDimension>>
class ITK_TEMPLATE_EXPORT BilateralDepthRelaxFilter : public ImageToImageFilter<TImage, TImage>
{
public:
  ITK_DISALLOW_COPY_AND_MOVE(BilateralDepthRelaxFilter);

  static_assert(TImage::ImageDimension == 2, "BilateralDepthRelaxFilter works on 2D depth maps");

  using Self = BilateralDepthRelaxFilter;
  using Superclass = ImageToImageFilter<TImage, TImage>;
  using Pointer = SmartPointer<Self>;
  using ConstPointer = SmartPointer<const Self>;

  using ImageType = TImage;
  using MaskImageType = TMaskImage;
  using PixelType = typename ImageType::PixelType;
  using RegionType = typename ImageType::RegionType;
  using SizeType = typename ImageType::SizeType;

  itkNewMacro(Self);
  itkTypeMacro(BilateralDepthRelaxFilter, ImageToImageFilter);

  /** a x^2 above this makes R underflow to 0: -ln(FLT_MIN), the exponent of float's smallest normal number. */
  static constexpr double WeightUnderflowExponent = 87.336544750553102;

  /** Relaxation w in [0, 1] (dimensionless): 0 keeps the image, 1 gives the pixel itself no weight. */
  itkSetMacro(Relaxation, double);
  itkGetConstMacro(Relaxation, double);

  /** The default jump threshold J, in mm: see the class comment. */
  static constexpr double DefaultJumpThreshold = 3.0;

  /** Anisotropy a >= 0, in mm^-2: the range kernel's sharpness, a = 1/J^2. 0 is isotropic (linear) smoothing.
   * Sets the jump threshold to 1/sqrt(a) (infinite for a = 0). */
  void
  SetAnisotropy(double anisotropy);
  itkGetConstMacro(Anisotropy, double);

  /** Jump threshold J > 0, in mm: R(x) = exp(-(x/J)^2). Sets the anisotropy to 1/J^2. */
  void
  SetJumpThreshold(double jumpThreshold);
  itkGetConstMacro(JumpThreshold, double);

  /** Number of Jacobi iterations N >= 0 (Jacobi only). */
  itkSetMacro(NumberOfIterations, unsigned int);
  itkGetConstMacro(NumberOfIterations, unsigned int);

  /** Jacobi passes each thread makes on its band of rows before the threads synchronize (temporal blocking,
   * docs/design.md "Relaxation"): the rows next to the neighbours' bands are computed again rather than exchanged after
   * every pass. It changes the speed only, never a bit of the result. 0 (the default) leaves the choice to the
   * kernel (BilateralDepthRelaxKernel::ChoosePassesBetweenSynchronizations: 1 for teams of up to 4 threads, blocks
   * for larger teams); 1 synchronizes after every pass with the plain row sweep. Float images only (the generic
   * loop meets after every pass). */
  itkSetMacro(PassesBetweenSynchronizations, unsigned int);
  itkGetConstMacro(PassesBetweenSynchronizations, unsigned int);

  /** Jacobi (the paper's, the default) or Steady. */
  itkSetEnumMacro(Solver, BilateralDepthRelaxSolver);
  itkGetEnumMacro(Solver, BilateralDepthRelaxSolver);

  /** The residual max |D_p - sum R D_q / sum R| over free pixels that the Steady solver reaches, in mm (> 0). */
  itkSetMacro(SteadyTolerance, double);
  itkGetConstMacro(SteadyTolerance, double);

  /** The most outer iterations on the image's own grid a Steady solve takes (>= 0); one that has not reached the
   * tolerance then stops with the last iterate as output and GetSteadyWarning() saying how far it got. */
  itkSetMacro(SteadyMaximumOuterIterations, unsigned int);
  itkGetConstMacro(SteadyMaximumOuterIterations, unsigned int);

  /** What the last Steady solve did (outer iterations, V-cycles, final residual, energy, whether it converged);
   * empty after a Jacobi update. */
  const BilateralDepthRelaxSteadySolver::Report &
  GetSteadyReport() const
  {
    return m_SteadyReport;
  }

  /** A sentence when the last Steady solve stopped at SteadyMaximumOuterIterations without reaching the tolerance
   * (how far it got), else "". */
  std::string
  GetSteadyWarning() const
  {
    return m_SteadyReport.Converged ? std::string()
                                    : BilateralDepthRelaxSteadySolver::Describe(m_SteadyReport, m_SteadyTolerance);
  }

  /** The number of threads the CPU paths use: GetNumberOfWorkUnits(), at most the multi-threader's maximum. Until the
   * work units are set (SetNumberOfWorkUnits), also at most ITK's default thread count (one per core, or as the
   * application configured ITK): ITK's pool threader gives four work units per thread, and the process's one pool
   * only grows, so the default team would otherwise follow whatever thread count another filter in the process once
   * asked for, and the kernels' teams, which meet at barriers, would share cores (the steady solve at 256 x 512:
   * 620 ms on 8 threads sharing 2 cores against 56 ms on 2). Set the work units to ask for more. */
  unsigned int
  GetNumberOfHostThreads();

  /** ProcessObject's, noting that the work units were asked for (see GetNumberOfHostThreads). */
  void
  SetNumberOfWorkUnits(ThreadIdType workUnits) override;

  /** The bytes of the workspace an update of a depth map of \a size allocates and the filter keeps from one update
   * to the next, with this filter's solver, iterations, passes and host threads, for a float map within the fast
   * kernel's range: BilateralDepthRelaxKernel::GetWorkspaceBytes for Jacobi (and the mask as bytes when its pixels
   * are not), BilateralDepthRelaxSteadySolver::GetWorkspaceBytes for Steady (the same whether a solve starts from
   * the coarser grids or not: they lie in the image's grid's scratch arrays).
   * A steady update also holds the relaxed map in float and the mask in bytes while it runs (5 bytes a pixel), which
   * it frees again. The memory check of a reformation asks this before an update. Virtual: the OpenCL filter counts
   * what it holds in host memory. */
  virtual std::size_t
  GetWorkspaceBytes(const SizeType & size);

  /** Optional fixed mask, same size as the depth image: non-zero pixels keep their depth. */
  itkSetInputMacro(FixedMask, MaskImageType);
  itkGetInputMacro(FixedMask, MaskImageType);

  /** The depth image to relax (input 0). */
  void
  SetDepthInput(const ImageType * depth)
  {
    this->SetInput(depth);
  }

protected:
  BilateralDepthRelaxFilter();
  ~BilateralDepthRelaxFilter() override = default;

  /** Checks w, a (or J, when it was set last) and the steady tolerance. */
  void
  VerifyPreconditions() ITKv5_CONST override;
  /** Checks that the mask has the depth image's size, then the physical space as usual. */
  void
  VerifyInputInformation() ITKv5_CONST override;

  /** The filter needs and produces whole images. */
  void
  GenerateInputRequestedRegion() override;
  void
  EnlargeOutputRequestedRegion(DataObject * output) override;
  /** Passes the input's metadata dictionary (the CPR view) on to the output. */
  void
  GenerateOutputInformation() override;

  /** Allocates the output, checks every depth is finite, then runs RelaxOnHost(). */
  void
  GenerateData() override;

  /** Throws itk::ProcessAborted when AbortGenerateData is on (checked after every iteration, so an abort takes
   * effect within about one pass). */
  void
  ThrowIfAborted(unsigned int completedIterations) const;

  /** Throws when a depth is not finite; names the pixel. Shared by the CPU and OpenCL variants. */
  void
  VerifyDepthIsFinite() const;

  /** The CPU relaxation. Jacobi: N sweeps over rows split among the work units (one thread each); float images
   * within BilateralDepthRelaxKernel::MaximumDepthMagnitude run the vectorised kernel, anything else the generic
   * loop. Steady: BilateralDepthRelaxSteadySolver. */
  void
  RelaxOnHost();

  void
  PrintSelf(std::ostream & os, Indent indent) const override;

private:
  /** Float depth maps: BilateralDepthRelaxKernel with min(GetNumberOfWorkUnits(), the multi-threader's maximum
   * number of threads) threads. */
  void
  RelaxOnHostFast();
  /** Any pixel type: a row-parallel loop evaluating Eq. 1 in double through ITK's threader. */
  void
  RelaxOnHostGeneric();
  /** The Steady solver, on the pixels as float. */
  void
  RelaxOnHostSteady();

  double       m_Relaxation{ 1.0 };
  double       m_JumpThreshold{ DefaultJumpThreshold };
  double       m_Anisotropy{ 1.0 / (DefaultJumpThreshold * DefaultJumpThreshold) };
  bool         m_JumpThresholdWasSet{ true }; // which of J and a the user set last, for messages
  unsigned int m_NumberOfIterations{ 500 };
  unsigned int m_PassesBetweenSynchronizations{ BilateralDepthRelaxKernel::AutomaticPassesBetweenSynchronizations };
  BilateralDepthRelaxSolver m_Solver{ BilateralDepthRelaxSolver::Jacobi };
  double                    m_SteadyTolerance{ BilateralDepthRelaxSteadySolver::DefaultTolerance };
  unsigned int m_SteadyMaximumOuterIterations{ BilateralDepthRelaxSteadySolver::DefaultMaximumOuterIterations };

  BilateralDepthRelaxSteadySolver::Report m_SteadyReport;

  // The fast kernels' buffers, kept between updates: relaxing again for a new view allocates nothing.
  BilateralDepthRelaxKernel::Workspace       m_KernelWorkspace;
  BilateralDepthRelaxSteadySolver::Workspace m_SteadyWorkspace;
  /** Whether SetNumberOfWorkUnits was called: otherwise the work units are ITK's default (see GetNumberOfHostThreads).
   * Not their value: a team asked for may have as many threads as ITK's default work units. */
  bool m_WorkUnitsWereSet{ false };
};

} // namespace itk

#ifndef ITK_MANUAL_INSTANTIATION
#include "itkBilateralDepthRelaxFilter.hxx"
#endif

namespace itk
{
// Instantiated once, in the VesselReformationFilters library, for the pixel types the module uses.
extern template class BilateralDepthRelaxFilter<Image<float, 2>>;
} // namespace itk

#endif
