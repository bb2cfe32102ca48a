// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrBranchColors_h
#define vrBranchColors_h

#include <vtkSmartPointer.h>

#include <array>

class vtkLookupTable;

namespace vr
{
/** \return the display colour of branch \a id (RGB in [0, 1]): one colour per branch, the same in the owner-label
 * overlay, the centerline overlay and the 3D tubes; neighbouring ids get distinct hues. */
std::array<double, 3>
BranchColor(int id);

/** \return a lookup table indexed by branch id 0..\a maximumId: id 0 (no owner) transparent, every other id its
 * BranchColor() at \a opacity. */
vtkSmartPointer<vtkLookupTable>
MakeBranchLookupTable(int maximumId, double opacity);

/** \return a colour map for depths in [\a nearest, \a farthest] mm (viridis: near dark blue, far yellow) at
 * \a opacity, as the demo's depth pictures. */
vtkSmartPointer<vtkLookupTable>
MakeDepthLookupTable(double nearest, double farthest, double opacity);
} // namespace vr

#endif
