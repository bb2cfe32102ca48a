// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrVesselReformationLogic_h
#define vrVesselReformationLogic_h

#include "itkCPRViewGeometry.h"
#include "vrCenterlineNode.h"
#include "vrReformationParameters.h"
#include "vrRelaxBackend.h"
#include "vrImageTypes.h"
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
  /** Nodes to ITK images and the centerline tree. */
  double Conversion{ 0.0 };
  /** CPRDepthImageFilter: depth, fixed mask, owner labels. */
  double Depth{ 0.0 };
  /** BilateralDepthRelaxFilter. */
  double Relax{ 0.0 };
  /** CPRResampleImageFilter on the unfiltered and the relaxed depth. */
  double Resample{ 0.0 };
  /** The cut surface. */
  double Surface{ 0.0 };
};

/** How many times each stage has run since the logic was made (DESIGN 3.7's recompute rules are tested on
 * these).
 * \ingroup VesselReformation
 */
struct StageCounts
{
  unsigned int Conversion{ 0 };
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
  vtkSmartPointer<VolumeNode> UnfilteredCPR;
  vtkSmartPointer<VolumeNode> CPR;
  /** The cut surface coloured by intensity; null while the surface is disabled. */
  vtkSmartPointer<vtkPolyData> Surface;
  /** The resolved view every output lies on. */
  itk::CPRViewGeometry View;
  /** The backend that relaxed the depth ("cpu" or "opencl"). */
  std::string RelaxBackendUsed;
  StageTimes  Times;
};

/** \class VesselReformationLogic
 * \brief The module logic of the multipath vessel reformation (DESIGN 3.7), shaped like a 3D Slicer loadable
 * module's logic.
 *
 * It takes a volume node, a centerline node and a parameter object, converts the nodes to ITK (vrNodeConversion.h,
 * the one place RAS meets LPS), and runs CPRDepthImageFilter, then BilateralDepthRelaxFilter on the backend the
 * parameters ask for (through vr::CreateRelaxFilter), then CPRResampleImageFilter on both the unfiltered and the
 * relaxed depth, and builds the cut surface. It returns output nodes with the time of each stage.
 *
 * Update() recomputes only what changed since the previous Update() invalidates:
 * - new volume or centerline node (or a modified one), view (up, angle, centre, size, spacing), depth mode or lumen
 *   fixing: everything;
 * - new relaxation w, anisotropy a, iterations N, backend or OpenCL device: relaxation, the relaxed CPR, surface;
 * - new interpolation or slab: both CPR images and the surface;
 * - new window or level: nothing (they only choose how the CPR is displayed, GetDisplayWindowLevel()).
 * GetStageExecutionCounts() counts every stage execution so that tests can check these rules.
 *
 * Failures are reported one way, by throwing vr::InputError with a message naming the node, the parameter and its
 * value (parameter checks, node conversion, a view that does not fit in memory, an unavailable backend, filter
 * errors). Warnings (most centerline points outside the volume: wrong RAS/LPS; the backend auto falling back to
 * the CPU) do not stop the run; they go to the warning callback and GetWarnings().
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
  /** Receives each warning as it arises. */
  using WarningCallback = std::function<void(const std::string & message)>;

  /** Bytes of memory one view pixel costs across every stage and output (see EstimateMemoryInBytes). */
  static constexpr double BytesPerViewPixel = 160.0;

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

  /** \param callback receives progress during Update(); may be empty. */
  void
  SetProgressCallback(ProgressCallback callback);
  /** \param callback receives warnings during Update(); may be empty. */
  void
  SetWarningCallback(WarningCallback callback);

  /** Runs the stages that the changes since the previous Update() invalidate.
   * \return the outputs, valid until the next Update().
   * Throws vr::InputError on bad nodes or parameters, or when a stage fails; the outputs of the stages that did
   * not run stay as they were. */
  const ReformationOutputs &
  Update();

  /** \return the outputs of the latest Update(). */
  const ReformationOutputs &
  GetOutputs() const;
  /** \return how many times each stage has run since construction. */
  StageCounts
  GetStageExecutionCounts() const;
  /** \return the warnings that hold for the current inputs (centerlines outside the volume, backend fallback). */
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
   * \return the relaxed depth, with the input's metadata. Throws vr::InputError. */
  static DepthImageType::Pointer
  RelaxDepthImage(const DepthImageType *        depth,
                  const MaskImageType *         mask,
                  const ReformationParameters & parameters,
                  const ProgressCallback &      progress,
                  std::vector<std::string> &    warnings);

  /** \param size a view's size in pixels.
   * \return the bytes the reformation of that view needs: depth, mask, labels, relaxation buffers, both CPRs,
   * the output nodes and the surface. */
  static double
  EstimateMemoryInBytes(const itk::Size<2> & size);
  /** \return the memory this process may still allocate, in bytes (MemAvailable of /proc/meminfo, else the
   * free physical pages). */
  static double
  AvailableMemoryInBytes();

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
