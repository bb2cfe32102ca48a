// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The mpCPR depth map on the device (docs/design.md "Depth"): what itk::detail::AssignDepth computes from the
// centerline pixels of a view (itkCPRDepthAssignment.cxx), with the same choices bit for bit. The host rasterises the
// centerlines into a list of centerline pixels (a few KB) and uploads it with, for Scanline mode, each row's nearest
// filled row; the kernels below do the rest for every pixel:
//
//   ScatterSlots        slot[k] = the list entry of centerline pixel k (the buffer is filled with -1 first)
//   NearestAlongLines   for every pixel, the nearest centerline pixel at or before it and at or after it along its
//                       line (rows for Scanline, columns for Nearest), by prefix scans in local memory
//   AssignScanline      each pixel of a row with centerline pixels takes the nearest one in its row
//   CopyEmptyRows       rows without one copy depth and owner of their nearest filled row (not fixed)
//   NearestColumnWinners, AssignNearest   the exact 2D nearest centerline pixel: per column, then outwards along
//                       the row until the horizontal distance alone exceeds the best (the CPU's separable search)
//
// Candidates are ordered as the CPU orders them: distance, then depth (nearer the viewer), then branch id. The CPU
// compares depths in double; the host passes each centerline pixel's double depth as a 64-bit key that orders as the
// doubles do (sign-magnitude turned into an unsigned order, -0 made +0), so no device needs double precision for
// it. Distances along a line are whole pixels; in Nearest mode the 2D distances (mm^2) are computed in double exactly
// as the CPU computes them (needs cl_khr_fp64; the host uses the CPU filter on a device without it). Contracting
// a * b + c into one fused multiply-add would round differently from the CPU: it is switched off.
//
// Build options (-D NAME=VALUE): LINE_GROUP_SIZE, the work-group size of NearestAlongLines (a power of two);
// HAS_DOUBLE, 1 when the device has cl_khr_fp64 (the Nearest kernels exist only then).

#pragma OPENCL FP_CONTRACT OFF
#if HAS_DOUBLE
#  pragma OPENCL EXTENSION cl_khr_fp64 : enable
#endif

#define NONE (-1)

/** The CPU's candidate order (itkCPRDepthAssignment.cxx, Precedes) with whole-pixel distances. */
inline bool
PrecedesAlongLine(int distance, ulong depthKey, uint owner, int otherDistance, ulong otherDepthKey, uint otherOwner)
{
  if (distance != otherDistance)
  {
    return distance < otherDistance;
  }
  if (depthKey != otherDepthKey)
  {
    return depthKey < otherDepthKey;
  }
  return owner < otherOwner;
}

__kernel void
ScatterSlots(__global const int * restrict pixelIndex, __global int * restrict slots, const int count)
{
  const int entry = get_global_id(0);
  if (entry < count)
  {
    slots[pixelIndex[entry]] = entry;
  }
}

