// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCheckedXMLPolyDataReader.h"

#include <vtkDataArray.h>
#include <vtkObjectFactory.h>
#include <vtkXMLDataElement.h>

#include <cstring>
#include <string>

namespace vr::detail
{
vtkStandardNewMacro(CheckedXMLPolyDataReader);

namespace
{
/** Whether \a element is a cell array ("offsets" or "connectivity") of Verts, Lines, Strips or Polys. */
bool
IsCellArray(vtkXMLDataElement * element, const char * name)
{
  const char *        arrayName = element != nullptr ? element->GetAttribute("Name") : nullptr;
  vtkXMLDataElement * parent = element != nullptr ? element->GetParent() : nullptr;
  const char *        section = parent != nullptr ? parent->GetName() : nullptr;
  if (arrayName == nullptr || section == nullptr || std::strcmp(arrayName, name) != 0)
  {
    return false;
  }
  for (const char * cells : { "Verts", "Lines", "Strips", "Polys" })
  {
    if (std::strcmp(section, cells) == 0)
    {
      return true;
    }
  }
  return false;
}

std::string
Section(vtkXMLDataElement * element)
{
  return element->GetParent()->GetName();
}
} // namespace

std::string
CheckedXMLPolyDataReader::CheckOffsets(vtkXMLDataElement * element,
                                       vtkDataArray *      array,
                                       vtkIdType           first,
                                       vtkIdType           count) const
{
  const std::string where = "the offsets array of " + Section(element);
  double            previous = 0.0;
  for (vtkIdType k = first; k < first + count; ++k)
  {
    const double offset = array->GetComponent(k, 0);
    if (offset < previous)
    {
      return where + ": offset " + std::to_string(k - first) + " (" + std::to_string(static_cast<long long>(offset)) +
             ") is below the one before";
    }
    previous = offset;
  }
  // The connectivity array beside it must hold exactly as many ids as the last offset says.
  vtkXMLDataElement * connectivity = nullptr;
  for (int k = 0; k < element->GetParent()->GetNumberOfNestedElements(); ++k)
  {
    vtkXMLDataElement * sibling = element->GetParent()->GetNestedElement(k);
    if (IsCellArray(sibling, "connectivity"))
    {
      connectivity = sibling;
    }
  }
  const auto held = m_Held.find(connectivity);
  if (count > 0 && held != m_Held.end() && previous != static_cast<double>(held->second))
  {
    return where + ": the last offset is " + std::to_string(static_cast<long long>(previous)) +
           ", but the connectivity array holds " + std::to_string(held->second) + " ids";
  }
  if (count > 0 && held == m_Held.end())
  {
    return where + ": no connectivity array of numbers beside it";
  }
  return {};
}

int
CheckedXMLPolyDataReader::ReadArrayValues(vtkXMLDataElement * element,
                                          vtkIdType           arrayIndex,
                                          vtkAbstractArray *  array,
                                          vtkIdType           startIndex,
                                          vtkIdType           numValues,
                                          FieldType           type)
{
  if (!m_Problem.empty())
  {
    return 0;
  }
  const int read = this->Superclass::ReadArrayValues(element, arrayIndex, array, startIndex, numValues, type);
  auto *    numbers = vtkDataArray::SafeDownCast(array);
  if (read == 0 || numbers == nullptr)
  {
    return read;
  }
  if (IsCellArray(element, "offsets"))
  {
    m_Problem = CheckOffsets(element, numbers, arrayIndex, numValues);
  }
  else if (IsCellArray(element, "connectivity"))
  {
    const vtkIdType points = this->GetNumberOfPointsInPiece(this->Piece);
    for (vtkIdType k = arrayIndex; k < arrayIndex + numValues && m_Problem.empty(); ++k)
    {
      const double id = numbers->GetComponent(k, 0);
      if (!(id >= 0.0 && id < static_cast<double>(points)))
      {
        m_Problem = "the connectivity array of " + Section(element) + ": id " + std::to_string(k - arrayIndex) +
                    " is point " + std::to_string(static_cast<long long>(id)) + " of the piece's " +
                    std::to_string(points);
      }
    }
  }
  return m_Problem.empty() ? read : 0;
}
} // namespace vr::detail
