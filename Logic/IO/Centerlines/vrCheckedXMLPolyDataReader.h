// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrCheckedXMLPolyDataReader_h
#define vrCheckedXMLPolyDataReader_h

#include <vtkXMLPolyDataReader.h>

#include <map>
#include <string>

namespace vr::detail
{
/** The values each DataArray element of a .vtp file holds, counted in the file before VTK reads it. */
using ValuesHeld = std::map<const vtkXMLDataElement *, long long>;

/** \class CheckedXMLPolyDataReader
 * \brief VTK's .vtp reader, with each cell array checked as soon as VTK has read it and before VTK builds cells.
 *
 * VTK 9.1 sizes the connectivity by the last offset it read (fuzzing: an offset of 8e18 for three ids made it
 * allocate until it failed) and never compares the ids with the points. Here the offsets of Verts, Lines, Strips
 * and Polys must not be negative, must not decrease, and must end at the values the connectivity array holds;
 * every connectivity id must be below the piece's point count. A failed check stops the read (VTK reports that it
 * could not read the array) and Problem() says what was wrong, naming the array.
 * \ingroup VesselReformation
 */
class CheckedXMLPolyDataReader : public vtkXMLPolyDataReader
{
public:
  static CheckedXMLPolyDataReader *
  New();
  vtkTypeMacro(CheckedXMLPolyDataReader, vtkXMLPolyDataReader);

  /** What the file's arrays hold, from the check of the file's structure. */
  void
  SetValuesHeld(ValuesHeld held)
  {
    m_Held = std::move(held);
  }
  /** Empty when every cell array passed. */
  const std::string &
  Problem() const
  {
    return m_Problem;
  }

protected:
  CheckedXMLPolyDataReader() = default;
  ~CheckedXMLPolyDataReader() override = default;

  int
  ReadArrayValues(vtkXMLDataElement * element,
                  vtkIdType           arrayIndex,
                  vtkAbstractArray *  array,
                  vtkIdType           startIndex,
                  vtkIdType           numValues,
                  FieldType           type) override;

private:
  /** The problem with the offsets VTK just read into \a array at \a first..first+count; empty when none. */
  std::string
  CheckOffsets(vtkXMLDataElement * element, vtkDataArray * array, vtkIdType first, vtkIdType count) const;

  ValuesHeld  m_Held;
  std::string m_Problem;
};
} // namespace vr::detail

#endif
