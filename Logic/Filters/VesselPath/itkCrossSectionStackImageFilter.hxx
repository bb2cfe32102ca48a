// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCrossSectionStackImageFilter_hxx
#define itkCrossSectionStackImageFilter_hxx

#include "itkCrossSectionStackImageFilter.h"

#include "itkRotationMinimizingFrame.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace itk
{

template<typename TVolumeImage, typename TOutputImage>
CrossSectionStackImageFilter<TVolumeImage, TOutputImage>::CrossSectionStackImageFilter()
{
  this->SetPrimaryInputName("Volume");
  m_SectionSpacing.Fill(0.5);
}

template<typename TVolumeImage, typename TOutputImage>
void
CrossSectionStackImageFilter<TVolumeImage, TOutputImage>::SetPath(const VesselPath & path)
{
  m_Path = path;
  this->Modified();
}

template<typename TVolumeImage, typename TOutputImage>
void
CrossSectionStackImageFilter<TVolumeImage, TOutputImage>::SetView(const CPRViewGeometry & view)
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
CrossSectionStackImageFilter<TVolumeImage, TOutputImage>::SetIntensityRescale(const CPRIntensityRescale & rescale)
{
  if (m_IntensityRescale != rescale)
  {
    m_IntensityRescale = rescale;
    this->Modified();
  }
}

template<typename TVolumeImage, typename TOutputImage>
void
CrossSectionStackImageFilter<TVolumeImage, TOutputImage>::SetDefaultValue(OutputPixelType value)
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
void
CrossSectionStackImageFilter<TVolumeImage, TOutputImage>::VerifyPreconditions() ITKv5_CONST
{
  Superclass::VerifyPreconditions();
  if (!(std::isfinite(m_SectionStep) && m_SectionStep > 0.0))
  {
    itkExceptionMacro(<< "SectionStep = " << m_SectionStep << " mm is invalid: it must be finite and > 0");
  }
  for (unsigned int k = 0; k < 2; ++k)
  {
    if (!(std::isfinite(m_SectionSpacing[k]) && m_SectionSpacing[k] > 0.0))
    {
      itkExceptionMacro(<< "SectionSpacing = " << m_SectionSpacing << " mm is invalid: both must be finite and > 0");
    }
    if (m_SectionSize[k] == 0)
    {
      itkExceptionMacro(<< "SectionSize = " << m_SectionSize << " is invalid: both must be > 0");
    }
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
  if (!(m_Path.GetLength() > 0.0))
  {
    itkExceptionMacro(<< "no path: SetPath() with a VesselPath of some length first");
  }
}

template<typename TVolumeImage, typename TOutputImage>
void
CrossSectionStackImageFilter<TVolumeImage, TOutputImage>::GenerateOutputInformation()
{
  if (m_Path.GetLength() < m_SectionStep)
  {
    itkExceptionMacro(<< "the path (branches " << m_Path.GetBranchChain().front() << " to "
                      << m_Path.GetBranchChain().back() << ") is " << m_Path.GetLength()
                      << " mm long, shorter than one section of SectionStep = " << m_SectionStep << " mm");
  }
  m_Sections = RotationMinimizingFrame::Compute(m_Path, m_SectionStep, m_View, m_RollAngle);
  const double voxels = static_cast<double>(m_SectionSize[0]) * static_cast<double>(m_SectionSize[1]) *
                        static_cast<double>(m_Sections.size());
  if (!(voxels <= static_cast<double>(std::numeric_limits<std::int64_t>::max() / 8)))
  {
    itkExceptionMacro(<< "SectionSize = " << m_SectionSize << " and SectionStep = " << m_SectionStep << " mm give "
                      << voxels << " voxels, more than an image may have");
  }

  OutputImageType * output = this->GetOutput();
  OutputRegionType  region;
  region.SetSize(0, m_SectionSize[0]);
  region.SetSize(1, m_SectionSize[1]);
  region.SetSize(2, m_Sections.size());
  output->SetLargestPossibleRegion(region);
  typename OutputImageType::SpacingType spacing;
  spacing[0] = m_SectionSpacing[0];
  spacing[1] = m_SectionSpacing[1];
  spacing[2] = m_SectionStep;
  output->SetSpacing(spacing);
  typename OutputImageType::PointType origin;
  origin[0] = -0.5 * static_cast<double>(m_SectionSize[0] - 1) * m_SectionSpacing[0];
  origin[1] = -0.5 * static_cast<double>(m_SectionSize[1] - 1) * m_SectionSpacing[1];
  origin[2] = 0.0;
  output->SetOrigin(origin);
  typename OutputImageType::DirectionType direction;
  direction.SetIdentity();
  output->SetDirection(direction);
}

template<typename TVolumeImage, typename TOutputImage>
void
CrossSectionStackImageFilter<TVolumeImage, TOutputImage>::GenerateInputRequestedRegion()
{
  if (auto * volume = const_cast<VolumeImageType *>(this->GetVolume()))
  {
    volume->SetRequestedRegionToLargestPossibleRegion();
  }
}

template<typename TVolumeImage, typename TOutputImage>
auto
CrossSectionStackImageFilter<TVolumeImage, TOutputImage>::ComputePoint(double i, double j, double k) const -> PointType
{
  if (m_Sections.empty())
  {
    itkExceptionMacro(<< "ComputePoint before UpdateOutputInformation(): the planes are not known yet");
  }
  const double u = (i - 0.5 * static_cast<double>(m_SectionSize[0] - 1)) * m_SectionSpacing[0];
  const double v = (j - 0.5 * static_cast<double>(m_SectionSize[1] - 1)) * m_SectionSpacing[1];
  k = std::clamp(k, 0.0, static_cast<double>(m_Sections.size() - 1));
  const auto      plane = std::min(static_cast<std::size_t>(k), m_Sections.size() - 1);
  const double    fraction = k - static_cast<double>(plane);
  const auto &    a = m_Sections[plane];
  const auto &    b = m_Sections[std::min(plane + 1, m_Sections.size() - 1)];
  const PointType onA = a.Center + a.Lateral * u + a.Up * v;
  const PointType onB = b.Center + b.Lateral * u + b.Up * v;
  return onA + (onB - onA) * fraction;
}

template<typename TVolumeImage, typename TOutputImage>
void
CrossSectionStackImageFilter<TVolumeImage, TOutputImage>::BeforeThreadedGenerateData()
{
  const VolumeImageType * volume = this->GetVolume();
  m_Sampler.Prepare(volume, m_Interpolation, m_IntensityRescale);
  m_OutsideValue = m_UseVolumeMinimumAsDefault
                     ? static_cast<OutputPixelType>(m_VolumeMinimum.Get(volume, m_IntensityRescale))
                     : m_DefaultValue;
  m_SlabOffsets = CPRVolumeSampler<VolumeImageType>::SlabOffsets(volume, m_SlabThickness);

  m_IndexFrames = SectionIndexFrames(volume, m_Sections);
}

template<typename TVolumeImage, typename TOutputImage>
void
CrossSectionStackImageFilter<TVolumeImage, TOutputImage>::DynamicThreadedGenerateData(const OutputRegionType & region)
{
  OutputImageType * output = this->GetOutput();
  const double      centerU = 0.5 * static_cast<double>(m_SectionSize[0] - 1);
  const double      centerV = 0.5 * static_cast<double>(m_SectionSize[1] - 1);
  const auto        start = region.GetIndex();
  const auto        size = region.GetSize();
  for (SizeValueType p = 0; p < size[2]; ++p)
  {
    const auto                plane = static_cast<std::size_t>(start[2] + static_cast<IndexValueType>(p));
    const Vector<double, 3> & center = m_IndexFrames[plane].Center;
    const Vector<double, 3> & lateral = m_IndexFrames[plane].Lateral;
    const Vector<double, 3> & up = m_IndexFrames[plane].Up;
    const Vector<double, 3> & tangent = m_IndexFrames[plane].Tangent;
    for (SizeValueType r = 0; r < size[1]; ++r)
    {
      const typename OutputImageType::IndexType rowStart{
        { start[0], start[1] + static_cast<IndexValueType>(r), static_cast<IndexValueType>(plane) }
      };
      const double            v = (static_cast<double>(rowStart[1]) - centerV) * m_SectionSpacing[1];
      const Vector<double, 3> rowBase = center + up * v;
      OutputPixelType *       outputRow = output->GetBufferPointer() + output->ComputeOffset(rowStart);
      for (SizeValueType c = 0; c < size[0]; ++c)
      {
        const double u =
          (static_cast<double>(rowStart[0] + static_cast<IndexValueType>(c)) - centerU) * m_SectionSpacing[0];
        double value;
        outputRow[c] = m_Sampler.Sample(rowBase + lateral * u, tangent, m_SlabOffsets, m_SlabMode, value)
                         ? static_cast<OutputPixelType>(value)
                         : m_OutsideValue;
      }
    }
  }
}

template<typename TVolumeImage, typename TOutputImage>
void
CrossSectionStackImageFilter<TVolumeImage, TOutputImage>::PrintSelf(std::ostream & os, Indent indent) const
{
  Superclass::PrintSelf(os, indent);
  os << indent << "Path: " << m_Path.GetLength() << " mm, " << m_Path.GetBranchChain().size() << " branches"
     << std::endl;
  os << indent << "RollAngle (degrees): " << m_RollAngle << std::endl;
  os << indent << "SectionStep (mm): " << m_SectionStep << std::endl;
  os << indent << "SectionSize: " << m_SectionSize << std::endl;
  os << indent << "SectionSpacing (mm): " << m_SectionSpacing << std::endl;
  os << indent << "Interpolation: " << m_Interpolation << std::endl;
  os << indent << "SlabThickness (mm): " << m_SlabThickness << std::endl;
  os << indent << "SlabMode: " << m_SlabMode << std::endl;
  os << indent << "IntensityRescale: " << m_IntensityRescale << std::endl;
  os << indent << "UseVolumeMinimumAsDefault: " << (m_UseVolumeMinimumAsDefault ? "On" : "Off") << std::endl;
  os << indent << "DefaultValue: " << static_cast<double>(m_DefaultValue) << std::endl;
  os << indent << "Planes: " << m_Sections.size() << std::endl;
}

} // namespace itk

#endif
