#include "vrRelaxBackend.h"

#include "vrInputError.h"

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
CreateRelaxFilter(RelaxBackend backend, const std::string & /*deviceRequest*/, std::string & notice,
                  RelaxBackend * chosen)
{
  notice.clear();
  if (backend == RelaxBackend::OpenCL)
  {
    throw InputError("backend opencl: this build has no OpenCL support (configure with VR_USE_OPENCL=ON)");
  }
  if (backend == RelaxBackend::Auto)
  {
    notice = "backend auto: this build has no OpenCL support, relaxing on the CPU";
  }
  if (chosen)
  {
    *chosen = RelaxBackend::CPU;
  }
  return RelaxFilterType::New();
}
} // namespace vr
