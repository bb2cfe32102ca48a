// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCPRResampleImageFilter_hxx
#define itkCPRResampleImageFilter_hxx

#include "itkCPRResampleImageFilter.h"

#include "itkBSplineInterpolateImageFunction.h"
#include "itkLinearInterpolateImageFunction.h"
#include "itkNearestNeighborInterpolateImageFunction.h"

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
  const VolumeImageType * volume = this->GetVolume();
  switch (m_Interpolation)
  {
    case CPRInterpolationMode::Nearest:
      m_Interpolator = NearestNeighborInterpolateImageFunction<VolumeImageType, double>::New();
      break;
    case CPRInterpolationMode::Cubic:
    {
      auto bspline = BSplineInterpolateImageFunction<VolumeImageType, double, float>::New();
      bspline->SetSplineOrder(3);
      m_Interpolator = bspline;
      break;
    }
    default:
      m_Interpolator = LinearInterpolateImageFunction<VolumeImageType, double>::New();
  }
  m_Interpolator->SetInputImage(volume);

  m_OutsideValue = m_UseVolumeMinimumAsDefault ? this->VolumeMinimum() : m_DefaultValue;

  const auto & buffered = volume->GetBufferedRegion();
  m_VolumeBuffer = volume->GetBufferPointer();
  m_VolumeBufferStart = buffered.GetIndex();
  for (unsigned int k = 0; k < 3; ++k)
  {
    m_VolumeBufferEnd[k] = m_VolumeBufferStart[k] + static_cast<IndexValueType>(buffered.GetSize()[k]) - 1;
  }
  m_VolumeOffsetTable[0] = 1;
  m_VolumeOffsetTable[1] = static_cast<OffsetValueType>(buffered.GetSize()[0]);
  m_VolumeOffsetTable[2] = m_VolumeOffsetTable[1] * static_cast<OffsetValueType>(buffered.GetSize()[1]);

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

  m_SlabOffsets.assign(1, 0.0);
  if (m_SlabThickness > 0.0)
  {
    const auto & spacing = volume->GetSpacing();
    const double step = 0.5 * std::min({ spacing[0], spacing[1], spacing[2] });
    const auto   intervals = static_cast<std::size_t>(std::ceil(m_SlabThickness / step - 1e-9));
    m_SlabOffsets.resize(intervals + 1);
    for (std::size_t k = 0; k <= intervals; ++k)
    {
      m_SlabOffsets[k] = -0.5 * m_SlabThickness + m_SlabThickness * static_cast<double>(k) / intervals;
    }
  }
}

template<typename TVolumeImage, typename TDepthImage, typename TOutputImage>
auto
CPRResampleImageFilter<TVolumeImage, TDepthImage, TOutputImage>::VolumeMinimum() -> OutputPixelType
{
  const VolumeImageType * volume = this->GetVolume();
  if (volume != m_MinimumVolume || volume->GetBufferPointer() != m_MinimumBuffer ||
      volume->GetMTime() != m_MinimumVolumeTime)
  {
    // As MinimumMaximumImageCalculator over the buffered region (NaN voxels are passed over), without iterators.
    using VolumePixelType = typename VolumeImageType::PixelType;
    const VolumePixelType * values = volume->GetBufferPointer();
    const std::size_t       count = volume->GetBufferedRegion().GetNumberOfPixels();
    VolumePixelType         minimum = NumericTraits<VolumePixelType>::max();
    for (std::size_t k = 0; k < count; ++k)
    {
      minimum = values[k] < minimum ? values[k] : minimum;
    }
    m_CachedVolumeMinimum = static_cast<OutputPixelType>(minimum);
    m_MinimumVolume = volume;
    m_MinimumBuffer = values;
    m_MinimumVolumeTime = volume->GetMTime();
  }
  return m_CachedVolumeMinimum;
}

