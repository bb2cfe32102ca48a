// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCLIRelaxParameters.h"

#include "vrInputError.h"
#include "vrRelaxBackend.h"

namespace vr
{
void
ReadRelaxParameters(const CLIArguments & arguments, ReformationParameters & parameters)
{
  parameters.Relaxation = arguments.Double("relaxation");
  if (arguments.Given("jumpThreshold") && arguments.Given("anisotropy"))
  {
    throw InputError("both " + arguments.Spelling("jumpThreshold") + " and " + arguments.Spelling("anisotropy") +
                     " give the range kernel (a = 1/J^2); give one of them");
  }
  if (arguments.Given("jumpThreshold"))
  {
    parameters.JumpThreshold = arguments.Double("jumpThreshold");
  }
  if (arguments.Given("anisotropy"))
  {
    parameters.Anisotropy = arguments.Double("anisotropy");
  }
  parameters.Iterations = arguments.Integer("iterations");
  parameters.Solver = ParseRelaxSolver(arguments.String("solver"), arguments.Spelling("solver"));
  parameters.Backend = ParseRelaxBackend(arguments.String("backend"), arguments.Spelling("backend"));
  parameters.OpenCLDevice = arguments.String("openclDevice");
}
} // namespace vr
