// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// One Jacobi iteration of the bilateral depth relaxation (docs/design.md "Relaxation"; Kretschmer et al., EuroVis 2014,
// Eq. 1-2), the equation of BilateralDepthRelaxFilter::RelaxOnHost() in its difference form
//   D'_p = D_p + w sum R (D_q - D_p) / ((1 - w)|Omega| + w sum R),   R(x) = exp(-a x^2),
// R = 0 when a x^2 > -ln(FLT_MIN), a zero denominator keeps D_p, fixed pixels keep their value.
// R is computed as 2^u, u = -a log2(e) x^2, with the CPU kernel's polynomial (itkBilateralDepthRelaxRows.hxx): the
// built-in exp costs a third of the kernel's time on a CPU device, and its accuracy is not needed.
//
// Depths are pairs of floats, high + low, like the CPU kernel's (itkBilateralDepthRelaxKernel.h): a plain float
// loses the small late steps to rounding and drifts by a few 1e-4 mm over 500 iterations. Each buffer holds the
// high plane and, `plane` floats further, the low plane. Differences are (high_q - high_p) + (low_q - low_p); the
// new depth is D + step as a new pair (Fast2Sum).
//
// The host passes these definitions as build options (-D NAME=VALUE), so this file reaches the compiler unchanged:
//   VECTOR_WIDTH               lanes per vector: 1, 2, 4, 8 or 16 (the device's preferred float width)
//   VECTORS_PER_ITEM           vectors a work-item relaxes side by side in a row
//   ROWS_PER_ITEM              rows a work-item relaxes one below the other
//   LOCAL_WIDTH, LOCAL_HEIGHT  the work-group size
//   WEIGHT_UNDERFLOW_POWER     -log2(FLT_MIN) = 126: R = 0 when a log2(e) x^2 exceeds it (the same rule)
//   PASSES_PER_LAUNCH          only for RelaxPasses (several passes a launch on tiles in local memory, GPUs), with
//   TILE_WIDTH, TILE_HEIGHT    the pixels a work-group keeps of its tile (the tile has a border of PASSES_PER_LAUNCH)
//
// Layout (in each plane): row y of a W-pixel image starts at y * pitch; pixel x lies at y * pitch + VECTOR_WIDTH + x. The pitch
// holds a vector of padding before the row and at least one pixel after it, and the pixels of a row are padded to
// whole blocks of VECTORS_PER_ITEM vectors, so every load and store is inside the buffer. Padding holds finite
// values (the host fills it with 0) and never changes: lanes outside the image are kept like fixed pixels.
//
// Each edge weight is computed once and shared by the two pixels of the edge: a work-item walks its block row by
// row, handing each row's down-edges on as the next row's up-edges, and vector by vector, handing each vector's
// last right-edge on as the next vector's first left-edge. Image borders are edges of weight 0, so the hot path
// has no branch.

#define CONCATENATE_(a, b) a##b
#define CONCATENATE(a, b) CONCATENATE_(a, b)

#if VECTOR_WIDTH == 1
typedef float RealVector;
typedef int   IntVector;
#  define LOAD_REALS(pointer) (*(pointer))
#  define LOAD_BYTES_AS_INTS(pointer) ((int)*(pointer))
#  define AS_UINTS(reals) as_uint(reals)
#  define UINTS_AS_REALS(uints) as_float(uints)
#  define STORE_REALS(value, pointer) (*(pointer) = (value))
#  define LANE_INDICES 0
#  define LAST_LANE(vector) (vector)
#  define SHIFT_IN_FROM_LEFT(previous, vector) (previous)
#else
typedef CONCATENATE(float, VECTOR_WIDTH) RealVector;
typedef CONCATENATE(int, VECTOR_WIDTH) IntVector;
typedef CONCATENATE(uint, VECTOR_WIDTH) UIntVector;
#  define LOAD_REALS(pointer) CONCATENATE(vload, VECTOR_WIDTH)(0, (pointer))
#  define LOAD_BYTES_AS_INTS(pointer) CONCATENATE(convert_int, VECTOR_WIDTH)(CONCATENATE(vload, VECTOR_WIDTH)(0, (pointer)))
#  define AS_UINTS(reals) CONCATENATE(as_uint, VECTOR_WIDTH)(reals)
#  define UINTS_AS_REALS(uints) CONCATENATE(as_float, VECTOR_WIDTH)(uints)
#  define STORE_REALS(value, pointer) CONCATENATE(vstore, VECTOR_WIDTH)((value), 0, (pointer))
// Lane i of the result is lane i-1 of vector; lane 0 is the last lane of previous.
#  define SHIFT_IN_FROM_LEFT(previous, vector) shuffle2((previous), (vector), SHIFT_MASK)
#  if VECTOR_WIDTH == 2
#    define LANE_INDICES ((IntVector)(0, 1))
#    define SHIFT_MASK ((UIntVector)(1, 2))
#    define LAST_LANE(vector) ((vector).s1)
#  elif VECTOR_WIDTH == 4
#    define LANE_INDICES ((IntVector)(0, 1, 2, 3))
#    define SHIFT_MASK ((UIntVector)(3, 4, 5, 6))
#    define LAST_LANE(vector) ((vector).s3)
#  elif VECTOR_WIDTH == 8
#    define LANE_INDICES ((IntVector)(0, 1, 2, 3, 4, 5, 6, 7))
#    define SHIFT_MASK ((UIntVector)(7, 8, 9, 10, 11, 12, 13, 14))
#    define LAST_LANE(vector) ((vector).s7)
#  elif VECTOR_WIDTH == 16
#    define LANE_INDICES ((IntVector)(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15))
#    define SHIFT_MASK ((UIntVector)(15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30))
#    define LAST_LANE(vector) ((vector).sf)
#  else
#    error "VECTOR_WIDTH must be 1, 2, 4, 8 or 16"
#  endif
#endif

