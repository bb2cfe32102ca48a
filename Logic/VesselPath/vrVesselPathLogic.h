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
#include "vrCenterlineNode.h"
#include "vrImageTypes.h"
#include "vrReformationInputCache.h"
#include "vrVesselPathParameters.h"
#include "vrVolumeNode.h"

#include <functional>
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

/** \class VesselPathOutputs
 * \brief What a single-vessel reading returns (docs/vessel-path.md): the path, its sections, the images and the
 * lumen. Images are ITK images in LPS; an image not asked for is null.
 * \ingroup VesselReformation
 */
struct VesselPathOutputs
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
DescribePath(const VesselPathOutputs & results);

/** The section of \a outputs at arc length \a s (mm), interpolated along the frame: what a cross-section view shows.
 * Reads \a outputs alone, so a host may call it on a copy of the outputs on any thread. Throws vr::InputError when
 * \a outputs hold no path. */
itk::VesselPathSection
SectionAt(const VesselPathOutputs & outputs, double s);

/** \class VesselPathLogic
 * \brief The single-vessel reading of the module (docs/vessel-path.md): one path of the centerline tree, its
 * straightened or stretched CPR, its cross-sections and its lumen, recomputing only what a change invalidates.
 *
 * It takes the nodes vr::VesselReformationLogic takes (docs/module-logic.md): a volume node, a centerline node (RAS)
 * and, for the lumen, a segmentation node, and converts them through a vr::ReformationInputCache (the one place RAS
 * meets LPS; a host shares one cache between both logics to convert the nodes once), again only when a node changes.
 *
 * A roll, a width, a spacing of the image or a sampling change reruns the resampling alone; a change of the path
 * (branch, range), the section spacing or the tree view reruns the frame, the resampling and the measurement; a
 * change of the segmentation, the reference points or method, or the grading scale reruns the measurement alone; a
 * new centerline node (or a change to it) reruns everything, a new volume node the frame (with an automatic up axis)
 * and the resampling. The lumen comes from the segmentation when one is set, else from the centerline radii, else it
 * is not measured. GetStageCounts() counts every stage's runs so that tests can check these rules. A stage that
 * reruns makes new output images: the outputs of an earlier Update() stay as they were, so a host may keep and show
 * them while the logic runs again on another thread.
 *
 * Errors are vr::InputError naming the parameter by its meaning (vr::ParameterName) or the node. AbortUpdate() stops a
 * running Update(), which throws vr::Cancelled. Progress goes to the progress callback, warnings (folds, sections
 * outside the segmentation, a path without radii) to the warning callback and GetWarnings(), as the tree logic's.
 * \sa VesselPathParameters, VesselReformationLogic, itk::StraightenedCPRImageFilter, itk::CrossSectionStackImageFilter
 * \ingroup VesselReformation
 */
class VesselPathLogic
{
public:
  /** Receives the overall progress in [0, 1] and the name of the running stage (as the tree logic's). */
  using ProgressCallback = std::function<void(double fraction, const std::string & stage)>;
  /** Receives each warning, and the parameter it concerns by meaning (vr::ParameterName), or "". */
  using WarningCallback = std::function<void(const std::string & message, const std::string & parameter)>;

  VesselPathLogic();
  ~VesselPathLogic();
  VesselPathLogic(const VesselPathLogic &) = delete;
  VesselPathLogic &
  operator=(const VesselPathLogic &) = delete;

  /** \param node the volume sampled (role "volume"), read in its stored pixel type without a copy; the logic keeps a
   * reference. */
  void
  SetVolumeNode(VolumeNode * node);
  VolumeNode *
  GetVolumeNode() const;
  /** \param node the centerlines the path is taken from (role "centerlines", RAS); the logic keeps a reference. */
  void
  SetCenterlineNode(CenterlineNode * node);
  CenterlineNode *
  GetCenterlineNode() const;
  /** \param node a vessel segmentation to measure the lumen on (a label map, mask, level set or probability map node,
   * vr::MakeSegmentationMask; every non-zero label is vessel), named in messages as the tree logic names it
   * (ReformationInputCache::DescribeSegmentationNode); null: measure from the centerline radii. */
  void
  SetSegmentationNode(VolumeNode * node);
  VolumeNode *
  GetSegmentationNode() const;
  /** \param cache where the nodes are converted (shared with the tree logic's to convert them once); null gives the
   * logic a cache of its own again, as it has from construction. */
  void
  SetInputCache(std::shared_ptr<ReformationInputCache> cache);
  std::shared_ptr<ReformationInputCache>
  GetInputCache() const;

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

  /** \param callback receives progress during Update(); may be empty. */
  void
  SetProgressCallback(ProgressCallback callback);
  /** \param callback receives the warnings of each Update(); may be empty. */
  void
  SetWarningCallback(WarningCallback callback);

  /** Runs the stages a change since the last call invalidated. Throws vr::InputError without a volume or centerline
   * node, on a node that does not convert, an unknown branch, a range or reference point outside the path, a path
   * shorter than one section, or a segmentation that contains no section's centre; vr::Cancelled after
   * AbortUpdate(). */
  const VesselPathOutputs &
  Update();
  /** Asks a running Update() (on another thread) to stop as soon as its current filter can; that Update() throws
   * vr::Cancelled. Without a running Update() it does nothing. Thread-safe. */
  void
  AbortUpdate();
  /** The most recent outputs. */
  const VesselPathOutputs &
  GetOutputs() const;
  /** \return how many times each stage has run since construction. */
  const VesselPathStageCounts &
  GetStageCounts() const;
  /** \return the warnings of the latest Update() (GetOutputs().Warnings). */
  std::vector<std::string>
  GetWarnings() const;

  /** The LPS point of continuous CPR pixel (column, row) of the last Update. */
  itk::Point<double, 3>
  ComputePoint(double column, double row) const;
  /** The continuous CPR row of arc length \a s (mm, on the path read). */
  double
  RowOfArcLength(double s) const;
  /** The section at arc length \a s (mm): vr::SectionAt(GetOutputs(), s). */
  itk::VesselPathSection
  SectionAt(double s) const;

private:
  struct Internals;
  std::unique_ptr<Internals> m;
};
} // namespace vr

#endif
