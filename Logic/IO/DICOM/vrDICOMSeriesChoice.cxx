// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrDICOMSeriesChoice.h"

#include "vrParameterName.h"

#include <utility>

namespace vr
{
std::string
DescribeDICOMSeries(const DICOMSeriesSummary & series)
{
  std::string text = std::to_string(series.Number) + ":";
  if (!series.SeriesNumber.empty())
  {
    text += " series " + series.SeriesNumber;
  }
  if (!series.SeriesDescription.empty())
  {
    text += " \"" + series.SeriesDescription + "\"";
  }
  if (!series.Modality.empty())
  {
    text += text.back() == ':' ? " " + series.Modality : " (" + series.Modality + ")";
  }
  text += (text.back() == ':' ? " " : ", ") + std::to_string(series.Files) + (series.Files == 1 ? " file" : " files") +
          " of " + std::to_string(series.Columns) + " x " + std::to_string(series.Rows) +
          " pixels, Series Instance UID " + (series.SeriesInstanceUID.empty() ? "(none)" : series.SeriesInstanceUID);
  if (!series.Detail.empty())
  {
    text += "; " + series.Detail;
  }
  return text;
}

DICOMSeriesChoiceRequired::DICOMSeriesChoiceRequired(const std::string &             message,
                                                     std::vector<DICOMSeriesSummary> series)
  : InputError(message, ParameterName::DICOMSeries)
  , m_Series(std::move(series))
{
}
} // namespace vr
