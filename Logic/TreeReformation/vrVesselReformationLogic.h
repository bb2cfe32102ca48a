// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrVesselReformationLogic_h
#define vrVesselReformationLogic_h

#include "itkCPRDepthImageFilter.h"
#include "itkCPROcclusionProfile.h"
#include "itkCPRResampleImageFilter.h"
#include "itkCPRViewGeometry.h"
#include "vrCenterlineExtraction.h"
#include "vrCenterlineNode.h"
#include "vrReformationInputCache.h"
#include "vrReformationParameters.h"
#include "vrRelaxBackend.h"
#include "vrImageTypes.h"
#include "vrOcclusionTableIO.h"
#include "vrVolumeNode.h"

#include <vtkSmartPointer.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

class vtkPolyData;

namespace vr
{
/** Seconds each stage took in the most recent Update(); 0 for a stage that Update() did not need to run.
 * \ingroup VesselReformation
 */
struct StageTimes
{
  /** Nodes to ITK images and the centerline tree (or the segmentation's vessel mask). */
  double Conversion{ 0.0 };
  /** CenterlineExtractionFilter: the centerlines of the segmentation node. */
  double Extraction{ 0.0 };
  /** CPRDepthImageFilter: depth, fixed mask, owner labels. */
  double Depth{ 0.0 };
  /** BilateralDepthRelaxFilter. */
  double Relax{ 0.0 };
  /** CPRResampleImageFilter on the unfiltered and the relaxed depth. */
  double Resample{ 0.0 };
  /** The cut surface. */
  double Surface{ 0.0 };
  /** The occlusion profile over 180 angles (when it was computed anew). */
  double OcclusionProfile{ 0.0 };
};

/** How many times each stage has run since the logic was made (docs/design.md "Module logic"'s recompute rules are
 * tested on these). \ingroup VesselReformation
 */
struct ReformationStageCounts
{
  unsigned int Conversion{ 0 };
  /** Executions of the centerline extraction (segmentation input only). */
  unsigned int Extraction{ 0 };
  unsigned int Depth{ 0 };
  unsigned int Relax{ 0 };
  /** Executions of the resample stage, whichever of its two images it sampled. */
  unsigned int Resample{ 0 };
  /** CPR images sampled on the unfiltered and on the relaxed depth. */
  unsigned int UnfilteredSamplings{ 0 };
  unsigned int RelaxedSamplings{ 0 };
  unsigned int Surface{ 0 };
};

/** What a reformation returns: output nodes as a platform takes them. The 2D images are one-slice volume nodes
 * lying on the view plane, their view in the "CPR_*" attributes (see vrNodeConversion.h); the surface is in RAS.
 * A node object is replaced only when its stage reruns.
 * \ingroup VesselReformation
 */
struct ReformationOutputs
{
  vtkSmartPointer<VolumeNode> Depth;
  vtkSmartPointer<VolumeNode> RelaxedDepth;
  vtkSmartPointer<VolumeNode> FixedMask;
  vtkSmartPointer<VolumeNode> OwnerLabels;
  /** Visibility mode: the branch whose lumen lies behind the visible one, per pixel (0 = none); null in the other
   * modes. */
  vtkSmartPointer<VolumeNode> HiddenLabels;
  /** Visibility mode: each branch's centerline length and the part this view hides, with its name; empty in the
   * other modes. */
  std::vector<BranchOcclusionRow> BranchOcclusions;
  /** The hidden length against the angle about the view's up axis (0-179 degrees), when the parameters ask for the
   * least occluded angle or SetOcclusionProfileEnabled() is on; else null. */
  std::shared_ptr<const itk::CPROcclusionProfile> OcclusionProfile;
  /** Whether View's angle was chosen as the least occluded one (ReformationParameters::LeastOccludedAngle). */
  bool                        AngleChosen{ false };
  vtkSmartPointer<VolumeNode> UnfilteredCPR;
  vtkSmartPointer<VolumeNode> CPR;
  /** The centerlines extracted from the segmentation node (RAS, radius per point, one polyline per branch); null
   * when the centerlines come from a centerline node. */
  vtkSmartPointer<CenterlineNode> ExtractedCenterlines;
  /** The cut surface coloured by intensity; null while the surface is disabled. */
  vtkSmartPointer<vtkPolyData> Surface;
  /** The resolved view every output lies on. */
  itk::CPRViewGeometry View;
  /** The backend that relaxed the depth ("cpu" or "opencl"), and why that one (e.g. "auto: the OpenCL device ... is
   * a CPU device, where the native CPU path is faster on the same cores, so the CPU"). */
  std::string RelaxBackendUsed;
  std::string RelaxBackendReason;
  /** Where the depth map and the resampling ran ("cpu" or "opencl"), and why: on the relaxation's OpenCL device
   * when it has one, unless the stage has no kernel for the parameters (e.g. cubic interpolation), which the reason
   * then names. */
  std::string DepthBackendUsed;
  std::string DepthBackendReason;
  std::string ResampleBackendUsed;
  std::string ResampleBackendReason;
  StageTimes  Times;
};

/** \class VesselReformationLogic
 * \brief The module logic of the multipath vessel reformation (docs/design.md "Module logic"), shaped like a 3D Slicer
 * loadable module's logic.
 *
 * It takes a volume node, the centerlines (a centerline node, or a segmentation node whose centerlines it extracts)
 * and a parameter object, converts the nodes to ITK through a vr::ReformationInputCache (vrNodeConversion.h, the one
 * place RAS meets LPS), and keeps one
 * ITK pipeline for its lifetime: with a segmentation, CenterlineExtractionFilter first; CPRDepthImageFilter, then
 * BilateralDepthRelaxFilter on the backend the parameters ask for (one CPU filter, and one OpenCL filter per device
 * asked for), then a CPRResampleImageFilter on the unfiltered and one on the relaxed depth; then it builds the cut
 * surface. Where the relaxation runs on an OpenCL device, the depth map and the resampling run on it too (their
 * OpenCL filters, one set per device, sharing the relaxation's session: the volume is uploaded once and the images
 * pass between the stages on the device, vrViewBackend.h); GetDepthFilter() and the resample getters return the
 * filters in use. Each Update() passes the parameters to the filters, whose setters change nothing when a value is the
 * same, and updates the two resample filters: ITK's modified times decide what reruns. Output nodes are made
 * anew for the stages that ran. So:
 * - a new segmentation node (or a change to it), new vessel labels: its vessel mask, the extraction, and everything
 *   after it when the centerlines differ; new root points or minimum branch length: the extraction, and the rest when
 *   the centerlines differ;
 * - new centerlines, view (up, angle, centre, size, spacing), depth mode or lumen fixing: everything;
 * - a new volume: resampling and the surface; the depth map and its relaxation too only when the volume's geometry
 *   changed (it supplies the view's defaults);
 * - new relaxation w, anisotropy a, iterations N: relaxation, the relaxed CPR, surface; a new backend or OpenCL
 *   device: the same, and where the view moves between the CPU and a device, its depth map and unfiltered CPR too
 *   (on the other backend's filters; a set still up to date from before does not rerun);
 * - new interpolation or slab: both CPR images and the surface;
 * - new window or level: nothing (they only choose how the CPR is displayed, GetDisplayWindowLevel()).
 * GetStageCounts() counts every stage execution (the filters' StartEvent) so that tests can check these
 * rules; the filters themselves are reachable for observers of a platform's own.
 *
 * Failures are reported one way, by throwing vr::InputError with a message naming the node, or the parameter by its
 * meaning (also in InputError::Parameter(), see vr::ParameterName) and its value: parameter checks, node
 * conversion, centerlines with no point inside the volume (vr::CheckCenterlineVolumeFit), a view that does not fit in
 * memory, an unavailable backend, filter errors. AbortUpdate() stops a
 * running Update() through ITK's abort flag; that Update() throws vr::Cancelled. Warnings (most centerline points
 * outside the volume: wrong RAS/LPS; the backend auto falling back to the CPU; a steady solve that stopped at its bound
 * of outer iterations, with how far it got; branches without radii in Visibility mode) do not stop the run; they go
 * to the warning callback and GetWarnings().
 *
 * \sa ReformationParameters, VolumeNode, CenterlineNode, itk::CPRDepthImageFilter,
 * itk::BilateralDepthRelaxFilter, itk::CPRResampleImageFilter
 * \ingroup VesselReformation
 */
class VesselReformationLogic
{
public:
  /** Receives the overall progress in [0, 1] and the name of the running stage. */
  using ProgressCallback = std::function<void(double fraction, const std::string & stage)>;
  /** Receives each warning as it arises, and the parameter it concerns by meaning (vr::ParameterName), or "". */
  using WarningCallback = std::function<void(const std::string & message, const std::string & parameter)>;
  using DepthFilterType = itk::CPRDepthImageFilter<DepthImageType>;
  /** Samples the volume in its stored pixel type, whichever it is (docs/design.md "Volumes in their stored type"). */
  using ResampleFilterType = itk::CPRResampleImageFilter<itk::ImageBase<3>, DepthImageType, DepthImageType>;

