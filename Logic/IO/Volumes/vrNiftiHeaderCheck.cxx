// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrNiftiHeaderCheck.h"

#include "vrInputError.h"

// ITK's own NIfTI library: the header file it reads is the one checked (nifti_findhdrname, nifti_is_gzfile).
#include "nifti1_io.h"

#include <zlib.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <memory>
#include <sstream>

namespace vr::detail
{
namespace
{
constexpr std::size_t Nifti1Size = 348;
constexpr std::size_t Nifti2Size = 540;
/** Geometry beyond this (mm, or the file's units) is a corrupt header, and keeps vnl's SVD away from overflow. */
constexpr double LargestGeometryValue = 1e7;
constexpr double SmallestSpacing = 1e-6; // mm
constexpr double LargestSpacing = 1e6;   // mm
constexpr double MostVoxels = 4294967296.0;

/** Reads fixed-size values from the header bytes in the byte order the header was found in. */
class HeaderBytes
{
public:
  HeaderBytes(const unsigned char * bytes, bool swap)
    : m_Bytes(bytes)
    , m_Swap(swap)
  {
  }

  template<typename T>
  T
  Get(std::size_t offset) const
  {
    unsigned char copy[sizeof(T)];
    std::memcpy(copy, m_Bytes + offset, sizeof(T));
    if (m_Swap)
    {
      for (std::size_t k = 0; k < sizeof(T) / 2; ++k)
      {
        std::swap(copy[k], copy[sizeof(T) - 1 - k]);
      }
    }
    T value;
    std::memcpy(&value, copy, sizeof(T));
    return value;
  }

private:
  const unsigned char * m_Bytes;
  bool                  m_Swap;
};

/** The fields that matter, widened to one representation for both layouts. */
struct Header
{
  bool                                 IsNifti = false; // false: Analyze 7.5 (no magic)
  bool                                 IsNifti2Layout = false;
  std::int64_t                         Dim[8] = {};
  int                                  Datatype = 0;
  int                                  Bitpix = 0;
  double                               Pixdim[8] = {};
  double                               VoxOffset = 0.0;
  double                               SclSlope = 0.0;
  double                               SclInter = 0.0;
  int                                  XyztUnits = 0;
  int                                  QformCode = 0;
  int                                  SformCode = 0;
  double                               Quatern[3] = {};
  double                               Qoffset[3] = {};
  std::array<std::array<double, 4>, 3> Srow = {};
};

/** A number as a message shows it: "nan", "inf", "1e+30", "2.5". */
std::string
Text(double value)
{
  std::ostringstream text;
  text << value;
  return text.str();
}

/** The magic as printable text: "n+1", "ni1", or escaped bytes. */
std::string
MagicText(const unsigned char * magic, std::size_t count)
{
  std::string text;
  for (std::size_t k = 0; k < count && magic[k] != 0; ++k)
  {
    if (magic[k] >= 32 && magic[k] < 127)
    {
      text += static_cast<char>(magic[k]);
    }
    else
    {
      char escaped[8];
      std::snprintf(escaped, sizeof(escaped), "\\x%02x", magic[k]);
      text += escaped;
    }
  }
  return text;
}

/** The NIfTI library's NIFTI_VERSION test on the 4 magic bytes at \a magic: 'n', 'i' or '+', a digit 1-9, NUL. */
int
NiftiVersion(const unsigned char * magic)
{
  return magic[0] == 'n' && magic[3] == '\0' && (magic[1] == 'i' || magic[1] == '+') && magic[2] >= '1' &&
             magic[2] <= '9'
           ? magic[2] - '0'
           : 0;
}

/** Bytes per voxel of a NIfTI datatype (the NIfTI library's table), 0 for an unknown one. */
int
DatatypeBytes(int datatype)
{
  switch (datatype)
  {
    case 2:   // UINT8
    case 256: // INT8
      return 1;
    case 4:   // INT16
    case 512: // UINT16
      return 2;
    case 128: // RGB24
      return 3;
    case 8:    // INT32
    case 768:  // UINT32
    case 16:   // FLOAT32
    case 2304: // RGBA32
      return 4;
    case 32:   // COMPLEX64
    case 64:   // FLOAT64
    case 1024: // INT64
    case 1280: // UINT64
      return 8;
    case 1536: // FLOAT128
    case 1792: // COMPLEX128
      return 16;
    case 2048: // COMPLEX256
      return 32;
    default:
      return 0;
  }
}

/** NIfTI-1 layout (also Analyze 7.5's for the fields read here), with the byte order the library would pick. */
Header
ReadNifti1Layout(const unsigned char * bytes, const std::string & where)
{
  // The library's need_nhdr_swap: dim[0] decides when it is not 0, else sizeof_hdr does.
  std::int16_t dim0 = HeaderBytes(bytes, false).Get<std::int16_t>(40);
  bool         swap = false;
  if (dim0 != 0)
  {
    swap = !(dim0 >= 1 && dim0 <= 7);
  }
  else
  {
    swap = HeaderBytes(bytes, false).Get<std::int32_t>(0) != static_cast<std::int32_t>(Nifti1Size);
  }
  const HeaderBytes  field(bytes, swap);
  const std::int32_t sizeofHdr = field.Get<std::int32_t>(0);
  Header             header;
  header.IsNifti = NiftiVersion(bytes + 344) != 0;
  header.IsNifti2Layout = false;
  for (int k = 0; k < 8; ++k)
  {
    header.Dim[k] = field.Get<std::int16_t>(40 + 2 * k);
  }
  if (!(header.Dim[0] >= 1 && header.Dim[0] <= 7))
  {
    throw InputError(where + ": NIfTI header field dim[0] holds " + std::to_string(header.Dim[0]) +
                     " in either byte order; it must be 1 to 7 (the number of axes)");
  }
  if (sizeofHdr != static_cast<std::int32_t>(Nifti1Size))
  {
    throw InputError(where + ": NIfTI header field sizeof_hdr holds " + std::to_string(sizeofHdr) +
                     " (in the byte order dim[0] gives); a NIfTI-1 header says 348");
  }
  if (header.IsNifti && !(bytes[344] == 'n' && (bytes[345] == '+' || bytes[345] == 'i') && bytes[346] == '1'))
  {
    throw InputError(where + ": NIfTI header field magic holds \"" + MagicText(bytes + 344, 4) +
                     "\" in a 348-byte NIfTI-1 header; \"n+1\" or \"ni1\" is expected");
  }
  header.Datatype = field.Get<std::int16_t>(70);
  header.Bitpix = field.Get<std::int16_t>(72);
  for (int k = 0; k < 8; ++k)
  {
    header.Pixdim[k] = field.Get<float>(76 + 4 * k);
  }
  header.VoxOffset = field.Get<float>(108);
  header.SclSlope = field.Get<float>(112);
  header.SclInter = field.Get<float>(116);
  header.XyztUnits = bytes[123];
  header.QformCode = field.Get<std::int16_t>(252);
  header.SformCode = field.Get<std::int16_t>(254);
  for (int k = 0; k < 3; ++k)
  {
    header.Quatern[k] = field.Get<float>(256 + 4 * k);
    header.Qoffset[k] = field.Get<float>(268 + 4 * k);
    for (int c = 0; c < 4; ++c)
    {
      header.Srow[k][c] = field.Get<float>(280 + 16 * k + 4 * c);
    }
  }
  return header;
}

/** NIfTI-2 layout (540 bytes, 64-bit fields); the byte order is the one that makes sizeof_hdr 540. */
Header
ReadNifti2Layout(const unsigned char * bytes, const std::string & where)
{
  const bool        swap = HeaderBytes(bytes, false).Get<std::int32_t>(0) != static_cast<std::int32_t>(Nifti2Size);
  const HeaderBytes field(bytes, swap);
  Header            header;
  header.IsNifti = true;
  header.IsNifti2Layout = true;
  if (!(bytes[4] == 'n' && (bytes[5] == '+' || bytes[5] == 'i') && bytes[6] == '2' && bytes[7] == '\0'))
  {
    throw InputError(where + ": NIfTI header field magic holds \"" + MagicText(bytes + 4, 4) +
                     "\" in a 540-byte NIfTI-2 header; \"n+2\" or \"ni2\" is expected");
  }
  for (int k = 0; k < 8; ++k)
  {
    header.Dim[k] = field.Get<std::int64_t>(16 + 8 * k);
  }
  if (!(header.Dim[0] >= 1 && header.Dim[0] <= 7))
  {
    throw InputError(where + ": NIfTI header field dim[0] holds " + std::to_string(header.Dim[0]) +
                     "; it must be 1 to 7 (the number of axes)");
  }
  header.Datatype = field.Get<std::int16_t>(12);
  header.Bitpix = field.Get<std::int16_t>(14);
  for (int k = 0; k < 8; ++k)
  {
    header.Pixdim[k] = field.Get<double>(104 + 8 * k);
  }
  header.VoxOffset = static_cast<double>(field.Get<std::int64_t>(168));
  header.SclSlope = field.Get<double>(176);
  header.SclInter = field.Get<double>(184);
  header.QformCode = field.Get<std::int32_t>(344);
  header.SformCode = field.Get<std::int32_t>(348);
  for (int k = 0; k < 3; ++k)
  {
    header.Quatern[k] = field.Get<double>(352 + 8 * k);
    header.Qoffset[k] = field.Get<double>(376 + 8 * k);
    for (int c = 0; c < 4; ++c)
    {
      header.Srow[k][c] = field.Get<double>(400 + 32 * k + 8 * c);
    }
  }
  header.XyztUnits = field.Get<std::int32_t>(500);
  return header;
}

/** mm per unit of pixdim (xyzt_units' spatial bits), as ITK 5.2 scales the spacing: metres, mm, microns, else mm. */
double
SpatialUnitInMillimetres(int xyztUnits)
{
  switch (xyztUnits & 0x07)
  {
    case 1:
      return 1e3;
    case 3:
      return 1e-3;
    default:
      return 1.0;
  }
}

void
RequireFinite(double value, const std::string & name, const std::string & where)
{
  if (!std::isfinite(value) || std::abs(value) > LargestGeometryValue)
  {
    throw InputError(where + ": NIfTI header field " + name + " holds " + Text(value) +
                     "; a geometry value must be a finite number within 1e7");
  }
}

void
CheckFields(const Header & header, const std::string & where)
{
  const auto axes = static_cast<int>(header.Dim[0]);
  double     voxels = 1.0;
  for (int k = 1; k <= axes; ++k)
  {
    if (header.Dim[k] < 1)
    {
      throw InputError(where + ": NIfTI header field dim[" + std::to_string(k) + "] holds " +
                       std::to_string(header.Dim[k]) + "; every axis must have at least one voxel");
    }
    voxels *= static_cast<double>(header.Dim[k]);
  }
  if (voxels > MostVoxels)
  {
    std::string sizes;
    for (int k = 1; k <= axes; ++k)
    {
      sizes += (k == 1 ? "" : " x ") + std::to_string(header.Dim[k]);
    }
    throw InputError(where + ": NIfTI header field dim holds " + sizes +
                     " voxels, more than 2^32 in all; is the header corrupt?");
  }
  const int bytesPerVoxel = DatatypeBytes(header.Datatype);
  if (bytesPerVoxel == 0)
  {
    throw InputError(where + ": NIfTI header field datatype holds " + std::to_string(header.Datatype) +
                     ", which is no NIfTI data type");
  }
  if (header.Bitpix != 8 * bytesPerVoxel)
  {
    throw InputError(where + ": NIfTI header field bitpix holds " + std::to_string(header.Bitpix) + "; datatype " +
                     std::to_string(header.Datatype) + " has " + std::to_string(8 * bytesPerVoxel) + " bits per voxel");
  }
  if (!std::isfinite(header.VoxOffset) || header.VoxOffset < 0.0 || header.VoxOffset >= 2147483648.0)
  {
    throw InputError(where + ": NIfTI header field vox_offset holds " + Text(header.VoxOffset) +
                     "; it must be a byte offset from 0 to 2^31");
  }
  if (!std::isfinite(header.Pixdim[0]))
  {
    throw InputError(where + ": NIfTI header field pixdim[0] (qfac) holds " + Text(header.Pixdim[0]) +
                     "; it must be a finite number");
  }
  // The library reads xyzt_units from NIfTI headers only (Analyze 7.5 has no such field there): mm otherwise.
  const double unit = header.IsNifti ? SpatialUnitInMillimetres(header.XyztUnits) : 1.0;
  for (int k = 1; k <= axes; ++k)
  {
    const double value = header.Pixdim[k];
    const bool   spatial = k <= 3;
    if (!std::isfinite(value) || (spatial && !(value * unit >= SmallestSpacing && value * unit <= LargestSpacing)))
    {
      throw InputError(where + ": NIfTI header field pixdim[" + std::to_string(k) + "] holds " + Text(value) +
                       (spatial ? std::string(unit == 1.0 ? "" : " (in the units xyzt_units gives)") +
                                    "; a voxel spacing must be a finite number from 1e-6 to 1e6 mm"
                                : std::string("; it must be a finite number")));
    }
  }
  if (!header.IsNifti)
  {
    return; // Analyze 7.5: the fields below are NIfTI's, and the library does not read them
  }
  if (!std::isfinite(header.SclSlope) || !std::isfinite(header.SclInter))
  {
    throw InputError(where + ": NIfTI header field " +
                     (std::isfinite(header.SclSlope) ? "scl_inter holds " + Text(header.SclInter)
                                                     : "scl_slope holds " + Text(header.SclSlope)) +
                     "; the voxel scaling must be finite");
  }
  for (const auto & [name, code] : { std::pair<const char *, int>{ "qform_code", header.QformCode },
                                     std::pair<const char *, int>{ "sform_code", header.SformCode } })
  {
    if (code < 0 || code > 5)
    {
      throw InputError(where + ": NIfTI header field " + name + " holds " + std::to_string(code) +
                       "; a NIfTI transform code is 0 to 5");
    }
  }
  static const char * const quaternNames[] = { "quatern_b", "quatern_c", "quatern_d" };
  static const char * const qoffsetNames[] = { "qoffset_x", "qoffset_y", "qoffset_z" };
  static const char * const srowNames[] = { "srow_x", "srow_y", "srow_z" };
  for (int k = 0; k < 3; ++k)
  {
    RequireFinite(header.Quatern[k], quaternNames[k], where);
    RequireFinite(header.Qoffset[k], qoffsetNames[k], where);
    for (int c = 0; c < 4; ++c)
    {
      RequireFinite(header.Srow[k][c], std::string(srowNames[k]) + "[" + std::to_string(c) + "]", where);
    }
  }
  if (header.QformCode > 0)
  {
    const double norm2 = header.Quatern[0] * header.Quatern[0] + header.Quatern[1] * header.Quatern[1] +
                         header.Quatern[2] * header.Quatern[2];
    if (norm2 > 1.0 + 1e-3)
    {
      throw InputError(where + ": NIfTI header fields quatern_b/c/d hold (" + Text(header.Quatern[0]) + ", " +
                       Text(header.Quatern[1]) + ", " + Text(header.Quatern[2]) +
                       "), longer than 1; they are not a rotation quaternion's");
    }
  }
  if (header.SformCode > 0)
  {
    // The sform's columns are the voxel axes in mm: each of a plausible length, and together not flat.
    double length[3];
    for (int c = 0; c < 3; ++c)
    {
      length[c] = std::sqrt(header.Srow[0][c] * header.Srow[0][c] + header.Srow[1][c] * header.Srow[1][c] +
                            header.Srow[2][c] * header.Srow[2][c]);
      if (!(length[c] * unit >= SmallestSpacing && length[c] * unit <= LargestSpacing))
      {
        throw InputError(where + ": NIfTI header fields srow_x/y/z give voxel axis " + std::to_string(c) +
                         " a length of " + Text(length[c]) +
                         "; with sform_code > 0 each must be a spacing from 1e-6 to 1e6 mm");
      }
    }
    const auto & s = header.Srow;
    const double determinant = s[0][0] * (s[1][1] * s[2][2] - s[1][2] * s[2][1]) -
                               s[0][1] * (s[1][0] * s[2][2] - s[1][2] * s[2][0]) +
                               s[0][2] * (s[1][0] * s[2][1] - s[1][1] * s[2][0]);
    // |det| / (product of the column lengths) is the volume of the unit cell the axes span, 1 when orthogonal.
    if (!(std::abs(determinant) >= 1e-3 * length[0] * length[1] * length[2]))
    {
      throw InputError(where + ": NIfTI header fields srow_x/y/z hold a transform that cannot be inverted (its voxel "
                               "axes lie in a plane or a line)");
    }
  }
}
} // namespace

void
CheckNiftiHeaderBytes(const unsigned char * bytes, std::size_t count, const std::string & where)
{
  if (count >= 12 && std::memcmp(bytes, "<nifti_image", 12) == 0)
  {
    throw InputError(where + ": is an ASCII NIfTI header (<nifti_image ...>), which is not read; save it as .nii");
  }
  if (count < Nifti1Size)
  {
    return; // too short for any header: the library refuses it itself
  }
  const std::int32_t size = HeaderBytes(bytes, false).Get<std::int32_t>(0);
  const std::int32_t swappedSize = HeaderBytes(bytes, true).Get<std::int32_t>(0);
  Header             header;
  // The library's own test first: its magic at byte 344 makes a NIfTI-1 header whatever sizeof_hdr holds.
  if (NiftiVersion(bytes + 344) != 0 || size == static_cast<std::int32_t>(Nifti1Size) ||
      swappedSize == static_cast<std::int32_t>(Nifti1Size))
  {
    header = ReadNifti1Layout(bytes, where);
  }
  else if (size == static_cast<std::int32_t>(Nifti2Size) || swappedSize == static_cast<std::int32_t>(Nifti2Size))
  {
    if (count < Nifti2Size)
    {
      throw InputError(where + ": NIfTI header field sizeof_hdr says 540 (NIfTI-2), but the file holds only " +
                       std::to_string(count) + " bytes");
    }
    header = ReadNifti2Layout(bytes, where);
  }
  else
  {
    return; // not a NIfTI or Analyze header: no NIfTI reader takes it
  }
  CheckFields(header, where);
}

void
CheckNiftiHeader(const std::string & path, const std::string & where)
{
  // The header file the library itself reads: x.img (or a name without extension) reads x.hdr or x.nii.
  const std::unique_ptr<char, decltype(&std::free)> found(nifti_findhdrname(path.c_str()), &std::free);
  if (!found)
  {
    return; // the library finds no header; ITK's reader says so
  }
  const std::string headerPath = found.get();
  const std::string named = headerPath == path ? where : where + ": its header " + headerPath;
  unsigned char     bytes[Nifti2Size] = {};
  std::size_t       count = 0;
  if (nifti_is_gzfile(headerPath.c_str()))
  {
    gzFile file = gzopen(headerPath.c_str(), "rb");
    if (file == nullptr)
    {
      return;
    }
    const int read = gzread(file, bytes, sizeof(bytes));
    gzclose(file);
    count = read > 0 ? static_cast<std::size_t>(read) : 0;
  }
  else
  {
    std::ifstream file(headerPath, std::ios::binary);
    file.read(reinterpret_cast<char *>(bytes), sizeof(bytes));
    count = static_cast<std::size_t>(file.gcount());
  }
  CheckNiftiHeaderBytes(bytes, count, named);
}
} // namespace vr::detail
