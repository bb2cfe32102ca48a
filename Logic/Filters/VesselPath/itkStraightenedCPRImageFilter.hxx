// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkStraightenedCPRImageFilter_hxx
#define itkStraightenedCPRImageFilter_hxx

#include "itkStraightenedCPRImageFilter.h"

#include "itkRotationMinimizingFrame.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace itk
{

template<typename TVolumeImage, typename TOutputImage>
StraightenedCPRImageFilter<TVolumeImage, TOutputImage>::StraightenedCPRImageFilter()
{
  this->SetPrimaryInputName("Volume");
  this->SetNumberOfRequiredOutputs(3);
  this->SetNthOutput(1, this->MakeOutput(1));
  this->SetNthOutput(2, this->MakeOutput(2));
  m_StretchDirection.Fill(0.0);
}

template<typename TVolumeImage, typename TOutputImage>
ProcessObject::DataObjectPointer
StraightenedCPRImageFilter<TVolumeImage, TOutputImage>::MakeOutput(ProcessObject::DataObjectPointerArraySizeType index)
{
  switch (index)
  {
    case 1:
      return PointImageType::New().GetPointer();
    case 2:
      return MaskImageType::New().GetPointer();
    default:
      return Superclass::MakeOutput(index);
  }
}

template<typename TVolumeImage, typename TOutputImage>
auto
StraightenedCPRImageFilter<TVolumeImage, TOutputImage>::GetPointImage() -> PointImageType *
{
  return dynamic_cast<PointImageType *>(this->ProcessObject::GetOutput(1));
}

template<typename TVolumeImage, typename TOutputImage>
auto
StraightenedCPRImageFilter<TVolumeImage, TOutputImage>::GetFoldMask() -> MaskImageType *
{
  return dynamic_cast<MaskImageType *>(this->ProcessObject::GetOutput(2));
}

template<typename TVolumeImage, typename TOutputImage>
void
StraightenedCPRImageFilter<TVolumeImage, TOutputImage>::SetPath(const VesselPath & path)
{
  m_Path = path;
  this->Modified();
}

template<typename TVolumeImage, typename TOutputImage>
void
StraightenedCPRImageFilter<TVolumeImage, TOutputImage>::SetView(const CPRViewGeometry & view)
{
  if (m_View == view)
  {
    return;
  }
  m_View = view;
  this->Modified();
}

template<typename TVolumeImage, typename TOutputImage>
void
StraightenedCPRImageFilter<TVolumeImage, TOutputImage>::SetStretchDirection(const VectorType & direction)
{
  if (m_HasStretchDirection && m_StretchDirection == direction)
  {
    return;
  }
  m_StretchDirection = direction;
  m_HasStretchDirection = true;
  this->Modified();
}

template<typename TVolumeImage, typename TOutputImage>
void
StraightenedCPRImageFilter<TVolumeImage, TOutputImage>::ClearStretchDirection()
{
  if (m_HasStretchDirection)
  {
    m_HasStretchDirection = false;
    this->Modified();
  }
}

template<typename TVolumeImage, typename TOutputImage>
void
StraightenedCPRImageFilter<TVolumeImage, TOutputImage>::SetIntensityRescale(const CPRIntensityRescale & rescale)
{
  if (m_IntensityRescale != rescale)
  {
    m_IntensityRescale = rescale;
    this->Modified();
  }
}

template<typename TVolumeImage, typename TOutputImage>
void
StraightenedCPRImageFilter<TVolumeImage, TOutputImage>::SetDefaultValue(OutputPixelType value)
{
  const auto same = [](double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); };
  if (!m_UseVolumeMinimumAsDefault && same(static_cast<double>(m_DefaultValue), static_cast<double>(value)))
  {
    return;
  }
  m_DefaultValue = value;
  m_UseVolumeMinimumAsDefault = false;
  this->Modified();
}

template<typename TVolumeImage, typename TOutputImage>
double
StraightenedCPRImageFilter<TVolumeImage, TOutputImage>::GetHalfWidth() const
{
  return m_Columns > 0 ? 0.5 * static_cast<double>(m_Columns - 1) * m_PixelSpacing : 0.0;
}

