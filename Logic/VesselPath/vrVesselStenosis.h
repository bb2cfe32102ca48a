// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrVesselStenosis_h
#define vrVesselStenosis_h

#include "itkVesselLumenMeasurement.h"
#include "vrPathSegments.h"
#include "vrStenosisScale.h"

#include <limits>
#include <string>
#include <vector>

namespace vr
{
/** How the reference (healthy) diameter is found (docs/lumen-measurement.md, "Reference"). */
enum class VesselReferenceMethod
{
  /** DICOM PS3.17 Annex T.4's interpolated reference: linear between the profile's diameters at the reference
   * points, constant beyond the first and the last. */
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
  /** The user's reference points (arc lengths, the sections' own): one reference through them over the whole path,
   * whatever its junctions. Empty (the default): each segment's own reference, between the ends of its candidate
   * sections. */
  std::vector<double> ReferenceArcLengths;
  /** The path's junctions and segments (vr::FindPathLayout). No segment: the whole path is one segment without a
   * name, and both its ends are vessel ends. */
  PathLayout Layout;
  /** The scale of every segment; Automatic chooses it per segment (ScaleOfVesselName, then by size). */
  StenosisScale Scale{ StenosisScale::Automatic };
};

/** Sections closer than this to a vessel end of the path or to a junction are no candidates for the MLD (mm),
 * whatever the vessel's radius. */
constexpr double MinimumExclusionMargin = 2.0;
/** A segment is graded when at least this many candidate sections are measured: two reference points and one
 * between. */
constexpr std::size_t MinimumCandidates = 3;

/** \class SectionGrading
 * \brief How one section of the profile takes part in the grading.
 * \ingroup VesselReformation
 */
struct SectionGrading
{
  /** Index into VesselStenosisSummary::Segments. */
  std::size_t Segment{ 0 };
  /** Whether the section may hold the MLD (and the maximum diameter): measured, and outside every margin. */
  bool Candidate{ false };
  /** Why it may not: "not measured", "path start", "path end", "branch origin (branch 4)", "junction into branch 7";
   * empty for a candidate. */
  std::string ExcludedBecause;
};

/** \class SegmentGrading
 * \brief The grading of one segment of the path. Millimetres; NaN where nothing was found.
 * \ingroup VesselReformation
 */
struct SegmentGrading
{
  static constexpr double NaN = std::numeric_limits<double>::quiet_NaN();
  using PointType = itk::Point<double, 3>;

  PathSegment Segment;
  /** The scale used and why ("by name", "by size: median diameter 17.2 mm", "chosen by the user", "not named as
   * aorta, coronary or carotid artery"). */
  StenosisScale Scale{ StenosisScale::Peripheral };
  std::string   ScaleReason;
  std::size_t   Candidates{ 0 };
  /** The reference points used (arc lengths): the ends of the candidate span, or the user's. */
  std::vector<double> ReferenceArcLengths;
  /** The narrowest candidate: MLD, its arc length and centre (LPS), the reference diameter there and the % diameter
   * stenosis 100 (1 - MLD / RVD); the smallest area likewise. */
  double    MinimalLumenDiameter{ NaN };
  double    MinimalLumenDiameterArcLength{ NaN };
  PointType MinimalLumenDiameterCenter;
  double    ReferenceDiameter{ NaN };
  double    DiameterStenosisPercent{ NaN };
  double    MinimalLumenArea{ NaN };
  double    MinimalLumenAreaArcLength{ NaN };
  double    ReferenceArea{ NaN };
  double    AreaStenosisPercent{ NaN };
  /** The widest candidate (the aorta's headline): its diameter and arc length. */
  double MaximumDiameter{ NaN };
  double MaximumDiameterArcLength{ NaN };
  /** The category on Scale (vr::StenosisCategory) and its text, or -1 and empty where not graded. */
  int         Category{ -1 };
  std::string Grade;
  /** Why the segment's stenosis is not graded (too short, nothing measured, the aorta's scale); empty when graded. */
  std::string NotGradedBecause;