// One work-group per line of `length` pixels; element p of line l is slots[l * lineStride + p * elementStride].
// before[k] / after[k]: the position along the line of the nearest centerline pixel at or before / at or after the
// pixel, NONE when there is none. The line is scanned in chunks of LINE_GROUP_SIZE, carrying the last chunk's result.
__kernel __attribute__((reqd_work_group_size(LINE_GROUP_SIZE, 1, 1))) void
NearestAlongLines(__global const int * restrict slots,
                  __global int * restrict       before,
                  __global int * restrict       after,
                  const int                     length,
                  const int                     lineStride,
                  const int                     elementStride)
{
  __local int scan[LINE_GROUP_SIZE];
  const int   line = get_group_id(0);
  const int   item = get_local_id(0);
  const int   first = line * lineStride;

  int carry = NONE; // the last centerline position before this chunk
  for (int start = 0; start < length; start += LINE_GROUP_SIZE)
  {
    const int position = start + item;
    const int k = first + position * elementStride;
    scan[item] = position < length && slots[k] >= 0 ? position : NONE;
    barrier(CLK_LOCAL_MEM_FENCE);
    for (int offset = 1; offset < LINE_GROUP_SIZE; offset <<= 1)
    {
      const int other = item >= offset ? scan[item - offset] : NONE;
      barrier(CLK_LOCAL_MEM_FENCE);
      scan[item] = max(scan[item], other);
      barrier(CLK_LOCAL_MEM_FENCE);
    }
    if (position < length)
    {
      before[k] = max(scan[item], carry);
    }
    carry = max(carry, scan[LINE_GROUP_SIZE - 1]);
    barrier(CLK_LOCAL_MEM_FENCE);
  }

  carry = INT_MAX; // the first centerline position after this chunk
  const int chunks = (length + LINE_GROUP_SIZE - 1) / LINE_GROUP_SIZE;
  for (int chunk = chunks - 1; chunk >= 0; --chunk)
  {
    // Item i holds the chunk's pixel i from its end, so that the inclusive scan runs from the right.
    const int position = chunk * LINE_GROUP_SIZE + (LINE_GROUP_SIZE - 1 - item);
    const int k = first + position * elementStride;
    scan[item] = position < length && slots[k] >= 0 ? position : INT_MAX;
    barrier(CLK_LOCAL_MEM_FENCE);
    for (int offset = 1; offset < LINE_GROUP_SIZE; offset <<= 1)
    {
      const int other = item >= offset ? scan[item - offset] : INT_MAX;
      barrier(CLK_LOCAL_MEM_FENCE);
      scan[item] = min(scan[item], other);
      barrier(CLK_LOCAL_MEM_FENCE);
    }
    if (position < length)
    {
      const int nearest = min(scan[item], carry);
      after[k] = nearest == INT_MAX ? NONE : nearest;
    }
    carry = min(carry, scan[LINE_GROUP_SIZE - 1]);
    barrier(CLK_LOCAL_MEM_FENCE);
  }
}

// Scanline mode, rows that hold a centerline pixel (nearestFilledRow[y] == y): the nearest centerline pixel of the
// row; fixed when it is the pixel itself or, with lumen fixing, within the owner's lumen radius along the row
// (lumenReach: the most whole columns n with n * sx <= radius, from the host; -1 without a radius or lumen fixing).
__kernel void
AssignScanline(__global const int * restrict   slots,
               __global const int * restrict   before,
               __global const int * restrict   after,
               __global const int * restrict   nearestFilledRow,
               __global const ulong * restrict depthKey,
               __global const uint * restrict  owner,
               __global const float * restrict depth,
               __global const int * restrict   lumenReach,
               __global float * restrict       depthOut,
               __global uchar * restrict       fixedOut,
               __global uint * restrict        ownerOut,
               const int                       width,
               const int                       height)
{
  const int x = get_global_id(0);
  const int y = get_global_id(1);
  if (x >= width || y >= height || nearestFilledRow[y] != y)
  {
    return;
  }
  const int k = y * width + x;
  const int left = before[k];
  const int right = after[k];
  int       chosen = left;
  if (left == NONE)
  {
    chosen = right;
  }
  else if (right != NONE)
  {
    const int leftSlot = slots[y * width + left];
    const int rightSlot = slots[y * width + right];
    if (PrecedesAlongLine(
          right - x, depthKey[rightSlot], owner[rightSlot], x - left, depthKey[leftSlot], owner[leftSlot]))
    {
      chosen = right;
    }
  }
  const int source = slots[y * width + chosen];
  const int distance = x > chosen ? x - chosen : chosen - x; // not abs(), which is unsigned in OpenCL C
  depthOut[k] = depth[source];
  ownerOut[k] = owner[source];
  fixedOut[k] = (chosen == x || distance <= lumenReach[source]) ? 1 : 0;
}

// Scanline mode, rows without a centerline pixel: the depth and owner of the nearest row that has one.
__kernel void
CopyEmptyRows(__global const int * restrict nearestFilledRow,
              __global float * restrict     depthOut,
              __global uchar * restrict     fixedOut,
              __global uint * restrict      ownerOut,
              const int                     width,
              const int                     height)
{
  const int x = get_global_id(0);
  const int y = get_global_id(1);
  if (x >= width || y >= height)
  {
    return;
  }
  const int source = nearestFilledRow[y];
  if (source == y)
  {
    return;
  }
  const int k = y * width + x;
  depthOut[k] = depthOut[source * width + x];
  ownerOut[k] = ownerOut[source * width + x];
  fixedOut[k] = 0;
}