template<typename TVolumeImage, typename TOutputImage>
void
StraightenedCPRImageFilter<TVolumeImage, TOutputImage>::VerifyPreconditions() ITKv5_CONST
{
  Superclass::VerifyPreconditions();
  if (!(std::isfinite(m_Width) && m_Width > 0.0))
  {
    itkExceptionMacro(<< "Width = " << m_Width << " mm is invalid: it must be finite and > 0");
  }
  if (!(std::isfinite(m_PixelSpacing) && m_PixelSpacing > 0.0))
  {
    itkExceptionMacro(<< "PixelSpacing = " << m_PixelSpacing << " mm is invalid: it must be finite and > 0");
  }
  if (!std::isfinite(m_RollAngle))
  {
    itkExceptionMacro(<< "RollAngle = " << m_RollAngle << " degrees is not finite");
  }
  if (!(std::isfinite(m_SlabThickness) && m_SlabThickness >= 0.0))
  {
    itkExceptionMacro(<< "SlabThickness = " << m_SlabThickness << " mm is invalid: it must be finite and >= 0");
  }
  if (!m_UseVolumeMinimumAsDefault && !std::isfinite(static_cast<double>(m_DefaultValue)))
  {
    itkExceptionMacro(<< "DefaultValue = " << m_DefaultValue << " is not finite");
  }
  if (!m_IntensityRescale.IsValid())
  {
    itkExceptionMacro(<< "IntensityRescale = " << m_IntensityRescale
                      << " is invalid: both must be finite and the slope must not be 0");
  }
  if (m_HasStretchDirection && !(std::isfinite(m_StretchDirection.GetNorm()) && m_StretchDirection.GetNorm() > 0.0))
  {
    itkExceptionMacro(<< "StretchDirection = " << m_StretchDirection << " is not a finite non-zero vector");
  }
  if (!(m_Path.GetLength() > 0.0))
  {
    itkExceptionMacro(<< "no path: SetPath() with a VesselPath of some length first");
  }
}

template<typename TVolumeImage, typename TOutputImage>
VesselPathSectionList
StraightenedCPRImageFilter<TVolumeImage, TOutputImage>::StretchedSections(const VectorType & direction) const
{
  // sigma, the arc length of the path projected on the plane normal to D, at every point of the polyline: exact for
  // the polyline, whose segments project to segments.
  const auto &        points = m_Path.GetPoints();
  const auto &        arcLengths = m_Path.GetArcLengths();
  std::vector<double> sigma(points.size(), 0.0);
  for (std::size_t k = 1; k < points.size(); ++k)
  {
    const VectorType step = points[k] - points[k - 1];
    sigma[k] = sigma[k - 1] + (step - direction * (step * direction)).GetNorm();
  }
  const double projected = sigma.back();
  if (projected < m_PixelSpacing)
  {
    itkExceptionMacro(<< "the path (" << m_Path.GetLength() << " mm) projected on the plane normal to the stretch "
                      << "direction " << direction << " is " << projected << " mm long, shorter than one row of "
                      << "PixelSpacing = " << m_PixelSpacing << " mm");
  }
  const auto            rows = static_cast<std::size_t>(std::floor(projected / m_PixelSpacing + 1e-9)) + 1;
  VesselPathSectionList sections(rows);
  VectorType            previousUp = VesselPathSection::VectorType();
  for (std::size_t j = 0; j < rows; ++j)
  {
    const double target = std::min(projected, static_cast<double>(j) * m_PixelSpacing);
    // The first segment that reaches target with a positive projected length (one along D advances nothing).
    auto        upper = std::lower_bound(sigma.begin() + 1, sigma.end(), target);
    std::size_t k = static_cast<std::size_t>(upper - sigma.begin());
    k = std::min(std::max<std::size_t>(k, 1), sigma.size() - 1);
    const double span = sigma[k] - sigma[k - 1];
    const double fraction = span > 0.0 ? std::clamp((target - sigma[k - 1]) / span, 0.0, 1.0) : 1.0;
    const double s = arcLengths[k - 1] + fraction * (arcLengths[k] - arcLengths[k - 1]);

    VesselPathSection & section = sections[j];
    section.ArcLength = s;
    section.Center = m_Path.PointAt(s);
    section.Tangent = m_Path.TangentAt(s);
    section.Radius = m_Path.RadiusAt(s);
    section.BranchId = m_Path.BranchIdAt(s);
    section.Lateral = direction;
    VectorType up;
    up[0] = section.Tangent[1] * direction[2] - section.Tangent[2] * direction[1];
    up[1] = section.Tangent[2] * direction[0] - section.Tangent[0] * direction[2];
    up[2] = section.Tangent[0] * direction[1] - section.Tangent[1] * direction[0];
    if (up.GetNorm() > 1e-9)
    {
      up.Normalize();
      previousUp = up;
    }
    else
    {
      up = previousUp; // the path runs along D here; keep the last normal (zero only for a path along D throughout)
    }
    section.Up = up;
  }
  return sections;
}

