// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrDICOMSeriesProcess_h
#define vrDICOMSeriesProcess_h

#include "vrImageTypes.h"

#include <cstddef>
#include <string>

/** Reading a DICOM series in a child process. Not installed: an implementation detail of the IO library. */
namespace vr::detail
{
/** Reads the DICOM series with the most files in \a folder as ReadVolume() does, in the helper vrReadDICOMSeries
 * (a child process), so that a corrupt file that makes GDCM abort or crash ends the child only. Debian's GDCM is
 * built with assertions, and reading one corrupt file is enough to abort.
 *
 * A corrupt file is reported by name and the whole series is refused (its other files are not read: a volume with
 * a slice missing would be wrong without a word). Throws vr::InputError "<where>: ..." naming the file and the signal,
 * or GDCM's and ITK's failure in one line; nothing from GDCM or ITK reaches the terminal.
 *
 * A helper that has not finished after DICOMSeriesTimeoutSeconds() is killed, and the read fails with a message naming
 * the folder (and the file it was reading, where it said so).
 *
 * The helper is found at $VR_DICOM_SERIES_READER when set, else beside the executable or shared library holding
 * this code, in ../libexec/VesselReformation from there (an install tree's bin/ or lib/VesselReformation/cli-modules/
 * three levels down), then in the build tree and the install prefix this library was built for. */
VolumeImageType::Pointer
ReadDICOMSeriesInChildProcess(const std::string & folder, const std::string & where);

/** How long the helper may run on a folder of \a fileCount files before it is killed: 60 s plus 0.25 s per file
 * (a 500-file series gets 185 s; the helper read a 500-slice series of VMTK's aorta in 0.4-0.6 s, measured with
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
