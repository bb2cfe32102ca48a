// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrLumenMeasurement_h
#define vrLumenMeasurement_h

#include "vrLumenTableIO.h"
#include "vrSegmentationIO.h"
#include "vrVesselStenosis.h"

#include <string>
#include <utility>
#include <vector>

namespace vr
{
/** \class LumenMeasurementParameters
 * \brief What the lumen measurement along a path is asked (docs/lumen-measurement.md).
 * \ingroup VesselReformation
 */
struct LumenMeasurementParameters
{
  VesselReferenceMethod ReferenceMethod{ VesselReferenceMethod::Interpolated };
  /** Arc lengths (mm) of the user's reference points; empty: each segment's own reference. */
  std::vector<double> ReferenceArcLengths;
  /** The path's junctions and segments (vr::FindPathLayout); empty: the whole path is one segment. */
  PathLayout Layout;
  /** The grading scale; Automatic: per segment, from its vessel's name. */
  StenosisScale Scale{ StenosisScale::Automatic };
  /** In-plane sampling step (mm; 0: a quarter of the segmentation's smallest voxel spacing) and half-width (mm). */
  double SamplingStep{ 0.0 };
  double MaximumHalfWidth{ 30.0 };
};

/** \class LumenMeasurement
 * \brief The lumen table (one row per section, vr::WriteLumenTable) and the grading a command-line module returns.
 * \ingroup VesselReformation
 */
struct LumenMeasurement
{
  itk::VesselLumenProfile Profile;
  VesselStenosisSummary   Summary;
};

/** Measures the lumen along a path and grades its stenosis segment by segment (vr::AnalyseVesselStenosis): from
 * \a segmentation when one is given, else from the sections' centerline radii (the profile says which,
 * Profile.Source).
 * \param sections the path's cross-sections (itk::VesselPathSection), in order of arc length.
 * \param segmentation the vessel mask (vr::ReadSegmentationMask, vr::MakeSegmentationMask) or null.
 * \param segmentationName how messages name the segmentation ("segmentation aorta.nii.gz").
 * \param parameters reference method and points, the path's layout, the scale, sampling.
 * Throws vr::InputError: naming \a segmentationName when no section's centre lies inside the segmentation (a
 * segmentation of another vessel or another scan); naming the reference points (vr::ParameterName::ReferencePoints)
 * that lie outside the path, with the path's extent; when the path has fewer than two sections; when there is no
 * segmentation and the centerlines carry no radius; on a bad sampling step or half-width
 * (vr::ParameterName::LumenSampling). Sections outside the segmentation on part of the path are no error: they are
 * counted in Profile.SectionsOutsideSegmentation and left unmeasured. */
LumenMeasurement
MeasureLumen(const itk::VesselPathSectionList & sections,
             const SegmentationMaskType *       segmentation,
             const std::string &                segmentationName,
             const LumenMeasurementParameters & parameters);

/** The summary as a command-line module returns it: (name, value) pairs in this order, numbers in mm, mm^2 or %,
 * an empty value where nothing was found: pathLength, lumenSource ("segmentation" or "centerline radius"),
 * referenceMethod ("interpolated" or "robust fit"),
 * referencePoints (the headline segment's, comma-separated), minimalLumenDiameter, minimalLumenDiameterArcLength,
 * minimalLumenDiameterPoint ("r,a,s", RAS mm), minimalLumenArea, minimalLumenAreaArcLength, referenceDiameter,
 * referenceArea, diameterStenosis, areaStenosis, cadRads (0 to 5, only on the CAD-RADS scale),
 * sectionsOutsideSegmentation; then referenceScope ("each segment" or "the user's points"), gradingScale (the
 * headline's), grade (its category, e.g. "50–99 % (peripheral)"), gradedSegment (the headline segment described),
 * notGradedBecause, maximumDiameter and maximumDiameterArcLength (the aorta's), excludedSections and segments (one line
 * per segment, "; " between). */
std::vector<std::pair<std::string, std::string>>
LumenSummaryValues(const LumenMeasurement & measurement);

/** The grading in words, one line each: the source, the reference method, the margins, each segment (its scale and
 * why, its values or why none), and the headline. What the lumen table's comment lines and the module's printed
 * summary say. \a pathDescription ("395.7 mm: aorta → celiac trunk") opens it when not empty. */
std::vector<std::string>
LumenSummaryLines(const LumenMeasurement & measurement, const std::string & pathDescription = std::string());

/** One segment in words: "segment 2 (celiac trunk, 120.0–160.0 mm), peripheral by its name: 52 % diameter stenosis,
 * 50–99 % (peripheral); MLD 3.1 mm at 140.2 mm, reference 6.5 mm; 77 % area stenosis", or its maximum diameter and
 * why it is not graded. */
std::string
DescribeSegmentGrading(const VesselStenosisSummary & summary, std::size_t segment);

/** The lumen table's notes (vr::WriteLumenTable): LumenSummaryLines as comments and each section's marks. */
LumenTableNotes
LumenTableNotesOf(const LumenMeasurement & measurement, const std::string & pathDescription = std::string());
} // namespace vr

#endif
