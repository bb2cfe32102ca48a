// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The BilateralDepthRelax command-line module: the relaxation stage alone, depth map [+ mask] -> relaxed depth.

#include "vrCLIModuleRunner.h"
#include "vrCLIRelaxParameters.h"
#include "vrImageIO.h"
#include "vrInputError.h"
#include "vrModuleExport.h"
#include "vrParameterName.h"
#include "vrStagedOutputs.h"
#include "vrVesselReformationLogic.h"

#include <chrono>
#include <iomanip>
#include <iostream>
#include <sstream>

extern "C" VR_MODULE_EXPORT char XMLModuleDescription[];

namespace
{
void
RunBilateralDepthRelax(const vr::CLIArguments & arguments, vr::CLIProgress & progress)
{
  vr::ReformationParameters parameters;
  vr::ReadRelaxParameters(arguments, parameters);
  parameters.Validate();

  vr::StagedOutputs staged;
  const std::size_t output = staged.Add(arguments.String("outputDepth"), arguments.Spelling("outputDepth"));

  const std::string           depthPath = arguments.String("inputDepth");
  vr::DepthImageType::Pointer depth = vr::ReadDepthImage(depthPath);
  vr::MaskImageType::Pointer  mask;
  if (arguments.Given("mask"))
  {
    const std::string maskPath = arguments.String("mask");
    mask = vr::ReadMaskImage(maskPath);
    const auto depthSize = depth->GetLargestPossibleRegion().GetSize();
    const auto maskSize = mask->GetLargestPossibleRegion().GetSize();
    if (depthSize != maskSize)
    {
      std::ostringstream message;
      message << "--mask " << maskPath << ": " << maskSize[0] << " x " << maskSize[1] << " pixels, but the depth map "
              << depthPath << " has " << depthSize[0] << " x " << depthSize[1];
      throw vr::InputError(message.str());
    }
  }

  std::vector<std::string> warnings;
  std::string              backend = "cpu";
  std::string              backendReason;
  const auto               start = std::chrono::steady_clock::now();
  const auto               relaxed = vr::VesselReformationLogic::RelaxDepthImage(
    depth,
    mask,
    parameters,
    [&progress](double fraction, const std::string & stage)
    {
      if (progress.AbortRequested())
      {
        throw vr::Cancelled("relaxation: cancelled by the caller");
      }
      progress.Update(fraction, stage);
    },
    warnings,
    &backend,
    &backendReason);
  for (const auto & warning : warnings)
  {
    progress.Print(std::cerr, "warning: " + warning);
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  staged.Write(output, [&relaxed](const std::string & path) { vr::WriteImage2D(relaxed.GetPointer(), path); });
  staged.CommitAll();

  const auto &       size = relaxed->GetLargestPossibleRegion().GetSize();
  std::ostringstream milliseconds;
  milliseconds << std::fixed << std::setprecision(3) << 1e3 * seconds;
  progress.SetReturnValue("backendUsed", backend);
  progress.SetReturnValue("imageSize", std::to_string(size[0]) + "," + std::to_string(size[1]));
  progress.SetReturnValue("relaxTime", milliseconds.str());
  // The backend's reason goes to the log, not to a returned value: a free text cannot be one of CTK's index-1000
  // parameters, whose values hosts pass back after the positional arguments.
  progress.Print(std::cout,
                 "BilateralDepthRelax: " + std::to_string(size[0]) + " x " + std::to_string(size[1]) + " pixels, " +
                   milliseconds.str() + " ms on " + backend + "; relax backend: " + backendReason);
}
} // namespace

extern "C" VR_MODULE_EXPORT int
ModuleEntryPoint(int argc, char * argv[])
{
  return vr::RunCLIModule(argc,
                          argv,
                          XMLModuleDescription,
                          "BilateralDepthRelax",
                          "Bilateral relaxation of a CPR depth map",
                          RunBilateralDepthRelax);
}
