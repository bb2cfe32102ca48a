// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrVesselPathParameters_h
#define vrVesselPathParameters_h

#include "itkCPRResampleImageFilter.h"
#include "vrVesselStenosis.h"
#include "itkVector.h"
#include "vrParameterName.h"

#include <vector>

namespace vr
{
/** How one vessel's path is laid out in its image (docs/vessel-path.md). */
enum class PathReformation
{
  /** The path is the image's middle column; rows are the planes perpendicular to it. */
  Straightened,
  /** Sampling lines along one fixed direction; rows spaced by the arc length of the path projected across it. */
  Stretched
};

/** \class VesselPathParameters
 * \brief Every setting of the single-vessel reading in one object: which path, how it is laid out, how the volume
 * is sampled, where the lumen's reference points lie. Lengths in mm, angles in degrees, vectors in LPS.
 *
 * Validate() names the parameter by its meaning (vr::ParameterName) and the bad value. VesselPathLogic compares
 * the parameters of successive runs to recompute only what a change invalidates: the roll reruns the resampling
 * alone, the path's choice reruns the frame, the resampling and the measurement.
 * \ingroup VesselReformation
 */
struct VesselPathParameters
{
  using VectorType = itk::Vector<double, 3>;

  /** Every parameter at its default (below). */
  VesselPathParameters();

  /** The branch whose far end the path runs to, from the tree's root; 0: the longest root-to-leaf path. */
  int BranchId{ 0 };
  /** Read only the part of the path between RangeStart and RangeEnd (arc lengths from the root, mm). */
  bool   HasRange{ false };
  double RangeStart{ 0.0 };
  double RangeEnd{ 0.0 };

  PathReformation Reformation{ PathReformation::Straightened };
  /** Rotation of the image about the path, degrees. */
  double RollInDegrees{ 0.0 };
  /** Width of the CPR across the vessel and of the cross-sections, mm (> 0). */
  double Width{ 40.0 };
  /** Pixel spacing of the CPR and the cross-sections, mm; 0: the volume's smallest voxel spacing. */
  double PixelSpacing{ 0.0 };
  /** Distance between cross-sections along the path, mm; 0: the pixel spacing. */
  double SectionSpacing{ 0.0 };

  /** The tree view whose look the frame takes at roll 0 (as ReformationParameters' up axis and angle). */
  bool       AutomaticUp{ false };
  VectorType Up;
  double     ViewAngleInDegrees{ 0.0 };

  itk::CPRInterpolationMode Interpolation{ itk::CPRInterpolationMode::Linear };
  /** Slab across the CPR's plane, mm; 0 samples the plane alone. */
  double           SlabThickness{ 0.0 };
  itk::CPRSlabMode SlabMode{ itk::CPRSlabMode::MIP };

  /** Arc lengths (mm, on the path read) of the user's reference points, one reference through them over the whole
   * path; empty: each segment between junctions has its own (docs/lumen-measurement.md, "Reference"). */
  std::vector<double> ReferencePoints;
  /** How the reference diameter is found: interpolated between the reference points, or a robust fit to the profile
   * (docs/lumen-measurement.md). */
  vr::VesselReferenceMethod ReferenceMethod{ vr::VesselReferenceMethod::Interpolated };
  /** The clinical scale the stenosis is graded on; Automatic: per segment, from the vessel's name (CAD-RADS for a
   * coronary artery only; docs/lumen-measurement.md, "Grading scales"). */
  StenosisScale GradingScale{ StenosisScale::Automatic };

  /** Throws vr::InputError naming the parameter and its value when one is out of range or not finite. Whether
   * the range and the reference points lie on the path is known only once the path is: the logic checks that. */
  void
  Validate() const;

  bool
  operator==(const VesselPathParameters & other) const;
  bool
  operator!=(const VesselPathParameters & other) const
  {
    return !(*this == other);
  }
};
} // namespace vr

#endif
