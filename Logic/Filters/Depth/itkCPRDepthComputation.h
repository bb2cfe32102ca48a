// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCPRDepthComputation_h
#define itkCPRDepthComputation_h

#include "itkCPRBranchOcclusion.h"
#include "itkCPRDepthMode.h"
#include "itkCPRDepthWorkspace.h"
#include "itkCPRViewGeometry.h"
#include "itkCenterlineTree.h"
#include "itkMultiThreaderBase.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace itk
{
// The depth computation without a pipeline: what every CPRDepthImageFilter runs (compiled once, in
// itkCPRDepthImageFilter.cxx, whatever the filter's pixel type), on row-major buffers a caller may read directly.

/** Row-major W x H results of ComputeCPRDepth, owned by the workspace.
 * \ingroup VesselReformation
 */
struct CPRDepthResult
{
  const float *         Depth;
  const unsigned char * Fixed;
  const uint32_t *      Owner;
  /** Visibility mode: the hidden labels and each branch's hidden length; null in the other modes. */
  const uint32_t *                        Hidden;
  const std::vector<CPRBranchOcclusion> * Occlusion;
};

/** Rasterises \a tree into \a view (centerline pixels, docs/design.md "Depth" step 1), then assigns every pixel its
 * depth, owner and fixed flag by \a mode; \a rasterized is called in between. Creates \a workspace when null. The
 * non-template work of every CPRDepthImageFilter, compiled once. In Visibility mode \a fixLumen applies to the
 * branches with radii; the caller of the other modes passes it only when every branch has them. */
CPRDepthResult
ComputeCPRDepth(const CenterlineTree &        tree,
                const CPRViewGeometry &       view,
                CPRDepthMode                  mode,
                bool                          fixLumen,
                MultiThreaderBase *           threader,
                CPRDepthWorkspacePointer &    workspace,
                const std::function<void()> & rasterized);
} // namespace itk

#endif