// 2^u for -127 <= u <= 0: u = n + f with n the integer nearest u and |f| <= 1/2 (adding 1.5 * 2^23 rounds u to n
// and leaves n in the low mantissa bits; the built-in rint is a slow library call on some CPU devices), 2^f by a
// degree-5 minimax polynomial (relative error 7.5e-8, 2.3e-7 after float rounding), 2^n written into the exponent
// bits (a normal float for n >= -126).
inline RealVector
PowerOfTwo(const RealVector u)
{
  const RealVector shifted = u + 12582912.0f;
  const RealVector n = shifted - 12582912.0f;
  const RealVector f = u - n;
  RealVector       p = f * 1.327647198e-3f + 9.675541334e-3f;
  p = p * f + 5.550713274e-2f;
  p = p * f + 2.402211972e-1f;
  p = p * f + 6.931469671e-1f;
  p = p * f + 1.000000072f;
  return p * UINTS_AS_REALS((AS_UINTS(shifted) << 23) + 0x3F800000u);
}

// R(d) = exp(-a d^2) = 2^(-weightPower d^2), weightPower = a log2(e); exactly 0 once the power passes the underflow
// bound, exactly 1 when a = 0 (isotropic); `valid` is 0 for edges leaving the image.
#define EDGE_WEIGHT(difference, valid)                                                                                \
  select((RealVector)(0.0f),                                                                                          \
         isotropic ? (RealVector)(1.0f)                                                                               \
                   : PowerOfTwo(fmax(-weightPower * (difference) * (difference), (RealVector)(-127.0f))),            \
         (valid) & (weightPower * (difference) * (difference) <= (RealVector)(WEIGHT_UNDERFLOW_POWER)))

