// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkBilateralDepthRelaxFilter_h
#define itkBilateralDepthRelaxFilter_h

#include "itkBilateralDepthRelaxKernel.h"
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
 *                 {(1-w)|\Omega| + w \sum_{q \in \Omega(p)} R(D_p - D_q)}, \qquad R(x) = e^{-a x^2} \f]
 *
 * where Omega(p) are the 4-neighbours inside the image (2 at corners, 3 on borders). Fixed pixels (mask != 0)
 * keep their value and still feed their neighbours. w = 0 changes nothing; a = 0 is linear Laplacian
 * smoothing; a larger a stops smoothing across larger depth jumps.
 *
 * A weight R underflows to 0 when a x^2 exceeds WeightUnderflowExponent (the exponent of float's smallest
 * normal number), identically on every backend. When w = 1 and every weight of a pixel underflows, the pixel
 * keeps its value: never 0/0, never NaN.
 *
 * The output does not depend on the number of threads (bit-identical), and carries the input's metadata
 * dictionary (the CPR view) along. Float images are relaxed by BilateralDepthRelaxKernel (shared edge weights, a
 * vectorised exponential, a team of GetNumberOfWorkUnits() threads at most as many as the multi-threader's);
 * other pixel types by a plain loop in double.
 *
 * AbortGenerateData() is honoured after every iteration: the update ends with itk::ProcessAborted.
 *
 * Bad parameters or inputs (w outside [0, 1], a < 0, a non-finite parameter, a mask of another size, a
 * non-finite depth) raise an itk::ExceptionObject naming the parameter and its value.
 *
 * \sa CPRDepthImageFilter, CPRResampleImageFilter, OpenCLBilateralDepthRelaxFilter, BilateralDepthRelaxKernel
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

  itkNewMacro(Self);
  itkTypeMacro(BilateralDepthRelaxFilter, ImageToImageFilter);

  /** a x^2 above this makes R underflow to 0: -ln(FLT_MIN), the exponent of float's smallest normal number. */
  static constexpr double WeightUnderflowExponent = 87.336544750553102;

  /** Relaxation w in [0, 1] (dimensionless): 0 keeps the image, 1 gives the pixel itself no weight. */
  itkSetMacro(Relaxation, double);
  itkGetConstMacro(Relaxation, double);

  /** Anisotropy a >= 0, in mm^-2: the range kernel's sharpness. 0 is isotropic (linear) smoothing. */
  itkSetMacro(Anisotropy, double);
  itkGetConstMacro(Anisotropy, double);

  /** Number of Jacobi iterations N >= 0. */
  itkSetMacro(NumberOfIterations, unsigned int);
  itkGetConstMacro(NumberOfIterations, unsigned int);

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

  /** Checks w, a and the number of iterations. */
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
   * effect within one pass). */
  void
  ThrowIfAborted(unsigned int completedIterations) const;

  /** Throws when a depth is not finite; names the pixel. Shared by the CPU and OpenCL variants. */
  void
  VerifyDepthIsFinite() const;

  /** The CPU relaxation: N Jacobi sweeps over rows split among the work units (one thread each). Float images
   * within BilateralDepthRelaxKernel::MaximumDepthMagnitude run the vectorised kernel; anything else the generic
   * loop. */
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

  double       m_Relaxation{ 1.0 };
  double       m_Anisotropy{ 0.5 };
  unsigned int m_NumberOfIterations{ 500 };

  // The fast kernel's buffers, kept between updates: relaxing again for a new view allocates nothing.
  BilateralDepthRelaxKernel::Workspace m_KernelWorkspace;
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
