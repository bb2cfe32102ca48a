// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCPRDepthImageFilter_h
#define itkCPRDepthImageFilter_h

#include "itkCPRBranchOcclusion.h"
#include "itkCPRDepthMode.h"
#include "itkCPRDepthWorkspace.h"
#include "itkCPRViewGeometry.h"
#include "itkCenterlineTree.h"
#include "itkImage.h"
#include "itkImageSource.h"

#include <vector>

namespace itk
{
/** \class CPRDepthImageFilter
 * \brief Computes the multipath CPR depth map of a centerline tree for a view (docs/design.md "Depth").
 *
 * Four outputs on the view's image grid: the depth along the view direction v in mm (output 0), the fixed
 * mask (output 1, 1 = fixed: centerline pixels and, with FixLumen, pixels within the owner's lumen radius), the
 * owner labels (output 2, the id of the branch whose centerline pixel gave the depth, 0 = none) and the hidden labels
 * (output 3, Visibility mode: the id of the branch whose lumen lies behind the visible one, 0 = none; all 0 in the
 * other modes).
 *
 * Every centerline point is projected into the view; each pixel a projected segment passes through is a
 * centerline pixel, with depth and radius interpolated along the segment and the nearer vessel winning where
 * two cross. In Scanline mode (mpCPR, the default) every pixel takes the nearest centerline pixel of its own
 * row and rows without one copy the nearest row that has one, which gives the classical projected CPR and its
 * vertical and horizontal seams. In Nearest mode every pixel takes the nearest centerline pixel in 2D. In
 * Visibility mode every vessel's projected lumen footprint shows the lumen the view ray meets first, so that where
 * vessels overlap in projection the one in front is shown whole and no row alternates between them; the pixels
 * outside every footprint take the nearest footprint pixel in 2D; the hidden labels and GetBranchOcclusions() say what
 * lies behind. Its footprints need radii: a branch without them is its centerline alone.
 *
 * Depth on another device: a subclass that computes some modes elsewhere (OpenCL) overrides GenerateData() and calls
 * this class's GenerateData() for a mode it lacks; the mode is a parameter like any other, so the fallback needs no
 * other seam.
 *
 * The view is given as a CPRViewSpecification and resolved against the tree and the optional reference volume
 * (used only for defaults: the smallest spacing and the automatic up axis); GetView() returns it after
 * UpdateOutputInformation(). Each output carries the view in its metadata dictionary.
 *
 * Only the reference volume's geometry (origin, spacing, direction, largest region) matters, never its voxels: it
 * is not a pipeline input, its information is brought up to date and compared when this filter's is, and the
 * filter reruns only when that geometry changed. So a new volume of the same geometry (another phase, a filtered
 * copy) reruns the resampling downstream but not the depth map or its relaxation. Setting a parameter to the
 * value it has changes nothing, as in ITK's own filters.
 *
 * Reference: Kretschmer, Preim, Stamminger, "Bilateral Depth Filtering for Enhanced Vessel Reformation",
 * EuroVis 2014; Kanitsar et al., "CPR - Curved Planar Reformation", IEEE Visualization 2002.
 *
 * \sa BilateralDepthRelaxFilter, CPRResampleImageFilter, CPRViewGeometry, CenterlineTree
 * \ingroup VesselReformation
 */
template<typename TDepthImage = Image<float, 2>>
class ITK_TEMPLATE_EXPORT CPRDepthImageFilter : public ImageSource<TDepthImage>
{
public:
  ITK_DISALLOW_COPY_AND_MOVE(CPRDepthImageFilter);

  static_assert(TDepthImage::ImageDimension == 2, "the depth map is a 2D image");

  using Self = CPRDepthImageFilter;
  using Superclass = ImageSource<TDepthImage>;
  using Pointer = SmartPointer<Self>;
  using ConstPointer = SmartPointer<const Self>;

  using DepthImageType = TDepthImage;
  using MaskImageType = Image<unsigned char, 2>;
  using LabelPixelType = uint32_t;
  using LabelImageType = Image<LabelPixelType, 2>;
  using ReferenceVolumeType = ImageBase<3>;

