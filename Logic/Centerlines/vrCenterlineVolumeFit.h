// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrCenterlineVolumeFit_h
#define vrCenterlineVolumeFit_h

#include "itkCenterlineTree.h"
#include "vrImageTypes.h"
#include "vrVolumeNode.h"

#include <cstddef>
#include <string>

namespace vr
{
/** \class CenterlineVolumeFit
 * \brief How many of a centerline tree's points lie in a volume's voxel grid (within half a voxel of its outer
 * voxel centres): centerlines that miss the volume are almost always in the other coordinate system (RAS against
 * LPS) or belong to another scan.
 * \ingroup VesselReformation
 */
struct CenterlineVolumeFit
{
  std::size_t Points{ 0 };
  std::size_t Outside{ 0 };

  double
  OutsideFraction() const
  {
    return Points == 0 ? 0.0 : static_cast<double>(Outside) / static_cast<double>(Points);
  }
};

/** \return the fit of \a tree (LPS mm) in \a volume's voxel grid. */
CenterlineVolumeFit
MeasureCenterlineVolumeFit(const itk::CenterlineTree & tree, const itk::ImageBase<3> * volume);
/** The same against a volume node's grid (its IJK->RAS matrix and extent), without converting its voxels. */
CenterlineVolumeFit
MeasureCenterlineVolumeFit(const itk::CenterlineTree & tree, const VolumeNode * volume);

/** What a fit means for a reformation: an error when no point lies in the volume, a warning when most do not.
 * \param fit the measured fit.
 * \param centerlines names the centerlines in the message ("centerlines \"tree.vtp\"", "the centerlines of
 *        segmentation \"mask.nii.gz\"").
 * \param volume names the volume ("volume \"cta.nrrd\"").
 * \param extracted true for centerlines extracted from a segmentation (no coordinate system to blame).
 * \return the warning's whole text, or empty when at least half of the points lie in the volume.
 * Throws vr::InputError (parameter ParameterName::CenterlineSpace unless \a extracted) naming both when no point
 * lies in the volume: a reformation of centerlines outside the volume shows nothing. */
std::string
CheckCenterlineVolumeFit(const CenterlineVolumeFit & fit,
                         const std::string &         centerlines,
                         const std::string &         volume,
                         bool                        extracted);
} // namespace vr

#endif
