// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCPRDepthImageFilter_hxx
#define itkCPRDepthImageFilter_hxx

#include "itkCPRDepthImageFilter.h"

#include <algorithm>

namespace itk
{

template<typename TDepthImage>
CPRDepthImageFilter<TDepthImage>::CPRDepthImageFilter()
{
  this->SetNumberOfRequiredInputs(0);
  this->AddOptionalInputName("ReferenceVolume");
  this->SetNumberOfRequiredOutputs(3);
  this->SetNthOutput(1, this->MakeOutput(1));
  this->SetNthOutput(2, this->MakeOutput(2));
}

template<typename TDepthImage>
DataObject::Pointer
CPRDepthImageFilter<TDepthImage>::MakeOutput(ProcessObject::DataObjectPointerArraySizeType index)
{
  switch (index)
  {
    case 1:
      return MaskImageType::New().GetPointer();
    case 2:
      return LabelImageType::New().GetPointer();
    default:
      return DepthImageType::New().GetPointer();
  }
}

template<typename TDepthImage>
void
CPRDepthImageFilter<TDepthImage>::SetCenterlineTree(const CenterlineTree & tree)
{
  m_CenterlineTree = tree;
  this->Modified();
}

template<typename TDepthImage>
void
CPRDepthImageFilter<TDepthImage>::SetViewSpecification(const CPRViewSpecification & specification)
{
  m_ViewSpecification = specification;
  this->Modified();
}

template<typename TDepthImage>
void
CPRDepthImageFilter<TDepthImage>::SetReferenceVolume(const ReferenceVolumeType * volume)
{
  this->ProcessObject::SetInput("ReferenceVolume", const_cast<ReferenceVolumeType *>(volume));
}

template<typename TDepthImage>
auto
CPRDepthImageFilter<TDepthImage>::GetReferenceVolume() const -> const ReferenceVolumeType *
{
  return dynamic_cast<const ReferenceVolumeType *>(this->ProcessObject::GetInput("ReferenceVolume"));
}

template<typename TDepthImage>
auto
CPRDepthImageFilter<TDepthImage>::GetFixedMaskOutput() -> MaskImageType *
{
  return dynamic_cast<MaskImageType *>(this->ProcessObject::GetOutput(1));
}

template<typename TDepthImage>
auto
CPRDepthImageFilter<TDepthImage>::GetOwnerLabelOutput() -> LabelImageType *
{
  return dynamic_cast<LabelImageType *>(this->ProcessObject::GetOutput(2));
}

template<typename TDepthImage>
void
CPRDepthImageFilter<TDepthImage>::GenerateOutputInformation()
{
  m_CenterlineTree.Validate();
  m_View = CPRViewGeometry::Resolve(m_ViewSpecification, m_CenterlineTree, this->GetReferenceVolume());
  m_View.ConfigureImage(this->GetDepthOutput());
  m_View.ConfigureImage(this->GetFixedMaskOutput());
  m_View.ConfigureImage(this->GetOwnerLabelOutput());
}

template<typename TDepthImage>
void
CPRDepthImageFilter<TDepthImage>::EnlargeOutputRequestedRegion(DataObject * output)
{
  Superclass::EnlargeOutputRequestedRegion(output);
  output->SetRequestedRegionToLargestPossibleRegion();
}

template<typename TDepthImage>
void
CPRDepthImageFilter<TDepthImage>::GenerateData()
{
  DepthImageType * depth = this->GetDepthOutput();
  MaskImageType *  mask = this->GetFixedMaskOutput();
  LabelImageType * labels = this->GetOwnerLabelOutput();
  depth->SetBufferedRegion(depth->GetRequestedRegion());
  depth->Allocate();
  mask->SetBufferedRegion(mask->GetRequestedRegion());
  mask->Allocate();
  labels->SetBufferedRegion(labels->GetRequestedRegion());
  labels->Allocate();

  MultiThreaderBase * threader = this->GetMultiThreader();
  threader->SetNumberOfWorkUnits(this->GetNumberOfWorkUnits());
  const detail::CPRDepthResult result = detail::ComputeCPRDepth(m_CenterlineTree,
                                                                m_View,
                                                                m_Mode,
                                                                m_FixLumen && m_CenterlineTree.HasRadii(),
                                                                threader,
                                                                m_Workspace,
                                                                [this]() { this->UpdateProgress(0.3f); });
  const std::size_t count = depth->GetBufferedRegion().GetNumberOfPixels();
  std::copy(result.Depth, result.Depth + count, depth->GetBufferPointer());
  std::copy(result.Fixed, result.Fixed + count, mask->GetBufferPointer());
  std::copy(result.Owner, result.Owner + count, labels->GetBufferPointer());
  this->UpdateProgress(1.0f);
}

template<typename TDepthImage>
void
CPRDepthImageFilter<TDepthImage>::PrintSelf(std::ostream & os, Indent indent) const
{
  Superclass::PrintSelf(os, indent);
  os << indent << "Mode: " << m_Mode << std::endl;
  os << indent << "FixLumen: " << (m_FixLumen ? "On" : "Off") << std::endl;
  os << indent << "CenterlineTree: " << m_CenterlineTree.GetNumberOfBranches() << " branches, "
     << m_CenterlineTree.GetNumberOfPoints() << " points" << std::endl;
  os << indent << "ViewSpecification: up " << m_ViewSpecification.Up
     << (m_ViewSpecification.AutomaticUp ? " (auto)" : "") << ", angle " << m_ViewSpecification.AngleInDegrees
     << " degrees" << std::endl;
  os << indent << "View:" << std::endl;
  m_View.Print(os, indent.GetNextIndent());
}

} // namespace itk

#endif
