// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Structure-aware fuzz harness: NIfTI-1 and NIfTI-2 single files (.nii) read through vr::ReadVolume, as the modules
// read a volume (our whole-header check, ITK's NIfTI reader, our checks of the geometry, then the voxels). Its
// custom mutator sets one binary header field at a time (dims, datatype, bitpix, pixdim, vox_offset, the qform and
// sform codes, the quaternion, srow, ...) to a value that has broken readers before: NaN, an infinity, 0, -1, a
// denormal, the type's extremes, a neighbour of the value there; in the file's own byte order. A quarter of the
// mutations are libFuzzer's byte-level ones (lengths, truncation, the data). Any input must end in a volume or a
// vr::InputError.
#include "vrFuzzFieldMutation.h"
#include "vrFuzzSupport.h"

#include <cstring>
#include <iterator>

namespace
{
using vr::fuzz::Field;
using vr::fuzz::FieldType;

// nifti1.h: the 348-byte NIfTI-1 header; offsets in bytes.
const Field Nifti1Fields[] = {
  { 0, FieldType::Int32, 1 },      // sizeof_hdr
  { 39, FieldType::Int8, 1 },      // dim_info
  { 40, FieldType::Int16, 8 },     // dim[8]
  { 56, FieldType::Float32, 3 },   // intent_p1..p3
  { 68, FieldType::Int16, 1 },     // intent_code
  { 70, FieldType::Int16, 1 },     // datatype
  { 72, FieldType::Int16, 1 },     // bitpix
  { 74, FieldType::Int16, 1 },     // slice_start
  { 76, FieldType::Float32, 8 },   // pixdim[8]
  { 108, FieldType::Float32, 1 },  // vox_offset
  { 112, FieldType::Float32, 2 },  // scl_slope, scl_inter
  { 120, FieldType::Int16, 1 },    // slice_end
  { 122, FieldType::Int8, 2 },     // slice_code, xyzt_units
  { 124, FieldType::Float32, 6 },  // cal_max, cal_min, slice_duration, toffset, glmax, glmin
  { 252, FieldType::Int16, 2 },    // qform_code, sform_code
  { 256, FieldType::Float32, 6 },  // quatern_b/c/d, qoffset_x/y/z
  { 280, FieldType::Float32, 12 }, // srow_x, srow_y, srow_z
  { 344, FieldType::Int8, 4 },     // magic "n+1\0"
};

// nifti2.h: the 540-byte NIfTI-2 header.
const Field Nifti2Fields[] = {
  { 0, FieldType::Int32, 1 },      // sizeof_hdr
  { 4, FieldType::Int8, 8 },       // magic "n+2\0\r\n\032\n"
  { 12, FieldType::Int16, 2 },     // datatype, bitpix
  { 16, FieldType::Int64, 8 },     // dim[8]
  { 80, FieldType::Float64, 3 },   // intent_p1..p3
  { 104, FieldType::Float64, 8 },  // pixdim[8]
  { 168, FieldType::Int64, 1 },    // vox_offset
  { 176, FieldType::Float64, 6 },  // scl_slope, scl_inter, cal_max, cal_min, slice_duration, toffset
  { 224, FieldType::Int64, 2 },    // slice_start, slice_end
  { 344, FieldType::Int32, 2 },    // qform_code, sform_code
  { 352, FieldType::Float64, 6 },  // quatern_b/c/d, qoffset_x/y/z
  { 400, FieldType::Float64, 12 }, // srow_x, srow_y, srow_z
  { 496, FieldType::Int32, 3 },    // slice_code, xyzt_units, intent_code
  { 524, FieldType::Int8, 1 },     // dim_info
};

/** The header's byte order from sizeof_hdr (348 or 540 either way round); false when it is neither. */
bool
HeaderLayout(const std::uint8_t * data, std::size_t size, bool & nifti2, bool & swapped)
{
  if (size < 348)
  {
    return false;
  }
  std::uint32_t value = 0;
  std::memcpy(&value, data, 4);
  const std::uint32_t reversed = __builtin_bswap32(value);
  nifti2 = value == 540 || reversed == 540;
  swapped = reversed == 348 || reversed == 540;
  return (value == 348 || reversed == 348 || nifti2) && (!nifti2 || size >= 540);
}
} // namespace

extern "C" std::size_t
LLVMFuzzerCustomMutator(std::uint8_t * data, std::size_t size, std::size_t maxSize, unsigned int seed)
{
  vr::fuzz::Random random(seed);
  bool             nifti2 = false;
  bool             swapped = false;
  if (random.Below(4) == 0 || !HeaderLayout(data, size, nifti2, swapped))
  {
    return LLVMFuzzerMutate(data, size, maxSize);
  }
  if (nifti2)
  {
    vr::fuzz::MutateField(data, Nifti2Fields, std::size(Nifti2Fields), swapped, random);
  }
  else
  {
    vr::fuzz::MutateField(data, Nifti1Fields, std::size(Nifti1Fields), swapped, random);
  }
  return size;
}

extern "C" int
LLVMFuzzerTestOneInput(const std::uint8_t * data, std::size_t size)
{
  vr::fuzz::ReadVolumeOfBoundedSize(vr::fuzz::WriteInput(data, size, ".nii"));
  return 0;
}
