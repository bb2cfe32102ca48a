// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrAvailableMemory_h
#define vrAvailableMemory_h

#include <string>

/** \file vrAvailableMemory.h
 * \brief How much memory this process may still allocate, for the checks that refuse a volume or a view before
 * anything is allocated (docs/design.md "Volumes in their stored type", 3.7), and how their messages name bytes.
 * \ingroup VesselReformation
 */
namespace vr
{
/** \return the memory this process may still allocate, in bytes: the smallest of the system's (MemAvailable of
 * /proc/meminfo, else the free physical pages), what is left below the process's memory control group limit
 * (cgroup v2 memory.max less memory.current, as in a container) and what is left of its address-space limit
 * (RLIMIT_AS, `ulimit -v`, less the address space it already uses). */
double
AvailableMemoryInBytes();

/** \return \a bytes for a message: "2.05 GiB (2,202,009,600 bytes)"; below 1 GiB in MiB. */
std::string
DescribeBytes(double bytes);
} // namespace vr

#endif
