// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCPRSamplingModes_h
#define itkCPRSamplingModes_h

#include <ostream>

namespace itk
{

/** How the volume is interpolated at a sampled point (docs/design.md "Resampling"): the tree CPR and the path view's
 * filters take the same modes. */
enum class CPRInterpolationMode
{
  Linear,
  Nearest,
  /** Cubic B-spline. */
  Cubic
};

/** How the samples of a slab are combined. */
enum class CPRSlabMode
{
  /** Maximum intensity projection. */
  MIP,
  /** Minimum intensity projection. */
  MinIP,
  Mean
};

std::ostream &
operator<<(std::ostream & os, CPRInterpolationMode mode);
std::ostream &
operator<<(std::ostream & os, CPRSlabMode mode);

} // namespace itk

#endif
