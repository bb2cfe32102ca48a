// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrCenterlineReport_h
#define vrCenterlineReport_h

#include "vrCoordinateFrames.h"

#include <cstddef>
#include <string>

namespace vr
{
/** What reading centerlines found (a file, or a node's polylines), for logs and warnings.
 * \ingroup VesselReformation */
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

} // namespace vr

#endif
