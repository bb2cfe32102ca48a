// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCenterlineBranchGeometry_h
#define itkCenterlineBranchGeometry_h

#include "itkCenterlineForeground.h"
#include "itkCenterlineSkeleton.h"
#include "itkCenterlineTree.h"

#include <array>
#include <vector>

namespace itk
{
namespace detail
{
/** \class BranchGeometryParameters
 * \brief Settings of the smooth centerline made from a voxel skeleton. Lengths in mm.
 * \ingroup VesselReformation
 */
struct BranchGeometryParameters
{
  /** Distance between consecutive output points along a branch (mm), > 0. */
  double PointSpacing{ 0.5 };
  /** Width (standard deviation, mm) of the smoothing along a branch: the larger of SmoothingRadiusRatio times the
   * branch's median radius and the voxel diagonal's half. */
  double SmoothingRadiusRatio{ 0.5 };
  /** The distance to the nearest background voxel centre, interpolated at a centerline point, falls short of the
   * lumen radius of a voxelised tube: the interpolation flattens its ridge. RadiusCorrection times the voxel size
   * across the branch is added back (calibrated on voxelised tubes). */
  double RadiusCorrection{ 0.3 };
};

/** Local linear regression of a polyline against its arc length with Gaussian weights of width \a sigma (mm): a
 * straight line stays exactly straight, to its ends, while the staircase of a voxel path is averaged away.
 * Points are in any Cartesian frame in mm. */
std::vector<std::array<double, 3>>
SmoothPolyline(const std::vector<std::array<double, 3>> & points, double sigma);

/** Points at equal arc-length steps of about \a spacing (mm) along a polyline, its two ends included (the count
 * chosen from \a spacing, the points placed by itk::ResamplePolylineEvenly). */
std::vector<std::array<double, 3>>
ResamplePolyline(const std::vector<std::array<double, 3>> & points, double spacing);

/** Turns the voxel branches of \a skeleton into centerline branches: smoothed, centred on the ridge of the
 * foreground's distance to the background, smoothed again (junctions shared by the branches that meet there, placed
 * on the smoothed path of the parent and its widest child), resampled, mapped to LPS through \a grid's origin,
 * spacing and direction (the mask \a foreground was made from), with the lumen radius at each point from the
 * interpolated distance. Ids count up from \a firstId in the skeleton's branch order. */
std::vector<CenterlineBranch>
MakeCenterlineBranches(const SkeletonTree &                        skeleton,
                       const CenterlineForeground &                foreground,
                       const CenterlineForeground::MaskImageType * grid,
                       const BranchGeometryParameters &            parameters,
                       int                                         firstId);
} // namespace detail
} // namespace itk

#endif
