// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkBilateralDepthRelaxSteadyNested.h"

#include "itkBilateralDepthRelaxRangeWeight.h"

#include <algorithm>

namespace itk::detail::BilateralDepthRelaxSteady
{
void
CoarsenMap(Bands &               bands,
           const float *         depth,
           const unsigned char * fixed,
           long                  width,
           long                  height,
           float *               coarseDepth,
           unsigned char *       coarseFixed,
           long                  coarseWidth,
           long                  coarseHeight)
{
  bands.ForRows(coarseHeight,
                coarseWidth * coarseHeight >= ParallelPoints,
                [&](long j0, long j1)
                {
                  for (long j = j0; j < j1; ++j)
                  {
                    const long y1 = std::min(2 * j + 2, height);
                    for (long i = 0; i < coarseWidth; ++i)
                    {
                      const long x1 = std::min(2 * i + 2, width);
                      // The block's first fixed pixel in raster order, else its first pixel: values of the input
                      // itself, never a mean across a depth jump.
                      long chosen = j * 2 * width + 2 * i;
                      bool isFixed = false;
                      for (long y = 2 * j; y < y1 && !isFixed; ++y)
                      {
                        for (long x = 2 * i; x < x1 && !isFixed; ++x)
                        {
                          const long k = y * width + x;
                          if (fixed && fixed[k])
                          {
                            chosen = k;
                            isFixed = true;
                          }
                        }
                      }
                      const long c = j * coarseWidth + i;
                      coarseFixed[c] = isFixed ? 1 : 0;
                      coarseDepth[c] = depth[chosen];
                    }
                  }
                });
}

void
ProlongStart(Bands &       bands,
             const float * coarse,
             long          coarseWidth,
             long          coarseHeight,
             float         scale,
             const float * active,
             double *      depth,
             long          width,
             long          height,
             long          stride)
{
  bands.ForRows(height,
                true,
                [&](long y0, long y1)
                {
                  for (long y = y0; y < y1; ++y)
                  {
                    // The fine pixel's centre lies a quarter of a coarse pixel from its own coarse pixel's, towards
                    // the neighbour on that side (clamped at the border): bilinear weights 3/4 and 1/4 per axis.
                    const long    j = y / 2;
                    const long    jn = std::clamp(y % 2 ? j + 1 : j - 1, 0L, coarseHeight - 1);
                    const float * own = coarse + j * coarseWidth;
                    const float * other = coarse + jn * coarseWidth;
                    const long    row = (y + 1) * stride + 1;
                    for (long x = 0; x < width; ++x)
                    {
                      if (active[row + x] == 0.0f)
                      {
                        continue;
                      }
                      const long  i = x / 2;
                      const long  in = std::clamp(x % 2 ? i + 1 : i - 1, 0L, coarseWidth - 1);
                      const float centre = own[i];
                      const float values[3] = { own[in], other[i], other[in] };
                      const float bilinear[3] = { 3.0f / 16.0f, 3.0f / 16.0f, 1.0f / 16.0f };
                      float       sum = 9.0f / 16.0f * centre;
                      float       weights = 9.0f / 16.0f;
                      for (int n = 0; n < 3; ++n)
                      {
                        const float w = bilinear[n] * (scale > 0.0f ? RangeWeight(values[n] - centre, scale) : 1.0f);
                        sum += w * values[n];
                        weights += w;
                      }
                      depth[row + x] = sum / weights;
                    }
                  }
                });
}
} // namespace itk::detail::BilateralDepthRelaxSteady
