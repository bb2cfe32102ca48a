// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrIntensityWindow_h
#define vrIntensityWindow_h

#include "vrVolumeNode.h"

#include <string>

namespace vr
{
/** The CTA window (W 900, L 200 HU): lumen, soft tissue and bone at once, as the demo's pictures; the viewer's
 * "CTA" preset and the default of a rotation series of a CT. */
constexpr double CTAWindow = 900.0;
constexpr double CTALevel = 200.0;

/** \return "HU" when \a volume holds a CT, else empty: a volume whose intensities reach -500 or below holds air
 * in Hounsfield units (about -1000 HU); MR and the other modalities store no such values. Files rarely say their
 * modality (NRRD, NIfTI and MetaImage do not), so the data decides. */
std::string
IntensityUnitOf(VolumeNode * volume);

/** The window (p99 - p1, at least 1) and level ((p1 + p99) / 2) of \a volume's 1st and 99th intensity percentiles:
 * a window that suits data without a fixed intensity scale, which a few bright voxels do not wash out as the full
 * range does. Percentiles of every voxel up to 4 million, of an even sample of them beyond; non-finite voxels are
 * skipped.
 * \param volume a node with scalar image data.
 * \param window receives the window; \param level the level (both 0 for a node without finite voxels). */
void
PercentileWindowOf(VolumeNode * volume, double & window, double & level);

/** The window a volume is first shown with: the CTA window for a CT (IntensityUnitOf is "HU"), else the
 * percentile window (PercentileWindowOf).
 * \param volume the volume node.
 * \param window receives the window; \param level the level (both 0 for a node without finite voxels). */
void
DefaultWindowOf(VolumeNode * volume, double & window, double & level);
} // namespace vr

#endif
