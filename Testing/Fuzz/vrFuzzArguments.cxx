// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Fuzz harness: the command-line argument parser with the VesselReformation module's own XML description, and the
// parsers of the values it hands on (--up, --size, --spacing, --centerlineSpace and the enumerations). The input is
// argv[1..], separated by NUL bytes. Any input must end in arguments or a vr::InputError.
#include "vrCLIArguments.h"
#include "vrCoordinateFrames.h"
#include "vrFuzzSupport.h"
#include "vrInputError.h"
#include "vrReformationParameters.h"
#include "vrRelaxBackend.h"

#include <vector>

extern "C" char XMLModuleDescription[];

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t * data, std::size_t size)
{
  static const vr::CLIModuleDescription description = vr::CLIModuleDescription::FromXML(XMLModuleDescription);
  std::vector<std::string>              words{ "VesselReformation" };
  std::string                           word;
  for (std::size_t k = 0; k < size; ++k)
  {
    if (data[k] == 0)
    {
      words.push_back(word);
      word.clear();
    }
    else
    {
      word.push_back(static_cast<char>(data[k]));
    }
  }
  words.push_back(word);
  std::vector<char *> argv;
  for (auto & each : words)
  {
    argv.push_back(each.data());
  }
  argv.push_back(nullptr);
  try
  {
    const vr::CLIArguments arguments =
      vr::CLIArguments::Parse(description, static_cast<int>(words.size()), argv.data());
    if (arguments.XMLRequested || arguments.HelpRequested)
    {
      return 0;
    }
    vr::ParseUpAxis(arguments.String("up"), "--up");
    if (arguments.Given("size"))
    {
      vr::ParseImageSize(arguments.String("size"), "--size");
    }
    if (arguments.Given("spacing"))
    {
      vr::ParsePixelSpacing(arguments.String("spacing"), "--spacing");
    }
    vr::ParseCoordinateSpace(arguments.String("centerlineSpace"), "--centerlineSpace");
    vr::ParseDepthMode(arguments.String("mode"), "--mode");
    vr::ParseOnOff(arguments.String("fixLumen"), "--fixLumen");
    vr::ParseRelaxBackend(arguments.String("backend"), "--backend");
    vr::ParseInterpolation(arguments.String("interpolation"), "--interpolation");
    vr::ParseSlabMode(arguments.String("slabMode"), "--slabMode");
    arguments.Double("angle");
    arguments.Integer("iterations");
  }
  catch (const vr::InputError &)
  {
  }
  return 0;
}
