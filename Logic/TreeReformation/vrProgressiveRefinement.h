// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrProgressiveRefinement_h
#define vrProgressiveRefinement_h

#include "itkCPRViewGeometry.h"
#include "vrReformationParameters.h"

#include <array>

namespace vr
{
/** The preview factors k a viewer chooses from while the user moves the view: 1 (no preview), 2 and 4.
 * \ingroup VesselReformation
 */
constexpr std::array<unsigned int, 3> PreviewFactors{ 1, 2, 4 };

/** The parameters of a preview of the view \a fullView (the resolved view of \a full, VesselReformationLogic's
 * Outputs.View) at \a factor times its pixel spacing (docs/progressive-refinement.md):
 * - the same centre, the same up axis and angle, the same extent in mm: ceil(W / k) x ceil(H / k) pixels of
 *   k sx x k sy mm (the last row and column may reach up to (k - 1) pixels of the full grid beyond its edge);
 * - the same physical smoothing: ceil(N / k^2) Jacobi passes, at least 1 when N >= 1 (a pass spreads depth about one
 *   pixel, so N passes reach about sqrt(N) pixels; at k times the spacing N / k^2 passes reach as far in mm); the
 *   steady solver, w and the jump threshold J unchanged;
 * - everything else (depth mode, lumen fixing, backend, sampling, window) unchanged; the fixed pixels are
 *   rasterised anew on the preview's grid by the depth stage.
 * \param factor k >= 1 (1 returns \a full with its view made explicit).
 * \return the preview's parameters. */
ReformationParameters
PreviewParameters(const ReformationParameters & full, const itk::CPRViewGeometry & fullView, unsigned int factor);

/** ceil(N / k^2), at least 1 when \a iterations >= 1 (0 stays 0). */
long long
PreviewIterations(long long iterations, unsigned int factor);

/** Chooses the preview factor for the next step of an interaction from the measured times of recent updates:
 * the finest k of PreviewFactors whose update is expected to fit \a budgetSeconds; the coarsest when none is.
 * \param seconds the measured time of an update at each factor of PreviewFactors (same order); a negative entry has
 *        not been measured, and is predicted from the measured ones by the pixel count, t(k) = t(j) (j/k)^2 (the
 *        smallest of these predictions: an unmeasured factor is tried once, then its measured time decides).
 * \return k (1 when the full update fits, or when nothing was measured yet). */
unsigned int
ChoosePreviewFactor(const std::array<double, 3> & seconds, double budgetSeconds);
} // namespace vr

#endif