#if HAS_DOUBLE
/** The CPU's candidate order (Precedes) with distances in mm^2. */
inline bool
PrecedesInPlane(double distance, ulong depthKey, uint owner, double otherDistance, ulong otherDepthKey, uint otherOwner)
{
  if (distance != otherDistance)
  {
    return distance < otherDistance;
  }
  if (depthKey != otherDepthKey)
  {
    return depthKey < otherDepthKey;
  }
  return owner < otherOwner;
}

// Nearest mode, pass 1: per pixel, the nearest centerline pixel of its column (its row, NONE without one) and the
// square of the vertical distance in mm. Rows are whole multiples of sy, so comparing the row differences compares
// the CPU's distances.
__kernel void
NearestColumnWinners(__global const int * restrict   slots,
                     __global const int * restrict   before,
                     __global const int * restrict   after,
                     __global const ulong * restrict depthKey,
                     __global const uint * restrict  owner,
                     __global int * restrict         winner,
                     __global double * restrict      columnDistance,
                     const int                       width,
                     const int                       height,
                     const double                    spacingY)
{
  const int x = get_global_id(0);
  const int y = get_global_id(1);
  if (x >= width || y >= height)
  {
    return;
  }
  const int k = y * width + x;
  const int upper = before[k];
  const int lower = after[k];
  int       chosen = upper;
  if (upper == NONE)
  {
    chosen = lower;
  }
  else if (lower != NONE)
  {
    const int upperSlot = slots[upper * width + x];
    const int lowerSlot = slots[lower * width + x];
    if (PrecedesAlongLine(
          lower - y, depthKey[lowerSlot], owner[lowerSlot], y - upper, depthKey[upperSlot], owner[upperSlot]))
    {
      chosen = lower;
    }
  }
  winner[k] = chosen;
  if (chosen != NONE)
  {
    const double dy = (double)(y - chosen) * spacingY;
    columnDistance[k] = dy * dy;
  }
}

// Nearest mode, pass 2: outwards along the row over the column winners until the horizontal distance alone
// exceeds the best; fixed when the pixel is a centerline pixel or, with lumen fixing, within the owner's radius.
__kernel void
AssignNearest(__global const int * restrict    slots,
              __global const int * restrict    winner,
              __global const double * restrict columnDistance,
              __global const ulong * restrict  depthKey,
              __global const uint * restrict   owner,
              __global const float * restrict  depth,
              __global const double * restrict radius,
              __global float * restrict        depthOut,
              __global uchar * restrict        fixedOut,
              __global uint * restrict         ownerOut,
              const int                        width,
              const int                        height,
              const double                     spacingX,
              const int                        fixLumen)
{
  const int x = get_global_id(0);
  const int y = get_global_id(1);
  if (x >= width || y >= height)
  {
    return;
  }
  const int first = y * width;
  double    bestDistance = INFINITY;
  ulong     bestKey = 0;
  uint      bestOwner = 0;
  int       bestSlot = NONE;
  int       bestSource = 0;
  for (int offset = 0; offset < width; ++offset)
  {
    const double dx = (double)offset * spacingX;
    const double dx2 = dx * dx;
    if (dx2 > bestDistance)
    {
      break;
    }
    for (int side = 0; side < (offset == 0 ? 1 : 2); ++side)
    {
      const int candidate = side == 0 ? x - offset : x + offset;
      if (candidate < 0 || candidate >= width)
      {
        continue;
      }
      const int winnerRow = winner[first + candidate];
      if (winnerRow == NONE)
      {
        continue;
      }
      const int    source = winnerRow * width + candidate;
      const int    slot = slots[source];
      const double distance = dx2 + columnDistance[first + candidate];
      if (bestOwner == 0 || PrecedesInPlane(distance, depthKey[slot], owner[slot], bestDistance, bestKey, bestOwner))
      {
        bestDistance = distance;
        bestKey = depthKey[slot];
        bestOwner = owner[slot];
        bestSlot = slot;
        bestSource = source;
      }
    }
  }
  const int k = first + x;
  if (bestSlot == NONE)
  {
    depthOut[k] = 0.0f;
    ownerOut[k] = 0;
    fixedOut[k] = 0;
    return;
  }
  depthOut[k] = depth[bestSlot];
  ownerOut[k] = bestOwner;
  const double lumen = radius[bestSlot];
  fixedOut[k] = (bestSource == k || (fixLumen && !isnan(lumen) && sqrt(bestDistance) <= lumen)) ? 1 : 0;
}
#endif