template<typename TVolumeImage, typename TDepthImage, typename TOutputImage>
double
CPRResampleImageFilter<TVolumeImage, TDepthImage, TOutputImage>::InterpolateLinearly(
  const ContinuousIndexType & index) const
{
  // Base voxel clamped to the buffer's start; a negative fraction (within half a voxel before the start) and a
  // neighbour past the end both leave that axis uninterpolated, exactly where the ITK interpolator skips it.
  OffsetValueType offset = 0;
  OffsetValueType step[3];
  double          fraction[3];
  for (unsigned int k = 0; k < 3; ++k)
  {
    IndexValueType base = Math::Floor<IndexValueType>(index[k]);
    base = std::max(base, m_VolumeBufferStart[k]);
    fraction[k] = std::max(0.0, index[k] - static_cast<double>(base));
    offset += (base - m_VolumeBufferStart[k]) * m_VolumeOffsetTable[k];
    step[k] = base < m_VolumeBufferEnd[k] ? m_VolumeOffsetTable[k] : 0;
  }
  const auto * v = m_VolumeBuffer + offset;
  const double v000 = static_cast<double>(v[0]);
  const double v100 = static_cast<double>(v[step[0]]);
  const double v010 = static_cast<double>(v[step[1]]);
  const double v110 = static_cast<double>(v[step[0] + step[1]]);
  const double v001 = static_cast<double>(v[step[2]]);
  const double v101 = static_cast<double>(v[step[0] + step[2]]);
  const double v011 = static_cast<double>(v[step[1] + step[2]]);
  const double v111 = static_cast<double>(v[step[0] + step[1] + step[2]]);
  const double vx00 = v000 + (v100 - v000) * fraction[0];
  const double vx10 = v010 + (v110 - v010) * fraction[0];
  const double vx01 = v001 + (v101 - v001) * fraction[0];
  const double vx11 = v011 + (v111 - v011) * fraction[0];
  const double vxx0 = vx00 + (vx10 - vx00) * fraction[1];
  const double vxx1 = vx01 + (vx11 - vx01) * fraction[1];
  return vxx0 + (vxx1 - vxx0) * fraction[2];
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
  const bool             linear = m_Interpolation == CPRInterpolationMode::Linear;
  const bool             mean = m_SlabMode == CPRSlabMode::Mean && m_SlabOffsets.size() > 1;

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
      double sum = 0.0;
      double extreme = 0.0;
      int    inside = 0;
      for (const double offset : m_SlabOffsets)
      {
        ContinuousIndexType sample;
        for (unsigned int k = 0; k < 3; ++k)
        {
          sample[k] = surface[k] + m_IndexStepPerMillimetreDepth[k] * offset;
        }
        if (!m_Interpolator->IsInsideBuffer(sample))
        {
          continue;
        }
        const double value =
          linear ? this->InterpolateLinearly(sample) : m_Interpolator->EvaluateAtContinuousIndex(sample);
        if (inside == 0)
        {
          extreme = value;
        }
        else if (m_SlabMode == CPRSlabMode::MIP)
        {
          extreme = std::max(extreme, value);
        }
        else if (m_SlabMode == CPRSlabMode::MinIP)
        {
          extreme = std::min(extreme, value);
        }
        sum += value;
        ++inside;
      }
      if (inside == 0)
      {
        outputRow[c] = m_OutsideValue;
      }
      else
      {
        outputRow[c] = static_cast<OutputPixelType>(mean ? sum / inside : extreme);
      }
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
  os << indent << "View (" << (m_HasExplicitView ? "explicit" : "from the depth image") << "):" << std::endl;
  m_View.Print(os, indent.GetNextIndent());
  os << indent << "Interpolator: " << m_Interpolator.GetPointer() << std::endl;
  os << indent << "SlabOffsets (mm): " << m_SlabOffsets.size() << " samples" << std::endl;
  os << indent << "OutsideValue (last update): " << static_cast<double>(m_OutsideValue) << std::endl;
  os << indent << "CachedVolumeMinimum: " << static_cast<double>(m_CachedVolumeMinimum) << " (volume "
     << m_MinimumVolume << ", modified time " << m_MinimumVolumeTime << ")" << std::endl;
}

} // namespace itk

#endif
