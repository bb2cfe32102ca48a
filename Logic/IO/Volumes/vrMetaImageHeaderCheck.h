// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrMetaImageHeaderCheck_h
#define vrMetaImageHeaderCheck_h

#include <cstddef>
#include <string>

/** The check of a whole MetaImage header (.mha, .mhd) before ITK's MetaIO parses it. Not installed: an implementation
 * detail of the IO library. */
namespace vr::detail
{
/** Walks the header of \a path record by record as MetaIO 5.2's MET_Read will (a name up to "=" or ":", then the value
 * after any run of "=", ":" and blanks) and throws vr::InputError "<where>: MetaImage header line N: ..." naming the
 * line and field at fault.
 *
 * MetaIO trusts the header: an NDims of -3 makes it read 2^64 numbers for the next array field (a hang), an NDims over
 * 10 overflows its fixed arrays, a numeric field short of values reads them from the next line, and a value it cannot
 * parse leaves its stream failed. So the accepted header is the subset on which MetaIO's reading and this walk agree:
 * every line "Name = value" in printable ASCII, at most 400 characters, its name ended by "=" (not ":"); each field at
 * most once; NDims a whole number from 1 to 4 before any field sized by it; every numeric field exactly as many plain
 * decimal numbers as MetaIO reads (NDims for DimSize, ElementSpacing, Offset and the like, NDims x NDims for
 * TransformMatrix, 4 for Color), all finite, whole and in range where MetaIO stores an integer (DimSize >= 1,
 * HeaderSize >= -1); ElementType one of MetaIO's type names; the header ending at ElementDataFile within 64 KiB. Fields
 * MetaIO does not know are kept as text by MetaIO and are accepted here when well formed.
 *
 * Returns the header's length in bytes: where MetaIO's stream stands after the ElementDataFile line, the first byte of
 * the voxels when they follow the header (LOCAL). */
std::size_t
CheckMetaImageHeader(const std::string & path, const std::string & where);

/** CheckMetaImageHeader() on \a count bytes of a file already read. */
std::size_t
CheckMetaImageHeaderBytes(const char * bytes, std::size_t count, const std::string & where);
} // namespace vr::detail

#endif
