// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkVesselLumenMeasurement_h
#define itkVesselLumenMeasurement_h

#include "itkImage.h"
#include "itkVesselPathSection.h"

#include <cstddef>
#include <limits>
#include <vector>

namespace itk
{

/** Where a lumen profile's diameters come from (docs/lumen-measurement.md). */
enum class VesselLumenSource
{
  /** The region of a segmentation around the path point, in each section's plane. */
  Segmentation,
  /** The centerline's radius (the inscribed sphere's): diameter 2r, no area. */
  CenterlineRadius
};

/** "segmentation" or "centerline radius". */
const char *
ToString(VesselLumenSource source);

/** \class VesselLumenSection
 * \brief The lumen measured at one cross-section of a vessel path (docs/lumen-measurement.md). Millimetres; a value
 * not measured is NaN.
 * \ingroup VesselReformation
 */
struct VesselLumenSection
{
  using PointType = Point<double, 3>;

  /** The section's arc length along the path (mm) and centre (LPS mm), copied from its VesselPathSection. */
  double    ArcLength{ 0.0 };
  PointType Center;
  int       BranchId{ 0 };
  /** Segmentation source: whether the path point lies inside the segmentation (mask interpolated >= 0.5). When it
   * does not, nothing is measured here from the segmentation. Always false for the centerline-radius source. */
  bool CenterInSegmentation{ false };
  /** Segmentation source: the region reached the edge of the sampled square (its half-width), so area and
   * diameters are lower bounds. */
  bool RegionClipped{ false };
  /** Area of the connected lumen region containing the path point, in the section's plane (mm^2). */
  double Area{ std::numeric_limits<double>::quiet_NaN() };
  /** Circle-equivalent diameter 2 sqrt(Area / pi). */
  double EquivalentDiameter{ std::numeric_limits<double>::quiet_NaN() };
  /** The region's smallest and largest caliper (Feret) diameter over all directions in the plane. */
  double MinimumDiameter{ std::numeric_limits<double>::quiet_NaN() };
  double MaximumDiameter{ std::numeric_limits<double>::quiet_NaN() };
  /** The centerline's inscribed-sphere diameter 2r, whatever the source, when the path carries radii. */
  double InscribedDiameter{ std::numeric_limits<double>::quiet_NaN() };
  /** The profile's diameter, which the reference and the stenosis use: EquivalentDiameter for the segmentation
   * source, InscribedDiameter for the centerline-radius source. */
  double Diameter{ std::numeric_limits<double>::quiet_NaN() };
  /** The reference (healthy) diameter and area here, once AnalyseVesselStenosis has run (vrVesselStenosis.h, the
   * one-vessel logic). */
  double ReferenceDiameter{ std::numeric_limits<double>::quiet_NaN() };
  double ReferenceArea{ std::numeric_limits<double>::quiet_NaN() };

  /** Whether Diameter is known. */
  bool
  IsMeasured() const
  {
    return Diameter == Diameter;
  }
};

/** \class VesselLumenProfile
 * \brief The lumen along a vessel path: one VesselLumenSection per path section, in the path's order.
 * \ingroup VesselReformation
 */
struct VesselLumenProfile
{
  VesselLumenSource               Source{ VesselLumenSource::Segmentation };
  std::vector<VesselLumenSection> Sections;
  /** Segmentation source: sections whose path point lies outside the segmentation (not measured). */
  std::size_t SectionsOutsideSegmentation{ 0 };
  /** Segmentation source: sections whose region reached the edge of the sampled square. */
  std::size_t ClippedSections{ 0 };
  /** Sections without a centerline radius (the centerline-radius source measures nothing there). */
  std::size_t SectionsWithoutRadius{ 0 };
  /** Segmentation source: the in-plane sampling step used (mm). */
  double SamplingStep{ 0.0 };
};

/** \class VesselLumenMeasurementOptions
 * \brief How a section's plane is sampled (docs/lumen-measurement.md, "Sampling").
 * \ingroup VesselReformation
 */
struct VesselLumenMeasurementOptions
{
  /** In-plane grid step, mm; 0: a quarter of the mask's smallest voxel spacing. */
  double SamplingStep{ 0.0 };
  /** Half the side of the sampled square around the path point, mm: the largest lumen radius measured whole. */
  double MaximumHalfWidth{ 30.0 };
  /** Threads; 0: ITK's global default. */
  unsigned int NumberOfWorkUnits{ 0 };
};

/** The type of the segmentation masks measured: non-zero = vessel, on any grid (origin, spacing, direction). */
using VesselLumenMaskType = Image<unsigned char, 3>;

/** Measures the lumen of \a mask in every section's plane: the mask is sampled on a square grid in the plane
 * (Center + i h Lateral + j h Up) by trilinear interpolation of its 0/1 values, thresholded at 0.5, and the
 * 4-connected region containing the path point is measured: its area (pixel count x h^2), circle-equivalent
 * diameter and Feret diameters (of the convex hull of the points where the interpolated mask crosses 0.5 on the
 * grid's edges). Voxels outside the mask's buffer count as background.
 * Throws itk::ExceptionObject on a null or empty mask, a step or half-width that is not > 0 and finite (a step
 * leaving more than 4096 samples per side), or a section with a non-finite centre or frame. A path that misses the
 * mask is no exception here: see VesselLumenProfile::SectionsOutsideSegmentation. */
VesselLumenProfile
MeasureVesselLumen(const VesselLumenMaskType *           mask,
                   const VesselPathSectionList &         sections,
                   const VesselLumenMeasurementOptions & options = {});

/** One section alone (the viewer's cross-section), as MeasureVesselLumen measures it. */
VesselLumenSection
MeasureVesselLumenSection(const VesselLumenMaskType *           mask,
                          const VesselPathSection &             section,
                          const VesselLumenMeasurementOptions & options = {});

/** The lumen from the centerline radii alone: Diameter = InscribedDiameter = 2 Radius; area and Feret diameters
 * are not measured (NaN). Sections without a radius are counted in SectionsWithoutRadius. */
VesselLumenProfile
VesselLumenFromRadii(const VesselPathSectionList & sections);

} // namespace itk

#endif
