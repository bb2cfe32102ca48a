// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The first look at a DICOM folder, file by file with GDCM (up to the pixel data): which entries are DICOM images and
// their attributes, and which are skipped (sub-folders, empty files, files that are not DICOM, DICOMDIRs, DICOM files
// that hold no image). Internal (namespace vr::detail): the DICOM reader process only, where GDCM may abort.
#ifndef vrDICOMFolderExamination_h
#define vrDICOMFolderExamination_h

#include "vrDICOMFileAttributes.h"

#include <functional>
#include <string>
#include <vector>

namespace vr::detail
{
struct DICOMFolderExamination
{
  /** The files that hold a DICOM image (Rows or Columns present; pixel data not looked at yet), by name. */
  std::vector<DICOMFileAttributes> Images;
  /** What was skipped, by path. */
  std::vector<std::string> SubFolders;
  std::vector<std::string> EmptyFiles;
  std::vector<std::string> NotDICOM;
  std::vector<std::string> DICOMDIRs;
  std::vector<std::string> NotImages;
  /** Why the folder is not read: a file that says it is DICOM (the "DICM" marker, or a DICOM preamble of zeros) and
   * that GDCM cannot parse, named. Empty otherwise. */
  std::string Refusal;
};

/** Examines the entries of \a folder in their names' order. \a beforeReading(path) is called before GDCM opens each
 * file, so that a file GDCM dies on is known by whoever watches. */
DICOMFolderExamination
ExamineDICOMFolder(const std::string & folder, const std::function<void(const std::string &)> & beforeReading);

/** What was skipped, for the user: "3 of the folder's entries were not read: 1 sub-folder (...), 2 files that are not
 * DICOM (...)"; the first three names of each kind. Empty when nothing was skipped. */
std::string
SkippedEntriesNote(const DICOMFolderExamination & examination);
} // namespace vr::detail

#endif