__kernel __attribute__((reqd_work_group_size(LOCAL_WIDTH, LOCAL_HEIGHT, 1))) void
RelaxIteration(__global const float * restrict current,
               __global float * restrict       next,
               __global const uchar * restrict fixedMask,
               const int                       width,
               const int                       height,
               const int                       pitch,
               const int                       blocksPerRow,
               const float                     relaxation,
               const float                     weightPower,
               const int                       plane)
{
  const int block = get_global_id(0);
  const int firstRow = get_global_id(1) * ROWS_PER_ITEM;
  if (block >= blocksPerRow || firstRow >= height)
  {
    return;
  }
  const int   firstColumn = block * VECTORS_PER_ITEM * VECTOR_WIDTH;
  const int   lastRow = min(firstRow + ROWS_PER_ITEM, height);
  const float selfWeight = 1.0f - relaxation;
  const bool  isotropic = weightPower == 0.0f;

  // Up-edges, kept as the down-edges of the row above: weight and R (D_row - D_above).
  RealVector upWeight[VECTORS_PER_ITEM];
  RealVector upWeightedDifference[VECTORS_PER_ITEM];
  {
    const int aboveRow = max(firstRow - 1, 0);
    const int upValid = firstRow > 0 ? -1 : 0;
    for (int v = 0; v < VECTORS_PER_ITEM; ++v)
    {
      const int        k = VECTOR_WIDTH + firstColumn + v * VECTOR_WIDTH;
      const RealVector fromAbove =
        (LOAD_REALS(current + firstRow * pitch + k) - LOAD_REALS(current + aboveRow * pitch + k)) +
        (LOAD_REALS(current + plane + firstRow * pitch + k) - LOAD_REALS(current + plane + aboveRow * pitch + k));
      upWeight[v] = EDGE_WEIGHT(fromAbove, (IntVector)(upValid));
      upWeightedDifference[v] = upWeight[v] * fromAbove;
    }
  }

  for (int y = firstRow; y < lastRow; ++y)
  {
    const int   belowRow = min(y + 1, height - 1);
    const int   downValid = y + 1 < height ? -1 : 0;
    const float verticalNeighbours = (float)(y > 0) + (float)(y + 1 < height);

    __global const float * row = current + y * pitch + VECTOR_WIDTH;
    __global const float * below = current + belowRow * pitch + VECTOR_WIDTH;
    __global const float * rowLow = row + plane;
    __global const float * belowLow = below + plane;

    // The left-edge of the block's first pixel, as if it were the right-edge of a vector before the block.
    RealVector previousRightWeight;
    RealVector previousRightWeightedDifference;
    {
      const float toLeft = (row[firstColumn - 1] - row[firstColumn]) + (rowLow[firstColumn - 1] - rowLow[firstColumn]);
      previousRightWeight = EDGE_WEIGHT((RealVector)(toLeft), (IntVector)(firstColumn > 0 ? -1 : 0));
      previousRightWeightedDifference = -previousRightWeight * toLeft;
    }

    for (int v = 0; v < VECTORS_PER_ITEM; ++v)
    {
      const int        x0 = firstColumn + v * VECTOR_WIDTH;
      const IntVector  x = (IntVector)(x0) + LANE_INDICES;
      const RealVector dp = LOAD_REALS(row + x0);
      const RealVector dpLow = LOAD_REALS(rowLow + x0);
      const RealVector toRight = (LOAD_REALS(row + x0 + 1) - dp) + (LOAD_REALS(rowLow + x0 + 1) - dpLow);
      const RealVector toBelow = (LOAD_REALS(below + x0) - dp) + (LOAD_REALS(belowLow + x0) - dpLow);

      const RealVector rightWeight = EDGE_WEIGHT(toRight, x + 1 < (IntVector)(width));
      const RealVector rightWeightedDifference = rightWeight * toRight;
      const RealVector downWeight = EDGE_WEIGHT(toBelow, (IntVector)(downValid));
      const RealVector downWeightedDifference = downWeight * toBelow;
      // A left-edge is the right-edge of the pixel before, seen from the other side: same weight, opposite sign.
      const RealVector leftWeight = SHIFT_IN_FROM_LEFT(previousRightWeight, rightWeight);
      const RealVector leftWeightedDifference =
        -SHIFT_IN_FROM_LEFT(previousRightWeightedDifference, rightWeightedDifference);

      const RealVector neighbours = (RealVector)(verticalNeighbours) +
                                    select((RealVector)(0.0f), (RealVector)(1.0f), x > (IntVector)(0)) +
                                    select((RealVector)(0.0f), (RealVector)(1.0f), x + 1 < (IntVector)(width));
      const RealVector weightSum = leftWeight + rightWeight + upWeight[v] + downWeight;
      const RealVector weightedDifference =
        leftWeightedDifference + rightWeightedDifference - upWeightedDifference[v] + downWeightedDifference;
      const RealVector denominator = selfWeight * neighbours + relaxation * weightSum;
      const RealVector step = relaxation * weightedDifference / denominator;
      const RealVector lowAndStep = dpLow + step;
      const RealVector relaxed = dp + lowAndStep;
      const RealVector relaxedLow = lowAndStep - (relaxed - dp);

      const IntVector keep = (LOAD_BYTES_AS_INTS(fixedMask + y * pitch + VECTOR_WIDTH + x0) != (IntVector)(0)) |
                             (x >= (IntVector)(width)) | !(denominator > (RealVector)(0.0f));
      STORE_REALS(select(relaxed, dp, keep), next + y * pitch + VECTOR_WIDTH + x0);
      STORE_REALS(select(relaxedLow, dpLow, keep), next + plane + y * pitch + VECTOR_WIDTH + x0);

      previousRightWeight = rightWeight;
      previousRightWeightedDifference = rightWeightedDifference;
      upWeight[v] = downWeight;
      upWeightedDifference[v] = downWeightedDifference;
    }
  }
}

