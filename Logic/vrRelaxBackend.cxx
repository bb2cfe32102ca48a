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

OpenCLDeviceKind
QueryOpenCLDevice(const std::string & deviceRequest)
{
  OpenCLDeviceKind kind;
#ifdef VESSELREFORMATION_HAS_OPENCL
  try
  {
    const OpenCLDeviceInfo device = FindOpenCLDevice(deviceRequest, "device request");
    kind.Label = device.Label();
    kind.Type = device.TypeName();
  }
  catch (const InputError & error)
  {
    kind.WhyNot = error.what();
  }
#else
  (void)deviceRequest;
  kind.WhyNot = "this build has no OpenCL support (configure with VR_USE_OPENCL=ON)";
#endif
  return kind;
}

RelaxBackendDecision
DecideAutoRelaxBackend(const std::string & deviceRequest, const OpenCLDeviceQuery & query)
{
  const OpenCLDeviceKind device = query(deviceRequest);
  RelaxBackendDecision   decision;
  if (!device.WhyNot.empty())
  {
    decision.Reason = "auto: no usable OpenCL device (" + device.WhyNot + "), so the CPU";
    decision.DeviceProblem = device.WhyNot;
  }
  else if (device.Type == "CPU")
  {
    decision.Reason = "auto: the OpenCL device " + device.Label +
                      " is a CPU device, where the native CPU path is faster on the same cores, so the CPU";
  }
  else
  {
    decision.Backend = RelaxBackend::OpenCL;
    decision.Reason = "auto: OpenCL on " + device.Label + ", a " + device.Type;
  }
  return decision;
}

RelaxFilterType::Pointer
CreateRelaxFilter(RelaxBackend              backend,
                  const std::string &       deviceRequest,
                  std::string &             notice,
                  RelaxBackend *            chosen,
                  std::string *             reason,
                  const OpenCLDeviceQuery & query)
{
  notice.clear();
  auto report = [&](RelaxBackend used, const std::string & why)
  {
    if (chosen)
    {
      *chosen = used;
    }
    if (reason)
    {
      *reason = why;
    }
  };
  report(RelaxBackend::CPU, "cpu requested");
  if (backend == RelaxBackend::CPU)
  {
    return RelaxFilterType::New();
  }
  std::string openCLReason = "opencl requested";
  if (backend == RelaxBackend::Auto)
  {
    const RelaxBackendDecision decision = DecideAutoRelaxBackend(deviceRequest, query);
    if (decision.Backend == RelaxBackend::CPU)
    {
      report(RelaxBackend::CPU, decision.Reason);
      if (!decision.DeviceProblem.empty())
      {
        notice =
          "relax backend auto: OpenCL is not usable, relaxing on the CPU instead. Reason: " + decision.DeviceProblem;
      }
      return RelaxFilterType::New();
    }
    openCLReason = decision.Reason;
  }
  std::string why;
  if (auto filter = TryCreateOpenCLRelaxFilter(deviceRequest, why))
  {
    report(RelaxBackend::OpenCL, openCLReason);
    return filter;
  }
  if (backend == RelaxBackend::OpenCL)
  {
    throw InputError("relax backend opencl: no usable OpenCL device: " + why, ParameterName::Backend);
  }
  notice = "relax backend auto: OpenCL is not usable, relaxing on the CPU instead. Reason: " + why;
  report(RelaxBackend::CPU, "auto: OpenCL failed on the device (" + why + "), so the CPU");
  return RelaxFilterType::New();
}
} // namespace vr
