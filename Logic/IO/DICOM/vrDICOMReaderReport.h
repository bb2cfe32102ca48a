// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// What the DICOM reader process tells its caller besides the volume, one line each in its report file, written as it
// goes (a line is on disk before GDCM opens the next file, so that a crash is named). The caller
// (vrDICOMSeriesProcess.cxx) reads the lines after the process has ended:
//   file <path>                 GDCM is about to read this file
//   step <examine|decode|write> what the process does next (when it is no file's reading)
//   warning <text>              the volume differs from the files in a way the user must know (a gap interpolated)
//   note <text>                 what was skipped (files that are not DICOM images)
//   series <fields>             one series of the folder (DICOMSeriesSummary, tab-separated), before "error choose"
//   identity <key>\t<value>     the patient and study of the series' first file (vr::DICOMAttribute keys)
//   error <kind>                the end: message, choose (several series), choice (a choice that names none), none,
//                               write; the lines after it say why
//   done <slices>               the end: the volume is handed over
// Internal (namespace vr::detail): the reader process and its caller.
#ifndef vrDICOMReaderReport_h
#define vrDICOMReaderReport_h

#include "vrDICOMSeriesChoice.h"

#include <optional>
#include <string>

namespace vr::detail
{
/** \a text as one report line holds it: line breaks and tabs as spaces. */
std::string
ReportText(std::string text);

/** A series' fields, tab-separated, for a "series" line. */
std::string
SeriesReportLine(const DICOMSeriesSummary & series);

/** The series a "series" line (without its word) gives; none when it is no such line. */
std::optional<DICOMSeriesSummary>
ParseSeriesReportLine(const std::string & line);
} // namespace vr::detail

#endif