// The relaxed depth as one float a pixel, high + low (what the host made of the two planes before), in a packed
// W x H buffer: downloaded once, and read by the resampling of the same view on the device.
__kernel void
CombinePlanes(__global const float * restrict depth,
              __global float * restrict       packed,
              const int                       width,
              const int                       height,
              const int                       pitch,
              const int                       plane)
{
  const int x = get_global_id(0);
  const int y = get_global_id(1);
  if (x >= width || y >= height)
  {
    return;
  }
  const int k = y * pitch + VECTOR_WIDTH + x;
  packed[y * width + x] = depth[k] + depth[plane + k];
}

#ifdef PASSES_PER_LAUNCH
// Several Jacobi passes per launch (GPUs): a work-group loads a tile of TILE_WIDTH x TILE_HEIGHT pixels with a
// border of PASSES_PER_LAUNCH pixels (clipped nowhere: pixels outside the image are kept and their edges have
// weight 0) into local memory, runs `passes` passes there, and writes the tile's own pixels back. Pass j (from 0)
// relaxes the pixels at least j + 1 from the border's outer edge: after `passes` <= PASSES_PER_LAUNCH passes the
// tile's own pixels hold what `passes` launches of RelaxIteration give, computed by the same expressions (each
// edge's difference and weight from the pixel's side: a - b is exactly -(b - a), and a weight depends on the
// difference's square), so the bits do not depend on PASSES_PER_LAUNCH. Pixels of neighbouring tiles' borders are
// computed again by each tile that needs them instead of being exchanged between passes.
#  if VECTOR_WIDTH != 1
#    error "the multi-pass kernel relaxes one pixel at a time: VECTOR_WIDTH must be 1"
#  endif
#  define TILE_EXTENDED_WIDTH (TILE_WIDTH + 2 * PASSES_PER_LAUNCH)
#  define TILE_EXTENDED_HEIGHT (TILE_HEIGHT + 2 * PASSES_PER_LAUNCH)
#  define TILE_PIXELS (TILE_EXTENDED_WIDTH * TILE_EXTENDED_HEIGHT)
#  define SLOTS_X ((TILE_EXTENDED_WIDTH + LOCAL_WIDTH - 1) / LOCAL_WIDTH)
#  define SLOTS_Y ((TILE_EXTENDED_HEIGHT + LOCAL_HEIGHT - 1) / LOCAL_HEIGHT)

