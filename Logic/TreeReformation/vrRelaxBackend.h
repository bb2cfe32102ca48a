// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrRelaxBackend_h
#define vrRelaxBackend_h

#include "itkBilateralDepthRelaxFilter.h"

#include <functional>
#include <string>

namespace vr
{
/** Where BilateralDepthRelaxFilter runs (docs/design.md "Module logic"). */
enum class RelaxBackend
{
  /** OpenCL when the device it would use is a GPU or an accelerator and works; on a CPU device (PoCL) the native
   * CPU path, which is faster on the same cores; without a working device the CPU with a notice saying why. */
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

/** The OpenCL device a relaxation would use, as far as the Auto rule needs to know it.
 * \ingroup VesselReformation */
struct OpenCLDeviceKind
{
  /** Empty when there is a usable device; otherwise why there is none. */
  std::string WhyNot;
  /** How messages name the device, e.g. "0:0 cpu-haswell (Portable Computing Language, CPU)". */
  std::string Label;
  /** "GPU", "CPU" or "accelerator". */
  std::string Type;
};

/** Answers which OpenCL device \a deviceRequest ("" = VR_OPENCL_DEVICE, else the default choice) gives. */
using OpenCLDeviceQuery = std::function<OpenCLDeviceKind(const std::string & deviceRequest)>;

/** The installed drivers' answer (vr::FindOpenCLDevice); in a build without OpenCL, none. Never throws. */
OpenCLDeviceKind
QueryOpenCLDevice(const std::string & deviceRequest);

/** A backend choice and the reason for it, in words for the results and the stage log.
 * \ingroup VesselReformation */
struct RelaxBackendDecision
{
  RelaxBackend Backend{ RelaxBackend::CPU };
  std::string  Reason;
  /** Why there is no usable OpenCL device, when that is the reason; else empty. */
  std::string DeviceProblem;
};

/** The Auto rule: OpenCL only when \a query reports a usable GPU or accelerator for \a deviceRequest; a CPU device
 * (PoCL) or no device gives the CPU. The reason names the device and the rule. */
RelaxBackendDecision
DecideAutoRelaxBackend(const std::string & deviceRequest, const OpenCLDeviceQuery & query = QueryOpenCLDevice);

/** Makes (or finds) the OpenCL relax filter for a device request, as TryCreateOpenCLRelaxFilter; null and \a whyNot
 * when there is none. */
using OpenCLRelaxFilterSource =
  std::function<RelaxFilterType::Pointer(const std::string & deviceRequest, std::string & whyNot)>;

/** What a relaxation runs on, and why, in words for the results and the stage log.
 * \ingroup VesselReformation */
struct RelaxFilterChoice
{
  /** The OpenCL filter when Backend is OpenCL; null for the CPU, whose filter the caller owns. */
  RelaxFilterType::Pointer Filter;
  RelaxBackend             Backend{ RelaxBackend::CPU };
  std::string              Reason;
  /** What the user should hear (a fallback, a backend asked for by name and not used); else empty. */
  std::string Notice;
};

/** The one backend decision of the project (docs/design.md "Module logic"): cpu gives the CPU; the steady solver, which
 * has no OpenCL kernel, gives the CPU (with a notice when OpenCL was asked for by name); auto applies
 * DecideAutoRelaxBackend(), asking \a query, and takes OpenCL only when \a openCL then makes a filter, else the CPU
 * with a notice saying why; opencl takes the filter \a openCL makes or throws vr::InputError naming why there is
 * none. */
RelaxFilterChoice
ChooseRelaxFilter(RelaxBackend                    requested,
                  itk::BilateralDepthRelaxSolver  solver,
                  const std::string &             deviceRequest,
                  const OpenCLRelaxFilterSource & openCL = TryCreateOpenCLRelaxFilter,
                  const OpenCLDeviceQuery &       query = QueryOpenCLDevice);

/** Creates the relax filter for \a backend (ChooseRelaxFilter() for the Jacobi solver). \a deviceRequest picks an
 * OpenCL device ("" = the default choice, see the OpenCL variant). On Auto without a usable device, returns the CPU
 * filter and sets \a notice to why; on OpenCL without one, throws vr::InputError naming what was found. \a chosen
 * receives the backend used and \a reason why (DecideAutoRelaxBackend() for Auto, which asks \a query). */
RelaxFilterType::Pointer
CreateRelaxFilter(RelaxBackend              backend,
                  const std::string &       deviceRequest,
                  std::string &             notice,
                  RelaxBackend *            chosen = nullptr,
                  std::string *             reason = nullptr,
                  const OpenCLDeviceQuery & query = QueryOpenCLDevice);
} // namespace vr

#endif
