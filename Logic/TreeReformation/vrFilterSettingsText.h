// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrFilterSettingsText_h
#define vrFilterSettingsText_h

#include "vrReformationParameters.h"

#include <string>

namespace vr
{
/** How captions and summaries name the image without relaxation. */
constexpr const char * UnfilteredSettingsText = "unfiltered (w = 0)";

/** The relaxation's settings as every caption and summary states them (the module's summary, the viewer's CPR
 * caption, the demo's figure): the range kernel as it was given, "J = 3 mm" or "a = 0.5 mm^-2", then for the Jacobi
 * solver the relaxation and the iterations, "w = 1, 500 iterations", or for the steady solver, where neither
 * applies, "steady solver". E.g. "J = 3 mm, w = 1, 500 iterations" or "a = 0.5 mm^-2, steady solver".
 * \param parameters the reformation's parameters.
 * \param breakBefore what stands between the kernel (with w) and the solver: ", " on one line, "\n" for two
 * short lines. */
std::string
DescribeFilterSettings(const ReformationParameters & parameters, const std::string & breakBefore = ", ");
} // namespace vr

#endif
