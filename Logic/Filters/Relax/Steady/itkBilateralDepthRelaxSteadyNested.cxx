// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkBilateralDepthRelaxSteadyNested.h"

#include "itkBilateralDepthRelaxSteadyRows.h"

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
  bands.ForRows(
    height,
    true,
    [&](long y0, long y1)
    {
      for (long y = y0; y < y1; ++y)
      {
        const long j = y / 2;
        const long jn = std::clamp(y % 2 ? j + 1 : j - 1, 0L, coarseHeight - 1);
        const long row = (y + 1) * stride + 1;
        Rows().ProlongStartRow(
          depth + row, active + row, coarse + j * coarseWidth, coarse + jn * coarseWidth, coarseWidth, scale, width);
      }
    });
}
} // namespace itk::detail::BilateralDepthRelaxSteady