template<typename TVolumeImage, typename TOutputImage>
void
StraightenedCPRImageFilter<TVolumeImage, TOutputImage>::GenerateOutputInformation()
{
  if (m_Mode == VesselPathCPRMode::Straightened)
  {
    if (m_Path.GetLength() < m_PixelSpacing)
    {
      itkExceptionMacro(<< "the path (branches " << m_Path.GetBranchChain().front() << " to "
                        << m_Path.GetBranchChain().back() << ") is " << m_Path.GetLength()
                        << " mm long, shorter than one row of PixelSpacing = " << m_PixelSpacing << " mm");
    }
    m_Sections = RotationMinimizingFrame::Compute(m_Path, m_PixelSpacing, m_View, m_RollAngle);
  }
  else
  {
    VectorType direction = m_HasStretchDirection ? m_StretchDirection : m_View.GetU();
    direction.Normalize();
    m_Sections = StretchedSections(direction);
  }

  const double halfColumns = std::round(0.5 * m_Width / m_PixelSpacing);
  const double columns = 2.0 * halfColumns + 1.0;
  const double rows = static_cast<double>(m_Sections.size());
  if (!(columns * rows <= static_cast<double>(std::numeric_limits<int>::max())))
  {
    itkExceptionMacro(<< "Width = " << m_Width << " mm and PixelSpacing = " << m_PixelSpacing << " mm give " << columns
                      << " x " << rows << " pixels, more than an image may have");
  }
  m_Columns = static_cast<SizeValueType>(columns);

  // Folds: x (K . Lateral) >= 1 (docs/vessel-path.md "Folds"). The radius of curvature bounds it at any roll.
  const std::vector<VectorType> curvature = RotationMinimizingFrame::CurvatureVectors(m_Sections);
  m_LateralCurvature.assign(m_Sections.size(), 0.0);
  double largestCurvature = 0.0;
  for (std::size_t j = 0; j < m_Sections.size(); ++j)
  {
    m_LateralCurvature[j] = curvature[j] * m_Sections[j].Lateral;
    largestCurvature = std::max(largestCurvature, curvature[j].GetNorm());
  }
  m_FoldFreeHalfWidth = largestCurvature > 0.0 ? 1.0 / largestCurvature : std::numeric_limits<double>::infinity();

  typename OutputImageType::RegionType region;
  region.SetSize(0, m_Columns);
  region.SetSize(1, m_Sections.size());
  typename OutputImageType::SpacingType spacing;
  spacing.Fill(m_PixelSpacing);
  typename OutputImageType::PointType origin;
  origin[0] = -halfColumns * m_PixelSpacing;
  origin[1] = 0.0;
  typename OutputImageType::DirectionType direction;
  direction.SetIdentity();
  for (unsigned int k = 0; k < 3; ++k)
  {
    auto *                               output = dynamic_cast<ImageBase<2> *>(this->ProcessObject::GetOutput(k));
    typename OutputImageType::RegionType outputRegion = region;
    if (k == 1 && !m_ComputePointImage)
    {
      outputRegion.SetSize({ { 0, 0 } });
    }
    output->SetLargestPossibleRegion(outputRegion);
    output->SetSpacing(spacing);
    output->SetOrigin(origin);
    output->SetDirection(direction);
  }
}

template<typename TVolumeImage, typename TOutputImage>
void
StraightenedCPRImageFilter<TVolumeImage, TOutputImage>::GenerateInputRequestedRegion()
{
  if (auto * volume = const_cast<VolumeImageType *>(this->GetVolume()))
  {
    volume->SetRequestedRegionToLargestPossibleRegion();
  }
}

