// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrCenterlineOverlay_h
#define vrCenterlineOverlay_h

#include "itkCPRViewGeometry.h"
#include "itkCenterlineTree.h"
#include "vrOcclusionTableIO.h"

#include <vtkSmartPointer.h>

#include <vector>

class vtkPolyData;

namespace vr
{
/** The cell array of the centerline overlay that marks the dashes of hidden stretches (1) and the solid lines (0). */
constexpr const char * HiddenStretchArrayName = "HiddenStretch";

/** The length of a dash of a hidden stretch, and of the gap after it, in pixels of the view. */
constexpr double HiddenDashPixels = 3.0;

/** Builds the centerline overlay of a CPR view: every branch of \a tree projected into \a view and drawn at world
 * (origin + column sx, origin + row sy) with \a origin and \a spacing, one colour per branch (cell scalars
 * "BranchColors", vr::BranchColor). The hidden stretches of \a occlusions (Visibility mode, the logic's
 * BranchOcclusions) are drawn dashed: dashes of HiddenDashPixels pixels with gaps as long, each a line cell marked 1 in
 * HiddenStretchArrayName; the rest of each branch is solid, marked 0. Without hidden stretches a branch is one
 * polyline. */
vtkSmartPointer<vtkPolyData>
BuildCenterlineOverlay(const itk::CenterlineTree &             tree,
                       const itk::CPRViewGeometry &            view,
                       const std::vector<BranchOcclusionRow> & occlusions,
                       const double                            origin[2],
                       const double                            spacing[2]);
} // namespace vr

#endif