__kernel __attribute__((reqd_work_group_size(LOCAL_WIDTH, LOCAL_HEIGHT, 1))) void
RelaxPasses(__global const float * restrict current,
            __global float * restrict       next,
            __global const uchar * restrict fixedMask,
            const int                       width,
            const int                       height,
            const int                       pitch,
            const float                     relaxation,
            const float                     weightPower,
            const int                       plane,
            const int                       passes)
{
  __local float high[TILE_PIXELS];
  __local float low[TILE_PIXELS];
  __local uchar kept[TILE_PIXELS]; // fixed, or outside the image

  const int localX = get_local_id(0);
  const int localY = get_local_id(1);
  // The image position of the bordered tile's first pixel.
  const int originX = get_group_id(0) * TILE_WIDTH - PASSES_PER_LAUNCH;
  const int originY = get_group_id(1) * TILE_HEIGHT - PASSES_PER_LAUNCH;
  const float selfWeight = 1.0f - relaxation;
  const bool  isotropic = weightPower == 0.0f;

  for (int ty = localY; ty < TILE_EXTENDED_HEIGHT; ty += LOCAL_HEIGHT)
  {
    for (int tx = localX; tx < TILE_EXTENDED_WIDTH; tx += LOCAL_WIDTH)
    {
      const int  x = originX + tx;
      const int  y = originY + ty;
      const int  t = ty * TILE_EXTENDED_WIDTH + tx;
      const bool inside = x >= 0 && x < width && y >= 0 && y < height;
      const int  k = inside ? y * pitch + VECTOR_WIDTH + x : 0;
      high[t] = inside ? current[k] : 0.0f;
      low[t] = inside ? current[plane + k] : 0.0f;
      kept[t] = inside ? (fixedMask[k] != 0) : 1;
    }
  }
  barrier(CLK_LOCAL_MEM_FENCE);

  for (int pass = 0; pass < passes; ++pass)
  {
    const int margin = pass + 1;
    float     nextHigh[SLOTS_Y][SLOTS_X];
    float     nextLow[SLOTS_Y][SLOTS_X];
    for (int sy = 0; sy < SLOTS_Y; ++sy)
    {
      for (int sx = 0; sx < SLOTS_X; ++sx)
      {
        const int tx = localX + sx * LOCAL_WIDTH;
        const int ty = localY + sy * LOCAL_HEIGHT;
        if (tx < margin || tx >= TILE_EXTENDED_WIDTH - margin || ty < margin || ty >= TILE_EXTENDED_HEIGHT - margin)
        {
          continue;
        }
        const int   t = ty * TILE_EXTENDED_WIDTH + tx;
        const int   x = originX + tx;
        const int   y = originY + ty;
        const float dp = high[t];
        const float dpLow = low[t];
        const float toLeft = (high[t - 1] - dp) + (low[t - 1] - dpLow);
        const float toRight = (high[t + 1] - dp) + (low[t + 1] - dpLow);
        const float toAbove = (high[t - TILE_EXTENDED_WIDTH] - dp) + (low[t - TILE_EXTENDED_WIDTH] - dpLow);
        const float toBelow = (high[t + TILE_EXTENDED_WIDTH] - dp) + (low[t + TILE_EXTENDED_WIDTH] - dpLow);

        const float leftWeight = EDGE_WEIGHT(toLeft, x > 0);
        const float rightWeight = EDGE_WEIGHT(toRight, x + 1 < width);
        const float upWeight = EDGE_WEIGHT(toAbove, y > 0);
        const float downWeight = EDGE_WEIGHT(toBelow, y + 1 < height);
        // One product a statement, as RelaxIteration computes them: no fused multiply-add may join two of them.
        const float leftWeightedDifference = leftWeight * toLeft;
        const float rightWeightedDifference = rightWeight * toRight;
        const float upWeightedDifference = upWeight * toAbove;
        const float downWeightedDifference = downWeight * toBelow;

        const float verticalNeighbours = (float)(y > 0) + (float)(y + 1 < height);
        const float neighbours =
          verticalNeighbours + select(0.0f, 1.0f, x > 0) + select(0.0f, 1.0f, x + 1 < width);
        const float weightSum = leftWeight + rightWeight + upWeight + downWeight;
        const float weightedDifference =
          leftWeightedDifference + rightWeightedDifference + upWeightedDifference + downWeightedDifference;
        const float denominator = selfWeight * neighbours + relaxation * weightSum;
        const float step = relaxation * weightedDifference / denominator;
        const float lowAndStep = dpLow + step;
        const float relaxed = dp + lowAndStep;
        const float relaxedLow = lowAndStep - (relaxed - dp);

        const bool keep = kept[t] != 0 || !(denominator > 0.0f);
        nextHigh[sy][sx] = keep ? dp : relaxed;
        nextLow[sy][sx] = keep ? dpLow : relaxedLow;
      }
    }
    barrier(CLK_LOCAL_MEM_FENCE);
    for (int sy = 0; sy < SLOTS_Y; ++sy)
    {
      for (int sx = 0; sx < SLOTS_X; ++sx)
      {
        const int tx = localX + sx * LOCAL_WIDTH;
        const int ty = localY + sy * LOCAL_HEIGHT;
        if (tx < margin || tx >= TILE_EXTENDED_WIDTH - margin || ty < margin || ty >= TILE_EXTENDED_HEIGHT - margin)
        {
          continue;
        }
        const int t = ty * TILE_EXTENDED_WIDTH + tx;
        high[t] = nextHigh[sy][sx];
        low[t] = nextLow[sy][sx];
      }
    }
    barrier(CLK_LOCAL_MEM_FENCE);
  }

  for (int ty = PASSES_PER_LAUNCH + localY; ty < PASSES_PER_LAUNCH + TILE_HEIGHT; ty += LOCAL_HEIGHT)
  {
    for (int tx = PASSES_PER_LAUNCH + localX; tx < PASSES_PER_LAUNCH + TILE_WIDTH; tx += LOCAL_WIDTH)
    {
      const int x = originX + tx;
      const int y = originY + ty;
      if (x < width && y < height)
      {
        const int t = ty * TILE_EXTENDED_WIDTH + tx;
        const int k = y * pitch + VECTOR_WIDTH + x;
        next[k] = high[t];
        next[plane + k] = low[t];
      }
    }
  }
}
#endif
