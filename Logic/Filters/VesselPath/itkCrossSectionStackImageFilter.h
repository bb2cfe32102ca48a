// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCrossSectionStackImageFilter_h
#define itkCrossSectionStackImageFilter_h

#include "itkCPRSamplingModes.h"
#include "itkCPRViewGeometry.h"
#include "itkCPRVolumeSampler.h"
#include "itkVesselPathIndexFrames.h"
#include "itkImage.h"
#include "itkImageSource.h"
#include "itkVesselPath.h"
#include "itkVesselPathSection.h"

namespace itk
{

/** \class CrossSectionStackImageFilter
 * \brief The planes perpendicular to a vessel path every SectionStep mm, stacked into a 3D image (u, v, s): the
 * "straightened volume" (docs/vessel-path.md "Cross-section stack").
 *
 * Voxel (i, j, k) samples C(s_k) + (i - (U-1)/2) su Lateral(s_k) + (j - (V-1)/2) sv Up(s_k), s_k = k SectionStep,
 * with the rotation-minimising frame (RotationMinimizingFrame) started from the view and turned by RollAngle degrees:
 * with the same view, roll and step, plane k is the section of the straightened CPR's row k. The image has spacing
 * (su, sv, SectionStep), origin (-(U-1)/2 su, -(V-1)/2 sv, 0) and identity direction. Interpolation, default value
 * and slab (thickness along the tangent: thick sections) work as in CPRResampleImageFilter.
 *
 * Bad parameters (SectionStep or a PixelSpacing not finite and > 0, a zero size, a non-finite roll, a bad slab, no
 * path, a path shorter than one step) throw itk::ExceptionObject naming the parameter and its value.
 * \sa StraightenedCPRImageFilter, RotationMinimizingFrame
 * \ingroup VesselReformation
 */
template<typename TVolumeImage, typename TOutputImage = Image<float, 3>>
class ITK_TEMPLATE_EXPORT CrossSectionStackImageFilter : public ImageSource<TOutputImage>
{
public:
  ITK_DISALLOW_COPY_AND_MOVE(CrossSectionStackImageFilter);

  static_assert(TVolumeImage::ImageDimension == 3 && TOutputImage::ImageDimension == 3, "a stack of planes is 3D");

  using Self = CrossSectionStackImageFilter;
  using Superclass = ImageSource<TOutputImage>;
  using Pointer = SmartPointer<Self>;
  using ConstPointer = SmartPointer<const Self>;

  using VolumeImageType = TVolumeImage;
  using OutputImageType = TOutputImage;
  using OutputPixelType = typename OutputImageType::PixelType;
  using OutputRegionType = typename OutputImageType::RegionType;
  using PointType = VesselPathSection::PointType;
  using SectionSizeType = Size<2>;
  using SectionSpacingType = Vector<double, 2>;

  itkNewMacro(Self);
  itkTypeMacro(CrossSectionStackImageFilter, ImageSource);

  /** The volume to sample (required). */
  itkSetInputMacro(Volume, VolumeImageType);
  itkGetInputMacro(Volume, VolumeImageType);

  /** The path (required). */
  void
  SetPath(const VesselPath & path);
  const VesselPath &
  GetPath() const
  {
    return m_Path;
  }
  /** The tree view the frame starts from (the default view unless set). */
  void
  SetView(const CPRViewGeometry & view);
  const CPRViewGeometry &
  GetView() const
  {
    return m_View;
  }

  /** Roll about the path in degrees. */
  itkSetMacro(RollAngle, double);
  itkGetConstMacro(RollAngle, double);
  /** Distance between planes along the path, mm (default 1). */
  itkSetMacro(SectionStep, double);
  itkGetConstMacro(SectionStep, double);
  /** Pixels per plane, U x V (default 64 x 64). */
  itkSetMacro(SectionSize, SectionSizeType);
  itkGetConstMacro(SectionSize, SectionSizeType);
  /** Pixel spacing in the plane, su and sv in mm (default 0.5). */
  itkSetMacro(SectionSpacing, SectionSpacingType);
  itkGetConstMacro(SectionSpacing, SectionSpacingType);

