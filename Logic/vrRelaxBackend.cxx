// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrRelaxBackend.h"

#include "vrInputError.h"

#ifdef VESSELREFORMATION_HAS_OPENCL
#include "itkOpenCLBilateralDepthRelaxFilter.h"
#include "vrOpenCLDevices.h"
#endif

#include <algorithm>
#include <cctype>

namespace vr
{
const char *
ToString(RelaxBackend backend)
{
  switch (backend)
  {
    case RelaxBackend::CPU:
      return "cpu";
    case RelaxBackend::OpenCL:
      return "opencl";
    default:
      return "auto";
  }
}

RelaxBackend
ParseRelaxBackend(const std::string & text, const std::string & what)
{
  std::string lower = text;
  std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return std::tolower(c); });
  if (lower == "auto")
  {
    return RelaxBackend::Auto;
  }
  if (lower == "cpu")
  {
    return RelaxBackend::CPU;
  }
  if (lower == "opencl")
  {
    return RelaxBackend::OpenCL;
  }
  throw InputError(what + ": \"" + text + "\" is not a backend; use auto, cpu or opencl");
}

RelaxFilterType::Pointer
CreateRelaxFilter(RelaxBackend backend, const std::string & deviceRequest, std::string & notice, RelaxBackend * chosen)
{
  notice.clear();
  if (chosen)
  {
    *chosen = RelaxBackend::CPU;
  }
  if (backend == RelaxBackend::CPU)
  {
    return RelaxFilterType::New();
  }
  const std::string requested = backend == RelaxBackend::OpenCL ? "backend opencl" : "backend auto";

#ifdef VESSELREFORMATION_HAS_OPENCL
  // The same checks the filter's first Update() would make, done now so that auto can still fall back: is there a
  // device (VR_OPENCL_DEVICE and deviceRequest as the filter reads them), and does the kernel build on it?
  std::string why;
  try
  {
    vr::FindOpenCLDevice(deviceRequest, "device request");
    auto filter = itk::OpenCLBilateralDepthRelaxFilter::New();
    filter->SetDeviceRequest(deviceRequest);
    filter->PrepareDevice();
    if (chosen)
    {
      *chosen = RelaxBackend::OpenCL;
    }
    return filter.GetPointer();
  }
  catch (const InputError & error)
  {
    why = error.what();
  }
  catch (const itk::ExceptionObject & error)
  {
    why = error.GetDescription();
  }
  if (backend == RelaxBackend::OpenCL)
  {
    throw InputError(requested + ": no usable OpenCL device: " + why);
  }
  notice = requested + ": OpenCL is not usable, relaxing on the CPU instead. Reason: " + why;
#else
  (void)deviceRequest;
  if (backend == RelaxBackend::OpenCL)
  {
    throw InputError(requested + ": this build has no OpenCL support (configure with VR_USE_OPENCL=ON)");
  }
  notice = requested + ": this build has no OpenCL support, relaxing on the CPU";
#endif
  return RelaxFilterType::New();
}
} // namespace vr
