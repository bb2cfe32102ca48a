// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCenterlineExtractionFilter_hxx
#define itkCenterlineExtractionFilter_hxx

#include "itkCenterlineExtractionFilter.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <type_traits>

namespace itk
{

template<typename TLabelImage>
CenterlineExtractionFilter<TLabelImage>::CenterlineExtractionFilter()
{
  this->SetNumberOfRequiredInputs(1);
  this->SetNumberOfRequiredOutputs(1);
  this->SetNthOutput(0, this->MakeOutput(0));
}

template<typename TLabelImage>
DataObject::Pointer
CenterlineExtractionFilter<TLabelImage>::MakeOutput(DataObjectPointerArraySizeType)
{
  return CenterlineTreeObjectType::New().GetPointer();
}

template<typename TLabelImage>
void
CenterlineExtractionFilter<TLabelImage>::SetInput(const LabelImageType * image)
{
  this->ProcessObject::SetNthInput(0, const_cast<LabelImageType *>(image));
}

template<typename TLabelImage>
auto
CenterlineExtractionFilter<TLabelImage>::GetInput() const -> const LabelImageType *
{
  return dynamic_cast<const LabelImageType *>(this->ProcessObject::GetInput(0));
}

template<typename TLabelImage>
void
CenterlineExtractionFilter<TLabelImage>::SetForegroundLabels(const LabelListType & labels)
{
  if (labels != m_ForegroundLabels)
  {
    m_ForegroundLabels = labels;
    this->Modified();
  }
}

template<typename TLabelImage>
void
CenterlineExtractionFilter<TLabelImage>::SetRootPoints(const PointListType & points)
{
  if (points != m_RootPoints)
  {
    m_RootPoints = points;
    this->Modified();
  }
}

template<typename TLabelImage>
auto
CenterlineExtractionFilter<TLabelImage>::GetOutput() -> CenterlineTreeObjectType *
{
  return dynamic_cast<CenterlineTreeObjectType *>(this->ProcessObject::GetOutput(0));
}

template<typename TLabelImage>
const CenterlineTree &
CenterlineExtractionFilter<TLabelImage>::GetCenterlineTree() const
{
  return dynamic_cast<const CenterlineTreeObjectType *>(this->ProcessObject::GetOutput(0))->Get();
}

template<typename TLabelImage>
void
CenterlineExtractionFilter<TLabelImage>::VerifyPreconditions() ITKv5_CONST
{
  Superclass::VerifyPreconditions();
  if (!(std::isfinite(m_MinimumBranchLength) && m_MinimumBranchLength >= 0.0))
  {
    itkExceptionMacro(<< "MinimumBranchLength = " << m_MinimumBranchLength
                      << " mm is invalid: it must be finite and >= 0");
  }
  if (!(std::isfinite(m_SpurRadiusRatio) && m_SpurRadiusRatio >= 0.0))
  {
    itkExceptionMacro(<< "SpurRadiusRatio = " << m_SpurRadiusRatio << " is invalid: it must be finite and >= 0");
  }
  if (!(std::isfinite(m_InvalidationScale) && m_InvalidationScale >= 1.0 && m_InvalidationScale <= 100.0))
  {
    itkExceptionMacro(<< "InvalidationScale = " << m_InvalidationScale
                      << " is invalid: it must lie in [1, 100] (below 1 a path does not cover its own lumen)");
  }
  if (!(std::isfinite(m_PointSpacing) && m_PointSpacing >= 0.0))
  {
    itkExceptionMacro(<< "PointSpacing = " << m_PointSpacing << " mm is invalid: it must be finite and >= 0");
  }
  if (!(std::isfinite(m_RootPointTolerance) && m_RootPointTolerance > 0.0))
  {
    itkExceptionMacro(<< "RootPointTolerance = " << m_RootPointTolerance
                      << " mm is invalid: it must be finite and > 0");
  }
  for (std::size_t k = 0; k < m_RootPoints.size(); ++k)
  {
    const PointType & point = m_RootPoints[k];
    if (!(std::isfinite(point[0]) && std::isfinite(point[1]) && std::isfinite(point[2])))
    {
      itkExceptionMacro(<< "RootPoints[" << k << "] = " << point << " is invalid: its coordinates must be finite");
    }
  }
  for (const LabelType label : m_ForegroundLabels)
  {
    if (!(label == label))
    {
      itkExceptionMacro(<< "ForegroundLabels holds NaN; labels must be numbers");
    }
  }
}

template<typename TLabelImage>
void
CenterlineExtractionFilter<TLabelImage>::GenerateInputRequestedRegion()
{
  Superclass::GenerateInputRequestedRegion();
  if (auto * input = const_cast<LabelImageType *>(this->GetInput()))
  {
    input->SetRequestedRegionToLargestPossibleRegion();
  }
}

template<typename TLabelImage>
void
CenterlineExtractionFilter<TLabelImage>::GenerateData()
{
  const LabelImageType *                    input = this->GetInput();
  const typename LabelImageType::RegionType region = input->GetBufferedRegion();
  const auto                                size = region.GetSize();
  const LabelType *                         buffer = input->GetBufferPointer();

  // The foreground's bounding box, in buffer coordinates. With a few labels, a sorted copy is searched.
  LabelListType sortedLabels(m_ForegroundLabels);
  std::sort(sortedLabels.begin(), sortedLabels.end());
  const bool anyNonZero = sortedLabels.empty();
  const auto isForeground = [&](LabelType value)
  {
    return anyNonZero ? (value > LabelType{} || value < LabelType{})
                      : std::binary_search(sortedLabels.begin(), sortedLabels.end(), value);
  };
  std::array<SizeValueType, 3> low{ size[0], size[1], size[2] };
  std::array<SizeValueType, 3> high{ 0, 0, 0 };
  bool                         found = false;
  for (SizeValueType z = 0; z < size[2]; ++z)
  {
    for (SizeValueType y = 0; y < size[1]; ++y)
    {
      const LabelType * row = buffer + (z * size[1] + y) * size[0];
      for (SizeValueType x = 0; x < size[0]; ++x)
      {
        if (isForeground(row[x]))
        {
          found = true;
          low[0] = std::min(low[0], x);
          high[0] = std::max(high[0], x);
          low[1] = std::min(low[1], y);
          high[1] = std::max(high[1], y);
          low[2] = std::min(low[2], z);
          high[2] = std::max(high[2], z);
        }
      }
    }
  }
  if (!found)
  {
    // Say what the segmentation holds instead: its distinct values (a few), or their range.
    std::set<LabelType> values;
    LabelType           smallest = buffer[0];
    LabelType           largest = buffer[0];
    for (SizeValueType k = 0; k < region.GetNumberOfPixels(); ++k)
    {
      smallest = std::min(smallest, buffer[k]);
      largest = std::max(largest, buffer[k]);
      if (values.size() <= 12)
      {
        values.insert(buffer[k]);
      }
    }
    std::ostringstream held;
    if (values.size() <= 12)
    {
      held << "its values are";
      for (const LabelType value : values)
      {
        held << " " << static_cast<typename NumericTraits<LabelType>::PrintType>(value);
      }
    }
    else
    {
      held << "its values range from " << static_cast<typename NumericTraits<LabelType>::PrintType>(smallest) << " to "
           << static_cast<typename NumericTraits<LabelType>::PrintType>(largest);
    }
    if (anyNonZero)
    {
      itkExceptionMacro(<< "the segmentation has no foreground: every voxel is 0");
    }
    std::ostringstream labels;
    for (std::size_t k = 0; k < m_ForegroundLabels.size(); ++k)
    {
      labels << (k == 0 ? "" : ", ")
             << static_cast<typename NumericTraits<LabelType>::PrintType>(m_ForegroundLabels[k]);
    }
    itkExceptionMacro(<< "the segmentation has no voxel with label " << labels.str() << "; " << held.str());
  }

  // The mask of the foreground over its bounding box plus a background margin of one voxel, on the input's grid.
  using MaskImageType = Image<unsigned char, 3>;
  typename MaskImageType::IndexType maskStart;
  typename MaskImageType::SizeType  maskSize;
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    maskStart[axis] = region.GetIndex(axis) + static_cast<IndexValueType>(low[axis]) - 1;
    maskSize[axis] = high[axis] - low[axis] + 3;
  }
  auto mask = MaskImageType::New();
  mask->SetRegions(typename MaskImageType::RegionType(maskStart, maskSize));
  mask->SetOrigin(input->GetOrigin());
  mask->SetSpacing(input->GetSpacing());
  mask->SetDirection(input->GetDirection());
  mask->Allocate(true);
  unsigned char * maskBuffer = mask->GetBufferPointer();
  for (SizeValueType z = low[2]; z <= high[2]; ++z)
  {
    for (SizeValueType y = low[1]; y <= high[1]; ++y)
    {
      const LabelType * row = buffer + (z * size[1] + y) * size[0];
      unsigned char *   maskRow = maskBuffer + ((z - low[2] + 1) * maskSize[1] + (y - low[1] + 1)) * maskSize[0] + 1;
      for (SizeValueType x = low[0]; x <= high[0]; ++x)
      {
        maskRow[x - low[0]] = isForeground(row[x]) ? 1 : 0;
      }
    }
  }
  this->UpdateProgress(0.05f);

