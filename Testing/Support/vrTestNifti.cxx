// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrTestNifti.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace vr::test
{
namespace
{
template<typename T>
void
Put(std::vector<unsigned char> & bytes, std::size_t at, T value, bool bigEndian)
{
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (bigEndian)
  {
    std::reverse(raw, raw + sizeof(T));
  }
  std::memcpy(bytes.data() + at, raw, sizeof(T));
}
} // namespace

std::vector<unsigned char>
Nifti1Header(const itk::Size<3> & size,
             short                datatype,
             short                bitpix,
             const double         spacing[3],
             float                slope,
             float                intercept,
             bool                 bigEndian)
{
  std::vector<unsigned char> bytes(352, 0);
  Put<std::int32_t>(bytes, 0, 348, bigEndian); // sizeof_hdr
  const std::int16_t dims[8] = { 3,
                                 static_cast<std::int16_t>(size[0]),
                                 static_cast<std::int16_t>(size[1]),
                                 static_cast<std::int16_t>(size[2]),
                                 1,
                                 1,
                                 1,
                                 1 };
  for (int k = 0; k < 8; ++k)
  {
    Put<std::int16_t>(bytes, 40 + 2 * k, dims[k], bigEndian);
  }
  Put<std::int16_t>(bytes, 70, datatype, bigEndian);
  Put<std::int16_t>(bytes, 72, bitpix, bigEndian);
  const float pixdim[8] = { 1.0f,
                            static_cast<float>(spacing[0]),
                            static_cast<float>(spacing[1]),
                            static_cast<float>(spacing[2]),
                            1.0f,
                            1.0f,
                            1.0f,
                            1.0f };
  for (int k = 0; k < 8; ++k)
  {
    Put<float>(bytes, 76 + 4 * k, pixdim[k], bigEndian);
  }
  Put<float>(bytes, 108, 352.0f, bigEndian); // vox_offset
  Put<float>(bytes, 112, slope, bigEndian);  // scl_slope
  Put<float>(bytes, 116, intercept, bigEndian);
  bytes[123] = 2;                              // xyzt_units: millimetres
  Put<std::int16_t>(bytes, 252, 1, bigEndian); // qform_code: scanner
  Put<float>(bytes, 268, -10.0f, bigEndian);   // qoffset_x
  Put<float>(bytes, 272, 20.0f, bigEndian);    // qoffset_y
  Put<float>(bytes, 276, 30.0f, bigEndian);    // qoffset_z
  std::memcpy(bytes.data() + 344, "n+1\0", 4);
  return bytes;
}
} // namespace vr::test
