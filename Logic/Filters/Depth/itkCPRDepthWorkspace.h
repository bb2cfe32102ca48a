// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCPRDepthWorkspace_h
#define itkCPRDepthWorkspace_h

#include <memory>

namespace itk
{
/** The depth filter's work buffers (the centerline raster and the depth assignment), kept between updates so that
 * a new angle allocates nothing; opaque here (itkCPRDepthComputation.h works on them). */
struct CPRDepthWorkspace;
struct CPRDepthWorkspaceDeleter
{
  void
  operator()(CPRDepthWorkspace * workspace) const;
};
using CPRDepthWorkspacePointer = std::unique_ptr<CPRDepthWorkspace, CPRDepthWorkspaceDeleter>;
} // namespace itk

#endif
