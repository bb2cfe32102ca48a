// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrSurfacePreview_h
#define vrSurfacePreview_h

#include "vrVesselReformationLogic.h"

#include <vtkSmartPointer.h>

class vtkPolyData;

namespace vr
{
/** The number of view pixels a preview surface aims at: about 32k points, which Mesa's software renderer draws in
 * a few milliseconds where the full 512 x 1024 surface takes about 290 ms a frame. */
constexpr double PreviewSurfacePointBudget = 32768.0;

/** \return the pixel stride of the preview surface of a W x H view: the smallest s >= 1 with
 * (W/s)(H/s) <= PreviewSurfacePointBudget. */
unsigned int
PreviewSurfaceStride(unsigned int width, unsigned int height);

/** The cut surface of \a outputs at every \a stride-th pixel, for the 3D view while the user drags: the logic's own
 * vr::BuildCutSurface on the relaxed depth and the CPR picked at pixels (s i, s j), on the view whose pixel (i, j)
 * is the full view's (s i, s j). Its points therefore lie exactly on the full surface; only triangles are coarser.
 * \param outputs outputs with a relaxed depth, a CPR and their view.
 * \param stride the pixel stride, >= 1.
 * \return the surface (RAS), or null when the outputs have no CPR yet. Throws vr::InputError on inconsistent
 * outputs. */
vtkSmartPointer<vtkPolyData>
BuildPreviewSurface(const ReformationOutputs & outputs, unsigned int stride);
} // namespace vr

#endif
