// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrViewBackend_h
#define vrViewBackend_h

#include "itkCPRDepthImageFilter.h"
#include "itkCPRResampleImageFilter.h"
#include "vrImageTypes.h"
#include "vrRelaxBackend.h"

#include <string>

namespace vr
{
using ViewDepthFilterType = itk::CPRDepthImageFilter<DepthImageType>;
/** The logic's resampling: a volume in its stored pixel type (vr::StoredVolume), whichever it is. */
using ViewResampleFilterType = itk::CPRResampleImageFilter<itk::ImageBase<3>, DepthImageType, DepthImageType>;

/** The depth and resampling filters of a view on the OpenCL device that relaxes it (docs/opencl.md "The whole view
 * on the device"), sharing that relax filter's session, so that the depth map, the relaxed depth and the volume
 * pass between the stages in the device's memory.
 * \ingroup VesselReformation */
struct OpenCLViewFilters
{
  ViewDepthFilterType::Pointer    Depth;
  ViewResampleFilterType::Pointer UnfilteredResample;
  ViewResampleFilterType::Pointer RelaxedResample;
};

/** The OpenCL depth and resampling filters on the session of \a openCLRelax, an OpenCL relax filter (as
 * TryCreateOpenCLRelaxFilter() makes them). Null filters, and \a whyNot, when the build has no OpenCL or
 * \a openCLRelax is not an OpenCL filter. */
OpenCLViewFilters
CreateOpenCLViewFilters(RelaxFilterType * openCLRelax, std::string & whyNot);

/** Where \a filter (a depth filter of the logic) computed its last output, "cpu" or "opencl", and why, in words:
 * an OpenCL depth filter that fell back to the CPU says why (a depth mode without a kernel). */
std::string
DescribeDepthBackend(const ViewDepthFilterType * filter, std::string & reason);

/** The same for a resampling filter (cubic interpolation, no double precision, a volume too large for the
 * device). */
std::string
DescribeResampleBackend(const ViewResampleFilterType * filter, std::string & reason);
} // namespace vr

#endif
