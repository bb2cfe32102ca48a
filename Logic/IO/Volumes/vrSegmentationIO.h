// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrSegmentationIO_h
#define vrSegmentationIO_h

#include "itkImage.h"
#include "vrImageTypes.h"

#include <map>
#include <string>
#include <vector>

namespace vr
{
/** A vessel mask on the grid of the segmentation it was read from (LPS: origin, spacing and direction kept):
 * 1 = vessel, 0 = background. */
using SegmentationMaskType = LabelMapVolumeType;

/** \class SegmentationReadReport
 * \brief What a segmentation file held and how it was read.
 * \ingroup VesselReformation
 */
struct SegmentationReadReport
{
  /** "label map", "level set (inside where < 0)" or "probability map (inside where >= 0.5)". */
  std::string Kind;
  /** Voxels that became vessel. */
  std::size_t ForegroundVoxels{ 0 };
  /** The distinct values of the file (up to 12, ascending, e.g. "0 1 2"), or their range ("-3.2 to 48.1"). */
  std::string Values;
  /** The names a label map's header gives its labels (3D Slicer's .seg.nrrd: SegmentN_Name and SegmentN_LabelValue,
   * layer 0), by label value; empty when it names none. */
  std::map<int, std::string> LabelNames;
  /** The file's values when LabelNames is not empty (to tell the named vessels apart), else null. */
  itk::Image<float, 3>::Pointer LabelValues;
};

/** The vessel mask of segmentation values already in memory (a platform's label map node), by the rules of
 * ReadSegmentationMask.
 * \param values the segmentation's values (LPS; origin, spacing and direction are copied to the mask).
 * \param labels the labels to take from a label map; empty: every non-zero voxel.
 * \param where how messages name the segmentation ("segmentation aorta.nii.gz").
 * \param report receives what it held; may be null.
 * \return the mask. Throws vr::InputError beginning with \a where on NaN, values that are neither labels, a level
 * set nor probabilities, or labels chosen in a level set or probability map. */
SegmentationMaskType::Pointer
MakeSegmentationMask(const itk::Image<float, 3> * values,
                     const std::vector<double> &  labels,
                     const std::string &          where,
                     SegmentationReadReport *     report = nullptr);

/** Reads a vessel segmentation file (NIfTI, NRRD, MetaImage, ...: what TotalSegmentator, nnU-Net, 3D Slicer and
 * VMTK write) as a mask on its own grid.
 *
 * - A label map or binary mask (whole-number values, of any pixel type): the vessel is every voxel whose value is
 *   one of \a labels, or, with no labels, every non-zero voxel.
 * - A level set or signed distance (floating-point values that are not all whole, some negative; VMTK's
 *   segmentations): the vessel is where the value is < 0.
 * - A probability map (values in [0, 1], not all whole): the vessel is where the value is >= 0.5.
 *
 * \param path the file.
 * \param labels the labels to take from a label map; empty: every non-zero voxel.
 * \param report receives what the file held; may be null.
 * \return the mask; it may be empty (the caller decides whether that is an error, see its report).
 * Throws vr::InputError naming the file when it is missing or unreadable, not 3D (a 2D image), not scalar, holds
 * NaN, or when \a labels are given for a level set or probability map. */
SegmentationMaskType::Pointer
ReadSegmentationMask(const std::string &         path,
                     const std::vector<double> & labels = {},
                     SegmentationReadReport *    report = nullptr);
} // namespace vr

#endif
