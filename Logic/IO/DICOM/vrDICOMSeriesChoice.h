// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrDICOMSeriesChoice_h
#define vrDICOMSeriesChoice_h

#include "vrInputError.h"

#include <cstddef>
#include <string>
#include <vector>

namespace vr
{
/** One series of a DICOM folder as the reader lists it when the folder holds several: a set of image files that can
 * be one volume (one Series Instance UID, split further where the size, the pixel format, the orientation or the frame
 * of reference differ). A caller chooses one by Number or by SeriesInstanceUID (vr::VolumeReadOptions::DICOMSeries).
 * \ingroup VesselReformation */
struct DICOMSeriesSummary
{
  /** Its place in the list, from 1. */
  unsigned int Number{ 0 };
  std::string  SeriesInstanceUID;
  /** Series Number (0020,0011), Series Description (0008,103E) and Modality (0008,0060) as written; empty if absent. */
  std::string  SeriesNumber;
  std::string  SeriesDescription;
  std::string  Modality;
  std::size_t  Files{ 0 };
  unsigned int Columns{ 0 };
  unsigned int Rows{ 0 };
  /** Where one Series Instance UID holds several sets: how this one differs from its largest ("Rows 256, not 512");
   * and the files themselves when they are few (three or fewer). Empty otherwise. */
  std::string Detail;
};

/** \return \a series in one line: "2: series 3 \"CTA 0.6 mm\" (CT), 164 files of 512 x 512 pixels, Series Instance UID
 * 1.2.3..." and its detail. */
std::string
DescribeDICOMSeries(const DICOMSeriesSummary & series);

/** A DICOM folder that holds several series, read without a choice of one, or with a choice that names none of them
 * (or a Series Instance UID that several share). The message lists the series one per line; Parameter() is
 * ParameterName::DICOMSeries, so that a front end points at its own control for the choice (the modules' --series, the
 * viewer's dialog). Nothing was read.
 * \ingroup VesselReformation */
class DICOMSeriesChoiceRequired : public InputError
{
public:
  DICOMSeriesChoiceRequired(const std::string & message, std::vector<DICOMSeriesSummary> series);

  /** The folder's series, in the order of their numbers. */
  const std::vector<DICOMSeriesSummary> &
  GetSeries() const
  {
    return m_Series;
  }

private:
  std::vector<DICOMSeriesSummary> m_Series;
};
} // namespace vr

#endif
