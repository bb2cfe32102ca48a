// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrOpenCLTestSupport_h
#define vrOpenCLTestSupport_h

// What the OpenCL tests share: skipping without a device, and scoped changes of the environment and of the
// kernel source (the filter's test hook), undone however a test ends.
#include "itkOpenCLBilateralDepthRelaxFilter.h"
#include "vrOpenCLDevices.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <optional>
#include <string>

namespace vr::test
{
/** True when ListOpenCLDevices() finds a device the filter can use; otherwise \a problem says why not. */
inline bool
HasUsableOpenCLDevice(std::string & problem)
{
  for (const auto & device : vr::ListOpenCLDevices(&problem))
  {
    if (device.Unusable.empty())
    {
      return true;
    }
  }
  if (problem.empty())
  {
    problem = "every OpenCL device found is unusable";
  }
  return false;
}

/** Sets (or, with nullptr, unsets) an environment variable until the end of the scope. */
class ScopedEnvironment
{
public:
  ScopedEnvironment(const char * name, const char * value)
    : m_Name(name)
  {
    if (const char * old = std::getenv(name))
    {
      m_Old = old;
    }
    if (value)
    {
      setenv(name, value, 1);
    }
    else
    {
      unsetenv(name);
    }
  }
  ~ScopedEnvironment()
  {
    if (m_Old)
    {
      setenv(m_Name.c_str(), m_Old->c_str(), 1);
    }
    else
    {
      unsetenv(m_Name.c_str());
    }
  }
  ScopedEnvironment(const ScopedEnvironment &) = delete;
  ScopedEnvironment &
  operator=(const ScopedEnvironment &) = delete;

private:
  std::string                m_Name;
  std::optional<std::string> m_Old;
};

/** Makes the OpenCL filter build \a source instead of its kernel until the end of the scope. */
class ScopedKernelSource
{
public:
  explicit ScopedKernelSource(const std::string & source)
  {
    itk::OpenCLBilateralDepthRelaxFilter::SetKernelSourceForTesting(source);
  }
  ~ScopedKernelSource() { itk::OpenCLBilateralDepthRelaxFilter::SetKernelSourceForTesting(std::string()); }
  ScopedKernelSource(const ScopedKernelSource &) = delete;
  ScopedKernelSource &
  operator=(const ScopedKernelSource &) = delete;
};
} // namespace vr::test

/** Skips the calling test, with the reason, when the machine has no usable OpenCL device. */
#define VR_SKIP_WITHOUT_OPENCL_DEVICE()                                                                                \
  do                                                                                                                   \
  {                                                                                                                    \
    std::string vrOpenCLProblem;                                                                                       \
    if (!vr::test::HasUsableOpenCLDevice(vrOpenCLProblem))                                                             \
    {                                                                                                                  \
      GTEST_SKIP() << "no usable OpenCL device: " << vrOpenCLProblem;                                                  \
    }                                                                                                                  \
  } while (false)

#endif
