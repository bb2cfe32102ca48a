// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Clinical-size CT angiographies made from the built-in phantoms, for the measurements and tests of full-size input
// (WriteClinicalVolume, the large-volume test and benchmarks; docs/benchmarks.md "Full-size volumes").
#ifndef vrClinicalVolume_h
#define vrClinicalVolume_h

#include "itkCTAPhantom.h"
#include "itkImage.h"

#include <functional>

namespace vr::test
{
/** The phantom \a kind drawn on a grid of \a size voxels as a CT scanner would store it: slices of size[0] x size[1]
 * square pixels that span the phantom's width and depth (the phantom centred, air of -1000 HU around it) and size[2]
 * slices spanning its length (a slice spacing of its own: clinical voxels are rarely cubes). The phantom is drawn at
 * the slices' pixel spacing, slab by slab (never whole), and each output slice interpolates linearly between the two
 * drawn slices around it. Values are Hounsfield units less \a intercept, rounded and clamped to TPixel (short, unsigned
 * short with intercept -1024, float, double). LPS, identity direction; the phantom's tree (MakeCTAPhantom) fits it.
 * \param progress called with the fraction done, now and then (may be empty). */
template<typename TPixel>
typename itk::Image<TPixel, 3>::Pointer
MakeClinicalVolume(itk::CTAPhantomKind                 kind,
                   const itk::Size<3> &                size,
                   double                              intercept = 0.0,
                   const std::function<void(double)> & progress = {});
} // namespace vr::test

#endif