  bool
  IsGraded() const
  {
    return Category >= 0;
  }
};

/** \class VesselStenosisSummary
 * \brief The grading along a path (docs/lumen-measurement.md): every segment's, and the headline a reader signs,
 * which is the most severe graded stenosis, or for a path of the aorta alone its maximum diameter. Millimetres; NaN
 * (and -1 for a class) where nothing was found.
 * \ingroup VesselReformation
 */
struct VesselStenosisSummary
{
  using PointType = itk::Point<double, 3>;
  static constexpr double NaN = std::numeric_limits<double>::quiet_NaN();

  itk::VesselLumenSource Source{ itk::VesselLumenSource::Segmentation };
  VesselReferenceMethod  Method{ VesselReferenceMethod::Interpolated };
  /** Whether the reference came from the user's points (one line over the path) rather than each segment's own. */
  bool UserReferencePoints{ false };
  /** Arc length from the first section to the last. */
  double PathLength{ 0.0 };
  /** Sections with a measured diameter, and those excluded from the MLD by a margin (measured or not). */
  std::size_t                 MeasuredSections{ 0 };
  std::size_t                 ExcludedSections{ 0 };
  std::vector<SegmentGrading> Segments;
  /** One per profile section, in order. */
  std::vector<SectionGrading> Sections;

  /** The headline segment (index into Segments), -1 when none: the graded segment with the largest % diameter
   * stenosis; else, on a path with aortic segments, the aortic segment with the largest maximum diameter. */
  int HeadlineSegment{ -1 };
  /** The headline segment's values (copied from it) and its scale. */
  StenosisScale       Scale{ StenosisScale::Peripheral };
  std::vector<double> ReferenceArcLengths;
  double              MinimalLumenDiameter{ NaN };
  double              MinimalLumenDiameterArcLength{ NaN };
  PointType           MinimalLumenDiameterCenter;
  double              MinimalLumenArea{ NaN };
  double              MinimalLumenAreaArcLength{ NaN };
  double              ReferenceDiameter{ NaN };
  double              ReferenceArea{ NaN };
  double              DiameterStenosisPercent{ NaN };
  double              AreaStenosisPercent{ NaN };
  /** The headline's category text ("CAD-RADS 3 (50–69 %)", "20–49 % (peripheral)"), empty when none is graded. */
  std::string Grade;
  /** The CAD-RADS class, only where the headline's scale is CAD-RADS; else -1. */
  int CADRADS{ -1 };
  /** The largest diameter over the aortic segments' candidates and its arc length (NaN without aortic segments). */
  double MaximumDiameter{ NaN };
  double MaximumDiameterArcLength{ NaN };
  /** Why no stenosis is graded on the path, when none is (each segment's reason, or the aorta's); else empty. */
  std::string NotGradedBecause;
};

/** Grades the stenosis along \a profile segment by segment (docs/lumen-measurement.md) and fills every section's
 * ReferenceDiameter and ReferenceArea (NaN in a segment without a reference).
 *
 * - Sections within max(MinimumExclusionMargin, the radius there) of a vessel end of the path, or within
 *   max(MinimumExclusionMargin, the parent's radius) of a junction, are no candidates (SectionGrading says why).
 * - Each segment's reference comes from its own candidates: the reference points are the first and the last
 *   candidate section (interpolated), or the fit runs over its candidates (robust); it never reaches across a
 *   junction. A segment with fewer than MinimumCandidates measured candidates is not graded, and says why. With the
 *   user's reference points, one reference through them serves every segment.
 * - The segment's scale: the options' Scale, or ScaleOfVesselName of its name, or for a vessel without a name the
 *   aorta when its median diameter is at least AortaSizedDiameter, else peripheral. The aorta's stenosis is
 *   computed but not graded.
 *
 * Throws vr::InputError naming the reference points (vr::ParameterName::ReferencePoints) when one is not finite or
 * lies outside the path, the robust fit gets fewer than two of them, the path has fewer than two sections or arc
 * lengths that decrease, or no section is measured. */
VesselStenosisSummary
AnalyseVesselStenosis(itk::VesselLumenProfile & profile, const VesselStenosisOptions & options = {});
} // namespace vr

#endif
