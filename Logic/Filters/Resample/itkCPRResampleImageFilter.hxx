// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCPRResampleImageFilter_hxx
#define itkCPRResampleImageFilter_hxx

#include "itkCPRResampleImageFilter.h"

#include <algorithm>
#include <cmath>

namespace itk
{

template<typename TVolumeImage, typename TDepthImage, typename TOutputImage>
CPRResampleImageFilter<TVolumeImage, TDepthImage, TOutputImage>::CPRResampleImageFilter()
{
  this->SetPrimaryInputName("Volume");
  this->AddRequiredInputName("Depth", 1);
}

template<typename TVolumeImage, typename TDepthImage, typename TOutputImage>
void
CPRResampleImageFilter<TVolumeImage, TDepthImage, TOutputImage>::SetView(const CPRViewGeometry & view)
{
  if (m_HasExplicitView && m_View == view)
  {
    return;
  }
  m_View = view;
  m_HasExplicitView = true;
  this->Modified();
}

template<typename TVolumeImage, typename TDepthImage, typename TOutputImage>
void
CPRResampleImageFilter<TVolumeImage, TDepthImage, TOutputImage>::ClearView()
{
  if (!m_HasExplicitView)
  {
    return;
  }
  m_HasExplicitView = false;
  this->Modified();
}

template<typename TVolumeImage, typename TDepthImage, typename TOutputImage>
void
CPRResampleImageFilter<TVolumeImage, TDepthImage, TOutputImage>::SetDefaultValue(OutputPixelType value)
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

template<typename TVolumeImage, typename TDepthImage, typename TOutputImage>
void
CPRResampleImageFilter<TVolumeImage, TDepthImage, TOutputImage>::SetIntensityRescale(
  const CPRIntensityRescale & rescale)
{
  if (m_IntensityRescale != rescale)
  {
    m_IntensityRescale = rescale;
    this->Modified();
  }
}

template<typename TVolumeImage, typename TDepthImage, typename TOutputImage>
void
CPRResampleImageFilter<TVolumeImage, TDepthImage, TOutputImage>::VerifyPreconditions() ITKv5_CONST
{
  Superclass::VerifyPreconditions();
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
}

template<typename TVolumeImage, typename TDepthImage, typename TOutputImage>
void
CPRResampleImageFilter<TVolumeImage, TDepthImage, TOutputImage>::GenerateOutputInformation()
{
  const DepthImageType * depth = this->GetDepth();
  OutputImageType *      output = this->GetOutput();
  if (!m_HasExplicitView)
  {
    if (!CPRViewGeometry::DictionaryHasView(depth->GetMetaDataDictionary()))
    {
      itkExceptionMacro(<< "Depth image carries no CPR view in its metadata and no view was set with SetView()");
    }
    m_View = CPRViewGeometry::ReadFromDictionary(depth->GetMetaDataDictionary());
  }
  const auto depthSize = depth->GetLargestPossibleRegion().GetSize();
  if (depthSize != m_View.GetSize())
  {
    itkExceptionMacro(<< "Depth image size " << depthSize << " differs from the view's size " << m_View.GetSize());
  }
  // The largest possible region only: a smaller region a consumer requested stays requested (ITK's contract).
  m_View.ConfigureImageInformation(output);
}

template<typename TVolumeImage, typename TDepthImage, typename TOutputImage>
void
CPRResampleImageFilter<TVolumeImage, TDepthImage, TOutputImage>::GenerateInputRequestedRegion()
{
  auto * volume = const_cast<VolumeImageType *>(this->GetVolume());
  auto * depth = const_cast<DepthImageType *>(this->GetDepth());
  if (volume)
  {
    volume->SetRequestedRegionToLargestPossibleRegion();
  }
  if (depth)
  {
    depth->SetRequestedRegion(this->GetOutput()->GetRequestedRegion());
  }
}

template<typename TVolumeImage, typename TDepthImage, typename TOutputImage>
void
CPRResampleImageFilter<TVolumeImage, TDepthImage, TOutputImage>::BeforeThreadedGenerateData()
{
  m_Sampler.Prepare(this->GetVolume(), m_Interpolation, m_IntensityRescale);
  this->PrepareIndexMapping();
}

template<typename TVolumeImage, typename TDepthImage, typename TOutputImage>
void
CPRResampleImageFilter<TVolumeImage, TDepthImage, TOutputImage>::PrepareIndexMapping()
{
  const VolumeImageType * volume = this->GetVolume();
  m_OutsideValue = m_UseVolumeMinimumAsDefault
                     ? static_cast<OutputPixelType>(m_VolumeMinimum.Get(volume, m_IntensityRescale))
                     : m_DefaultValue;

  // X = B(i, j) + d v is affine in (i, j, d), and so is the volume's continuous index of X.
  ContinuousIndexType atCenter;
  ContinuousIndexType atColumn;
  ContinuousIndexType atRow;
  ContinuousIndexType atDepth;
  const auto &        center = m_View.GetCenter();
  volume->TransformPhysicalPointToContinuousIndex(center, atCenter);
  volume->TransformPhysicalPointToContinuousIndex(center + m_View.GetU() * m_View.GetSpacing()[0], atColumn);
  volume->TransformPhysicalPointToContinuousIndex(center - m_View.GetUp() * m_View.GetSpacing()[1], atRow);
  volume->TransformPhysicalPointToContinuousIndex(center + m_View.GetV(), atDepth);
  m_IndexAtCenter = atCenter;
  m_IndexStepPerColumn = atColumn - atCenter;
  m_IndexStepPerRow = atRow - atCenter;
  m_IndexStepPerMillimetreDepth = atDepth - atCenter;

  m_SlabOffsets = CPRVolumeSampler<VolumeImageType>::SlabOffsets(volume, m_SlabThickness);
}

template<typename TVolumeImage, typename TDepthImage, typename TOutputImage>
void
CPRResampleImageFilter<TVolumeImage, TDepthImage, TOutputImage>::DynamicThreadedGenerateData(
  const OutputRegionType & region)
{
  const DepthImageType * depth = this->GetDepth();
  OutputImageType *      output = this->GetOutput();
  const auto &           size = m_View.GetSize();
  const double           centerColumn = 0.5 * (size[0] - 1.0);
  const double           centerRow = 0.5 * (size[1] - 1.0);

  const auto          start = region.GetIndex();
  const SizeValueType width = region.GetSize()[0];
  for (SizeValueType r = 0; r < region.GetSize()[1]; ++r)
  {
    typename OutputImageType::IndexType rowStart{ { start[0], start[1] + static_cast<IndexValueType>(r) } };
    const auto *                        depthRow = depth->GetBufferPointer() + depth->ComputeOffset(rowStart);
    OutputPixelType *                   outputRow = output->GetBufferPointer() + output->ComputeOffset(rowStart);
    for (SizeValueType c = 0; c < width; ++c)
    {
      const IndexValueType    column = rowStart[0] + static_cast<IndexValueType>(c);
      const double            d = static_cast<double>(depthRow[c]);
      const Vector<double, 3> surface =
        m_IndexAtCenter.GetVectorFromOrigin() + m_IndexStepPerColumn * (column - centerColumn) +
        m_IndexStepPerRow * (rowStart[1] - centerRow) + m_IndexStepPerMillimetreDepth * d;
      double value;
      outputRow[c] = m_Sampler.Sample(surface, m_IndexStepPerMillimetreDepth, m_SlabOffsets, m_SlabMode, value)
                       ? static_cast<OutputPixelType>(value)
                       : m_OutsideValue;
    }
  }
}

template<typename TVolumeImage, typename TDepthImage, typename TOutputImage>
void
CPRResampleImageFilter<TVolumeImage, TDepthImage, TOutputImage>::PrintSelf(std::ostream & os, Indent indent) const
{
  Superclass::PrintSelf(os, indent);
  os << indent << "Interpolation: " << m_Interpolation << std::endl;
  os << indent << "UseVolumeMinimumAsDefault: " << (m_UseVolumeMinimumAsDefault ? "On" : "Off") << std::endl;
  os << indent << "DefaultValue: " << static_cast<double>(m_DefaultValue) << std::endl;
  os << indent << "SlabThickness (mm): " << m_SlabThickness << std::endl;
  os << indent << "SlabMode: " << m_SlabMode << std::endl;
  os << indent << "IntensityRescale: " << m_IntensityRescale << std::endl;
  os << indent << "View (" << (m_HasExplicitView ? "explicit" : "from the depth image") << "):" << std::endl;
  m_View.Print(os, indent.GetNextIndent());
  os << indent << "Interpolator: " << m_Sampler.GetInterpolator() << std::endl;
  os << indent << "SlabOffsets (mm): " << m_SlabOffsets.size() << " samples" << std::endl;
  os << indent << "OutsideValue (last update): " << static_cast<double>(m_OutsideValue) << std::endl;
  os << indent << "CachedVolumeMinimum: ";
  m_VolumeMinimum.Print(os);
  os << std::endl;
}

} // namespace itk

#endif
