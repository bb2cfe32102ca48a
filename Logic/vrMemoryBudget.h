// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrMemoryBudget_h
#define vrMemoryBudget_h

#include "itkBilateralDepthRelaxSolver.h"
#include "itkSize.h"

namespace itk
{
class CPRViewGeometry;
}

namespace vr
{
/** \param size a view's size in pixels.
 * \param solver the relaxation's solver (the steady one keeps a larger workspace).
 * \param surface whether the update builds the cut surface.
 * \return the bytes the reformation of that view needs at its peak: depth, mask, labels, relaxation workspace, both
 * CPRs, the output nodes and the surface; within 10 % of what an update really takes (a test measures it). */
double
EstimateReformationBytes(const itk::Size<2> &           size,
                         itk::BilateralDepthRelaxSolver solver = itk::BilateralDepthRelaxSolver::Jacobi,
                         bool                           surface = true);

/** \return the memory this process may still allocate, in bytes (MemAvailable of /proc/meminfo, else the free
 * physical pages). */
double
AvailableMemoryInBytes();

/** Refuses, before anything is allocated, a view of more than INT_MAX pixels a side or one whose reformation would
 * need more than AvailableMemoryInBytes() (EstimateReformationBytes() with \a solver and \a surface): vr::InputError
 * naming the view size (\a sizeGiven) or else the pixel spacing it follows from. */
void
CheckViewFitsInMemory(const itk::CPRViewGeometry &   view,
                      bool                           sizeGiven,
                      itk::BilateralDepthRelaxSolver solver,
                      bool                           surface);
} // namespace vr

#endif
