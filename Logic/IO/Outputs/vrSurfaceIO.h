// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrSurfaceIO_h
#define vrSurfaceIO_h

#include "vrCoordinateFrames.h"

#include <vtkSmartPointer.h>

#include <string>

class vtkPolyData;

namespace vr
{
/** Writes a surface (.vtp XML or legacy .vtk) atomically, point and cell arrays included (the CPR intensity
 * as point scalars), its points as they are and with no coordinate system recorded. Throws vr::InputError naming the
 * path on an unknown extension, an empty surface or a failed write. */
void
WriteSurface(vtkPolyData * surface, const std::string & path);

/** Writes a surface the way 3D Slicer's model storage (vtkMRMLModelStorageNode) writes models: the points taken from
 * \a pointSpace to \a fileSpace, and \a fileSpace recorded in the file, as a "SPACE" field-data string array in
 * .vtp and as "SPACE=LPS" (or RAS) in the legacy .vtk header line, the two markers Slicer reads back. Slicer writes
 * LPS; the caller's surface is left as it was. Throws as WriteSurface(surface, path).
 * \param surface the surface.
 * \param path the file, .vtp or .vtk.
 * \param pointSpace the space of the surface's points (the module logic's surface is RAS).
 * \param fileSpace the space the file holds (RAS or LPS; Auto: \a pointSpace). */
void
WriteSurface(vtkPolyData *       surface,
             const std::string & path,
             CoordinateSpace     pointSpace,
             CoordinateSpace     fileSpace = CoordinateSpace::Auto);

/** Reads a surface (.vtp or legacy .vtk) the way 3D Slicer reads models: the coordinate system recorded in the file
 * (the "SPACE" field-data array of .vtp, "SPACE=RAS" or "SPACE=LPS" in the .vtk header) decides, and a file without
 * one is LPS, Slicer's default for models. The "SPACE" array is not kept in the result, as in Slicer.
 * \param path the file.
 * \param pointSpace the space wanted for the result's points (Auto: as the file holds them).
 * \param fileSpace if not null, receives the space the file holds.
 * \return the surface. Throws vr::InputError naming the file when it is missing, unreadable or has no point, or its
 * extension is neither .vtp nor .vtk. */
vtkSmartPointer<vtkPolyData>
ReadSurface(const std::string & path,
            CoordinateSpace     pointSpace = CoordinateSpace::RAS,
            CoordinateSpace *   fileSpace = nullptr);
} // namespace vr

#endif
