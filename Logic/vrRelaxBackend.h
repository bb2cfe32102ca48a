// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrRelaxBackend_h
#define vrRelaxBackend_h

#include "itkBilateralDepthRelaxFilter.h"

#include <string>

namespace vr
{
/** Where BilateralDepthRelaxFilter runs (DESIGN 3.7). */
enum class RelaxBackend
{
  /** OpenCL when a device works, else the CPU with a notice saying why. */
  Auto,
  CPU,
  /** OpenCL or an error that says which devices were found. */
  OpenCL
};

const char *
ToString(RelaxBackend backend);
/** Parses "auto", "cpu" or "opencl" (any case); throws vr::InputError naming \a what otherwise. */
RelaxBackend
ParseRelaxBackend(const std::string & text, const std::string & what);

using RelaxFilterType = itk::BilateralDepthRelaxFilter<itk::Image<float, 2>>;

/** The OpenCL relax filter on the device \a deviceRequest asks for ("" = the default choice, see the OpenCL
 * variant), with its kernel already built, so that a backend choice can still fall back.
 * \param deviceRequest the device asked for.
 * \param whyNot receives why no OpenCL filter could be made (no device, no OpenCL in this build, a failed
 * kernel build).
 * \return the filter, or null. */
RelaxFilterType::Pointer
TryCreateOpenCLRelaxFilter(const std::string & deviceRequest, std::string & whyNot);

/** Creates the relax filter for \a backend. \a deviceRequest picks an OpenCL device ("" = the default choice,
 * see the OpenCL variant). On Auto without a usable device, returns the CPU filter and sets \a notice to why;
 * on OpenCL without one, throws vr::InputError naming what was found. \a chosen receives the backend used. */
RelaxFilterType::Pointer
CreateRelaxFilter(RelaxBackend        backend,
                  const std::string & deviceRequest,
                  std::string &       notice,
                  RelaxBackend *      chosen = nullptr);
} // namespace vr

#endif