  itkNewMacro(Self);
  itkTypeMacro(CPRDepthImageFilter, ImageSource);

  /** The centerlines, in LPS mm. */
  void
  SetCenterlineTree(const CenterlineTree & tree);
  const CenterlineTree &
  GetCenterlineTree() const
  {
    return m_CenterlineTree;
  }

  /** What the user asks of the view; resolved in UpdateOutputInformation(). */
  void
  SetViewSpecification(const CPRViewSpecification & specification);
  const CPRViewSpecification &
  GetViewSpecification() const
  {
    return m_ViewSpecification;
  }
  /** The resolved view, valid after UpdateOutputInformation(). */
  const CPRViewGeometry &
  GetView() const
  {
    return m_View;
  }

  /** Optional volume whose geometry supplies the default spacing and the automatic up axis; kept by reference,
   * only its geometry is read (see the class comment). */
  void
  SetReferenceVolume(const ReferenceVolumeType * volume);
  const ReferenceVolumeType *
  GetReferenceVolume() const
  {
    return m_ReferenceVolume;
  }

  /** Brings the reference volume's information up to date first, and marks this filter modified when its
   * geometry changed since the previous update. */
  void
  UpdateOutputInformation() override;

  /** Scanline (mpCPR, default), Nearest or Visibility. */
  itkSetEnumMacro(Mode, CPRDepthMode);
  itkGetEnumMacro(Mode, CPRDepthMode);

  /** Also fix the pixels within the owner's lumen radius (mm), when the tree has radii. Default on. */
  itkSetMacro(FixLumen, bool);
  itkGetConstMacro(FixLumen, bool);
  itkBooleanMacro(FixLumen);

  DepthImageType *
  GetDepthOutput()
  {
    return this->GetOutput();
  }
  MaskImageType *
  GetFixedMaskOutput();
  LabelImageType *
  GetOwnerLabelOutput();
  /** Visibility mode: the branch whose lumen lies wholly behind the visible one, per pixel (0 = none). */
  LabelImageType *
  GetHiddenLabelOutput();

  /** Visibility mode, after an update: each branch's length and how much of it this view hides (in the tree's
   * order); empty after an update in another mode. */
  const std::vector<CPRBranchOcclusion> &
  GetBranchOcclusions() const
  {
    return m_BranchOcclusions;
  }

  /** Creates the outputs' data objects: depth, mask, owner and hidden labels. */
  using Superclass::MakeOutput;
  DataObject::Pointer
  MakeOutput(ProcessObject::DataObjectPointerArraySizeType index) override;

protected:
  CPRDepthImageFilter();
  ~CPRDepthImageFilter() override = default;

  /** Validates the tree and resolves the view; sets every output's grid and view metadata. */
  void
  GenerateOutputInformation() override;
  void
  EnlargeOutputRequestedRegion(DataObject * output) override;
  void
  GenerateData() override;

  void
  PrintSelf(std::ostream & os, Indent indent) const override;

private:
  CenterlineTree                             m_CenterlineTree;
  CPRViewSpecification                       m_ViewSpecification;
  typename ReferenceVolumeType::ConstPointer m_ReferenceVolume;
  /** The geometry of the reference volume the current view was resolved with (no voxels); null without one. */
  typename ReferenceVolumeType::Pointer m_ReferenceGeometry;
  CPRViewGeometry                       m_View;
  CPRDepthMode                          m_Mode{ CPRDepthMode::Scanline };
  bool                                  m_FixLumen{ true };
  std::vector<CPRBranchOcclusion>       m_BranchOcclusions;

  // Work buffers kept between updates: a new angle then allocates (and page-faults) nothing.
  CPRDepthWorkspacePointer m_Workspace;
};

} // namespace itk

#ifndef ITK_MANUAL_INSTANTIATION
#include "itkCPRDepthImageFilter.hxx"
#endif

namespace itk
{
// Instantiated once, in the VesselReformationFilters library, for the pixel types the module uses.
extern template class CPRDepthImageFilter<Image<float, 2>>;
} // namespace itk

#endif
