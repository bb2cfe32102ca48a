// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCPRDepthImageFilter_hxx
#define itkCPRDepthImageFilter_hxx

#include "itkCPRDepthImageFilter.h"

#include "itkCPRDepthComputation.h"

#include <algorithm>

namespace itk
{

template<typename TDepthImage>
CPRDepthImageFilter<TDepthImage>::CPRDepthImageFilter()
{
  this->SetNumberOfRequiredInputs(0);
  this->SetNumberOfRequiredOutputs(4);
  this->SetNthOutput(1, this->MakeOutput(1));
  this->SetNthOutput(2, this->MakeOutput(2));
  this->SetNthOutput(3, this->MakeOutput(3));
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
    case 3:
      return LabelImageType::New().GetPointer();
    default:
      return DepthImageType::New().GetPointer();
  }
}

template<typename TDepthImage>
void
CPRDepthImageFilter<TDepthImage>::SetCenterlineTree(const CenterlineTree & tree)
{
  if (tree != m_CenterlineTree)
  {
    m_CenterlineTree = tree;
    this->Modified();
  }
}

template<typename TDepthImage>
void
CPRDepthImageFilter<TDepthImage>::SetViewSpecification(const CPRViewSpecification & specification)
{
  if (specification != m_ViewSpecification)
  {
    m_ViewSpecification = specification;
    this->Modified();
  }
}

template<typename TDepthImage>
void
CPRDepthImageFilter<TDepthImage>::SetReferenceVolume(const ReferenceVolumeType * volume)
{
  // Not Modified(): UpdateOutputInformation() decides by the geometry, which a new object may share.
  m_ReferenceVolume = volume;
}

