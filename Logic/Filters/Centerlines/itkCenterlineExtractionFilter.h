// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCenterlineExtractionFilter_h
#define itkCenterlineExtractionFilter_h

#include "itkCenterlineTree.h"
#include "itkImage.h"
#include "itkProcessObject.h"
#include "itkSimpleDataObjectDecorator.h"

#include <functional>
#include <vector>

namespace itk
{
/** \class CenterlineExtractionSettings
 * \brief What the non-template part of CenterlineExtractionFilter needs (see the filter's parameters).
 * \ingroup VesselReformation
 */
struct CenterlineExtractionSettings
{
  std::vector<Point<double, 3>> RootPoints;
  double                        RootPointTolerance{ 10.0 };
  double                        MinimumBranchLength{ 0.0 };
  double                        SpurRadiusRatio{ 2.0 };
  double                        InvalidationScale{ 1.5 };
  double                        PointSpacing{ 0.0 };
  int                           NumberOfWorkUnits{ 1 };
};

/** \class CenterlineExtractionOutcome
 * \brief What it found: the tree, each branch's parent, the components.
 * \ingroup VesselReformation
 */
struct CenterlineExtractionOutcome
{
  CenterlineTree   Tree;
  std::vector<int> ParentBranchIds;
  std::size_t      NumberOfComponents{ 0 };
  std::size_t      NumberOfComponentsWithoutCenterline{ 0 };
  std::size_t      NumberOfForegroundVoxels{ 0 };
};

/** The work of every CenterlineExtractionFilter on the binary mask of the chosen labels (non-zero = foreground),
 * cropped to the foreground's bounding box plus a background margin of one voxel: distance map, components, TEASAR
 * skeletons, smooth branches. Compiled once. \a progress gets fractions in [0, 1]. Throws itk::ExceptionObject
 * on a bad root point or when no component yields a centerline. */
CenterlineExtractionOutcome
ExtractCenterlinesFromPaddedMask(const Image<unsigned char, 3> *      paddedMask,
                                 const CenterlineExtractionSettings & settings,
                                 const std::function<void(double)> &  progress);

/** \class CenterlineExtractionFilter
 * \brief Extracts the centerline tree of the vessels in a segmentation: a binary mask, or a label map with chosen
 * labels.
 *
 * The foreground (every non-zero voxel, or the voxels whose value is one of ForegroundLabels, so several masks
 * written into one label map combine) is cropped to its bounding box plus a one-voxel margin; the rest of the grid
 * is never visited. On it:
 *
 * 1. A compact list of the foreground voxels and the distance D from each to the nearest background voxel centre,
 *    in mm (the spacing honoured, so anisotropic voxels are measured right): the exact Euclidean distance transform,
 *    the one itk::SignedMaurerDistanceMapImageFilter gives (a test compares them), computed along only the lines
 *    of the box that cross the foreground, so that its cost grows with the vessels rather than with their box.
 * 2. The 26-connected components of the foreground, by a search over that list.
 * 3. Per component, the TEASAR skeleton (Sato et al., "TEASAR: tree-structure extraction algorithm for accurate
 *    and robust skeletons", Pacific Graphics 2000, as in kimimaro): one Dijkstra sweep from the root over the
 *    component, a unit of length through a voxel costing (Dmax / D)^2 (a minimal path of the speed D^2, which keeps
 *    to the middle of the lumen); then repeatedly the uncovered voxel farthest from the root along its minimal
 *    path, whose path back to the tree becomes a new branch once its end is trimmed to where it leaves the middle;
 *    voxels within InvalidationScale D + one voxel of each new path are covered. A terminal branch reaching less
 *    than SpurRadiusRatio times its own radius beyond its parent's lumen, or shorter than MinimumBranchLength, is
 *    a spur and dropped.
 * 4. The tree of each component is rooted at its most proximal end: the free end of largest radius (found by a
 *    first trace, the tree then traced again from there so that junctions form where branches leave their parent),
 *    or the voxel nearest a given root point. Branches are split at junctions and numbered 1, 2, ... from the root,
 *    wider children first; components by decreasing size.
 * 5. Each branch is smoothed (local linear regression along its arc length, width half its radius and at least a
 *    voxel diagonal), centred on the ridge of D in the plane across it (to a fraction of a voxel, where a voxel path
 *    cannot follow an axis running between voxel centres), smoothed again, resampled every PointSpacing mm and
 *    mapped to LPS through the image's origin, spacing and direction. Junctions are shared by the branches that
 *    meet there. The lumen radius at each point is D interpolated there plus 0.3 voxel across the branch (the
 *    interpolation flattens D's ridge; calibrated on voxelised tubes of radius 1.5 to 9 voxels), smoothed.
 *
 * Any orientation and spacing: every length is physical. The output is a SimpleDataObjectDecorator holding an
 * itk::CenterlineTree (LPS mm, a radius per point, ids >= 1); GetCenterlineTree() returns it after Update().
 * A segmentation without foreground, or without a component elongated enough to have a centerline (a speck, a
 * blob), raises an itk::ExceptionObject that says so.
 *
 * Memory: over the bounding box, the mask (1 byte a voxel) and the compact index (4 bytes); over the foreground,
 * a few arrays. One thread: a 256^3 tree of 63 sections takes about 0.2 s (Testing/Benchmarks).
 *
 * \sa CenterlineTree, CPRDepthImageFilter
 * \ingroup VesselReformation
 */
template<typename TLabelImage>
class ITK_TEMPLATE_EXPORT CenterlineExtractionFilter : public ProcessObject
{
public:
  ITK_DISALLOW_COPY_AND_MOVE(CenterlineExtractionFilter);

