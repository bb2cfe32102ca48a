#ifndef vrCenterlineIO_h
#define vrCenterlineIO_h

#include "itkCenterlineTree.h"
#include "vrCoordinateFrames.h"

#include <string>

namespace vr
{
/** What a centerline reader found, for logs and warnings. */
struct CenterlineReadReport
{
  std::string     Format;      // "VMTK .vtp", "Slicer markups", "TubeTK .tre", "CSV", ...
  CoordinateSpace FileSpace{}; // the space the coordinates were read in (after the override)
  std::string     SpaceSource; // where FileSpace came from: "override", "SPACE=LPS header", "default (RAS)", ...
  std::string     RadiusArray; // the array radii came from, empty when none
  std::size_t     InputPolylines{ 0 };
  std::size_t     MergedPoints{ 0 };         // points dropped because an overlapping path repeated them
  bool            UsedBranchGroups{ false }; // the vmtkbranchextractor GroupIds/Blanking arrays defined the branches
};

/** Reads a centerline tree in LPS mm from .vtp, .vtk (VMTK or 3D Slicer), .mrk.json (3D Slicer markups
 * curves), .tre (TubeTK) or .csv (DESIGN 3.3). \a space overrides the file's own coordinate system (Auto: the
 * file's, else RAS for VTK files). Throws vr::InputError naming the file and the field on any bad input. */
itk::CenterlineTree
ReadCenterlines(const std::string &    path,
                CoordinateSpace        space = CoordinateSpace::Auto,
                CenterlineReadReport * report = nullptr);

/** Writes \a tree (LPS) to .vtp, .vtk, .mrk.json, .tre or .csv, in \a space (Auto: LPS for .tre, RAS for VTK
 * and markups, LPS for CSV), atomically. Throws vr::InputError on failure. */
void
WriteCenterlines(const itk::CenterlineTree & tree,
                 const std::string &         path,
                 CoordinateSpace             space = CoordinateSpace::Auto);
} // namespace vr

#endif
