// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrCoordinateFrames_h
#define vrCoordinateFrames_h

#include "itkPoint.h"

#include <vtkSmartPointer.h>

#include <string>

class vtkPolyData;

namespace vr
{
/** The coordinate systems a file or a platform node may use. Auto: take it from the file, else RAS. */
enum class CoordinateSpace
{
  Auto,
  RAS,
  LPS
};

/** The one place where RAS (3D Slicer, VMTK) and LPS (ITK, DICOM) meet: negate x and y. The map is its own
 * inverse. */
inline itk::Point<double, 3>
RASToLPS(const itk::Point<double, 3> & point)
{
  itk::Point<double, 3> converted = point;
  converted[0] = -point[0];
  converted[1] = -point[1];
  return converted;
}

inline itk::Point<double, 3>
LPSToRAS(const itk::Point<double, 3> & point)
{
  return RASToLPS(point);
}

/** A copy of \a polyData whose points (and its point normals and vectors, cell normals, as 3D Slicer's model storage
 * turns them) are taken from \a from to \a to (x and y negated when the two differ); everything else is shared with
 * \a polyData, which is left as it was. Auto on either side, or
 * the same space on both, converts nothing.
 * \param polyData a surface or polylines.
 * \param from the space its points are in.
 * \param to the space wanted.
 * \return the converted copy (null for a null \a polyData). */
vtkSmartPointer<vtkPolyData>
ConvertPolyDataSpace(vtkPolyData * polyData, CoordinateSpace from, CoordinateSpace to);

/** "RAS", "LPS" or "auto". */
const char *
ToString(CoordinateSpace space);
/** Parses "RAS", "LPS" or "auto" (any case); throws vr::InputError naming \a what otherwise. */
CoordinateSpace
ParseCoordinateSpace(const std::string & text, const std::string & what);
} // namespace vr

#endif
