// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The CPR image on the device (docs/design.md "Resampling"): what CPRResampleImageFilter computes per pixel
// (itkCPRResampleImageFilter.hxx, itkCPRVolumeSampler.h), with the same arithmetic in double and in the same order.
// Pixel (c, r) samples the volume at the continuous index
//   centre + columnStep (c - centreColumn) + rowStep (r - centreRow) + depthStep (d + offset)
// for each slab offset (mm), combined by MIP, MinIP or mean, samples outside the volume left out, the outside value
// where none is inside. Linear interpolation is the CPU sampler's own trilinear code; nearest rounds half up as
// ITK's NearestNeighborInterpolateImageFunction does. ITK rounds through the processor's round-to-nearest-even
// conversion of 2x - 0.5 (floor) and 2x + 0.5 (round half up), halved: so do these kernels.
//
// The volume stays in its stored type (VOXEL_TYPE: short, ushort, char, uchar, float or double) and each voxel
// read becomes slope * stored + intercept in double (a rescale of 1 and 0 gives the stored value exactly). Indices
// into the volume are 64-bit: a volume may hold more than 2^31 voxels or bytes.
//
// Build options (-D NAME=VALUE): VOXEL_TYPE. Needs cl_khr_fp64 (the host samples on the CPU without it).
// Contracting a * b + c into a fused multiply-add would round differently from the CPU: it is switched off.

#pragma OPENCL FP_CONTRACT OFF
#pragma OPENCL EXTENSION cl_khr_fp64 : enable

#define INTERPOLATION_LINEAR 0
#define INTERPOLATION_NEAREST 1
#define SLAB_MIP 0
#define SLAB_MINIMUM_IP 1
#define SLAB_MEAN 2

inline double
Voxel(__global const VOXEL_TYPE * volume, const long offset, const double slope, const double intercept)
{
  return (double)volume[offset] * slope + intercept;
}

/** itk::Math::Floor<long> on x86-64: the round-to-nearest-even conversion of 2x - 0.5, halved. */
inline long
FloorAsITK(const double x)
{
  return convert_long_rte(2.0 * x - 0.5) >> 1;
}

/** itk::Math::Round<long> (half up) on x86-64. */
inline long
RoundAsITK(const double x)
{
  return convert_long_rte(2.0 * x + 0.5) >> 1;
}