template<typename TVolumeImage, typename TOutputImage>
void
StraightenedCPRImageFilter<TVolumeImage, TOutputImage>::EnlargeOutputRequestedRegion(DataObject *)
{
  for (unsigned int k = 0; k < 3; ++k)
  {
    this->ProcessObject::GetOutput(k)->SetRequestedRegionToLargestPossibleRegion();
  }
}

template<typename TVolumeImage, typename TOutputImage>
auto
StraightenedCPRImageFilter<TVolumeImage, TOutputImage>::ComputePoint(double column, double row) const -> PointType
{
  if (m_Sections.empty())
  {
    itkExceptionMacro(<< "ComputePoint before UpdateOutputInformation(): the rows are not known yet");
  }
  const double x = (column - 0.5 * static_cast<double>(m_Columns - 1)) * m_PixelSpacing;
  const double last = static_cast<double>(m_Sections.size() - 1);
  row = std::clamp(row, 0.0, last);
  const auto      j = std::min(static_cast<std::size_t>(row), m_Sections.size() - 1);
  const double    fraction = row - static_cast<double>(j);
  const auto &    a = m_Sections[j];
  const auto &    b = m_Sections[std::min(j + 1, m_Sections.size() - 1)];
  const PointType onA = a.Center + a.Lateral * x;
  const PointType onB = b.Center + b.Lateral * x;
  return onA + (onB - onA) * fraction;
}

template<typename TVolumeImage, typename TOutputImage>
double
StraightenedCPRImageFilter<TVolumeImage, TOutputImage>::RowOfArcLength(double s) const
{
  if (m_Sections.empty())
  {
    itkExceptionMacro(<< "RowOfArcLength before UpdateOutputInformation(): the rows are not known yet");
  }
  const auto after =
    std::upper_bound(m_Sections.begin(),
                     m_Sections.end(),
                     s,
                     [](double value, const VesselPathSection & section) { return value < section.ArcLength; });
  if (after == m_Sections.begin())
  {
    return 0.0;
  }
  if (after == m_Sections.end())
  {
    return static_cast<double>(m_Sections.size() - 1);
  }
  const auto   j = static_cast<std::size_t>(after - m_Sections.begin()) - 1;
  const double span = after->ArcLength - m_Sections[j].ArcLength;
  return static_cast<double>(j) + (span > 0.0 ? (s - m_Sections[j].ArcLength) / span : 0.0);
}

template<typename TVolumeImage, typename TOutputImage>
void
StraightenedCPRImageFilter<TVolumeImage, TOutputImage>::BeforeThreadedGenerateData()
{
  const VolumeImageType * volume = this->GetVolume();
  m_Sampler.Prepare(volume, m_Interpolation, m_IntensityRescale);
  m_OutsideValue = m_UseVolumeMinimumAsDefault
                     ? static_cast<OutputPixelType>(m_VolumeMinimum.Get(volume, m_IntensityRescale))
                     : m_DefaultValue;
  m_SlabOffsets = CPRVolumeSampler<VolumeImageType>::SlabOffsets(volume, m_SlabThickness);

  m_RowIndexFrames = SectionIndexFrames(volume, m_Sections);
}

