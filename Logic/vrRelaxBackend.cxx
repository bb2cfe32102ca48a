// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrRelaxBackend.h"

#include "vrInputError.h"
#include "vrParameterName.h"
#include "vrText.h"

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
  const std::string lower = ToLower(text);
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
  throw InputError(what + ": \"" + text + "\" is not a backend; use auto, cpu or opencl", ParameterName::Backend);
}

RelaxFilterType::Pointer
TryCreateOpenCLRelaxFilter(const std::string & deviceRequest, std::string & whyNot)
{
  whyNot.clear();
#ifdef VESSELREFORMATION_HAS_OPENCL
  // The same checks the filter's first Update() would make, done now: is there a device (VR_OPENCL_DEVICE and
  // deviceRequest as the filter reads them), and does the kernel build on it?
  try
  {
    vr::FindOpenCLDevice(deviceRequest, "device request");
    auto filter = itk::OpenCLBilateralDepthRelaxFilter::New();
    filter->SetDeviceRequest(deviceRequest);
    filter->PrepareDevice();
    return filter.GetPointer();
  }
  catch (const InputError & error)
  {
    whyNot = error.what();
  }
  catch (const itk::ExceptionObject & error)
  {
    whyNot = error.GetDescription();
  }
#else
  (void)deviceRequest;
  whyNot = "this build has no OpenCL support (configure with VR_USE_OPENCL=ON)";
#endif
  return nullptr;
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
  std::string why;
  if (auto filter = TryCreateOpenCLRelaxFilter(deviceRequest, why))
  {
    if (chosen)
    {
      *chosen = RelaxBackend::OpenCL;
    }
    return filter;
  }
  if (backend == RelaxBackend::OpenCL)
  {
    throw InputError("relax backend opencl: no usable OpenCL device: " + why, ParameterName::Backend);
  }
  notice = "relax backend auto: OpenCL is not usable, relaxing on the CPU instead. Reason: " + why;
  return RelaxFilterType::New();
}
} // namespace vr