  CenterlineExtractionSettings settings;
  settings.RootPoints = m_RootPoints;
  settings.RootPointTolerance = m_RootPointTolerance;
  settings.MinimumBranchLength = m_MinimumBranchLength;
  settings.SpurRadiusRatio = m_SpurRadiusRatio;
  settings.InvalidationScale = m_InvalidationScale;
  settings.PointSpacing = m_PointSpacing;
  settings.NumberOfWorkUnits = static_cast<int>(this->GetNumberOfWorkUnits());
  const auto progress = [this](double fraction)
  {
    this->UpdateProgress(static_cast<float>(0.05 + 0.95 * fraction));
    if (this->GetAbortGenerateData())
    {
      ProcessAborted aborted(__FILE__, __LINE__);
      aborted.SetDescription("CenterlineExtractionFilter: aborted");
      throw aborted;
    }
  };
  CenterlineExtractionOutcome outcome;
  try
  {
    outcome = ExtractCenterlinesFromPaddedMask(mask, settings, progress);
  }
  catch (const ProcessAborted &)
  {
    throw;
  }
  catch (const ExceptionObject & exception)
  {
    itkExceptionMacro(<< exception.GetDescription()); // with the filter's name
  }
  m_ParentBranchIds = std::move(outcome.ParentBranchIds);
  m_NumberOfComponents = outcome.NumberOfComponents;
  m_NumberOfComponentsWithoutCenterline = outcome.NumberOfComponentsWithoutCenterline;
  CenterlineTreeObjectType * output = this->GetOutput();
  output->Get() = std::move(outcome.Tree);
  output->Modified();
  this->UpdateProgress(1.0f);
}

