// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrTestLumenTubes_h
#define vrTestLumenTubes_h

#include "itkImage.h"
#include "itkVesselPathSection.h"

#include <functional>

/** Straight tubes of known cross-sections, drawn into a rotated, anisotropic mask, with the path sections along
 * their axis built analytically (constant frame): the references of the lumen measurement's tests and benchmark. */
namespace vr::test
{
/** \class LumenTube
 * \brief What MakeLumenTube draws. The axis runs from Start along the unit vector Axis; at axial position s (mm,
 * from Start) the cross-section is an ellipse of semi-axes Radius(s) * LateralScale along the sections' Lateral
 * vector and Radius(s) along their Up vector. The tube reaches 10 mm beyond both ends of the path.
 */
struct LumenTube
{
  std::function<double(double)> Radius = [](double) { return 4.0; };
  double                        LateralScale{ 1.0 };
  /** The path: from s = 0 to s = PathLength, a section every SectionStep mm. */
  double PathLength{ 80.0 };
  double SectionStep{ 0.2 };
  /** The mask's voxel size (mm) and the rotation of its direction matrix (axis, degrees). */
  itk::Vector<double, 3> Spacing;
  double                 RotationAxis[3]{ 1.0, 2.0, 3.0 };
  double                 RotationDegrees{ 30.0 };
  /** The tube's axis (need not be unit; normalised) and where s = 0 lies (LPS mm). */
  itk::Vector<double, 3> Axis;
  itk::Point<double, 3>  Start;

  LumenTube();
};

/** \class LumenTubeScene
 * \brief A drawn tube: the mask (1 inside: voxel centre inside the ellipse, 0 outside) and its path sections
 * (arc length s, centre on the axis, Tangent = Axis, Radius = the smaller semi-axis, BranchId 1).
 */
struct LumenTubeScene
{
  itk::Image<unsigned char, 3>::Pointer Mask;
  itk::VesselPathSectionList            Sections;
};

LumenTubeScene
MakeLumenTube(const LumenTube & tube);

/** The concentric stenosis of the issue: radius 4 mm, narrowing to 2 mm at s = 40 mm over 10 mm (a raised cosine,
 * 35 to 45 mm). */
double
StenosisRadius(double s);
} // namespace vr::test

#endif