  static_assert(TLabelImage::ImageDimension == 3, "the segmentation is a 3D image");

  using Self = CenterlineExtractionFilter;
  using Superclass = ProcessObject;
  using Pointer = SmartPointer<Self>;
  using ConstPointer = SmartPointer<const Self>;

  using LabelImageType = TLabelImage;
  using LabelType = typename TLabelImage::PixelType;
  using LabelListType = std::vector<LabelType>;
  using PointType = Point<double, 3>;
  using PointListType = std::vector<PointType>;
  using CenterlineTreeObjectType = SimpleDataObjectDecorator<CenterlineTree>;

  itkNewMacro(Self);
  itkTypeMacro(CenterlineExtractionFilter, ProcessObject);

  /** The segmentation: a binary mask or a label map, in any orientation and spacing. */
  using Superclass::SetInput;
  void
  SetInput(const LabelImageType * image);
  const LabelImageType *
  GetInput() const;

  /** The labels that make up the vessels; empty (the default): every non-zero voxel. */
  void
  SetForegroundLabels(const LabelListType & labels);
  const LabelListType &
  GetForegroundLabels() const
  {
    return m_ForegroundLabels;
  }

  /** Points (LPS, mm) at the proximal end of a vessel tree, at most one per connected component: that component's
   * tree is rooted at the foreground voxel nearest the point. Components without one are rooted at their free end
   * of largest radius. Empty by default. */
  void
  SetRootPoints(const PointListType & points);
  const PointListType &
  GetRootPoints() const
  {
    return m_RootPoints;
  }

  /** How far (mm) a root point may lie from the nearest foreground voxel. Default 10 mm. */
  itkSetMacro(RootPointTolerance, double);
  itkGetConstMacro(RootPointTolerance, double);

  /** Terminal branches shorter than this (mm) are dropped. Default 0: only spurs by the radius rule go. */
  itkSetMacro(MinimumBranchLength, double);
  itkGetConstMacro(MinimumBranchLength, double);

  /** A terminal branch reaching less than this many times its own radius beyond its parent's lumen is a spur
   * (dimensionless). Default 2. */
  itkSetMacro(SpurRadiusRatio, double);
  itkGetConstMacro(SpurRadiusRatio, double);

  /** Each new path covers the voxels within this many times its lumen radius plus one voxel (dimensionless):
   * smaller finds shorter side branches and more spurs. Default 1.5. */
  itkSetMacro(InvalidationScale, double);
  itkGetConstMacro(InvalidationScale, double);

  /** Distance between consecutive centerline points (mm); 0 (the default): half the smallest voxel spacing. */
  itkSetMacro(PointSpacing, double);
  itkGetConstMacro(PointSpacing, double);

  /** The centerlines, after Update(). */
  const CenterlineTree &
  GetCenterlineTree() const;
  CenterlineTreeObjectType *
  GetOutput();

  /** After Update(): per branch of the tree, in order, the id of its parent branch, 0 for a branch that starts at
   * a root. */
  const std::vector<int> &
  GetParentBranchIds() const
  {
    return m_ParentBranchIds;
  }
  /** After Update(): connected components of the foreground, and how many of them were too small or too round to
   * have a centerline. */
  itkGetConstMacro(NumberOfComponents, SizeValueType);
  itkGetConstMacro(NumberOfComponentsWithoutCenterline, SizeValueType);

  using Superclass::MakeOutput;
  DataObject::Pointer
  MakeOutput(DataObjectPointerArraySizeType index) override;

protected:
  CenterlineExtractionFilter();
  ~CenterlineExtractionFilter() override = default;

  void
  VerifyPreconditions() ITKv5_CONST override;
  /** The whole segmentation is needed. */
  void
  GenerateInputRequestedRegion() override;
  void
  GenerateData() override;

  void
  PrintSelf(std::ostream & os, Indent indent) const override;

private:
  LabelListType    m_ForegroundLabels;
  PointListType    m_RootPoints;
  double           m_RootPointTolerance{ 10.0 };
  double           m_MinimumBranchLength{ 0.0 };
  double           m_SpurRadiusRatio{ 2.0 };
  double           m_InvalidationScale{ 1.5 };
  double           m_PointSpacing{ 0.0 };
  std::vector<int> m_ParentBranchIds;
  SizeValueType    m_NumberOfComponents{ 0 };
  SizeValueType    m_NumberOfComponentsWithoutCenterline{ 0 };
};

} // namespace itk

#ifndef ITK_MANUAL_INSTANTIATION
#include "itkCenterlineExtractionFilter.hxx"
#endif

namespace itk
{
// Instantiated once, in the VesselReformationFilters library, for the label types segmentations come in.
extern template class CenterlineExtractionFilter<Image<unsigned char, 3>>;
extern template class CenterlineExtractionFilter<Image<short, 3>>;
extern template class CenterlineExtractionFilter<Image<unsigned short, 3>>;
extern template class CenterlineExtractionFilter<Image<int, 3>>;
extern template class CenterlineExtractionFilter<Image<float, 3>>;
} // namespace itk

#endif
