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

namespace
{
/** The notice when auto falls back to the CPU because OpenCL is not usable (\a why). */
std::string
UnusableOpenCLNotice(const std::string & why)
{
  return "relax backend auto: OpenCL is not usable, relaxing on the CPU instead. Reason: " + why;
}
} // namespace

RelaxFilterChoice
ChooseRelaxFilter(RelaxBackend                    requested,
                  itk::BilateralDepthRelaxSolver  solver,
                  const std::string &             deviceRequest,
                  const OpenCLRelaxFilterSource & openCL,
                  const OpenCLDeviceQuery &       query)
{
  RelaxFilterChoice choice;
  choice.Reason = "cpu requested";
  if (requested == RelaxBackend::CPU)
  {
    return choice;
  }
  if (solver == itk::BilateralDepthRelaxSolver::Steady)
  {
    // Asked for OpenCL by name, the user hears why it is not used; auto simply reports its reason.
    choice.Reason = std::string(ToString(requested)) + ": the steady solver has no OpenCL kernel, so the CPU";
    if (requested == RelaxBackend::OpenCL)
    {
      choice.Notice = "relax backend opencl: the steady solver has no OpenCL kernel; relaxing on the CPU instead";
    }
    return choice;
  }
  std::string openCLReason = "opencl requested";
  if (requested == RelaxBackend::Auto)
  {
    // OpenCL only on a GPU or an accelerator; on PoCL's CPU device the native path is faster.
    const RelaxBackendDecision decision = DecideAutoRelaxBackend(deviceRequest, query);
    if (decision.Backend == RelaxBackend::CPU)
    {
      choice.Reason = decision.Reason;
      if (!decision.DeviceProblem.empty())
      {
        choice.Notice = UnusableOpenCLNotice(decision.DeviceProblem);
      }
      return choice;
    }
    openCLReason = decision.Reason;
  }
  std::string why;
  if (auto filter = openCL(deviceRequest, why))
  {
    choice.Filter = filter;
    choice.Backend = RelaxBackend::OpenCL;
    choice.Reason = openCLReason;
    return choice;
  }
  if (requested == RelaxBackend::OpenCL)
  {
    throw InputError("relax backend opencl: no usable OpenCL device: " + why, ParameterName::Backend);
  }
  choice.Notice = UnusableOpenCLNotice(why);
  choice.Reason = "auto: OpenCL failed on the device (" + why + "), so the CPU";
  return choice;
}

RelaxFilterType::Pointer
CreateRelaxFilter(RelaxBackend              backend,
                  const std::string &       deviceRequest,
                  std::string &             notice,
                  RelaxBackend *            chosen,
                  std::string *             reason,
                  const OpenCLDeviceQuery & query)
{
  const RelaxFilterChoice choice = ChooseRelaxFilter(
    backend, itk::BilateralDepthRelaxSolver::Jacobi, deviceRequest, TryCreateOpenCLRelaxFilter, query);
  notice = choice.Notice;
  if (chosen)
  {
    *chosen = choice.Backend;
  }
  if (reason)
  {
    *reason = choice.Reason;
  }
  return choice.Filter ? choice.Filter : RelaxFilterType::New();
}
} // namespace vr
