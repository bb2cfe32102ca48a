// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrLumenMeasurement_h
#define vrLumenMeasurement_h

#include "vrVesselStenosis.h"
#include "vrSegmentationIO.h"

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
  vr::VesselReferenceMethod ReferenceMethod{ vr::VesselReferenceMethod::Interpolated };
  /** Arc lengths (mm) of the reference points; empty: 5 % and 95 % of the path. */
  std::vector<double> ReferenceArcLengths;
  /** In-plane sampling step (mm; 0: a quarter of the segmentation's smallest voxel spacing) and half-width (mm). */
  double SamplingStep{ 0.0 };
  double MaximumHalfWidth{ 30.0 };
};

/** \class LumenMeasurement
 * \brief The lumen table (one row per section, vr::WriteLumenTable) and the summary a command-line module returns.
 * \ingroup VesselReformation
 */
struct LumenMeasurement
{
  itk::VesselLumenProfile   Profile;
  vr::VesselStenosisSummary Summary;
};

/** Measures the lumen along a path and grades its stenosis: from \a segmentation when one is given, else from the
 * sections' centerline radii (the profile says which, Profile.Source).
 * \param sections the path's cross-sections (itk::VesselPathSection), in order of arc length.
 * \param segmentation the vessel mask (vr::ReadSegmentationMask, vr::MakeSegmentationMask) or null.
 * \param segmentationName how messages name the segmentation ("segmentation aorta.nii.gz").
 * \param parameters reference method and points, sampling.
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
 * an empty value where nothing was measured: pathLength, lumenSource ("segmentation" or "centerline radius"),
 * referenceMethod ("interpolated" or "robust fit"), referencePoints (arc lengths, comma-separated),
 * minimalLumenDiameter, minimalLumenDiameterArcLength, minimalLumenDiameterPoint ("r,a,s", RAS mm),
 * minimalLumenArea, minimalLumenAreaArcLength, referenceDiameter, referenceArea, diameterStenosis, areaStenosis,
 * cadRads (0 to 5), sectionsOutsideSegmentation. */
std::vector<std::pair<std::string, std::string>>
LumenSummaryValues(const LumenMeasurement & measurement);
} // namespace vr

#endif
