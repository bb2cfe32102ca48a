// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrVisibilityOutputs_h
#define vrVisibilityOutputs_h

#include "itkCPRBranchOcclusion.h"
#include "itkCPROcclusionProfile.h"
#include "itkCPRViewGeometry.h"
#include "itkCenterlineTree.h"
#include "vrOcclusionTableIO.h"

#include <memory>
#include <string>
#include <vector>

namespace vr::detail
{
// What the module logic adds to the depth filter's Visibility mode (docs/design.md "Depth"): the warning about
// branches without radii, the branches' names beside their hidden lengths, and the occlusion profile kept while only
// the angle changes.

/** \return the warning for Visibility mode when branches of \a tree have no radii (which, and what that costs), or "".
 */
std::string
DescribeBranchesWithoutRadii(const itk::CenterlineTree & tree);

/** \return \a occlusions (the depth filter's, in the tree's order) with each branch's name from \a tree. */
std::vector<BranchOcclusionRow>
NameBranchOcclusions(const itk::CenterlineTree & tree, const std::vector<itk::CPRBranchOcclusion> & occlusions);

/** The occlusion profile of the latest tree and view, computed again only when the tree, the view's up axis, centre or
 * pixel spacing change. */
class OcclusionProfileCache
{
public:
  /** \param tree the centerlines (kept: compared by identity).
   * \param view the view, its angle and size ignored.
   * \param seconds receives the time of the computation, 0 when the kept profile served.
   * \return the profile. */
  std::shared_ptr<const itk::CPROcclusionProfile>
  Get(const std::shared_ptr<const itk::CenterlineTree> & tree, const itk::CPRViewGeometry & view, double & seconds);

private:
  std::shared_ptr<const itk::CPROcclusionProfile> m_Profile;
  std::shared_ptr<const itk::CenterlineTree>      m_Tree;
  itk::CPRViewGeometry                            m_View;
};
} // namespace vr::detail

#endif