  itkSetEnumMacro(Interpolation, CPRInterpolationMode);
  itkGetEnumMacro(Interpolation, CPRInterpolationMode);
  /** Slab thickness along the tangent, mm; 0 samples the plane alone. */
  itkSetMacro(SlabThickness, double);
  itkGetConstMacro(SlabThickness, double);
  itkSetEnumMacro(SlabMode, CPRSlabMode);
  itkGetEnumMacro(SlabMode, CPRSlabMode);
  /** Stored values to intensities (DICOM's rescale slope and intercept), applied to every value read; the identity
   * by default (CPRResampleImageFilter::SetIntensityRescale). */
  void
  SetIntensityRescale(const CPRIntensityRescale & rescale);
  const CPRIntensityRescale &
  GetIntensityRescale() const
  {
    return m_IntensityRescale;
  }
  /** Value for points outside the volume. Setting it turns UseVolumeMinimumAsDefault off. */
  void
  SetDefaultValue(OutputPixelType value);
  itkGetConstMacro(DefaultValue, OutputPixelType);
  itkSetMacro(UseVolumeMinimumAsDefault, bool);
  itkGetConstMacro(UseVolumeMinimumAsDefault, bool);
  itkBooleanMacro(UseVolumeMinimumAsDefault);

  /** The section of every plane; valid after UpdateOutputInformation(). */
  const VesselPathSectionList &
  GetSections() const
  {
    return m_Sections;
  }
  /** The LPS point of continuous voxel (i, j, k), k clamped to the stack and interpolated linearly between planes;
   * valid after UpdateOutputInformation(). */
  PointType
  ComputePoint(double i, double j, double k) const;

protected:
  CrossSectionStackImageFilter();
  ~CrossSectionStackImageFilter() override = default;

  void
  VerifyPreconditions() ITKv5_CONST override;
  /** Computes the planes' sections and sets the output's grid. */
  void
  GenerateOutputInformation() override;
  void
  GenerateInputRequestedRegion() override;
  void
  BeforeThreadedGenerateData() override;
  void
  DynamicThreadedGenerateData(const OutputRegionType & region) override;

  void
  PrintSelf(std::ostream & os, Indent indent) const override;

private:
  VesselPath           m_Path;
  CPRViewGeometry      m_View;
  double               m_RollAngle{ 0.0 };
  double               m_SectionStep{ 1.0 };
  SectionSizeType      m_SectionSize{ { 64, 64 } };
  SectionSpacingType   m_SectionSpacing;
  CPRInterpolationMode m_Interpolation{ CPRInterpolationMode::Linear };
  double               m_SlabThickness{ 0.0 };
  CPRSlabMode          m_SlabMode{ CPRSlabMode::MIP };
  CPRIntensityRescale  m_IntensityRescale;
  OutputPixelType      m_DefaultValue{};
  bool                 m_UseVolumeMinimumAsDefault{ true };

  VesselPathSectionList m_Sections;

  CPRVolumeSampler<VolumeImageType> m_Sampler;
  CPRVolumeMinimum<VolumeImageType> m_VolumeMinimum;
  OutputPixelType                           m_OutsideValue{};
  std::vector<double>                       m_SlabOffsets;
  /** Per plane, in the volume's continuous index: the centre, and the steps per mm along Lateral, Up and Tangent. */
  std::vector<SectionIndexFrame> m_IndexFrames;
};

} // namespace itk

#ifndef ITK_MANUAL_INSTANTIATION
#include "itkCrossSectionStackImageFilter.hxx"
#endif

namespace itk
{
// Instantiated once, in the VesselReformationFilters library.
extern template class CrossSectionStackImageFilter<Image<float, 3>, Image<float, 3>>;
extern template class CrossSectionStackImageFilter<ImageBase<3>, Image<float, 3>>;
} // namespace itk

#endif
