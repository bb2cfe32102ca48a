// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrCenterlineExtraction_h
#define vrCenterlineExtraction_h

#include "itkCenterlineExtractionFilter.h"
#include "itkCenterlineTree.h"
#include "vrSegmentationIO.h"
#include "vrVolumeNode.h"

#include <vtkSmartPointer.h>

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace vr
{
/** \class CenterlineExtractionParameters
 * \brief What a user chooses when centerlines are extracted from a segmentation, named by meaning (the command
 * line maps its flags to these).
 * \ingroup VesselReformation
 */
struct CenterlineExtractionParameters
{
  /** The labels of a label map that make up the vessels (whole numbers >= 0); empty: every non-zero voxel. */
  std::vector<double> Labels;
  /** Points at the proximal end of a vessel tree, in RAS mm as a platform hands them over (3D Slicer's markups),
   * at most one per connected component, each within RootPointTolerance of a vessel voxel; components without one
   * are rooted at their widest free end. */
  std::vector<itk::Point<double, 3>> RootPointsRAS;
  /** How far (mm) a root point may lie from the nearest vessel voxel. */
  double RootPointTolerance{ 10.0 };
  /** Terminal branches shorter than this (mm, >= 0) are dropped. */
  double MinimumBranchLength{ 0.0 };

  /** Throws vr::InputError naming the parameter and the value when one is out of range. */
  void
  Validate() const;
};

/** \class Segmentation
 * \brief A vessel segmentation ready for extraction: the masks of one or more files (TotalSegmentator writes one
 * per vessel) combined on the first file's grid.
 * \ingroup VesselReformation
 */
struct Segmentation
{
  SegmentationMaskType::Pointer Mask;
  /** On the mask's grid, which file each vessel voxel came from: 0 outside, k for the k-th file (the first file that
   * has it where files overlap); for a single label map whose header names its labels (3D Slicer's .seg.nrrd), k for
   * the k-th named label; null otherwise (a single unnamed file, more than 255). */
  SegmentationMaskType::Pointer Regions;
  /** The vessel each region is: RegionNames[k - 1] for region k, from its file's name as TotalSegmentator writes
   * them ("iliac_artery_left.nii.gz" gives "iliac artery left"), or the label's name in the file's header. */
  std::vector<std::string> RegionNames;
  /** The file names (not paths), comma-separated: how messages name the segmentation. */
  std::string Name;
  /** One line per file: its name, what it held and how many vessel voxels it gave. */
  std::vector<std::string> Descriptions;
};

/** The prefix of a segmentation node's attributes that name its regions: attribute "<prefix><k>" names the voxels of
 * value k (vr::ReadSegmentationNode sets them; a platform may too). */
constexpr const char * RegionNameAttributePrefix = "VesselReformation.RegionName.";

/** \return the vessel a segmentation file holds, from its name: the folder and the extension (.nii.gz, .nii, .nrrd,
 * .seg.nrrd, .nhdr, .mha, .mhd) dropped and underscores read as spaces ("aorta.nii.gz": "aorta";
 * "common_carotid_artery_left.nii.gz": "common carotid artery left"). */
std::string
VesselNameOfFile(const std::string & path);

/** Names each branch of \a tree after the region most of its points lie in (the voxel nearest each point);
 * branches whose points lie in no named region keep their name.
 * \param tree LPS mm.
 * \param regions region values on a grid (LPS); non-integral values are rounded.
 * \param names the name of each region value. */
void
NameBranchesByRegion(itk::CenterlineTree &              tree,
                     const itk::Image<float, 3> *       regions,
                     const std::map<int, std::string> & names);
void
NameBranchesByRegion(itk::CenterlineTree &              tree,
                     const SegmentationMaskType *       regions,
                     const std::map<int, std::string> & names);

/** Splits a comma-separated list of segmentation files; a text that names an existing file as it is stays whole
 * (a file name may contain a comma).
 * \param text "a.nii.gz" or "a.nii.gz,b.nii.gz".
 * \return the paths; empty entries are dropped. */
std::vector<std::string>
SplitSegmentationPaths(const std::string & text);

/** Reads segmentation files (see vr::ReadSegmentationMask) and combines them: the vessel is the union of every
 * file's vessel voxels (with \a labels chosen in each label map), on the first file's grid. A file on another grid
 * is resampled onto it (nearest neighbour, in physical space), with a warning.
 * \param paths one or more files.
 * \param labels the labels to take from label maps; empty: every non-zero voxel.
 * \param warnings receives a line per warning.
 * \return the combined segmentation. Throws vr::InputError naming the file(s) when one cannot be read, when no
 * path is given, or when no file holds a vessel voxel (naming the labels and the values the files hold). */
Segmentation
ReadSegmentation(const std::vector<std::string> & paths,
                 const std::vector<double> &      labels,
                 std::vector<std::string> &       warnings);

/** \return region value -> name of \a segmentation's regions (empty without regions). */
std::map<int, std::string>
RegionNamesOf(const Segmentation & segmentation);

/** \a segmentation as a platform's label map node, for VesselReformationLogic::SetSegmentationNode: value k for the
 * k-th file's vessel voxels, each named by the attribute RegionNameAttributePrefix + k, so that the logic names the
 * extracted branches; the plain mask (1 = vessel) when it has no regions.
 * \param segmentation what ReadSegmentation returned.
 * \return a new node named segmentation.Name. */
vtkSmartPointer<VolumeNode>
MakeSegmentationNode(const Segmentation & segmentation);

/** \class CenterlineExtractionReport
 * \brief What an extraction found.
 * \ingroup VesselReformation
 */
struct CenterlineExtractionReport
{
  /** Connected components of the vessel mask, and those too small or round to have a centerline. */
  std::size_t Components{ 0 };
  std::size_t ComponentsWithoutCenterline{ 0 };
  /** Per branch of the tree, the id of its parent branch (0: it starts at a root). */
  std::vector<int> ParentBranchIds;
};

/** The extraction filter the logic runs: on a vessel mask (1 = vessel). */
using CenterlineExtractionFilterType = itk::CenterlineExtractionFilter<SegmentationMaskType>;

/** Passes \a parameters to \a filter: root points converted from RAS to LPS (the one place this extraction meets
 * RAS) and the minimum branch length; the filter's setters change nothing when a value is the same, so ITK reruns it
 * only on a change. Throws vr::InputError naming the parameter when \a parameters are out of range or a root point
 * lies farther than their tolerance from every vessel voxel of \a mask (said in RAS, with a hint about LPS).
 * \param filter the filter, its input already \a mask.
 * \param mask the vessel mask.
 * \param name how messages name the segmentation ("segmentation aorta.nii.gz"). */
void
ConfigureCenterlineExtraction(CenterlineExtractionFilterType *       filter,
                              const SegmentationMaskType *           mask,
                              const std::string &                    name,
                              const CenterlineExtractionParameters & parameters);

/** Extracts the centerline tree of a vessel mask with itk::CenterlineExtractionFilter, once (the ExtractCenterlines
 * module; VesselReformationLogic keeps a filter of its own).
 * \param mask 1 = vessel, LPS.
 * \param name how messages name the segmentation ("segmentation aorta.nii.gz").
 * \param parameters root points (RAS; converted to LPS here, the one place this extraction meets RAS) and the
 *        minimum branch length (Labels are the reader's business and ignored here).
 * \param progress called with a fraction in [0, 1] and "centerlines"; may be empty; it may throw to cancel.
 * \param warnings receives a line when components gave no centerline.
 * \param report receives the components and the branches' parents; may be null.
 * \return the tree, LPS mm, radii per point, ids 1, 2, ... Throws vr::InputError naming \a name and the parameter
 * on a bad parameter, an empty mask, a root point far from every vessel, or no elongated component. */
itk::CenterlineTree
ExtractCenterlineTree(const SegmentationMaskType *                                            mask,
                      const std::string &                                                     name,
                      const CenterlineExtractionParameters &                                  parameters,
                      const std::function<void(double fraction, const std::string & stage)> & progress,
                      std::vector<std::string> &                                              warnings,
                      CenterlineExtractionReport *                                            report = nullptr);
} // namespace vr

#endif
