// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrNiftiHeaderCheck_h
#define vrNiftiHeaderCheck_h

#include <cstddef>
#include <string>

/** The check of a whole NIfTI header before ITK's NIfTI reader acts on it. Not installed: an implementation detail of
 * the IO library. */
namespace vr::detail
{
/** Checks every field of the NIfTI header ITK 5.2 would read for \a path before ITK reads it, and throws
 * vr::InputError "<where>: NIfTI header field <name> ..." naming the first field at fault.
 *
 * The header file is the one ITK's NIfTI library picks (nifti_findhdrname: x.img reads x.hdr), decompressed when its
 * name ends in .gz, as the library does. Its layout and byte order are decided as the library decides them, not by
 * sizeof_hdr alone: the NIfTI magic at byte 344 makes a 348-byte NIfTI-1 header whatever sizeof_hdr says, and a
 * dim[0] of 1..7 (else sizeof_hdr) picks the byte order. Without that magic, a sizeof_hdr of 348 is an Analyze 7.5
 * header (its geometry fields are not NIfTI's and are not read) and 540 a NIfTI-2 header (which ITK 5.2 does not
 * read; checked all the same, for a reader that does).
 *
 * Checked: sizeof_hdr; the magic; dim[0] in 1..7, dim[1..dim[0]] >= 1, at most 2^32 voxels; a known datatype and a
 * bitpix that matches it; vox_offset finite, >= 0 and below 2^31; pixdim[0] finite, pixdim[1..dim[0]] finite, the
 * spatial ones > 0 and, in mm (xyzt_units), a plausible spacing (1e-6 to 1e6); scl_slope and scl_inter finite;
 * qform_code and sform_code in 0..5; quatern_b/c/d, qoffset_x/y/z and srow_x/y/z finite and within 1e7; with
 * qform_code > 0 a quaternion whose b, c, d have a norm <= 1; with sform_code > 0 an sform whose 3 x 3 part has
 * columns of a plausible length and is invertible (not flat). ITK 5.2 hands the sform to vnl's SVD, which aborts
 * the process on a non-finite matrix, so these are checked whichever of qform and sform ITK then prefers.
 * An ASCII NIfTI header (.nia, "<nifti_image") is refused. A file that is none of these is left to ITK. */
void
CheckNiftiHeader(const std::string & path, const std::string & where);

/** CheckNiftiHeader() on \a count header bytes already read (at least 348; 540 for NIfTI-2). */
void
CheckNiftiHeaderBytes(const unsigned char * bytes, std::size_t count, const std::string & where);
} // namespace vr::detail

#endif
