// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrMemoryBudget_h
#define vrMemoryBudget_h

#include "itkSize.h"

namespace itk
{
class CPRViewGeometry;
}

namespace vr
{
/** Bytes of memory one view pixel costs across every stage and output of a reformation (see
 * EstimateReformationBytes). */
constexpr double BytesPerViewPixel = 160.0;

/** \param size a view's size in pixels.
 * \return the bytes the reformation of that view needs: depth, mask, labels, relaxation buffers, both CPRs, the
 * output nodes and the surface. */
double
EstimateReformationBytes(const itk::Size<2> & size);

/** \return the memory this process may still allocate, in bytes (MemAvailable of /proc/meminfo, else the free
 * physical pages). */
double
AvailableMemoryInBytes();

/** Refuses, before anything is allocated, a view of more than INT_MAX pixels a side or one whose reformation would
 * need more than AvailableMemoryInBytes(): vr::InputError naming the view size (\a sizeGiven) or else the pixel
 * spacing it follows from. */
void
CheckViewFitsInMemory(const itk::CPRViewGeometry & view, bool sizeGiven);
} // namespace vr

#endif
