// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkCPRDepthImageFilter.h"

#include "itkCPRDepthComputation.h"

#include "itkCPRCenterlineRasterizer.h"
#include "itkCPRDepthAssignment.h"

namespace itk
{
namespace detail
{
struct CPRDepthWorkspace
{
  CPRCenterlinePixels CenterlinePixels;
  CPRDepthAssignment  Assignment;
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
  RasterizeCenterlines(tree, view, workspace->CenterlinePixels);
  if (rasterized)
  {
    rasterized();
  }
  AssignDepth(workspace->CenterlinePixels, mode, view.GetSpacing(), fixLumen, threader, workspace->Assignment);
  return { workspace->Assignment.Depth.data(), workspace->Assignment.Fixed.data(), workspace->Assignment.Owner.data() };
}
} // namespace detail

template class CPRDepthImageFilter<Image<float, 2>>;
} // namespace itk
