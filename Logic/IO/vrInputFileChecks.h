// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrInputFileChecks_h
#define vrInputFileChecks_h

#include <cstdint>
#include <string>
#include <vector>

/** Checks every reader makes before a library opens an input. Not installed: an implementation detail of the IO
 * library. */
namespace vr::detail
{
/** What an input path names. */
enum class InputKind
{
  RegularFile,
  Folder
};

/** Checks that \a path names an existing regular file (or, with \a folderAllowed, a folder) and returns which.
 * A named pipe, a device or a socket is refused at once, because opening one to read may block forever (a FIFO
 * nobody writes to) or never end (/dev/zero). Throws vr::InputError "<role> <path>: ..." when it is missing, a
 * folder (unless allowed), not a regular file, or (a file) empty. */
InputKind
CheckInputPath(const std::string & path, const std::string & role, bool folderAllowed = false);

/** The size of the regular file \a path in bytes (0 when it cannot be read). */
std::uintmax_t
InputFileSize(const std::string & path);

/** The data files a detached image header names: MetaImage's "ElementDataFile = name" (.mhd) and NRRD's "data
 * file: name" (.nhdr), relative to the header's folder; LOCAL, LIST and printf-style patterns are skipped. Reads at
 * most the first 64 KiB of \a headerPath. */
std::vector<std::string>
DetachedDataFiles(const std::string & headerPath);

/** The deepest nesting of arrays and objects in the JSON text of \a path (outside strings), found by a scan that
 * needs no memory per level, so that a hostile document is measured before a parser recurses into it. Throws
 * vr::InputError "<role> <path>: cannot be opened" when it cannot be read. */
std::size_t
JSONNestingDepth(const std::string & path, const std::string & role);

/** Refuses an ITK ImageIO (by its class name) other than NRRD, NIfTI and MetaImage (and DICOM when \a dicomAllowed):
 * ITK picks a reader by content, so a PNG, JPEG, TIFF or BMP named like a volume would reach libraries whose error
 * handling aborts the process on a corrupt file (ITK 5.2's PNG reader: libpng's default handler calls abort). */
void
CheckImageIOIsOneWeRead(const std::string & ioClassName, const std::string & where, bool dicomAllowed);
} // namespace vr::detail

#endif
