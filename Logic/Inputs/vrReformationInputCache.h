// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrReformationInputCache_h
#define vrReformationInputCache_h

#include "itkCenterlineTree.h"
#include "vrCenterlineNode.h"
#include "vrImageTypes.h"
#include "vrSegmentationIO.h"
#include "vrStoredVolume.h"
#include "vrVolumeNode.h"

#include <vtkWeakPointer.h>

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace vr
{
/** \class ReformationInputCache
 * \brief The inputs of a reformation as ITK sees them (docs/design.md "Module logic"): the volume node as an LPS image
 * with its minimum, the centerline node as a tree, the segmentation node as a vessel mask; each converted again only
 * when its node changed (another node, or the node's modified time).
 *
 * Each Get returns the converted value, shared: the same object as long as the node is unchanged, a new one after a
 * conversion, so that a user tells a change by comparing it with the object it used last. Several users on the same
 * nodes (the module logic and a view of one vessel path) share one cache, and so one conversion; the volume is never
 * copied (its image reads the node's voxels); the cache keeps one entry per role (volume, centerlines, segmentation). A
 * conversion that throws (vr::InputError naming the node) leaves no entry, so the next Get tries again. Thread-safe:
 * one conversion at a time. \ingroup VesselReformation
 */
class ReformationInputCache
{
public:
  /** The volume node as an ITK image (LPS) in the node's pixel type, sharing the node's voxels
   * (vr::ConvertVolumeNodeToStoredVolume), its intensity rescale and its smallest intensity (the resampling's default
   * value). */
  struct Volume
  {
    itk::ImageBase<3>::Pointer Image;
    itk::CPRIntensityRescale   Rescale;
    double                     Minimum{ 0.0 };
  };
  /** The segmentation node as a vessel mask (vr::MakeSegmentationMask) and the names of its regions
   * (RegionNameAttributePrefix attributes), by value; Values holds the node's voxels when it names a region (to name
   * the extracted branches), else null. */
  struct Segmentation
  {
    SegmentationMaskType::Pointer Mask;
    VolumeImageType::Pointer      Values;
    std::map<int, std::string>    RegionNames;
  };

  ReformationInputCache();
  ~ReformationInputCache();
  ReformationInputCache(const ReformationInputCache &) = delete;
  ReformationInputCache &
  operator=(const ReformationInputCache &) = delete;

  /** \param node the volume node (not null).
   * \return its conversion, converted now when \a node differs from the previous call's or was modified since. */
  std::shared_ptr<const Volume>
  GetVolume(VolumeNode * node);

  /** Gives the conversion of \a node ready-made, for a host that holds the voxels as an ITK image already and made
   * the node over the same memory (the Python package views a numpy array with both, vr::IJKToRASMatrixOf): until
   * the node changes, GetVolume(node) returns \a image itself, neither converted nor copied.
   * \param node the volume node (not null), whose voxels and IJK->RAS geometry are \a image's.
   * \param image the volume in LPS (not null); its minimum is computed now. */
  void
  SetVolume(VolumeNode * node, VolumeImageType::Pointer image);

  /** \param node the centerline node (RAS, not null).
   * \return its tree in LPS, converted now when \a node differs from the previous call's or was modified since. */
  std::shared_ptr<const itk::CenterlineTree>
  GetCenterlines(CenterlineNode * node);

  /** Gives the conversion of \a node ready-made, for a host that read the tree itself and made the node of it (a
   * command-line module, the Python package; vr::ConvertTreeToCenterlineNode): until the node changes,
   * GetCenterlines(node) returns \a tree as it is, not the tree converted back from the node's polylines (which cuts a
   * trunk where a child leaves it, and so may renumber the branches).
   * \param node the centerline node made of \a tree (not null).
   * \param tree the tree in LPS. */
  void
  SetCenterlines(CenterlineNode * node, const itk::CenterlineTree & tree);

  /** \param node the segmentation node (not null).
   * \param labels the vessel labels (vr::CenterlineExtractionParameters::Labels; empty: every non-zero voxel).
   * \return its vessel mask, made now when \a node or \a labels differ from the previous call's or the node was
   * modified since. Throws vr::InputError when no voxel is vessel. */
  std::shared_ptr<const Segmentation>
  GetSegmentation(VolumeNode * node, const std::vector<double> & labels);

  /** \return how the messages name \a node: segmentation "name", or segmentation when it has no name. */
  static std::string
  DescribeSegmentationNode(const VolumeNode * node);

private:
  /** Keeps \a stored as the conversion of \a node at modified time \a time, with its minimum (m_Mutex held). */
  void
  KeepVolume(VolumeNode * node, vtkMTimeType time, const StoredVolume & stored);

  std::mutex m_Mutex;

  vtkWeakPointer<VolumeNode>    m_VolumeNode;
  vtkMTimeType                  m_VolumeTime{ 0 };
  std::shared_ptr<const Volume> m_Volume;

  vtkWeakPointer<CenterlineNode>             m_CenterlineNode;
  vtkMTimeType                               m_CenterlineTime{ 0 };
  std::shared_ptr<const itk::CenterlineTree> m_Centerlines;

  vtkWeakPointer<VolumeNode>          m_SegmentationNode;
  vtkMTimeType                        m_SegmentationTime{ 0 };
  std::vector<double>                 m_SegmentationLabels;
  std::shared_ptr<const Segmentation> m_Segmentation;
};
} // namespace vr

#endif
