// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrVesselStenosis_h
#define vrVesselStenosis_h

#include "itkVesselLumenMeasurement.h"

#include <limits>
#include <vector>

namespace vr
{

/** How the reference (healthy) diameter along the path is found (docs/lumen-measurement.md, "Reference"). */
enum class VesselReferenceMethod
{
  /** DICOM PS3.17 Annex T.4's interpolated reference: linear between the profile's diameters at the reference
   * points (by default at 5 % and 95 % of the path), constant beyond the first and the last. */
  Interpolated,
  /** A straight line fitted to the profile between the first and the last reference point by iteratively
   * reweighted least squares with Tukey's biweight (c = 4.685 robust standard deviations, from the median absolute
   * deviation), started from the Theil-Sen line: the stenotic dip gets weight 0. */
  RobustFit
};

/** "interpolated" or "robust fit". */
const char *
ToString(VesselReferenceMethod method);

/** \class VesselStenosisOptions
 * \brief What AnalyseVesselStenosis is asked.
 * \ingroup VesselReformation
 */
struct VesselStenosisOptions
{
  VesselReferenceMethod Method{ VesselReferenceMethod::Interpolated };
  /** Arc lengths (mm, the sections' own) of the reference points; empty: 5 % and 95 % of the path. At least two
   * for the robust fit (its span); one or more for the interpolated method. */
  std::vector<double> ReferenceArcLengths;
};

/** \class VesselStenosisSummary
 * \brief The stenosis along a path (docs/lumen-measurement.md): what a command-line module returns. Millimetres;
 * NaN (and -1 for the class) where nothing was measured.
 * \ingroup VesselReformation
 */
struct VesselStenosisSummary
{
  using PointType = itk::Point<double, 3>;
  static constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

  itk::VesselLumenSource Source{ itk::VesselLumenSource::Segmentation };
  VesselReferenceMethod  Method{ VesselReferenceMethod::Interpolated };
  /** Arc length from the first section to the last. */
  double PathLength{ 0.0 };
  /** The reference points used, ascending (the defaults when none were given). The robust fit uses the profile
   * between the first and the last. */
  std::vector<double> ReferenceArcLengths;
  /** Sections measured (a diameter known) between the first and the last reference point, and on the whole path
   * (MLD and MLA are searched on the whole path). */
  std::size_t MeasuredSectionsInSpan{ 0 };
  std::size_t MeasuredSections{ 0 };
  /** Minimal lumen diameter, its arc length and centre (LPS). */
  double    MinimalLumenDiameter{ NaN };
  double    MinimalLumenDiameterArcLength{ NaN };
  PointType MinimalLumenDiameterCenter;
  /** Minimal lumen area and its arc length. For the centerline-radius source, the area of the circle of diameter
   * MLD (no area is measured). */
  double MinimalLumenArea{ NaN };
  double MinimalLumenAreaArcLength{ NaN };
  /** Reference diameter at the MLD's arc length (RVD), and the reference area at the MLA's (the same reference
   * method applied to the area profile). */
  double ReferenceDiameter{ NaN };
  double ReferenceArea{ NaN };
  /** 100 (1 - MLD / RVD). Negative where the lumen is wider than the reference. */
  double DiameterStenosisPercent{ NaN };
  /** 100 (1 - MLA / reference area at the MLA). */
  double AreaStenosisPercent{ NaN };
  /** The CAD-RADS class of DiameterStenosisPercent (CADRADSClass), -1 when not measured. */
  int CADRADS{ -1 };
};

/** The CAD-RADS stenosis class of a % diameter stenosis (docs/lumen-measurement.md, "CAD-RADS"): the percentage is
 * rounded to the nearest whole percent (halves up), then 0 % or less: 0; 1-24: 1; 25-49: 2; 50-69: 3; 70-99: 4;
 * 5 only for a lumen of diameter 0 (exactly 100 %): a stenosis rounded to 100 % with some lumen left stays 4.
 * \return the class, or -1 for NaN. */
int
CADRADSClass(double diameterStenosisPercent);

/** Fills every section's ReferenceDiameter and ReferenceArea in \a profile and returns the stenosis summary.
 * Throws itk::ExceptionObject naming the values when a reference point is not finite or lies outside the path
 * (before the first section's arc length or after the last's), the robust fit gets fewer than two reference
 * points, the path has fewer than two sections or arc lengths that decrease, or no section is measured (for the
 * robust fit: none between the first and the last reference point). */
VesselStenosisSummary
AnalyseVesselStenosis(itk::VesselLumenProfile & profile, const VesselStenosisOptions & options = {});

} // namespace vr

#endif