template<typename TDepthImage>
void
CPRDepthImageFilter<TDepthImage>::UpdateOutputInformation()
{
  const ReferenceVolumeType * volume = m_ReferenceVolume;
  if (volume != nullptr)
  {
    const_cast<ReferenceVolumeType *>(volume)->UpdateOutputInformation();
  }
  const bool same = volume == nullptr
                      ? m_ReferenceGeometry.IsNull()
                      : m_ReferenceGeometry.IsNotNull() && volume->GetOrigin() == m_ReferenceGeometry->GetOrigin() &&
                          volume->GetSpacing() == m_ReferenceGeometry->GetSpacing() &&
                          volume->GetDirection() == m_ReferenceGeometry->GetDirection() &&
                          volume->GetLargestPossibleRegion() == m_ReferenceGeometry->GetLargestPossibleRegion();
  if (!same)
  {
    m_ReferenceGeometry = nullptr;
    if (volume != nullptr)
    {
      m_ReferenceGeometry = ReferenceVolumeType::New();
      m_ReferenceGeometry->CopyInformation(volume);
      m_ReferenceGeometry->SetLargestPossibleRegion(volume->GetLargestPossibleRegion());
    }
    this->Modified();
  }
  Superclass::UpdateOutputInformation();
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
auto
CPRDepthImageFilter<TDepthImage>::GetHiddenLabelOutput() -> LabelImageType *
{
  return dynamic_cast<LabelImageType *>(this->ProcessObject::GetOutput(3));
}

template<typename TDepthImage>
void
CPRDepthImageFilter<TDepthImage>::GenerateOutputInformation()
{
  m_CenterlineTree.Validate();
  m_View = CPRViewGeometry::Resolve(m_ViewSpecification, m_CenterlineTree, m_ReferenceGeometry.GetPointer());
  m_View.ConfigureImageInformation(this->GetDepthOutput());
  m_View.ConfigureImageInformation(this->GetFixedMaskOutput());
  m_View.ConfigureImageInformation(this->GetOwnerLabelOutput());
  m_View.ConfigureImageInformation(this->GetHiddenLabelOutput());
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
  LabelImageType * hidden = this->GetHiddenLabelOutput();
  hidden->SetBufferedRegion(hidden->GetRequestedRegion());
  hidden->Allocate();

  MultiThreaderBase * threader = this->GetMultiThreader();
  threader->SetNumberOfWorkUnits(this->GetNumberOfWorkUnits());
  // Visibility mode fixes the lumen of every branch that has radii; the others only when all have them.
  const bool fixLumen = m_FixLumen && (m_Mode == CPRDepthMode::Visibility || m_CenterlineTree.HasRadii());
  const CPRDepthResult result = ComputeCPRDepth(
    m_CenterlineTree, m_View, m_Mode, fixLumen, threader, m_Workspace, [this]() { this->UpdateProgress(0.3f); });
  const std::size_t count = depth->GetBufferedRegion().GetNumberOfPixels();
  std::copy(result.Depth, result.Depth + count, depth->GetBufferPointer());
  std::copy(result.Fixed, result.Fixed + count, mask->GetBufferPointer());
  std::copy(result.Owner, result.Owner + count, labels->GetBufferPointer());
  if (result.Hidden != nullptr)
  {
    std::copy(result.Hidden, result.Hidden + count, hidden->GetBufferPointer());
    m_BranchOcclusions = *result.Occlusion;
  }
  else
  {
    std::fill_n(hidden->GetBufferPointer(), count, LabelPixelType{ 0 });
    m_BranchOcclusions.clear();
  }
  this->UpdateProgress(1.0f);
}

template<typename TDepthImage>
void
CPRDepthImageFilter<TDepthImage>::PrintSelf(std::ostream & os, Indent indent) const
{
  Superclass::PrintSelf(os, indent);
  const CPRViewSpecification & spec = m_ViewSpecification;
  os << indent << "Mode: " << m_Mode << std::endl;
  os << indent << "FixLumen: " << (m_FixLumen ? "On" : "Off") << std::endl;
  os << indent << "CenterlineTree: " << m_CenterlineTree.GetNumberOfBranches() << " branches, "
     << m_CenterlineTree.GetNumberOfPoints() << " points" << (m_CenterlineTree.HasRadii() ? ", with radii" : "")
     << std::endl;
  os << indent << "ViewSpecification:" << std::endl;
  const Indent inner = indent.GetNextIndent();
  os << inner << "Up: " << spec.Up << (spec.AutomaticUp ? " (ignored: AutomaticUp)" : "") << std::endl;
  os << inner << "AutomaticUp: " << (spec.AutomaticUp ? "On" : "Off") << std::endl;
  os << inner << "AngleInDegrees: " << spec.AngleInDegrees << std::endl;
  os << inner << "Center (LPS mm): ";
  if (spec.HasCenter)
  {
    os << spec.Center << std::endl;
  }
  else
  {
    os << "the tree's bounding box centre" << std::endl;
  }
  os << inner << "ImageSize: " << spec.ImageSize << " (0 = fit the tree)" << std::endl;
  os << inner << "PixelSpacing (mm): " << spec.PixelSpacing << " (0 = default)" << std::endl;
  os << inner << "MarginInMillimetres: " << spec.MarginInMillimetres << std::endl;
  os << indent << "ReferenceVolume: " << m_ReferenceVolume.GetPointer() << std::endl;
  if (m_ReferenceGeometry)
  {
    os << indent << "ReferenceGeometry: origin " << m_ReferenceGeometry->GetOrigin() << ", spacing "
       << m_ReferenceGeometry->GetSpacing() << ", size " << m_ReferenceGeometry->GetLargestPossibleRegion().GetSize()
       << std::endl;
  }
  else
  {
    os << indent << "ReferenceGeometry: (none)" << std::endl;
  }
  os << indent << "Workspace: " << (m_Workspace ? "allocated" : "not yet allocated") << std::endl;
  os << indent << "View:" << std::endl;
  m_View.Print(os, indent.GetNextIndent());
}

} // namespace itk

#endif
