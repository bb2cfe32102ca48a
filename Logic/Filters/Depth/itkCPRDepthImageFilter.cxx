// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkCPRDepthImageFilter.h"

#include "itkCPRDepthComputation.h"

#include "itkCPRCenterlineRasterizer.h"
#include "itkCPRDepthAssignment.h"
#include "itkCPRVisibilityDepth.h"

namespace itk
{
struct CPRDepthWorkspace
{
  detail::CPRCenterlinePixels     CenterlinePixels;
  detail::CPRDepthAssignment      Assignment;
  detail::CPRVisibilityWorkspace  Visibility;
  std::vector<CPRBranchOcclusion> Occlusion;
};

void
CPRDepthWorkspaceDeleter::operator()(CPRDepthWorkspace * workspace) const
{
  delete workspace;
}

CPRDepthResult
ComputeCPRDepth(const CenterlineTree &        tree,
                const CPRViewGeometry &       view,
                CPRDepthMode                  mode,
                bool                          fixLumen,
                MultiThreaderBase *           threader,
                CPRDepthWorkspacePointer &    workspace,
                const std::function<void()> & rasterized)
{
  if (!workspace)
  {
    workspace.reset(new CPRDepthWorkspace);
  }
  detail::RasterizeCenterlines(tree, view, workspace->CenterlinePixels);
  if (rasterized)
  {
    rasterized();
  }
  detail::CPRDepthAssignment & assignment = workspace->Assignment;
  if (mode == CPRDepthMode::Visibility)
  {
    detail::AssignVisibility(tree,
                             view,
                             workspace->CenterlinePixels,
                             fixLumen,
                             threader,
                             workspace->Visibility,
                             assignment,
                             workspace->Occlusion);
    return { assignment.Depth.data(),
             assignment.Fixed.data(),
             assignment.Owner.data(),
             assignment.Hidden.data(),
             &workspace->Occlusion };
  }
  detail::AssignDepth(workspace->CenterlinePixels, mode, view.GetSpacing(), fixLumen, threader, assignment);
  return { assignment.Depth.data(), assignment.Fixed.data(), assignment.Owner.data(), nullptr, nullptr };
}
template class CPRDepthImageFilter<Image<float, 2>>;
} // namespace itk
