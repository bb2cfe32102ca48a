// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCPRResampleImageFilter_h
#define itkCPRResampleImageFilter_h

#include "itkCPRSamplingModes.h"
#include "itkCPRVolumeSampler.h"
#include "itkCPRViewGeometry.h"
#include "itkImage.h"
#include "itkImageSource.h"

namespace itk
{

/** \class CPRResampleImageFilter
 * \brief Samples a volume along the cut surface of a CPR depth map (docs/design.md "Resampling").
 *
 * Pixel (i, j) of the output is the volume at X = B(i, j) + d(i, j) v, with B, v from the view (CPRViewGeometry)
 * and d the depth image's value, interpolated linearly (default), nearest or with a cubic B-spline. Points
 * outside the volume take DefaultValue, which is the volume's minimum unless set. With SlabThickness T > 0 mm
 * the pixel combines samples spaced at most half the volume's smallest spacing over [d - T/2, d + T/2] along v
 * by MIP, MinIP or mean (samples outside the volume are left out).
 *
 * The view is SetView()'s, or else read from the depth image's metadata dictionary (CPRDepthImageFilter and
 * BilateralDepthRelaxFilter put it there). The output has the depth image's grid and metadata. The volume's
 * origin, spacing and direction are honoured.
 *
 * TVolumeImage is an itk::Image<T, 3> of a scalar pixel type, or itk::ImageBase<3> for a volume of any of the stored
 * pixel types (CPRStoredPixelTypes) chosen at run time, as the module's logic holds a volume in the type of
 * its file. The volume is sampled in its stored type, its IntensityRescale applied to every value read (and to the
 * minimum): no float copy of it is made.
 *
 * \sa CPRDepthImageFilter, BilateralDepthRelaxFilter
 * \ingroup VesselReformation
 */
template<typename TVolumeImage, typename TDepthImage, typename TOutputImage = Image<float, 2>>
class ITK_TEMPLATE_EXPORT CPRResampleImageFilter : public ImageSource<TOutputImage>
{
public:
  ITK_DISALLOW_COPY_AND_MOVE(CPRResampleImageFilter);

  static_assert(TVolumeImage::ImageDimension == 3, "the volume is 3D");
  static_assert(TDepthImage::ImageDimension == 2 && TOutputImage::ImageDimension == 2, "CPR images are 2D");

  using Self = CPRResampleImageFilter;
  using Superclass = ImageSource<TOutputImage>;
  using Pointer = SmartPointer<Self>;
  using ConstPointer = SmartPointer<const Self>;

  using VolumeImageType = TVolumeImage;
  using DepthImageType = TDepthImage;
  using OutputImageType = TOutputImage;
  using OutputPixelType = typename OutputImageType::PixelType;
  using OutputRegionType = typename OutputImageType::RegionType;

  itkNewMacro(Self);
  itkTypeMacro(CPRResampleImageFilter, ImageSource);

  /** The volume to sample (required). */
  itkSetInputMacro(Volume, VolumeImageType);
  itkGetInputMacro(Volume, VolumeImageType);
  /** The depth along v in mm per pixel (required). */
  itkSetInputMacro(Depth, DepthImageType);
  itkGetInputMacro(Depth, DepthImageType);

  /** An explicit view; without one the depth image's metadata supplies it. */
  void
  SetView(const CPRViewGeometry & view);
  void
  ClearView();
  /** The view used; valid after UpdateOutputInformation(). */
  const CPRViewGeometry &
  GetView() const
  {
    return m_View;
  }

  itkSetEnumMacro(Interpolation, CPRInterpolationMode);
  itkGetEnumMacro(Interpolation, CPRInterpolationMode);

  /** Value for points outside the volume. Setting it turns UseVolumeMinimumAsDefault off. */
  void
  SetDefaultValue(OutputPixelType value);
  itkGetConstMacro(DefaultValue, OutputPixelType);
  /** Use the volume's minimum as the default value (on unless SetDefaultValue was called). */
  itkSetMacro(UseVolumeMinimumAsDefault, bool);
  itkGetConstMacro(UseVolumeMinimumAsDefault, bool);
  itkBooleanMacro(UseVolumeMinimumAsDefault);

