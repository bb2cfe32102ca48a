// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCenterlineNode.h"

#include <vtkObjectFactory.h>
#include <vtkPolyData.h>

#include <algorithm>

namespace vr
{
vtkStandardNewMacro(CenterlineNode);

CenterlineNode::CenterlineNode() = default;
CenterlineNode::~CenterlineNode() = default;

void
CenterlineNode::SetPolyData(vtkPolyData * polyData)
{
  if (m_PolyData != polyData)
  {
    m_PolyData = polyData;
    this->Modified();
  }
}

void
CenterlineNode::SetName(const std::string & name)
{
  if (m_Name != name)
  {
    m_Name = name;
    this->Modified();
  }
}

vtkMTimeType
CenterlineNode::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  if (m_PolyData)
  {
    time = std::max(time, m_PolyData->GetMTime());
  }
  return time;
}

void
CenterlineNode::PrintSelf(ostream & os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Name: " << m_Name << "\n";
  os << indent << "PolyData: " << m_PolyData.GetPointer() << "\n";
  if (m_PolyData)
  {
    os << indent << "Points: " << m_PolyData->GetNumberOfPoints() << ", polylines: " << m_PolyData->GetNumberOfLines()
       << "\n";
  }
}
} // namespace vr