  VesselReformationLogic();
  ~VesselReformationLogic();
  VesselReformationLogic(const VesselReformationLogic &) = delete;
  VesselReformationLogic &
  operator=(const VesselReformationLogic &) = delete;

  /** \param node the volume to reform (role "volume"); the logic keeps a reference. */
  void
  SetVolumeNode(VolumeNode * node);
  /** \return the volume node, or null. */
  VolumeNode *
  GetVolumeNode() const;

  /** \param node the centerlines (role "centerlines", RAS); the logic keeps a reference. */
  void
  SetCenterlineNode(CenterlineNode * node);
  /** \return the centerline node, or null. */
  CenterlineNode *
  GetCenterlineNode() const;

  /** The segmentation whose centerlines are reformed (role "segmentation"), instead of a centerline node: a label
   * map or mask volume node (3D Slicer's vtkMRMLLabelMapVolumeNode; IJK->RAS geometry, any orientation and spacing),
   * a level set (inside where < 0) or a probability map (>= 0.5), see vr::MakeSegmentationMask. Several masks are
   * combined before (vr::ReadSegmentation). Set exactly one of the segmentation and centerline nodes; Update() throws
   * when both or neither are. The segmentation may lie on another grid than the volume (a warning says so); it
   * must overlap it. The logic keeps a reference; it extracts again only when the node, its vessel labels or the
   * extraction parameters change, and GetOutputs().ExtractedCenterlines holds the result.
   * \param node the segmentation, or null to clear it. */
  void
  SetSegmentationNode(VolumeNode * node);
  /** \return the segmentation node, or null. */
  VolumeNode *
  GetSegmentationNode() const;

