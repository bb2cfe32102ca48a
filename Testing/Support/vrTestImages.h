// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrTestImages_h
#define vrTestImages_h

#include "itkCPRViewGeometry.h"
#include "itkCenterlineTree.h"
#include "itkImage.h"

#include <vector>

/** Small images built in code for the tests, and plain readers of their pixels. */
namespace vr::test
{
using DepthImage = itk::Image<float, 2>;
using MaskImage = itk::Image<unsigned char, 2>;
using VolumeImage = itk::Image<float, 3>;

/** The point (x, y, z), in mm. */
inline itk::Point<double, 3>
P(double x, double y, double z)
{
  itk::Point<double, 3> point;
  point[0] = x;
  point[1] = y;
  point[2] = z;
  return point;
}

/** A branch of \a id through \a points (LPS mm) with \a radii (none, or one per point). */
itk::CenterlineBranch
Branch(int id, std::vector<itk::Point<double, 3>> points, std::vector<double> radii = {});

/** A view of width x height pixels of sx x sy mm centred at the origin, turned by \a angle degrees about the default
 * up (+z): at 0 degrees it looks along LPS +y (docs/design.md "View"). */
itk::CPRViewSpecification
View(unsigned int width, unsigned int height, double sx = 1.0, double sy = 1.0, double angle = 0.0);

/** A W x H depth image from row-major values (unit spacing, zero origin). */
DepthImage::Pointer
MakeDepthImage(unsigned int width, unsigned int height, const std::vector<float> & values);
/** A W x H mask from row-major values. */
MaskImage::Pointer
MakeMaskImage(unsigned int width, unsigned int height, const std::vector<unsigned char> & values);
/** A W x H depth image of uniformly random values in [low, high) (seeded). */
DepthImage::Pointer
MakeRandomDepthImage(unsigned int width, unsigned int height, float low, float high, unsigned int seed);
/** A W x H mask with each pixel fixed with probability \a fraction (seeded). */
MaskImage::Pointer
MakeRandomMaskImage(unsigned int width, unsigned int height, double fraction, unsigned int seed);

/** The run-off phantom's scanline mpCPR depth map and fixed mask (no volume needed) at its design angle, 30 degrees,
 * on a W x H grid: pixels of \a spacing mm, or, with 0, the spacing the view derives from the tree. */
struct PhantomDepthMap
{
  DepthImage::Pointer Depth;
  MaskImage::Pointer  Fixed;
};
PhantomDepthMap
MakePhantomDepthMap(unsigned int width, unsigned int height, double spacing = 0.0);
/** The scanline mpCPR depth map and fixed mask of \a tree in \a view, disconnected from the filter that made them. */
PhantomDepthMap
MakeScanlineDepthMap(const itk::CenterlineTree & tree, const itk::CPRViewSpecification & view);

/** The pixels of a 2D image, row-major. */
template<typename TImage>
std::vector<typename TImage::PixelType>
PixelsOf(const TImage * image)
{
  const auto count = image->GetBufferedRegion().GetNumberOfPixels();
  return std::vector<typename TImage::PixelType>(image->GetBufferPointer(), image->GetBufferPointer() + count);
}

/** Steps in a depth map between 4-neighbours that are both free (docs/design.md "Relaxation"'s seams). A pair (p, q) is
 * a step when |D_q - D_p| >= minimum and the differences of the pairs beside it in the same direction are at most a
 * quarter of it: a jump, not part of a slope. */
struct DepthStep
{
  std::size_t P;
  std::size_t Q;
  double      Size;
};
std::vector<DepthStep>
FindDepthSteps(const DepthImage * depth, const MaskImage * fixed, double minimum);
/** |D'_q - D'_p| / |D_q - D_p| for each step, measured on \a relaxed. */
std::vector<double>
StepRatios(const std::vector<DepthStep> & steps, const DepthImage * relaxed);
double
Median(std::vector<double> values);
} // namespace vr::test

#endif
