// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkStraightenedCPRImageFilter_h
#define itkStraightenedCPRImageFilter_h

#include "itkCPRSamplingModes.h"
#include "itkCPRViewGeometry.h"
#include "itkCPRVolumeSampler.h"
#include "itkVesselPathIndexFrames.h"
#include "itkImage.h"
#include "itkImageSource.h"
#include "itkVesselPath.h"
#include "itkVesselPathSection.h"

#include <string>

namespace itk
{

/** How the rows of a single-vessel CPR follow the path (docs/vessel-path.md "Straightened CPR" and "Stretched CPR"). */
enum class VesselPathCPRMode
{
  /** Rows along the rotation-minimising frame's Lateral, one every PixelSpacing mm of arc length. */
  Straightened,
  /** Rows along one fixed direction, evenly spaced in the arc length of the path projected on its normal plane. */
  Stretched
};

std::ostream &
operator<<(std::ostream & os, VesselPathCPRMode mode);

/** \class StraightenedCPRImageFilter
 * \brief The straightened or stretched CPR of one vessel path (docs/vessel-path.md, "Straightened CPR" to "Folds"): x =
 * offset across the vessel (mm, the path in the middle column), y = arc length (mm).
 *
 * Straightened: pixel (i, j) samples C(s_j) + x_i Lateral(s_j), s_j = j PixelSpacing, with the rotation-minimising
 * frame (RotationMinimizingFrame) started from the view and turned by RollAngle degrees. Stretched: pixel (i, j)
 * samples C(s_j) + x_i D along one fixed direction D (StretchDirection, the view's screen-right by default), the
 * rows spaced PixelSpacing mm apart in the arc length of the path projected on the plane normal to D.
 *
 * The image is Width mm wide (an odd number of columns, rounded to the nearest) with square pixels of PixelSpacing
 * mm; its physical coordinates are (x, y) in mm (origin (-(W-1)/2 sx, 0), identity direction). Interpolation,
 * default value and slab (thickness along the plane's normal, Up) work as in CPRResampleImageFilter.
 *
 * Outputs: 0, the CPR (float); 1, the LPS point of every pixel (itk::Vector<float, 3>; empty unless
 * ComputePointImage is on); 2, the fold mask (unsigned char, 1 where neighbouring rows fold over each other:
 * x (K . Lateral) >= 1, K the curvature vector; straightened mode only). GetNumberOfFoldedPixels() counts them,
 * GetFoldFreeHalfWidth() is the smallest radius of curvature along the rows (the half-width below which no roll
 * folds), and GetFoldWarning() says so in words when pixels fold: the caller reports it (no ITK warning: a
 * module's stderr carries its own messages only).
 *
 * Bad parameters (Width or PixelSpacing not finite and > 0, a non-finite roll, a bad slab, no path, a path shorter
 * than one row) throw itk::ExceptionObject naming the parameter and its value.
 * \sa RotationMinimizingFrame, CrossSectionStackImageFilter, CPRResampleImageFilter
 * \ingroup VesselReformation
 */
template<typename TVolumeImage, typename TOutputImage = Image<float, 2>>
class ITK_TEMPLATE_EXPORT StraightenedCPRImageFilter : public ImageSource<TOutputImage>
{
public:
  ITK_DISALLOW_COPY_AND_MOVE(StraightenedCPRImageFilter);

  static_assert(TVolumeImage::ImageDimension == 3, "the volume is 3D");
  static_assert(TOutputImage::ImageDimension == 2, "a CPR is 2D");

  using Self = StraightenedCPRImageFilter;
  using Superclass = ImageSource<TOutputImage>;
  using Pointer = SmartPointer<Self>;
  using ConstPointer = SmartPointer<const Self>;

  using VolumeImageType = TVolumeImage;
  using OutputImageType = TOutputImage;
  using OutputPixelType = typename OutputImageType::PixelType;
  using OutputRegionType = typename OutputImageType::RegionType;
  using PointImageType = Image<Vector<float, 3>, 2>;
  using MaskImageType = Image<unsigned char, 2>;
  using PointType = VesselPathSection::PointType;
  using VectorType = VesselPathSection::VectorType;

  itkNewMacro(Self);
  itkTypeMacro(StraightenedCPRImageFilter, ImageSource);

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
  /** The tree view whose look the frame starts from, and whose screen-right is the default stretch direction;
   * the default view (docs/design.md "View") unless set. */
  void
  SetView(const CPRViewGeometry & view);
  const CPRViewGeometry &
  GetView() const
  {
    return m_View;
  }

  itkSetEnumMacro(Mode, VesselPathCPRMode);
  itkGetEnumMacro(Mode, VesselPathCPRMode);
  /** Roll about the path in degrees (straightened mode). */
  itkSetMacro(RollAngle, double);
  itkGetConstMacro(RollAngle, double);
  /** Image width across the vessel in mm (default 50). */
  itkSetMacro(Width, double);
  itkGetConstMacro(Width, double);
  /** Square pixel size in mm (default 0.5). */
  itkSetMacro(PixelSpacing, double);
  itkGetConstMacro(PixelSpacing, double);
  /** The stretched mode's sampling direction (normalised here); without one, the view's screen-right u. */
  void
  SetStretchDirection(const VectorType & direction);
  void
  ClearStretchDirection();

