// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrVisibilityFigure_h
#define vrVisibilityFigure_h

#include "vrFigure.h"
#include "vrVesselReformationLogic.h"

#include <string>

namespace vr
{
/** Draws the centerlines of \a tree as \a view projects them over \a image (one pixel per image pixel), in the branch
 * colours of a plain palette, solid; the hidden stretches of \a occlusions dashed (3 pixels drawn, 3 not) and
 * brighter, so that what lies behind another vessel reads at a glance. */
void
DrawCenterlines(RGBImageType *                          image,
                const itk::CenterlineTree &             tree,
                const itk::CPRViewGeometry &            view,
                const std::vector<BranchOcclusionRow> & occlusions);

/** The demo's comparison of the depth modes where vessels overlap (issue 38, the README's picture): the relaxed CPR in
 * Scanline mode beside the one in Visibility mode, both with the centerlines drawn (the hidden stretches dashed in the
 * visibility panel), their depth maps under them, and a magnified detail of the region with the most hidden pixels.
 * \a logic holds the inputs and \a parameters the view and filter; it is updated in both modes (and left in Visibility
 * mode). Writes the PNG at \a path.
 * \return the outputs of the Visibility run. Throws vr::InputError. */
ReformationOutputs
WriteVisibilityFigure(VesselReformationLogic &    logic,
                      ReformationParameters       parameters,
                      const itk::CenterlineTree & tree,
                      const std::string &         phantomName,
                      double                      window,
                      double                      level,
                      const std::string &         path);
} // namespace vr

#endif