__kernel void
ResampleAlongDepth(__global const VOXEL_TYPE * restrict volume,
                   __global const float * restrict      depth,
                   __global float * restrict            output,
                   __constant double *                  slabOffsets,
                   const int                            slabSamples,
                   const int                            slabMode,
                   const int                            interpolation,
                   const float                          outsideValue,
                   // the output region: its first pixel and size; the depth buffer's first pixel and row length
                   const int startColumn,
                   const int startRow,
                   const int columns,
                   const int rows,
                   const int depthStartColumn,
                   const int depthStartRow,
                   const int depthRowLength,
                   const double centreColumn,
                   const double centreRow,
                   // the view as continuous indices of the volume
                   const double indexAtCentreX,
                   const double indexAtCentreY,
                   const double indexAtCentreZ,
                   const double columnStepX,
                   const double columnStepY,
                   const double columnStepZ,
                   const double rowStepX,
                   const double rowStepY,
                   const double rowStepZ,
                   const double depthStepX,
                   const double depthStepY,
                   const double depthStepZ,
                   // the volume
                   const long   sizeX,
                   const long   sizeY,
                   const long   sizeZ,
                   const long   bufferStartX,
                   const long   bufferStartY,
                   const long   bufferStartZ,
                   const double slope,
                   const double intercept)
{
  const int i = get_global_id(0);
  const int j = get_global_id(1);
  if (i >= columns || j >= rows)
  {
    return;
  }
  const int    column = startColumn + i;
  const int    row = startRow + j;
  const double d = (double)depth[(long)(row - depthStartRow) * depthRowLength + (column - depthStartColumn)];
  const double dc = (double)column - centreColumn;
  const double dr = (double)row - centreRow;
  // The CPU's vector sum, component by component: ((centre + column step) + row step) + depth step.
  const double base[3] = { ((indexAtCentreX + columnStepX * dc) + rowStepX * dr) + depthStepX * d,
                           ((indexAtCentreY + columnStepY * dc) + rowStepY * dr) + depthStepY * d,
                           ((indexAtCentreZ + columnStepZ * dc) + rowStepZ * dr) + depthStepZ * d };
  const double normal[3] = { depthStepX, depthStepY, depthStepZ };
  const long   size[3] = { sizeX, sizeY, sizeZ };
  const long   start[3] = { bufferStartX, bufferStartY, bufferStartZ };
  const long   table[3] = { 1, sizeX, sizeX * sizeY };

  double sum = 0.0;
  double extreme = 0.0;
  int    inside = 0;
  for (int s = 0; s < slabSamples; ++s)
  {
    const double offset = slabOffsets[s];
    double       index[3];
    bool         within = true;
    for (int k = 0; k < 3; ++k)
    {
      index[k] = base[k] + normal[k] * offset;
      // ITK's IsInsideBuffer: within half a voxel of the buffer (a NaN fails).
      const double low = (double)start[k] - 0.5;
      const double high = (double)(start[k] + size[k] - 1) + 0.5;
      within = within && index[k] >= low && index[k] < high;
    }
    if (!within)
    {
      continue;
    }
    double value;
    if (interpolation == INTERPOLATION_NEAREST)
    {
      long at = 0;
      for (int k = 0; k < 3; ++k)
      {
        at += (RoundAsITK(index[k]) - start[k]) * table[k];
      }
      value = Voxel(volume, at, slope, intercept);
    }
    else
    {
      // CPRVolumeSampler::InterpolateLinearly.
      long   at = 0;
      long   step[3];
      double fraction[3];
      for (int k = 0; k < 3; ++k)
      {
        long voxel = FloorAsITK(index[k]);
        voxel = max(voxel, start[k]);
        fraction[k] = fmax(0.0, index[k] - (double)voxel);
        at += (voxel - start[k]) * table[k];
        step[k] = voxel < start[k] + size[k] - 1 ? table[k] : 0;
      }
      const double v000 = Voxel(volume, at, slope, intercept);
      const double v100 = Voxel(volume, at + step[0], slope, intercept);
      const double v010 = Voxel(volume, at + step[1], slope, intercept);
      const double v110 = Voxel(volume, at + step[0] + step[1], slope, intercept);
      const double v001 = Voxel(volume, at + step[2], slope, intercept);
      const double v101 = Voxel(volume, at + step[0] + step[2], slope, intercept);
      const double v011 = Voxel(volume, at + step[1] + step[2], slope, intercept);
      const double v111 = Voxel(volume, at + step[0] + step[1] + step[2], slope, intercept);
      const double vx00 = v000 + (v100 - v000) * fraction[0];
      const double vx10 = v010 + (v110 - v010) * fraction[0];
      const double vx01 = v001 + (v101 - v001) * fraction[0];
      const double vx11 = v011 + (v111 - v011) * fraction[0];
      const double vxx0 = vx00 + (vx10 - vx00) * fraction[1];
      const double vxx1 = vx01 + (vx11 - vx01) * fraction[1];
      value = vxx0 + (vxx1 - vxx0) * fraction[2];
    }
    if (inside == 0)
    {
      extreme = value;
    }
    else if (slabMode == SLAB_MIP)
    {
      extreme = extreme < value ? value : extreme; // std::max
    }
    else if (slabMode == SLAB_MINIMUM_IP)
    {
      extreme = value < extreme ? value : extreme; // std::min
    }
    sum += value;
    ++inside;
  }
  float result = outsideValue;
  if (inside > 0)
  {
    result = (float)(slabMode == SLAB_MEAN && slabSamples > 1 ? sum / inside : extreme);
  }
  output[(long)j * columns + i] = result;
}