  itkSetEnumMacro(Interpolation, CPRInterpolationMode);
  itkGetEnumMacro(Interpolation, CPRInterpolationMode);
  /** Slab thickness along the rows' plane normal (Up), mm; 0 samples the plane alone. */
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
  /** Fill output 1 with each pixel's LPS point (off: output 1 is empty). */
  itkSetMacro(ComputePointImage, bool);
  itkGetConstMacro(ComputePointImage, bool);
  itkBooleanMacro(ComputePointImage);

  PointImageType *
  GetPointImage();
  MaskImageType *
  GetFoldMask();

  /** The section of every row (centre, frame after the roll, arc length along the path); valid after
   * UpdateOutputInformation(). */
  const VesselPathSectionList &
  GetSections() const
  {
    return m_Sections;
  }
  /** The LPS point of continuous pixel (column, row), the row clamped to the image and interpolated linearly between
   * rows; valid after UpdateOutputInformation(). */
  PointType
  ComputePoint(double column, double row) const;
  /** The continuous row of arc length \a s along the path (mm), in straightened mode s / PixelSpacing. */
  double
  RowOfArcLength(double s) const;

  /** Pixels marked in the fold mask (after Update()). */
  SizeValueType
  GetNumberOfFoldedPixels() const
  {
    return m_NumberOfFoldedPixels;
  }
  /** The smallest radius of curvature along the rows, mm (infinite for a straight path): a half-width below it folds
   * at no roll. Valid after UpdateOutputInformation(). */
  double
  GetFoldFreeHalfWidth() const
  {
    return m_FoldFreeHalfWidth;
  }
  /** The half-width the image has, (W - 1)/2 PixelSpacing. */
  double
  GetHalfWidth() const;
  /** Empty, or the warning sent when pixels fold, naming the width that avoids it. */
  const std::string &
  GetFoldWarning() const
  {
    return m_FoldWarning;
  }

protected:
  StraightenedCPRImageFilter();
  ~StraightenedCPRImageFilter() override = default;

  using Superclass::MakeOutput;
  ProcessObject::DataObjectPointer
  MakeOutput(ProcessObject::DataObjectPointerArraySizeType index) override;

  void
  VerifyPreconditions() ITKv5_CONST override;
  /** Computes the rows' sections and the fold data; sets every output's grid. */
  void
  GenerateOutputInformation() override;
  void
  GenerateInputRequestedRegion() override;
  /** Every output whole: rows, points and mask are made together. */
  void
  EnlargeOutputRequestedRegion(DataObject * output) override;
  void
  BeforeThreadedGenerateData() override;
  void
  DynamicThreadedGenerateData(const OutputRegionType & region) override;
  void
  AfterThreadedGenerateData() override;

  void
  PrintSelf(std::ostream & os, Indent indent) const override;

private:
  /** The sections of the stretched mode's rows. */
  VesselPathSectionList
  StretchedSections(const VectorType & direction) const;

  VesselPath           m_Path;
  CPRViewGeometry      m_View;
  VesselPathCPRMode    m_Mode{ VesselPathCPRMode::Straightened };
  double               m_RollAngle{ 0.0 };
  double               m_Width{ 50.0 };
  double               m_PixelSpacing{ 0.5 };
  VectorType           m_StretchDirection;
  bool                 m_HasStretchDirection{ false };
  CPRInterpolationMode m_Interpolation{ CPRInterpolationMode::Linear };
  double               m_SlabThickness{ 0.0 };
  CPRSlabMode          m_SlabMode{ CPRSlabMode::MIP };
  CPRIntensityRescale  m_IntensityRescale;
  OutputPixelType      m_DefaultValue{};
  bool                 m_UseVolumeMinimumAsDefault{ true };
  bool                 m_ComputePointImage{ false };

  // Set by GenerateOutputInformation.
  VesselPathSectionList m_Sections;
  SizeValueType         m_Columns{ 0 };
  /** K . Lateral per row (1/mm): pixel x folds where x times it is >= 1. */
  std::vector<double> m_LateralCurvature;
  double              m_FoldFreeHalfWidth{ 0.0 };

  // Set by the update.
  SizeValueType m_NumberOfFoldedPixels{ 0 };
  std::string   m_FoldWarning;

  CPRVolumeSampler<VolumeImageType> m_Sampler;
  CPRVolumeMinimum<VolumeImageType> m_VolumeMinimum;
  OutputPixelType                           m_OutsideValue{};
  std::vector<double>                       m_SlabOffsets;
  /** Per row, in the volume's continuous index: the centre, and the steps per mm along Lateral and Up. */
  std::vector<SectionIndexFrame> m_RowIndexFrames;
};

} // namespace itk

#ifndef ITK_MANUAL_INSTANTIATION
#include "itkStraightenedCPRImageFilter.hxx"
#endif

namespace itk
{
// Instantiated once, in the VesselReformationFilters library.
extern template class StraightenedCPRImageFilter<Image<float, 3>, Image<float, 2>>;
extern template class StraightenedCPRImageFilter<ImageBase<3>, Image<float, 2>>;
} // namespace itk

#endif
