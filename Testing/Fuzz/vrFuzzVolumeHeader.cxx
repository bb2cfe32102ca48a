// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Fuzz harness: volume header parsing through the IO layer (vr::InspectVolumeFile: the file checks, ITK's choice of
// reader, the header, and our checks of dimensions, size, components and geometry), without reading voxel data.
// The first byte picks the file's extension, so one corpus covers NRRD, MetaImage and NIfTI, attached and detached.
#include "vrFuzzSupport.h"
#include "vrInputError.h"
#include "vrVolumeIO.h"

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t * data, std::size_t size)
{
  static const char * const extensions[] = { ".nrrd", ".mha", ".nii", ".nhdr", ".mhd", ".hdr" };
  if (size == 0)
  {
    return 0;
  }
  const std::string path = vr::fuzz::WriteInput(data + 1, size - 1, extensions[data[0] % 6]);
  try
  {
    vr::InspectVolumeFile(path);
  }
  catch (const vr::InputError &)
  {
  }
  return 0;
}
