// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCPRDepthComputation_h
#define itkCPRDepthComputation_h

#include "itkCPRDepthMode.h"
#include "itkCPRDepthWorkspace.h"
#include "itkCPRViewGeometry.h"
#include "itkCenterlineTree.h"
#include "itkMultiThreaderBase.h"

#include <cstdint>
#include <functional>

namespace itk
{
namespace detail
{
// The non-template work of every CPRDepthImageFilter, compiled once in itkCPRDepthImageFilter.cxx; installed only
// because the filter's .hxx (for pixel types other than float) calls it. Not an interface: it may change.

/** Row-major W x H results of ComputeCPRDepth, owned by the workspace.
 * \ingroup VesselReformation
 */
struct CPRDepthResult
{
  const float *         Depth;
  const unsigned char * Fixed;
  const uint32_t *      Owner;
};

/** Rasterises \a tree into \a view (centerline pixels, docs/design.md 3.4 step 1), then assigns every pixel its depth,
 * owner and fixed flag by \a mode; \a rasterized is called in between. Creates \a workspace when null. The
 * non-template work of every CPRDepthImageFilter, compiled once. */
CPRDepthResult
ComputeCPRDepth(const CenterlineTree &        tree,
                const CPRViewGeometry &       view,
                CPRDepthMode                  mode,
                bool                          fixLumen,
                MultiThreaderBase *           threader,
                CPRDepthWorkspacePointer &    workspace,
                const std::function<void()> & rasterized);
} // namespace detail
} // namespace itk

#endif
