// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Fuzz harness: the centerline reader for .tre files, through vr::ReadCenterlines as the modules call it. Any input
// must end in a tree or a vr::InputError; a crash, a leak, undefined behaviour, a hang or another exception is a
// finding.
#include "vrCenterlineIO.h"
#include "vrFuzzSupport.h"
#include "vrInputError.h"

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t * data, std::size_t size)
{
  const std::string path = vr::fuzz::WriteInput(data, size, ".tre");
  try
  {
    vr::ReadCenterlines(path);
  }
  catch (const vr::InputError &)
  {
  }
  return 0;
}