  /** \param parameters vessel labels, root points (RAS) and minimum branch length of the extraction; checked by
   * Update(). */
  void
  SetCenterlineExtractionParameters(const CenterlineExtractionParameters & parameters);
  /** \return the extraction parameters the next Update() uses. */
  const CenterlineExtractionParameters &
  GetCenterlineExtractionParameters() const;

  /** \param parameters every setting; checked by Update(). */
  void
  SetParameters(const ReformationParameters & parameters);
  /** \return the parameters the next Update() uses. */
  const ReformationParameters &
  GetParameters() const;

  /** \param enabled whether Update() builds the cut surface (default on; a command line that does not write it
   * saves the time and memory). */
  void
  SetSurfaceEnabled(bool enabled);
  /** \return whether the cut surface is built. */
  bool
  GetSurfaceEnabled() const;

  /** \param enabled whether Update() provides the occlusion profile of the tree about the view's up axis
   * (Outputs.OcclusionProfile), computed again only when the centerlines, the up axis, the centre or the pixel
   * spacing change (a new angle reuses it). Default off; the least occluded angle computes it anyway. */
  void
  SetOcclusionProfileEnabled(bool enabled);
  /** \return whether the occlusion profile is provided. */
  bool
  GetOcclusionProfileEnabled() const;

