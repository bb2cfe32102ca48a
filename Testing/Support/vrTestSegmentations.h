// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrTestSegmentations_h
#define vrTestSegmentations_h

#include "itkCenterlineTree.h"
#include "itkImage.h"

#include <vector>

/** Segmentations made in code for the centerline extraction tests: tubes of known axis and radius drawn into a
 * label map of any geometry, and the distances that compare an extracted tree with the true one. */
namespace vr::test
{
using LabelMap = itk::Image<unsigned char, 3>;
using PointType = itk::Point<double, 3>;

/** An empty label map of \a size voxels with the given spacing (mm), origin (LPS mm) and direction. */
LabelMap::Pointer
MakeLabelMap(const itk::Size<3> &              size,
             const itk::Vector<double, 3> &    spacing,
             const PointType &                 origin,
             const itk::Matrix<double, 3, 3> & direction);

/** The direction matrix of a rotation by \a degrees about the unit axis (x, y, z). */
itk::Matrix<double, 3, 3>
RotationMatrix(double x, double y, double z, double degrees);

/** Sets to \a label every voxel whose centre lies inside a tube of the tree: a chain of capsules between
 * consecutive points, the radius varying linearly along each (as the run-off phantom draws its vessels). Exact
 * per voxel centre, in physical space (any direction and spacing). */
void
DrawTubes(LabelMap * image, const itk::CenterlineTree & tree, unsigned char label = 1);

/** Points every \a step mm along a circular arc: centre \a center, radius \a radius (mm), in the plane spanned by the
 * unit vectors \a u and \a v, from angle \a from to \a to (degrees). */
std::vector<PointType>
ArcPoints(const PointType &              center,
          double                         radius,
          const itk::Vector<double, 3> & u,
          const itk::Vector<double, 3> & v,
          double                         from,
          double                         to,
          double                         step);

/** A branching tree of tubes filling a cube of \a size voxels of 1 mm (origin 0, identity direction): a trunk of radius
 * size/25 rising from the bottom face divides \a generations times, each child 0.72 times as wide and 0.75 times as
 * long as its parent, turned 32 degrees away from it and alternately about two axes. Branches are tube centerlines
 * (points every 0.5 mm, a radius each), ids 1, 2, ... parents first; children start at their parent's end. */
itk::CenterlineTree
MakeBranchingTree(unsigned int size, unsigned int generations);

/** Points every \a step mm on the segment from \a a to \a b, both ends included. */
std::vector<PointType>
SegmentPoints(const PointType & a, const PointType & b, double step);

/** A branch of constant \a radius through \a points. */
itk::CenterlineBranch
TubeBranch(int id, const std::vector<PointType> & points, double radius);

/** Distance (mm) from \a point to the nearest segment of \a polyline, and the radius interpolated there. */
struct NearestOnPolyline
{
  double Distance;
  double Radius;
  double ArcLength; // from the polyline's first point
};
NearestOnPolyline
NearestPointOnPolyline(const PointType &              point,
                       const std::vector<PointType> & polyline,
                       const std::vector<double> &    radii);

/** The same against every branch of a tree: the nearest branch's answer, and its index. */
struct NearestOnTree
{
  NearestOnPolyline Nearest;
  std::size_t       Branch;
};
NearestOnTree
NearestPointOnTree(const PointType & point, const itk::CenterlineTree & tree);

/** The length of a polyline (mm). */
double
PolylineLength(const std::vector<PointType> & polyline);

/** The value below which a fraction \a q of \a values lie (nearest rank). */
double
Quantile(std::vector<double> values, double q);
} // namespace vr::test

#endif
