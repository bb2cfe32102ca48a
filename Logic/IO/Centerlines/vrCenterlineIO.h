// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrCenterlineIO_h
#define vrCenterlineIO_h

#include "itkCenterlineTree.h"
#include "vrCenterlineReport.h"
#include "vrCoordinateFrames.h"

#include <cstdint>
#include <string>

namespace vr
{
/** The largest centerline file the readers accept (256 MiB; real trees take kilobytes to a few megabytes). */
constexpr std::uintmax_t MaximumCenterlineFileBytes = std::uintmax_t{ 256 } << 20;

/** Reads a centerline tree in LPS mm from .vtp, .vtk (VMTK or 3D Slicer), .mrk.json (3D Slicer markups
 * curves), .tre (TubeTK) or .csv (docs/design.md "Centerline tree"). \a space overrides the file's own coordinate
 * system (Auto: the file's, else RAS for VTK files). Throws vr::InputError naming the file and the field on any bad
 * input: the readers check counts, offsets, sizes and nesting against the file and sane limits before a library reads
 * it (see each format's reader), refuse named pipes, devices and files over MaximumCenterlineFileBytes, and treat VTK's
 * warnings as failures. */
itk::CenterlineTree
ReadCenterlines(const std::string &    path,
                CoordinateSpace        space = CoordinateSpace::Auto,
                CenterlineReadReport * report = nullptr);

/** Checks, before any work, that \a path names a centerline format WriteCenterlines knows; throws vr::InputError
 * naming \a role ("<outputCenterlines>") and the formats otherwise. */
void
CheckCenterlineFileName(const std::string & path, const std::string & role);

/** Writes \a tree (LPS) to .vtp, .vtk, .mrk.json, .tre or .csv, in \a space (Auto: LPS for .tre, RAS for VTK
 * and markups, LPS for CSV), atomically. VTK files carry the radius twice, as MaximumInscribedSphereRadius (VMTK)
 * and Radius (3D Slicer), and the ids in the cell array BranchIds. Throws vr::InputError on failure. */
void
WriteCenterlines(const itk::CenterlineTree & tree,
                 const std::string &         path,
                 CoordinateSpace             space = CoordinateSpace::Auto);
} // namespace vr

#endif
