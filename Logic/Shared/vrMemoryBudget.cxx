// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrMemoryBudget.h"

#include "itkCPRViewGeometry.h"
#include "vrInputError.h"
#include "vrParameterName.h"

#include <climits>
#include <sstream>
#include <string>

namespace vr
{
namespace
{
// Visibility mode's own bytes per pixel besides every update's (measured as those: 24.0 on both phantoms at
// 512 x 1024): its per-pixel footprint buffers (the visible branch and the nearest back), the nearest fill's column
// winners, the hidden labels of the assignment and their output node (4 each), and each thread's band-sized footprint
// samples (40 bytes x 32 rows x the width: about 4 a pixel at 512 x 1024, less on larger views).
constexpr double VisibilityBytesPerPixel = 24.0;
} // namespace

double
EstimateReformationBytes(const itk::Size<2> & size,
                         std::size_t          relaxWorkspaceBytes,
                         bool                 surface,
                         double               volumeSamplingBytes,
                         itk::CPRDepthMode    mode)
{
  // Bytes per view pixel at the peak of an update besides the relaxation's workspace, counted as allocated bytes
  // (Testing/Tools/MeasureReformationMemory; 74.7-75.0 and 83.8-83.9 at 256 x 512, 512 x 1024 and 1024 x 2048):
  // - every update: the centerline raster, the depth assignment, the depth filter's outputs (the hidden labels among
  //   them, 0 outside Visibility mode), the relaxed depth, both CPR images and the output nodes of all of them: 75;
  // - the cut surface: points, scalars and two triangles a pixel: 84.
  // The relax filter keeps its workspace through the stages after it, so it adds to the peak whole.
  double perPixel = 75.0;
  if (surface)
  {
    perPixel += 84.0;
  }
  if (mode == itk::CPRDepthMode::Visibility)
  {
    perPixel += VisibilityBytesPerPixel;
  }
  return perPixel * static_cast<double>(size[0]) * static_cast<double>(size[1]) +
         static_cast<double>(relaxWorkspaceBytes) + volumeSamplingBytes;
}

double
EstimateVolumeSamplingBytes(double voxels, itk::CPRInterpolationMode interpolation)
{
  // Both resample filters keep their interpolator between updates, and each cubic one its coefficients (float).
  return interpolation == itk::CPRInterpolationMode::Cubic ? 2.0 * sizeof(float) * voxels : 0.0;
}

void
CheckViewFitsInMemory(const itk::CPRViewGeometry &                           view,
                      bool                                                   sizeGiven,
                      itk::BilateralDepthRelaxFilter<itk::Image<float, 2>> & relax,
                      bool                                                   surface,
                      double                                                 volumeSamplingBytes,
                      itk::CPRDepthMode                                      mode)
{
  const auto &       size = view.GetSize();
  std::ostringstream origin;
  if (sizeGiven)
  {
    origin << "view size = " << size[0] << "," << size[1];
  }
  else
  {
    origin << "the view of " << size[0] << " x " << size[1] << " pixels (pixel spacing " << view.GetSpacing()[0] << ","
           << view.GetSpacing()[1] << " mm)";
  }
  const char * parameter = sizeGiven ? ParameterName::ViewSize : ParameterName::PixelSpacing;
  if (size[0] > static_cast<itk::SizeValueType>(INT_MAX) || size[1] > static_cast<itk::SizeValueType>(INT_MAX))
  {
    throw InputError(origin.str() + ": at most " + std::to_string(INT_MAX) + " pixels per side are supported",
                     parameter);
  }
  const double needed =
    EstimateReformationBytes(size, relax.GetWorkspaceBytes(size), surface, volumeSamplingBytes, mode);
  const double available = AvailableMemoryInBytes();
  if (needed > available)
  {
    throw InputError(origin.str() + ": the reformation would need about " + DescribeBytes(needed) +
                       (volumeSamplingBytes > 0.0 ? " (of it " + DescribeBytes(volumeSamplingBytes) +
                                                      " for the cubic interpolation's "
                                                      "coefficients of the volume)"
                                                  : std::string()) +
                       ", more than the " + DescribeBytes(available) +
                       " of memory available; choose a smaller view size or a larger pixel spacing" +
                       (volumeSamplingBytes > 0.0 ? ", or linear interpolation" : ""),
                     parameter);
  }
}
} // namespace vr
