// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrCLIRelaxParameters_h
#define vrCLIRelaxParameters_h

#include "vrCLIArguments.h"
#include "vrReformationParameters.h"

namespace vr
{
/** Reads the relaxation's parameters, as every module that relaxes spells them in its XML (relaxation,
 * jumpThreshold, anisotropy, iterations, solver, backend, openclDevice), into \a parameters. The range kernel comes
 * from --jumpThreshold or --anisotropy, unset from neither (the default J); both given is an InputError naming both
 * flags. Throws vr::InputError naming the flag on a value that does not parse. */
void
ReadRelaxParameters(const CLIArguments & arguments, ReformationParameters & parameters);
} // namespace vr

#endif
