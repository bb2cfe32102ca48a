// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrDICOMSeriesProcess_h
#define vrDICOMSeriesProcess_h

#include "vrStoredVolume.h"

#include <cstddef>
#include <string>
#include <vector>

/** Reading a DICOM series in a child process. Not installed: an implementation detail of the IO library. */
namespace vr::detail
{
/** A series as the reader process handed it over. */
struct DICOMSeriesRead
{
  /** In the series' stored type with its rescale, or float intensities where the files' rescales differ or a gap is
   * interpolated (docs/dicom-series.md "Values"); its buffer is the mapping the reader process wrote the voxels into.
   * The first file's patient and study in the image's dictionary (vr::DICOMAttribute keys). */
  StoredVolume Volume;
  /** What the volume's making changed that the user must know (a gap interpolated, a duplicate left out). */
  std::vector<std::string> Warnings;
  /** What was skipped and changes nothing (files that are not DICOM images). */
  std::vector<std::string> Notes;
};

/** Reads one DICOM series of \a folder as docs/dicom-series.md says, in the helper vrReadDICOMSeries (a child
 * process), so that a corrupt file that makes GDCM abort or crash ends the child only. Debian's GDCM is built with
 * assertions, and reading one corrupt file is enough to abort.
 *
 * \param series which series when the folder holds several: its number in the list or its Series Instance UID; empty
 * when the folder must hold one.
 * \param where how messages name the folder ("volume folder /data/ct").
 * Throws vr::DICOMSeriesChoiceRequired listing the series when the folder holds several and \a series chooses none of
 * them; vr::InputError "<where>: ..." naming the file and the attribute (or the signal GDCM died of) for a series that
 * is refused; nothing from GDCM or ITK reaches the terminal.
 *
 * A helper that has not finished after DICOMSeriesTimeoutSeconds() is killed, and the read fails with a message naming
 * the folder (and the file it was reading, where it said so).
 *
 * The helper is found at $VR_DICOM_SERIES_READER when set, else beside the executable or shared library holding
 * this code, in ../libexec/VesselReformation from there (an install tree's bin/ or lib/VesselReformation/cli-modules/
 * three levels down), then in the build tree and the install prefix this library was built for. */
DICOMSeriesRead
ReadDICOMSeriesInChildProcess(const std::string & folder, const std::string & series, const std::string & where);

/** How long the helper may run on a folder of \a fileCount files before it is killed: 60 s plus 0.25 s per file
 * (a 500-file series gets 185 s; the helper reads a 500-slice series of VMTK's aorta in under a second, measured with
 * WriteDICOMSeries --time-read, so only a hang or a stalled disk meets the bound).
 * $VR_DICOM_SERIES_TIMEOUT (seconds, a positive number) replaces it, for slow disks and for tests; any other value
 * of it is a vr::InputError naming the variable. */
double
DICOMSeriesTimeoutSeconds(std::size_t fileCount);

/** The helper's path as ReadDICOMSeriesInChildProcess() finds it; empty when there is none. */
std::string
DICOMSeriesReaderPath();
} // namespace vr::detail

#endif