template<typename TVolumeImage, typename TOutputImage>
void
StraightenedCPRImageFilter<TVolumeImage, TOutputImage>::DynamicThreadedGenerateData(const OutputRegionType & region)
{
  OutputImageType * output = this->GetOutput();
  PointImageType *  points = m_ComputePointImage ? this->GetPointImage() : nullptr;
  MaskImageType *   mask = this->GetFoldMask();
  const bool        straightened = m_Mode == VesselPathCPRMode::Straightened;
  const double      centerColumn = 0.5 * static_cast<double>(m_Columns - 1);

  const auto          start = region.GetIndex();
  const SizeValueType width = region.GetSize()[0];
  for (SizeValueType r = 0; r < region.GetSize()[1]; ++r)
  {
    const typename OutputImageType::IndexType rowStart{ { start[0], start[1] + static_cast<IndexValueType>(r) } };
    const auto                                j = static_cast<std::size_t>(rowStart[1]);
    const VesselPathSection &                 section = m_Sections[j];
    const Vector<double, 3> &                 center = m_RowIndexFrames[j].Center;
    const Vector<double, 3> &                 lateral = m_RowIndexFrames[j].Lateral;
    const Vector<double, 3> &                 normal = m_RowIndexFrames[j].Up;
    const double                              bend = straightened ? m_LateralCurvature[j] : 0.0;
    OutputPixelType *                         outputRow = output->GetBufferPointer() + output->ComputeOffset(rowStart);
    unsigned char *                           maskRow = mask->GetBufferPointer() + mask->ComputeOffset(rowStart);
    Vector<float, 3> * pointRow = points ? points->GetBufferPointer() + points->ComputeOffset(rowStart) : nullptr;
    for (SizeValueType c = 0; c < width; ++c)
    {
      const double x =
        (static_cast<double>(rowStart[0] + static_cast<IndexValueType>(c)) - centerColumn) * m_PixelSpacing;
      double value;
      outputRow[c] = m_Sampler.Sample(center + lateral * x, normal, m_SlabOffsets, m_SlabMode, value)
                       ? static_cast<OutputPixelType>(value)
                       : m_OutsideValue;
      maskRow[c] = x * bend >= 1.0 ? 1 : 0;
      if (pointRow)
      {
        const PointType point = section.Center + section.Lateral * x;
        for (unsigned int k = 0; k < 3; ++k)
        {
          pointRow[c][k] = static_cast<float>(point[k]);
        }
      }
    }
  }
}

template<typename TVolumeImage, typename TOutputImage>
void
StraightenedCPRImageFilter<TVolumeImage, TOutputImage>::AfterThreadedGenerateData()
{
  const MaskImageType * mask = this->GetFoldMask();
  const unsigned char * values = mask->GetBufferPointer();
  const SizeValueType   count = mask->GetBufferedRegion().GetNumberOfPixels();
  m_NumberOfFoldedPixels = 0;
  for (SizeValueType k = 0; k < count; ++k)
  {
    m_NumberOfFoldedPixels += values[k];
  }
  m_FoldWarning.clear();
  if (m_NumberOfFoldedPixels > 0)
  {
    std::ostringstream warning;
    warning << m_NumberOfFoldedPixels << " pixels of the straightened CPR fold over each other: its half-width "
            << this->GetHalfWidth() << " mm exceeds the path's smallest radius of curvature " << m_FoldFreeHalfWidth
            << " mm; a Width of at most " << 2.0 * m_FoldFreeHalfWidth << " mm avoids it";
    m_FoldWarning = warning.str();
  }
}

template<typename TVolumeImage, typename TOutputImage>
void
StraightenedCPRImageFilter<TVolumeImage, TOutputImage>::PrintSelf(std::ostream & os, Indent indent) const
{
  Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << m_Mode << std::endl;
  os << indent << "Path: " << m_Path.GetLength() << " mm, " << m_Path.GetBranchChain().size() << " branches"
     << std::endl;
  os << indent << "RollAngle (degrees): " << m_RollAngle << std::endl;
  os << indent << "Width (mm): " << m_Width << std::endl;
  os << indent << "PixelSpacing (mm): " << m_PixelSpacing << std::endl;
  os << indent << "StretchDirection: " << (m_HasStretchDirection ? "" : "(the view's u) ") << m_StretchDirection
     << std::endl;
  os << indent << "Interpolation: " << m_Interpolation << std::endl;
  os << indent << "SlabThickness (mm): " << m_SlabThickness << std::endl;
  os << indent << "SlabMode: " << m_SlabMode << std::endl;
  os << indent << "IntensityRescale: " << m_IntensityRescale << std::endl;
  os << indent << "UseVolumeMinimumAsDefault: " << (m_UseVolumeMinimumAsDefault ? "On" : "Off") << std::endl;
  os << indent << "DefaultValue: " << static_cast<double>(m_DefaultValue) << std::endl;
  os << indent << "ComputePointImage: " << (m_ComputePointImage ? "On" : "Off") << std::endl;
  os << indent << "Rows: " << m_Sections.size() << ", columns: " << m_Columns << std::endl;
  os << indent << "FoldFreeHalfWidth (mm): " << m_FoldFreeHalfWidth << std::endl;
  os << indent << "NumberOfFoldedPixels: " << m_NumberOfFoldedPixels << std::endl;
}

} // namespace itk

#endif
