// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The NIfTI header check (issue 25): headers built here from the NIfTI library's own struct definitions (NIfTI-1
// from ITK's nifti1.h, NIfTI-2 from nifti2.h), in both byte orders, each field made bad in turn; plain, gzip and
// .hdr/.img files; the fuzzers' finds. A valid header must pass and ITK must read it as built.
#include "vrInputError.h"
#include "vrNiftiHeaderCheck.h"
#include "vrTestFiles.h"

#include "itkImageFileReader.h"
#include "itkNiftiImageIO.h"

#include "nifti1.h"
#include <nifti/nifti2.h>

#include <zlib.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace
{
/** CheckNiftiHeader()'s message for \a path, empty when it passes. */
std::string
CheckMessage(const std::string & path, const std::string & where)
{
  try
  {
    vr::detail::CheckNiftiHeader(path, where);
  }
  catch (const vr::InputError & error)
  {
    return error.what();
  }
  return std::string();
}

constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
constexpr double Infinity = std::numeric_limits<double>::infinity();

template<typename T>
void
Swap(T & value)
{
  unsigned char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  for (std::size_t k = 0; k < sizeof(T) / 2; ++k)
  {
    std::swap(bytes[k], bytes[sizeof(T) - 1 - k]);
  }
  std::memcpy(&value, bytes, sizeof(T));
}

/** The fields a test changes, in one form for both versions; written into either struct. */
struct Fields
{
  double SizeofHdr = 0; // 0: the version's own size
  double Dim[8] = { 3, 4, 5, 6, 1, 1, 1, 1 };
  int    Datatype = 16; // FLOAT32
  int    Bitpix = 32;
  double Pixdim[8] = { 1, 0.5, 0.75, 2.5, 0, 0, 0, 0 };
  double VoxOffset = 0; // 0: just after the header and its 4 extension bytes
  double SclSlope = 1;
  double SclInter = 0;
  int    QformCode = 1;
  int    SformCode = 1;
  double Quatern[3] = { 0, 0, 0 };
  double Qoffset[3] = { -10, 20, 5 };
  double Srow[3][4] = { { 0.5, 0, 0, -10 }, { 0, 0.75, 0, 20 }, { 0, 0, 2.5, 5 } };
  int    XyztUnits = 2; // mm
  char   Magic[8] = {}; // empty: the version's own
};

std::string
Nifti1Bytes(const Fields & f, bool swap)
{
  nifti_1_header h;
  std::memset(&h, 0, sizeof(h));
  h.sizeof_hdr = f.SizeofHdr == 0 ? 348 : static_cast<int>(f.SizeofHdr);
  for (int k = 0; k < 8; ++k)
  {
    h.dim[k] = static_cast<short>(f.Dim[k]);
    h.pixdim[k] = static_cast<float>(f.Pixdim[k]);
  }
  h.datatype = static_cast<short>(f.Datatype);
  h.bitpix = static_cast<short>(f.Bitpix);
  h.vox_offset = static_cast<float>(f.VoxOffset == 0 ? 352 : f.VoxOffset);
  h.scl_slope = static_cast<float>(f.SclSlope);
  h.scl_inter = static_cast<float>(f.SclInter);
  h.qform_code = static_cast<short>(f.QformCode);
  h.sform_code = static_cast<short>(f.SformCode);
  h.quatern_b = static_cast<float>(f.Quatern[0]);
  h.quatern_c = static_cast<float>(f.Quatern[1]);
  h.quatern_d = static_cast<float>(f.Quatern[2]);
  h.qoffset_x = static_cast<float>(f.Qoffset[0]);
  h.qoffset_y = static_cast<float>(f.Qoffset[1]);
  h.qoffset_z = static_cast<float>(f.Qoffset[2]);
  for (int c = 0; c < 4; ++c)
  {
    h.srow_x[c] = static_cast<float>(f.Srow[0][c]);
    h.srow_y[c] = static_cast<float>(f.Srow[1][c]);
    h.srow_z[c] = static_cast<float>(f.Srow[2][c]);
  }
  h.xyzt_units = static_cast<char>(f.XyztUnits);
  std::memcpy(h.magic, f.Magic[0] != 0 ? f.Magic : "n+1", 4);
  if (swap)
  {
    Swap(h.sizeof_hdr);
    for (int k = 0; k < 8; ++k)
    {
      Swap(h.dim[k]);
      Swap(h.pixdim[k]);
    }
    for (auto * value : { &h.datatype,
                          &h.bitpix,
                          &h.qform_code,
                          &h.sform_code,
                          &h.intent_code,
                          &h.slice_start,
                          &h.slice_end,
                          &h.session_error })
    {
      Swap(*value);
    }
    for (auto * value : { &h.vox_offset,
                          &h.scl_slope,
                          &h.scl_inter,
                          &h.quatern_b,
                          &h.quatern_c,
                          &h.quatern_d,
                          &h.qoffset_x,
                          &h.qoffset_y,
                          &h.qoffset_z,
                          &h.intent_p1,
                          &h.intent_p2,
                          &h.intent_p3,
                          &h.cal_max,
                          &h.cal_min,
                          &h.slice_duration,
                          &h.toffset })
    {
      Swap(*value);
    }
    for (int c = 0; c < 4; ++c)
    {
      Swap(h.srow_x[c]);
      Swap(h.srow_y[c]);
      Swap(h.srow_z[c]);
    }
  }
  return std::string(reinterpret_cast<const char *>(&h), sizeof(h));
}

std::string
Nifti2Bytes(const Fields & f, bool swap)
{
  nifti_2_header h;
  std::memset(&h, 0, sizeof(h));
  h.sizeof_hdr = f.SizeofHdr == 0 ? 540 : static_cast<int>(f.SizeofHdr);
  for (int k = 0; k < 8; ++k)
  {
    h.dim[k] = static_cast<int64_t>(f.Dim[k]);
    h.pixdim[k] = f.Pixdim[k];
  }
  h.datatype = static_cast<int16_t>(f.Datatype);
  h.bitpix = static_cast<int16_t>(f.Bitpix);
  h.vox_offset = static_cast<int64_t>(f.VoxOffset == 0 ? 544 : f.VoxOffset);
  h.scl_slope = f.SclSlope;
  h.scl_inter = f.SclInter;
  h.qform_code = f.QformCode;
  h.sform_code = f.SformCode;
  h.quatern_b = f.Quatern[0];
  h.quatern_c = f.Quatern[1];
  h.quatern_d = f.Quatern[2];
  h.qoffset_x = f.Qoffset[0];
  h.qoffset_y = f.Qoffset[1];
  h.qoffset_z = f.Qoffset[2];
  for (int c = 0; c < 4; ++c)
  {
    h.srow_x[c] = f.Srow[0][c];
    h.srow_y[c] = f.Srow[1][c];
    h.srow_z[c] = f.Srow[2][c];
  }
  h.xyzt_units = f.XyztUnits;
  std::memcpy(h.magic, f.Magic[0] != 0 ? f.Magic : "n+2\0\r\n\032\n", 8);
  if (swap)
  {
    Swap(h.sizeof_hdr);
    for (int k = 0; k < 8; ++k)
    {
      Swap(h.dim[k]);
      Swap(h.pixdim[k]);
    }
    Swap(h.datatype);
    Swap(h.bitpix);
    Swap(h.vox_offset);
    for (auto * value : { &h.scl_slope,
                          &h.scl_inter,
                          &h.quatern_b,
                          &h.quatern_c,
                          &h.quatern_d,
                          &h.qoffset_x,
                          &h.qoffset_y,
                          &h.qoffset_z,
                          &h.intent_p1,
                          &h.intent_p2,
                          &h.intent_p3,
                          &h.cal_max,
                          &h.cal_min,
                          &h.slice_duration,
                          &h.toffset })
    {
      Swap(*value);
    }
    for (auto * value : { &h.qform_code, &h.sform_code, &h.slice_code, &h.xyzt_units, &h.intent_code })
    {
      Swap(*value);
    }
    for (int c = 0; c < 4; ++c)
    {
      Swap(h.srow_x[c]);
      Swap(h.srow_y[c]);
      Swap(h.srow_z[c]);
    }
  }
  return std::string(reinterpret_cast<const char *>(&h), sizeof(h));
}

/** A header version and byte order. */
struct Layout
{
  const char * Name;
  bool         Version2;
  bool         Swapped;
};

const Layout Layouts[] = { { "NIfTI-1 native", false, false },
                           { "NIfTI-1 swapped", false, true },
                           { "NIfTI-2 native", true, false },
                           { "NIfTI-2 swapped", true, true } };

/** A .nii: the header, 4 extension bytes, 4 x 5 x 6 float voxels. */
std::string
NiiBytes(const Fields & fields, const Layout & layout)
{
  const std::string header =
    layout.Version2 ? Nifti2Bytes(fields, layout.Swapped) : Nifti1Bytes(fields, layout.Swapped);
  return header + std::string(4, '\0') + std::string(4 * 5 * 6 * 4, '\0');
}

/** The message CheckNiftiHeader() throws for \a fields written as a .nii, empty when it passes. */
std::string
MessageFor(const Fields & fields, const Layout & layout)
{
  vr::test::ScopedTemporaryFolder folder;
  const std::string               path = folder.File("volume.nii");
  vr::test::WriteTextFile(path, NiiBytes(fields, layout));
  return CheckMessage(path, "volume " + path);
}

struct Mutation
{
  const char *                  Field; // what the message must name
  std::function<void(Fields &)> Apply;
};

const std::vector<Mutation> &
Mutations()
{
  static const std::vector<Mutation> mutations = {
    { "dim[0]", [](Fields & f) { f.Dim[0] = 0; } },
    { "dim[0]", [](Fields & f) { f.Dim[0] = 8; } },
    { "dim[1]", [](Fields & f) { f.Dim[1] = -3; } },
    { "dim[3]", [](Fields & f) { f.Dim[3] = 0; } },
    { "2^32", [](Fields & f) { f.Dim[1] = f.Dim[2] = f.Dim[3] = 30000; } },
    { "datatype", [](Fields & f) { f.Datatype = 3; } },
    { "datatype", [](Fields & f) { f.Datatype = 0; } },
    { "bitpix", [](Fields & f) { f.Bitpix = 16; } },
    { "vox_offset", [](Fields & f) { f.VoxOffset = -16; } },
    { "pixdim[0]", [](Fields & f) { f.Pixdim[0] = NaN; } },
    { "pixdim[1]", [](Fields & f) { f.Pixdim[1] = -0.5; } },
    { "pixdim[2]", [](Fields & f) { f.Pixdim[2] = NaN; } },
    { "pixdim[3]", [](Fields & f) { f.Pixdim[3] = 0; } },
    { "pixdim[1]", [](Fields & f) { f.Pixdim[1] = 1e9; } },
    { "pixdim[1]",
      [](Fields & f)
      {
        f.XyztUnits = 1;
        f.Pixdim[1] = 5000;
      } }, // 5 km in metres
    { "pixdim[4]",
      [](Fields & f)
      {
        f.Dim[0] = 4;
        f.Pixdim[4] = Infinity;
      } },
    { "scl_slope", [](Fields & f) { f.SclSlope = Infinity; } },
    { "scl_inter", [](Fields & f) { f.SclInter = NaN; } },
    { "qform_code", [](Fields & f) { f.QformCode = 7; } },
    { "qform_code", [](Fields & f) { f.QformCode = -1; } },
    { "sform_code", [](Fields & f) { f.SformCode = 9; } },
    { "quatern_c", [](Fields & f) { f.Quatern[1] = NaN; } },
    { "quatern_b/c/d", [](Fields & f) { f.Quatern[0] = f.Quatern[1] = 0.9; } },
    { "qoffset_z", [](Fields & f) { f.Qoffset[2] = Infinity; } },
    { "qoffset_x", [](Fields & f) { f.Qoffset[0] = 1e30; } },
    { "srow_x[1]", [](Fields & f) { f.Srow[0][1] = NaN; } },
    { "srow_y[0]", [](Fields & f) { f.Srow[1][0] = -Infinity; } },
    { "srow_z[3]", [](Fields & f) { f.Srow[2][3] = 1e30; } },
    { "axis 2", [](Fields & f) { f.Srow[0][2] = f.Srow[1][2] = f.Srow[2][2] = 0; } },
    { "cannot be inverted",
      [](Fields & f)
      {
        for (int r = 0; r < 3; ++r)
        {
          f.Srow[r][2] = 5 * f.Srow[r][0];
        }
      } },
    // NaN in an unused field of a valid-looking header is still a corrupt header (the fuzzers' find, with sform 0).
    { "srow_x[0]",
      [](Fields & f)
      {
        f.SformCode = 0;
        f.Srow[0][0] = NaN;
      } },
  };
  return mutations;
}

class NiftiHeaderCheckTest : public ::testing::TestWithParam<Layout>
{
};

TEST_P(NiftiHeaderCheckTest, AValidHeaderPasses)
{
  EXPECT_EQ(MessageFor(Fields(), GetParam()), "");
  Fields oblique; // a rotation of 90 degrees about z in both transforms, with the sform's skew-free columns
  oblique.Quatern[2] = std::sqrt(0.5);
  oblique.Srow[0][0] = 0;
  oblique.Srow[0][1] = -0.75;
  oblique.Srow[1][0] = 0.5;
  oblique.Srow[1][1] = 0;
  EXPECT_EQ(MessageFor(oblique, GetParam()), "");
  Fields microns; // 500 x 750 x 2500 microns
  microns.XyztUnits = 3;
  microns.Pixdim[1] = 500;
  microns.Pixdim[2] = 750;
  microns.Pixdim[3] = 2500;
  EXPECT_EQ(MessageFor(microns, GetParam()), "");
}

TEST_P(NiftiHeaderCheckTest, EachBadFieldIsNamed)
{
  for (const Mutation & mutation : Mutations())
  {
    Fields fields;
    mutation.Apply(fields);
    const std::string message = MessageFor(fields, GetParam());
    EXPECT_NE(message.find(mutation.Field), std::string::npos)
      << GetParam().Name << ": expected a message naming " << mutation.Field << ", got \"" << message << "\"";
    EXPECT_NE(message.find("volume.nii"), std::string::npos) << message;
  }
}

TEST_P(NiftiHeaderCheckTest, AWrongMagicIsNamed)
{
  Fields fields;
  // The other version's magic: eight bytes for a NIfTI-2 header, four (with the NUL) for a NIfTI-1 one.
  if (GetParam().Version2)
  {
    std::memcpy(fields.Magic, "n+1\0\r\n\032\n", 8);
  }
  else
  {
    std::memcpy(fields.Magic, "n+2", 4);
  }
  const std::string message = MessageFor(fields, GetParam());
  EXPECT_NE(message.find("magic"), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(BothVersionsBothByteOrders,
                         NiftiHeaderCheckTest,
                         ::testing::ValuesIn(Layouts),
                         [](const ::testing::TestParamInfo<Layout> & info)
                         {
                           std::string name = info.param.Name;
                           name.erase(std::remove_if(name.begin(),
                                                     name.end(),
                                                     [](char c)
                                                     { return !std::isalnum(static_cast<unsigned char>(c)); }),
                                      name.end());
                           return name;
                         });

TEST(NiftiHeaderCheck, ITKReadsTheValidHeaderAsBuilt)
{
  // The check must not refuse what ITK reads right: the valid NIfTI-1 header, in both byte orders, read by ITK.
  for (const bool swapped : { false, true })
  {
    vr::test::ScopedTemporaryFolder folder;
    const std::string               path = folder.File("volume.nii");
    std::string                     bytes = NiiBytes(Fields(), { "", false, swapped });
    vr::test::WriteTextFile(path, bytes);
    EXPECT_EQ(CheckMessage(path, path), "");
    auto io = itk::NiftiImageIO::New();
    io->SetFileName(path);
    io->ReadImageInformation();
    EXPECT_EQ(io->GetDimensions(0), 4u);
    EXPECT_EQ(io->GetDimensions(2), 6u);
    EXPECT_DOUBLE_EQ(io->GetSpacing(1), 0.75);
    EXPECT_DOUBLE_EQ(io->GetSpacing(2), 2.5);
    // ITK's LPS origin from the RAS qoffset/srow (-10, 20, 5).
    EXPECT_DOUBLE_EQ(io->GetOrigin(0), 10.0);
    EXPECT_DOUBLE_EQ(io->GetOrigin(1), -20.0);
    EXPECT_DOUBLE_EQ(io->GetOrigin(2), 5.0);
  }
}

TEST(NiftiHeaderCheck, TheLibrarysLayoutRulesAreFollowed)
{
  const Layout nifti1{ "", false, false };
  // The NIfTI magic at byte 344 makes a NIfTI-1 header whatever sizeof_hdr says (the fuzzers' find): refused.
  Fields garbageSize;
  garbageSize.SizeofHdr = 1573212;
  garbageSize.Srow[0][1] = NaN;
  EXPECT_NE(MessageFor(garbageSize, nifti1).find("sizeof_hdr"), std::string::npos);
  // dim[0] picks the byte order: a valid dim[0] with a byte-swapped 348 is a wrong sizeof_hdr.
  Fields swappedSize;
  swappedSize.SizeofHdr = 0x5c010000;
  EXPECT_NE(MessageFor(swappedSize, nifti1).find("sizeof_hdr"), std::string::npos);
  // Analyze 7.5 (no magic): the NIfTI-only fields are not read, so NaN there passes; its dims are still checked.
  Fields analyze;
  std::memcpy(analyze.Magic, "\x01\x02\x03", 4);
  analyze.Srow[0][0] = NaN;
  EXPECT_EQ(MessageFor(analyze, nifti1), "");
  // Nor are its units (byte 123 is no xyzt_units there): a pixdim of 5000 is 5000 mm, not 5 km.
  analyze.XyztUnits = 1;
  analyze.Pixdim[1] = 5000;
  EXPECT_EQ(MessageFor(analyze, nifti1), "");
  analyze.Dim[2] = 0;
  EXPECT_NE(MessageFor(analyze, nifti1).find("dim[2]"), std::string::npos);
  // Neither NIfTI nor Analyze: left to ITK, which reads no such file.
  Fields neither = analyze;
  neither.SizeofHdr = 1000;
  EXPECT_EQ(MessageFor(neither, nifti1), "");
}

TEST(NiftiHeaderCheck, AnASCIIHeaderIsRefused)
{
  vr::test::ScopedTemporaryFolder folder;
  const std::string               path = folder.File("volume.nii");
  vr::test::WriteTextFile(path, "<nifti_image\n  ndim = '3'\n" + std::string(400, ' ') + "/>\n");
  EXPECT_NE(CheckMessage(path, path).find("ASCII"), std::string::npos);
}

TEST(NiftiHeaderCheck, GzipAndHeaderImagePairsAreChecked)
{
  vr::test::ScopedTemporaryFolder folder;
  Fields                          bad;
  bad.Srow[0][0] = NaN;
  for (const bool swapped : { false, true })
  {
    const std::string gz = folder.File(swapped ? "swapped.nii.gz" : "volume.nii.gz");
    for (const Fields & fields : { Fields(), bad })
    {
      gzFile file = gzopen(gz.c_str(), "wb");
      ASSERT_NE(file, nullptr);
      const std::string bytes = NiiBytes(fields, { "", false, swapped });
      gzwrite(file, bytes.data(), static_cast<unsigned>(bytes.size()));
      gzclose(file);
      const std::string message = CheckMessage(gz, gz);
      if (std::isnan(fields.Srow[0][0]))
      {
        EXPECT_NE(message.find("srow_x[0]"), std::string::npos) << message;
      }
      else
      {
        EXPECT_EQ(message, "");
      }
    }
  }
  // x.img is read with x.hdr (magic "ni1"): the header's name is in the message.
  Fields pair = bad;
  std::memcpy(pair.Magic, "ni1", 4);
  pair.VoxOffset = 0.0;
  std::string header = Nifti1Bytes(pair, false);
  float       zero = 0.0F;
  std::memcpy(&header[108], &zero, sizeof(zero)); // vox_offset 0: the voxels start the .img
  vr::test::WriteTextFile(folder.File("pair.hdr"), header);
  vr::test::WriteTextFile(folder.File("pair.img"), std::string(4 * 5 * 6 * 4, '\0'));
  const std::string image = folder.File("pair.img");
  const std::string message = CheckMessage(image, "volume " + image);
  EXPECT_NE(message.find("pair.hdr"), std::string::npos) << message;
  EXPECT_NE(message.find("srow_x[0]"), std::string::npos) << message;
}

TEST(NiftiHeaderCheck, TheFuzzersFindsAreRefusedByName)
{
  for (const char * name : { "nifti-nan-srow-abort.nii", "nifti-nan-srow-abort-2.nii" })
  {
    const std::string path = std::string(VR_FINDINGS_DIR) + "/" + name;
    const std::string message = CheckMessage(path, "volume " + path);
    EXPECT_NE(message.find(name), std::string::npos) << message;
    EXPECT_NE(message.find("NIfTI header field sizeof_hdr"), std::string::npos) << message;
  }
}
} // namespace
