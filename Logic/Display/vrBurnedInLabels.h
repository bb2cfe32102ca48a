// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrBurnedInLabels_h
#define vrBurnedInLabels_h

#include "itkVector.h"
#include "vrImageTypes.h"

#include <string>

namespace vr
{
/** The patient-orientation letters of a direction (LPS), as a reader expects them at a screen edge: L or R for x, P
 * or A for y, S or I for z, the largest component first, a second letter when that component is at least 0.4 (more
 * than about 24 degrees off the first axis): "L", "LA", "SP". Empty for a zero vector. */
std::string
OrientationLetters(const itk::Vector<double, 3> & lps);

/** The pixel size of \a text burned in at \a scale (BurnInText): width and height. */
void
BurnedInTextSize(const std::string & text, int scale, long & width, long & height);

/** Burns \a text into \a image with its top-left corner at (\a x, \a y): white glyphs of a 5 x 7 pixel font, each
 * font pixel \a scale x \a scale image pixels, on a black outline one pixel wide, so that it reads on any grey. The
 * font has the digits, ". - +" and the degree sign, a space, and the letters A I L P R S (the angle and the
 * orientation letters): any other character is drawn as a space. What falls outside the image is left out.
 * Thread-safe (no font library). */
void
BurnInText(MaskImageType * image, const std::string & text, long x, long y, int scale);

/** Burns a reformation's reading labels into \a image (docs/viewer.md, "Rotation series"): the view's angle in the
 * top-left corner ("30°"), and the orientation letters of each screen edge at its middle: the right edge's of
 * \a screenRight (the view's u), the left's of -u, the top's of \a screenUp (the view's up) and the bottom's of -up.
 * The font's scale follows the image: its long side / 170, at least 2. */
void
BurnInViewLabels(MaskImageType *                image,
                 const itk::Vector<double, 3> & screenRight,
                 const itk::Vector<double, 3> & screenUp,
                 double                         angleInDegrees);
} // namespace vr

#endif
