// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCPRNearestFill_h
#define itkCPRNearestFill_h

#include "itkIntTypes.h"
#include "itkMultiThreaderBase.h"
#include "itkVector.h"

#include <cstdint>
#include <vector>

namespace itk::detail
{
/** The buffers of FillFromNearestSeeds, kept between updates. */
struct CPRNearestFillWorkspace
{
  /** Per pixel, the row of the nearest seed in its column (-1: none). */
  std::vector<int32_t> ColumnWinner;
};

/** Gives every pixel whose \a owner is 0 the depth and owner of the nearest pixel whose owner is not 0 (a seed),
 * by distance in mm on a grid of \a spacing (sx, sy); ties go to the smaller depth, then the smaller owner. Seeds keep
 * their values. The exact Euclidean nearest seed in linear time: the nearest seed of each column first, then per row
 * the lower envelope of the parabolas those column winners span (Felzenszwalb and Huttenlocher, "Distance Transforms
 * of Sampled Functions", Theory of Computing 2012), with the envelope's neighbours compared where they tie. \a depth
 * and \a owner are row-major \a width x \a height; columns, then rows, run in parallel on \a threader. Throws when
 * there is no seed. */
void
FillFromNearestSeeds(SizeValueType             width,
                     SizeValueType             height,
                     const Vector<double, 2> & spacing,
                     std::vector<float> &      depth,
                     std::vector<uint32_t> &   owner,
                     MultiThreaderBase *       threader,
                     CPRNearestFillWorkspace & workspace);
} // namespace itk::detail

#endif