  /** Stored values to intensities (DICOM's rescale slope and intercept); the identity by default. A slope of 0 or a
   * value that is not finite is refused when the filter runs. */
  void
  SetIntensityRescale(const CPRIntensityRescale & rescale);
  const CPRIntensityRescale &
  GetIntensityRescale() const
  {
    return m_IntensityRescale;
  }

  /** Slab thickness T along v, in mm; 0 samples the surface alone. */
  itkSetMacro(SlabThickness, double);
  itkGetConstMacro(SlabThickness, double);
  itkSetEnumMacro(SlabMode, CPRSlabMode);
  itkGetEnumMacro(SlabMode, CPRSlabMode);

protected:
  CPRResampleImageFilter();
  ~CPRResampleImageFilter() override = default;

  /** Checks the slab thickness and default value. */
  void
  VerifyPreconditions() ITKv5_CONST override;
  /** The output takes the depth image's grid and metadata; the view must match the depth image's size. */
  void
  GenerateOutputInformation() override;
  /** The whole volume (interpolators read anywhere) and the requested part of the depth image. */
  void
  GenerateInputRequestedRegion() override;
  /** Builds the interpolator and the pixel-to-volume-index mapping, and finds the default value. */
  void
  BeforeThreadedGenerateData() override;
  /** BeforeThreadedGenerateData() without the interpolator: the outside value, the pixel-to-volume-index mapping
   * and the slab offsets, read by the getters below (for a subclass that samples elsewhere, e.g. on a device). */
  void
  PrepareIndexMapping();
  /** The continuous volume index of the view's centre pixel's surface point at depth 0, and its change per column,
   * per row and per mm of depth; the slab's offsets (mm); the value of pixels with no sample inside the volume. */
  const ContinuousIndex<double, 3> &
  GetIndexAtCenter() const
  {
    return m_IndexAtCenter;
  }
  const Vector<double, 3> &
  GetIndexStepPerColumn() const
  {
    return m_IndexStepPerColumn;
  }
  const Vector<double, 3> &
  GetIndexStepPerRow() const
  {
    return m_IndexStepPerRow;
  }
  const Vector<double, 3> &
  GetIndexStepPerMillimetreDepth() const
  {
    return m_IndexStepPerMillimetreDepth;
  }
  const std::vector<double> &
  GetSlabOffsets() const
  {
    return m_SlabOffsets;
  }
  OutputPixelType
  GetOutsideValue() const
  {
    return m_OutsideValue;
  }
  void
  DynamicThreadedGenerateData(const OutputRegionType & region) override;

  void
  PrintSelf(std::ostream & os, Indent indent) const override;

private:
  using ContinuousIndexType = ContinuousIndex<double, 3>;

  CPRViewGeometry      m_View;
  bool                 m_HasExplicitView{ false };
  CPRInterpolationMode m_Interpolation{ CPRInterpolationMode::Linear };
  OutputPixelType      m_DefaultValue{};
  bool                 m_UseVolumeMinimumAsDefault{ true };
  double               m_SlabThickness{ 0.0 };
  CPRSlabMode          m_SlabMode{ CPRSlabMode::MIP };
  CPRIntensityRescale  m_IntensityRescale;

  // Per-update state, set in BeforeThreadedGenerateData: the sampling the path view's filters share.
  CPRVolumeSampler<VolumeImageType> m_Sampler;
  // The volume's minimum, kept between updates (rotating the view does not change it).
  CPRVolumeMinimum<VolumeImageType> m_VolumeMinimum;
  OutputPixelType                           m_OutsideValue{};
  ContinuousIndexType                       m_IndexAtCenter;
  Vector<double, 3>                         m_IndexStepPerColumn;
  Vector<double, 3>                         m_IndexStepPerRow;
  Vector<double, 3>                         m_IndexStepPerMillimetreDepth;
  std::vector<double>                       m_SlabOffsets;
};

} // namespace itk

#ifndef ITK_MANUAL_INSTANTIATION
#include "itkCPRResampleImageFilter.hxx"
#endif

namespace itk
{
// Instantiated once, in the VesselReformationFilters library, for the pixel types the module uses.
extern template class CPRResampleImageFilter<Image<float, 3>, Image<float, 2>, Image<float, 2>>;
extern template class CPRResampleImageFilter<ImageBase<3>, Image<float, 2>, Image<float, 2>>;
} // namespace itk

#endif