  /** \param callback receives progress during Update(); may be empty. */
  void
  SetProgressCallback(ProgressCallback callback);
  /** \param callback receives warnings during Update(); may be empty. */
  void
  SetWarningCallback(WarningCallback callback);
  /** \param cache where the nodes are converted to ITK (converted again only when a node changes): one shared with
   * another user of the same nodes (e.g. a view of one vessel path) converts them once for both; null gives the
   * logic a cache of its own again, as it has from construction. */
  void
  SetInputCache(std::shared_ptr<ReformationInputCache> cache);
  /** \return the cache the logic converts its input nodes through. */
  std::shared_ptr<ReformationInputCache>
  GetInputCache() const;
  /** \param query answers which OpenCL device the Auto backend would get (default vr::QueryOpenCLDevice, the
   * installed drivers); the next Update() chooses the backend again. */
  void
  SetOpenCLDeviceQuery(OpenCLDeviceQuery query);

  /** Runs the stages that the changes since the previous Update() invalidate.
   * \return the outputs, valid until the next Update().
   * Throws vr::InputError on bad nodes or parameters, or when a stage fails, and vr::Cancelled when AbortUpdate()
   * stopped it; the outputs of the stages that did not finish stay as they were. */
  const ReformationOutputs &
  Update();

  /** Asks a running Update() (on another thread) to stop as soon as its current filter can: the filter's
   * AbortGenerateData flag is raised from within its own progress report, and that Update() throws vr::Cancelled.
   * Without a running Update() it does nothing; the next Update() runs normally. Thread-safe. */
  void
  AbortUpdate();

  /** \return the centerline extraction filter of the pipeline (one for the logic's lifetime; it runs only with a
   * segmentation node). */
  CenterlineExtractionFilterType *
  GetCenterlineExtractionFilter() const;
  /** \return the depth filter of the pipeline (one for the logic's lifetime). */
  DepthFilterType *
  GetDepthFilter() const;
  /** \return the relax filter the latest Update() used, or null before the first. */
  RelaxFilterType *
  GetRelaxFilter() const;
  /** \return the resample filter of the unfiltered depth. */
  ResampleFilterType *
  GetUnfilteredResampleFilter() const;
  /** \return the resample filter of the relaxed depth (the CPR). */
  ResampleFilterType *
  GetResampleFilter() const;

  /** \return the outputs of the latest Update(). */
  const ReformationOutputs &
  GetOutputs() const;
  /** \return how many times each stage has run since construction. */
  ReformationStageCounts
  GetStageCounts() const;
  /** \return the warnings that hold for the current inputs (centerlines outside the volume, backend fallback, a
   * steady solve stopped short). */
  std::vector<std::string>
  GetWarnings() const;

  /** The window and level to display the CPR with: the parameters' when Window > 0, else the CPR's full range.
   * \param window receives the window width.
   * \param level receives the level (centre). */
  void
  GetDisplayWindowLevel(double & window, double & level) const;

  /** Relaxes one depth map on its own, the relaxation stage without the rest (the BilateralDepthRelax command
   * line module).
   * \param depth the depth map (mm).
   * \param mask the fixed mask (non-zero = fixed), or null.
   * \param parameters Relaxation, Anisotropy, Iterations, Backend and OpenCLDevice are used.
   * \param progress receives progress; may be empty.
   * \param warnings receives the backend notice, if any.
   * \param backendUsed if not null, receives the backend that relaxed ("cpu" or "opencl").
   * \param backendReason if not null, receives why, in words (as ReformationOutputs::RelaxBackendReason).
   * \return the relaxed depth, with the input's metadata. Throws vr::InputError. */
  static DepthImageType::Pointer
  RelaxDepthImage(const DepthImageType *        depth,
                  const MaskImageType *         mask,
                  const ReformationParameters & parameters,
                  const ProgressCallback &      progress,
                  std::vector<std::string> &    warnings,
                  std::string *                 backendUsed = nullptr,
                  std::string *                 backendReason = nullptr);

  /** \param tree centerlines in LPS.
   * \param volume the volume.
   * \return the fraction of centerline points that lie outside the volume's voxel grid. */
  static double
  FractionOfPointsOutside(const itk::CenterlineTree & tree, const VolumeImageType * volume);

private:
  struct Internals;
  std::unique_ptr<Internals> m_Internals;
};
} // namespace vr

#endif
