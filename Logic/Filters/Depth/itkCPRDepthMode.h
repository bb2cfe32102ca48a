// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkCPRDepthMode_h
#define itkCPRDepthMode_h

#include <ostream>

namespace itk
{
/** How the pixels away from the centerlines take their depth (docs/design.md "Depth").
 * \ingroup VesselReformation */
enum class CPRDepthMode
{
  /** mpCPR: the nearest centerline pixel in the pixel's own row; empty rows copy the nearest filled row. */
  Scanline,
  /** Centerline-reformation-like: the nearest centerline pixel in 2D (a Voronoi partition of the plane). */
  Nearest,
  /** Occlusion-aware: each vessel's projected lumen footprint shows the vessel whose lumen the view ray meets first
   * there; pixels outside every footprint take the nearest footprint pixel in 2D. A second label image names the
   * vessel hidden behind (docs/design.md "Depth", Visibility mode). */
  Visibility
};

/** Prints "Scanline", "Nearest" or "Visibility". */
std::ostream &
operator<<(std::ostream & os, CPRDepthMode mode);
} // namespace itk

#endif
