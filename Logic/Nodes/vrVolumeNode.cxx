// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrVolumeNode.h"

#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkObjectFactory.h>

#include <algorithm>

namespace vr
{
vtkStandardNewMacro(VolumeNode);

VolumeNode::VolumeNode()
  : m_IJKToRAS(vtkSmartPointer<vtkMatrix4x4>::New())
{
}

VolumeNode::~VolumeNode() = default;

void
VolumeNode::SetImageData(vtkImageData * imageData)
{
  if (m_ImageData != imageData)
  {
    m_ImageData = imageData;
    this->Modified();
  }
}

void
VolumeNode::SetIJKToRASMatrix(vtkMatrix4x4 * matrix)
{
  if (matrix != nullptr)
  {
    m_IJKToRAS->DeepCopy(matrix);
  }
  else
  {
    m_IJKToRAS->Identity();
  }
  this->Modified();
}

void
VolumeNode::SetIntensityRescale(const itk::CPRIntensityRescale & rescale)
{
  if (m_IntensityRescale != rescale)
  {
    m_IntensityRescale = rescale;
    this->Modified();
  }
}

void
VolumeNode::SetName(const std::string & name)
{
  if (m_Name != name)
  {
    m_Name = name;
    this->Modified();
  }
}

void
VolumeNode::SetAttribute(const std::string & key, const std::string & value)
{
  m_Attributes[key] = value;
  this->Modified();
}

const char *
VolumeNode::GetAttribute(const std::string & key) const
{
  const auto found = m_Attributes.find(key);
  return found == m_Attributes.end() ? nullptr : found->second.c_str();
}

vtkMTimeType
VolumeNode::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  time = std::max(time, m_IJKToRAS->GetMTime());
  if (m_ImageData)
  {
    time = std::max(time, m_ImageData->GetMTime());
  }
  return time;
}

void
VolumeNode::PrintSelf(ostream & os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Name: " << m_Name << "\n";
  os << indent << "ImageData: " << m_ImageData.GetPointer() << "\n";
  if (m_ImageData)
  {
    int dimensions[3];
    m_ImageData->GetDimensions(dimensions);
    os << indent << "Dimensions: " << dimensions[0] << " x " << dimensions[1] << " x " << dimensions[2] << "\n";
  }
  if (!m_IntensityRescale.IsIdentity())
  {
    os << indent << "IntensityRescale: " << m_IntensityRescale << "\n";
  }
  os << indent << "IJKToRAS:\n";
  m_IJKToRAS->PrintSelf(os, indent.GetNextIndent());
  for (const auto & attribute : m_Attributes)
  {
    os << indent << "Attribute " << attribute.first << ": " << attribute.second << "\n";
  }
}
} // namespace vr
