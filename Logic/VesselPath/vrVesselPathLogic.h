// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrVesselPathLogic_h
#define vrVesselPathLogic_h

#include "itkCenterlineTree.h"
#include "itkVesselLumenMeasurement.h"
#include "itkVesselPath.h"
#include "itkVesselPathSection.h"
#include "itkCPRIntensityRescale.h"
#include "vrPathSegments.h"
#include "vrVesselStenosis.h"
#include "vrImageTypes.h"
#include "vrVesselPathParameters.h"

#include <memory>
#include <string>
#include <vector>

namespace vr
{
/** How many times each stage of the single-vessel reading has run since the logic was made: the recompute rules
 * (docs/vessel-path.md, "Logic") are tested on these.
 * \ingroup VesselReformation
 */
struct VesselPathStageCounts
{
  /** The path: the chain of branches and its cut. */
  unsigned int Path{ 0 };
  /** The rotation-minimising frame at the section spacing. */
  unsigned int Frame{ 0 };
  /** The CPR image (with its point image and fold mask) and the cross-section stack. */
  unsigned int Resampling{ 0 };
  /** The lumen profile and the stenosis grading (docs/lumen-measurement.md). */
  unsigned int Measurement{ 0 };
};

/** \class VesselPathResults
 * \brief What a single-vessel reading returns (docs/vessel-path.md): the path, its sections, the images and the
 * lumen. Images are ITK images in LPS; an image not asked for is null.
 * \ingroup VesselReformation
 */
struct VesselPathResults
{
  using PointImageType = itk::Image<itk::Vector<float, 3>, 2>;

  /** The path read (after the range's cut), arc length from its start. */
  itk::VesselPath Path;
  /** Its branches' names joined, each repeated name once ("ascending aorta → celiac trunk"; "branch N" for a branch
   * without a name). */
  std::string PathName;
  /** Its junctions and the segments between them (what the grading takes its references within). */
  PathLayout Layout;
  /** The cross-sections every section spacing, their frame turned by the roll. */
  itk::VesselPathSectionList Sections;
  /** The straightened or stretched CPR: x across the vessel (mm), y along the path (mm). */
  DepthImageType::Pointer CPR;
  /** The LPS point of every CPR pixel; null unless asked for. */
  PointImageType::Pointer Points;
  /** 1 where neighbouring rows fold over each other. */
  MaskImageType::Pointer FoldMask;
  std::size_t            FoldedPixels{ 0 };
  /** The half-width below which nothing folds, mm (infinite on a straight path). */
  double FoldFreeHalfWidth{ 0.0 };
  /** The stack of cross-sections (u, v, s); null unless asked for. */
  VolumeImageType::Pointer CrossSections;
  /** The lumen along the path, and its stenosis grading (segment by segment) when the lumen was measured. */
  itk::VesselLumenProfile   Lumen;
  bool                      HasLumen{ false };
  vr::VesselStenosisSummary Stenosis;
  /** The pixel spacing and section spacing used (the defaults resolved). */
  double PixelSpacing{ 0.0 };
  double SectionSpacing{ 0.0 };
  /** What the run found worth saying: folds, sections outside the segmentation, a path without radii. */
  std::vector<std::string> Warnings;
};

/** "395.7 mm: ascending aorta → celiac trunk": the path's length and names, as the lumen table and the panel open. */
std::string
DescribePath(const VesselPathResults & results);

/** \class VesselPathLogic
 * \brief The single-vessel reading of the module (docs/vessel-path.md): one path of the centerline tree, its
 * straightened or stretched CPR, its cross-sections and its lumen, recomputing only what a change invalidates.
 *
 * A roll, a width, a spacing of the image or a sampling change reruns the resampling alone; a change of the path
 * (branch, range), the section spacing or the tree view reruns the frame, the resampling and the measurement; a
 * change of the segmentation, the reference points or method, or the grading scale reruns the measurement alone. The
 * lumen comes from the segmentation when one is set, else from the centerline radii, else it is not measured.
 *
 * Errors are vr::InputError naming the parameter by its meaning (vr::ParameterName) or the segmentation.
 * \sa VesselPathParameters, itk::StraightenedCPRImageFilter, itk::CrossSectionStackImageFilter
 * \ingroup VesselReformation
 */
class VesselPathLogic
{
public:
  VesselPathLogic();
  ~VesselPathLogic();
  VesselPathLogic(const VesselPathLogic &) = delete;
  VesselPathLogic &
  operator=(const VesselPathLogic &) = delete;

  /** The volume sampled (LPS): an itk::Image<T, 3> of a stored pixel type (vr::StoredVolume), read in place, and the
   * rescale of its stored values to intensities. */
  void
  SetVolume(const itk::ImageBase<3> * volume, const itk::CPRIntensityRescale & rescale = {});
  /** The centerline tree the path is taken from (LPS mm). */
  void
  SetCenterlineTree(const itk::CenterlineTree & tree);
  /** A vessel mask (1 = vessel) to measure the lumen on, with how messages name it ("segmentation aorta.nii.gz");
   * null: measure from the centerline radii. */
  void
  SetSegmentationMask(const LabelMapVolumeType * mask, const std::string & name);
  /** Validates \a parameters (vr::InputError) and keeps them. */
  void
  SetParameters(const VesselPathParameters & parameters);
  const VesselPathParameters &
  GetParameters() const;
  /** Compute the cross-section stack and the point image (off by default: a viewer does not need them). */
  void
  SetCrossSectionsEnabled(bool enabled);
  void
  SetPointImageEnabled(bool enabled);

  /** Runs the stages a change since the last call invalidated. Throws vr::InputError without a volume or a tree,
   * on an unknown branch, a range or reference point outside the path, a path shorter than one section, or a
   * segmentation that contains no section's centre. */
  const VesselPathResults &
  Update();
  /** The most recent results. */
  const VesselPathResults &
  GetResults() const;
  const VesselPathStageCounts &
  GetStageCounts() const;

  /** The LPS point of continuous CPR pixel (column, row) of the last Update. */
  itk::Point<double, 3>
  ComputePoint(double column, double row) const;
  /** The continuous CPR row of arc length \a s (mm, on the path read). */
  double
  RowOfArcLength(double s) const;
  /** The section at arc length \a s (mm), interpolated along the frame: what a cross-section view shows. */
  itk::VesselPathSection
  SectionAt(double s) const;

private:
  struct Internals;
  std::unique_ptr<Internals> m;
};
} // namespace vr

#endif
