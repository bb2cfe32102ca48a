// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrFigure_h
#define vrFigure_h

#include "itkImage.h"
#include "itkRGBPixel.h"

#include <string>
#include <vector>

namespace vr
{
using RGBPixelType = itk::RGBPixel<unsigned char>;
using RGBImageType = itk::Image<RGBPixelType, 2>;
using FloatImage2DType = itk::Image<float, 2>;

/** A CPR or any scalar image as grey through window/level. */
RGBImageType::Pointer
RenderWindowLevel(const FloatImage2DType * image, double window, double level);

/** A depth map in a perceptual colour map (viridis-like): \a nearest (towards the viewer) dark blue,
 * \a farthest yellow. */
RGBImageType::Pointer
RenderDepth(const FloatImage2DType * depth, double nearest, double farthest);

/** RenderDepth's colours shaded as a relief lit from the upper left, so that steps of a millimetre (seams) show
 * as lines even when the colour range spans much more. */
RGBImageType::Pointer
RenderDepthRelief(const FloatImage2DType * depth, double nearest, double farthest);

/** The part of \a image starting at pixel (x, y), \a width x \a height pixels (clipped to the image). */
RGBImageType::Pointer
Crop(const RGBImageType * image, unsigned int x, unsigned int y, unsigned int width, unsigned int height);

/** \a image scaled to \a width pixels wide (aspect kept), nearest neighbour so pixels stay visible. */
RGBImageType::Pointer
Magnify(const RGBImageType * image, unsigned int width);

/** The \a low and \a high quantiles (fractions in [0, 1]) of \a image inside the given pixel rectangle: a colour
 * range that a few outlying pixels do not stretch. */
std::pair<double, double>
RangeWithin(const FloatImage2DType * image,
            unsigned int             x,
            unsigned int             y,
            unsigned int             width,
            unsigned int             height,
            double                   low = 0.0,
            double                   high = 1.0);

/** One picture of a figure and its title.
 * \ingroup VesselReformation
 */
struct FigurePanel
{
  RGBImageType::ConstPointer Image;
  std::string                Title;
};

/** Lays panels out in rows (a grid; rows may differ in length) on a dark background, each titled above, with a
 * caption line at the bottom. Text is drawn with VTK's FreeType renderer, no display needed. */
RGBImageType::Pointer
ComposeFigure(const std::vector<std::vector<FigurePanel>> & rows, const std::string & caption);

/** A horizontal colour bar for RenderDepth's map, labelled with the depth range in mm. */
RGBImageType::Pointer
RenderDepthColorBar(double nearest, double farthest, unsigned int width);

/** Writes an RGB PNG under a temporary name and renames it (vr::AtomicOutput). Throws vr::InputError. */
void
WriteRGBPNG(const RGBImageType * image, const std::string & path);
} // namespace vr

#endif
