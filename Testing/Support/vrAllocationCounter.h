// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The bytes a process has allocated from the C heap, live and at their peak: an executable that links
// vrAllocationCounter.cxx replaces malloc and its relatives (glibc calls the replacement for its own allocations,
// and operator new, ITK's image buffers and VTK's arrays all come through it), counting each block's usable size.
#ifndef vrAllocationCounter_h
#define vrAllocationCounter_h

#include <cstddef>

namespace vr::test
{
/** The bytes allocated and not yet freed. */
long long
AllocatedBytes();

/** The most AllocatedBytes() has been since the last ResetAllocationPeak(). */
long long
AllocationPeak();

/** Sets AllocationPeak() to AllocatedBytes(). */
void
ResetAllocationPeak();

/** Starts counting the blocks of at least \a bytes allocated from now on (LargeAllocations()); 0 stops. */
void
CountAllocationsOfAtLeast(long long bytes);

/** The blocks of at least the size CountAllocationsOfAtLeast() set that were allocated since it was called (freed or
 * not), and their bytes. */
long long
LargeAllocations();
long long
LargeAllocationBytes();
} // namespace vr::test

#endif
