// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrOpenCLRuntime_h
#define vrOpenCLRuntime_h

// Private to VesselReformationOpenCL: the one header that includes the OpenCL C++ bindings. The target defines
// CL_HPP_TARGET_OPENCL_VERSION / CL_HPP_MINIMUM_OPENCL_VERSION 120 and CL_HPP_ENABLE_EXCEPTIONS, so every failed
// OpenCL call throws cl::Error naming the call.
#include <CL/opencl.hpp>

#include <string>

namespace vr
{
/** The symbolic name of an OpenCL status code, e.g. "CL_OUT_OF_RESOURCES"; "unknown OpenCL error" otherwise. */
const char *
OpenCLErrorName(cl_int status);

/** "clCreateBuffer failed: CL_INVALID_BUFFER_SIZE (-61)". */
std::string
DescribeOpenCLError(const cl::Error & error);

/** The device \a deviceIndex of platform \a platformIndex in clGetPlatformIDs' and clGetDeviceIDs' lists (as
 * OpenCLDeviceInfo records them). Throws cl::Error when the device has gone. */
cl::Device
GetOpenCLDevice(unsigned int platformIndex, unsigned int deviceIndex);
} // namespace vr

#endif
