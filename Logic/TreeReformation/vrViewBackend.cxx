// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrViewBackend.h"

#ifdef VESSELREFORMATION_HAS_OPENCL
#include "itkOpenCLBilateralDepthRelaxFilter.h"
#include "itkOpenCLCPRDepthImageFilter.h"
#include "itkOpenCLCPRResampleImageFilter.h"
#endif

namespace vr
{
#ifdef VESSELREFORMATION_HAS_OPENCL
namespace
{
using OpenCLDepthFilterType = itk::OpenCLCPRDepthImageFilter;
using OpenCLResampleFilterType = itk::OpenCLCPRResampleImageFilter<itk::ImageBase<3>>;
} // namespace
#endif

OpenCLViewFilters
CreateOpenCLViewFilters(RelaxFilterType * openCLRelax, std::string & whyNot)
{
  whyNot.clear();
  OpenCLViewFilters filters;
#ifdef VESSELREFORMATION_HAS_OPENCL
  auto *     relax = dynamic_cast<itk::OpenCLBilateralDepthRelaxFilter *>(openCLRelax);
  const auto session = relax ? relax->GetSession() : nullptr;
  if (!session)
  {
    whyNot = "the relaxation does not run on an OpenCL device";
    return filters;
  }
  auto depth = OpenCLDepthFilterType::New();
  depth->SetSession(session);
  filters.Depth = depth.GetPointer();
  for (ViewResampleFilterType::Pointer * resample : { &filters.UnfilteredResample, &filters.RelaxedResample })
  {
    auto filter = OpenCLResampleFilterType::New();
    filter->SetSession(session);
    *resample = filter.GetPointer();
  }
  // The relaxation reads the depth map and the resampling the relaxed depth from the device, in this session.
  relax->SetSession(session);
#else
  (void)openCLRelax;
  whyNot = "this build has no OpenCL support (configure with VR_USE_OPENCL=ON)";
#endif
  return filters;
}

std::string
DescribeDepthBackend(const ViewDepthFilterType * filter, std::string & reason)
{
#ifdef VESSELREFORMATION_HAS_OPENCL
  if (const auto * device = dynamic_cast<const OpenCLDepthFilterType *>(filter))
  {
    reason = device->GetHostReason().empty() ? "on " + device->GetDeviceLabel() + ", with the relaxation"
                                             : device->GetHostReason();
    return device->GetHostReason().empty() ? "opencl" : "cpu";
  }
#else
  (void)filter;
#endif
  reason = "with the relaxation on the CPU";
  return "cpu";
}

std::string
DescribeResampleBackend(const ViewResampleFilterType * filter, std::string & reason)
{
#ifdef VESSELREFORMATION_HAS_OPENCL
  if (const auto * device = dynamic_cast<const OpenCLResampleFilterType *>(filter))
  {
    reason = device->GetHostReason().empty() ? "on " + device->GetDeviceLabel() + ", with the relaxation"
                                             : device->GetHostReason();
    return device->GetHostReason().empty() ? "opencl" : "cpu";
  }
#else
  (void)filter;
#endif
  reason = "with the relaxation on the CPU";
  return "cpu";
}
} // namespace vr
