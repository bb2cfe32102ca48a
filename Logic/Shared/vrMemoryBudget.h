// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrMemoryBudget_h
#define vrMemoryBudget_h

#include "itkBilateralDepthRelaxFilter.h"
#include "itkCPRDepthMode.h"
#include "itkCPRSamplingModes.h"
#include "itkImage.h"
#include "itkSize.h"
#include "vrAvailableMemory.h"

#include <cstddef>

namespace itk
{
class CPRViewGeometry;
}

namespace vr
{
/** \param size a view's size in pixels.
 * \param relaxWorkspaceBytes the workspace the relax filter allocates for a depth map of that size and keeps through
 * the later stages (BilateralDepthRelaxFilter::GetWorkspaceBytes).
 * \param surface whether the update builds the cut surface.
 * \param mode the depth mode: Visibility mode's footprint buffers and hidden labels add to the peak.
 * \return the bytes the reformation of that view allocates at its peak: the stages' images and nodes (depth, mask,
 * labels, relaxed depth, both CPRs, the output nodes; measured per view pixel), the relaxation's workspace as its
 * filter reports it, and the surface. A test counts what updates allocate: with the workspace of the path a solve
 * takes, within 10 % (measured: 0.2 %); CheckViewFitsInMemory() counts the most a steady solve allocates (its
 * coarser grids), 14 to 21 % above an update whose solve needs none (docs/design.md "Module logic").
 * \param volumeSamplingBytes what sampling the volume allocates besides it (EstimateVolumeSamplingBytes()). */
double
EstimateReformationBytes(const itk::Size<2> & size,
                         std::size_t          relaxWorkspaceBytes,
                         bool                 surface = true,
                         double               volumeSamplingBytes = 0.0,
                         itk::CPRDepthMode    mode = itk::CPRDepthMode::Scanline);

/** \return the bytes the two resample filters of an update allocate for a volume of \a voxels voxels besides the
 * volume itself, which they read in its stored type and never copy: nothing for linear and nearest interpolation; for
 * cubic, each filter's B-spline coefficients, a float image the size of the volume (8 bytes a voxel for the two). */
double
EstimateVolumeSamplingBytes(double voxels, itk::CPRInterpolationMode interpolation);

/** Refuses, before anything is allocated, a view of more than INT_MAX pixels a side or one whose reformation would
 * need more than AvailableMemoryInBytes() (EstimateReformationBytes() with \a relax's workspace, \a surface and
 * \a volumeSamplingBytes and \a mode): vr::InputError naming the view size (\a sizeGiven) or else the pixel spacing it
 * follows from, and the bytes needed and available. */
void
CheckViewFitsInMemory(const itk::CPRViewGeometry &                           view,
                      bool                                                   sizeGiven,
                      itk::BilateralDepthRelaxFilter<itk::Image<float, 2>> & relax,
                      bool                                                   surface,
                      double                                                 volumeSamplingBytes = 0.0,
                      itk::CPRDepthMode                                      mode = itk::CPRDepthMode::Scanline);
} // namespace vr

#endif
