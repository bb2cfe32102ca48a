// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrSurfaceIO_h
#define vrSurfaceIO_h

#include "vrCoordinateFrames.h"

#include <string>

class vtkPolyData;

namespace vr
{
/** Writes a surface (.vtp XML or legacy .vtk) atomically, point and cell arrays included (the CPR intensity
 * as point scalars). Throws vr::InputError naming the path on an unknown extension, an empty surface or a
 * failed write. */
void
WriteSurface(vtkPolyData * surface, const std::string & path);
/** The same, marking the points' coordinate system the way 3D Slicer reads it: the "SPACE" field-data string
 * array in .vtp, "SPACE=RAS" or "SPACE=LPS" in the legacy .vtk header. */
void
WriteSurface(vtkPolyData * surface, const std::string & path, CoordinateSpace pointSpace);
} // namespace vr

#endif
