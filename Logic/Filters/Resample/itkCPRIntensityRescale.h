// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCPRIntensityRescale_h
#define itkCPRIntensityRescale_h

#include <cmath>
#include <ostream>

namespace itk
{

/** \class CPRIntensityRescale
 * \brief How a volume's stored values map to intensities: intensity = Slope x stored + Intercept (DICOM's Rescale
 * Slope and Rescale Intercept, NIfTI's scl_slope and scl_inter).
 *
 * A volume keeps the pixel type of its file (16-bit integers for most CT) and the reformation filters apply the
 * rescale to each voxel value they read (docs/design.md "Volumes in their stored type"), so that no float copy of the
 * volume is ever made. The identity (slope 1, intercept 0) is the default and costs nothing: a filter reads the
 * values as they are stored.
 *
 * \ingroup VesselReformation
 */
struct CPRIntensityRescale
{
  double Slope{ 1.0 };
  double Intercept{ 0.0 };

  /** \return whether the rescale leaves values as they are. */
  bool
  IsIdentity() const
  {
    return Slope == 1.0 && Intercept == 0.0;
  }
  /** \return whether both numbers are finite and the slope is not 0 (a slope of 0 would make every voxel one value). */
  bool
  IsValid() const
  {
    return std::isfinite(Slope) && std::isfinite(Intercept) && Slope != 0.0;
  }
  /** \return the intensity of a stored value. */
  double
  Apply(double stored) const
  {
    return Slope * stored + Intercept;
  }
  bool
  operator==(const CPRIntensityRescale & other) const
  {
    return Slope == other.Slope && Intercept == other.Intercept;
  }
  bool
  operator!=(const CPRIntensityRescale & other) const
  {
    return !(*this == other);
  }
};

/** Prints "slope 0.5, intercept -1024". */
inline std::ostream &
operator<<(std::ostream & os, const CPRIntensityRescale & rescale)
{
  return os << "slope " << rescale.Slope << ", intercept " << rescale.Intercept;
}

} // namespace itk

#endif
