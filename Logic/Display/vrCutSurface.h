// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrCutSurface_h
#define vrCutSurface_h

#include "itkCPRViewGeometry.h"
#include "vrImageTypes.h"

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace vr
{
/** Names of the point arrays of a cut surface. */
constexpr const char * CutSurfaceIntensityArrayName = "Intensity";
constexpr const char * CutSurfaceDepthArrayName = "Depth";

/** The largest depth step, in mm, that the cut surface bridges by default: four pixels' width. A larger step
 * between neighbouring pixels is a meaningful jump (the gap between two vessels) and stays open. */
double
DefaultMaximumBridgedDepthJump(const itk::CPRViewGeometry & view);

/** Builds the cut surface of a reformation for 3D display (Kretschmer et al., EuroVis 2014, Figures 3 and 5).
 *
 * Pixel (i, j) becomes the point X = B(i, j) + d(i, j) v, in RAS millimetres (converted through
 * vrCoordinateFrames.h), carrying the CPR intensity (active scalars, "Intensity") and the depth ("Depth"). Each
 * square of four neighbouring pixels gives two triangles, (i, j) (i+1, j) (i+1, j+1) and (i, j) (i+1, j+1)
 * (i, j+1); a triangle is left out when two of its corners differ in depth by more than
 * \a maximumBridgedJump mm.
 *
 * \param depth the depth map d (mm), on the view's grid.
 * \param intensity the CPR image sampled on that depth map, same size.
 * \param view the view both images were made on.
 * \param maximumBridgedJump the largest depth difference (mm) inside one triangle; >= 0.
 * \return the surface: W x H points and up to 2 (W-1)(H-1) triangles.
 * Throws vr::InputError when the sizes differ or the threshold is invalid. */
vtkSmartPointer<vtkPolyData>
BuildCutSurface(const DepthImageType *       depth,
                const DepthImageType *       intensity,
                const itk::CPRViewGeometry & view,
                double                       maximumBridgedJump);
} // namespace vr

#endif