template<typename TLabelImage>
void
CenterlineExtractionFilter<TLabelImage>::PrintSelf(std::ostream & os, Indent indent) const
{
  using PrintType = typename NumericTraits<LabelType>::PrintType;
  Superclass::PrintSelf(os, indent);
  os << indent << "ForegroundLabels:";
  if (m_ForegroundLabels.empty())
  {
    os << " (every non-zero voxel)";
  }
  for (const LabelType label : m_ForegroundLabels)
  {
    os << " " << static_cast<PrintType>(label);
  }
  os << std::endl;
  os << indent << "RootPoints (LPS, mm):";
  if (m_RootPoints.empty())
  {
    os << " (none: the free end of largest radius)";
  }
  for (const PointType & point : m_RootPoints)
  {
    os << " " << point;
  }
  os << std::endl;
  os << indent << "RootPointTolerance (mm): " << m_RootPointTolerance << std::endl;
  os << indent << "MinimumBranchLength (mm): " << m_MinimumBranchLength << std::endl;
  os << indent << "SpurRadiusRatio: " << m_SpurRadiusRatio << std::endl;
  os << indent << "InvalidationScale: " << m_InvalidationScale << std::endl;
  os << indent << "PointSpacing (mm): " << m_PointSpacing
     << (m_PointSpacing == 0.0 ? " (half the smallest spacing)" : "") << std::endl;
  os << indent << "NumberOfComponents: " << m_NumberOfComponents << std::endl;
  os << indent << "NumberOfComponentsWithoutCenterline: " << m_NumberOfComponentsWithoutCenterline << std::endl;
  os << indent << "ParentBranchIds: " << m_ParentBranchIds.size() << " branches" << std::endl;
}

} // namespace itk

#endif
