// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrDICOMReaderReport.h"

#include <algorithm>
#include <vector>

namespace vr::detail
{
std::string
ReportText(std::string text)
{
  std::replace_if(
    text.begin(), text.end(), [](char c) { return c == '\n' || c == '\r' || c == '\t'; }, ' ');
  return text;
}

std::string
SeriesReportLine(const DICOMSeriesSummary & series)
{
  const std::string fields[] = { std::to_string(series.Number),
                                 series.SeriesInstanceUID,
                                 series.SeriesNumber,
                                 series.SeriesDescription,
                                 series.Modality,
                                 std::to_string(series.Files),
                                 std::to_string(series.Columns),
                                 std::to_string(series.Rows),
                                 series.Detail };
  std::string       line;
  for (const std::string & field : fields)
  {
    line += (line.empty() ? "" : "\t") + ReportText(field);
  }
  return line;
}

std::optional<DICOMSeriesSummary>
ParseSeriesReportLine(const std::string & line)
{
  std::vector<std::string> fields;
  std::size_t              start = 0;
  for (;;)
  {
    const std::size_t tab = line.find('\t', start);
    fields.push_back(line.substr(start, tab - start));
    if (tab == std::string::npos)
    {
      break;
    }
    start = tab + 1;
  }
  if (fields.size() != 9)
  {
    return std::nullopt;
  }
  DICOMSeriesSummary series;
  try
  {
    series.Number = static_cast<unsigned int>(std::stoul(fields[0]));
    series.Files = std::stoul(fields[5]);
    series.Columns = static_cast<unsigned int>(std::stoul(fields[6]));
    series.Rows = static_cast<unsigned int>(std::stoul(fields[7]));
  }
  catch (const std::exception &)
  {
    return std::nullopt;
  }
  series.SeriesInstanceUID = fields[1];
  series.SeriesNumber = fields[2];
  series.SeriesDescription = fields[3];
  series.Modality = fields[4];
  series.Detail = fields[8];
  return series;
}
} // namespace vr::detail
