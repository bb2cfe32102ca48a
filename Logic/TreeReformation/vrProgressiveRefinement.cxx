// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrProgressiveRefinement.h"

#include <algorithm>
#include <cmath>

namespace vr
{
long long
PreviewIterations(long long iterations, unsigned int factor)
{
  if (iterations <= 0 || factor <= 1)
  {
    return iterations;
  }
  const long long area = static_cast<long long>(factor) * static_cast<long long>(factor);
  return std::max(1LL, (iterations + area - 1) / area);
}

ReformationParameters
PreviewParameters(const ReformationParameters & full, const itk::CPRViewGeometry & fullView, unsigned int factor)
{
  factor = std::max(1U, factor);
  ReformationParameters preview = full;
  // The view made explicit, so that the preview resolves to the same centre whatever the full request left unset.
  preview.HasCenter = true;
  preview.Center = fullView.GetCenter();
  for (unsigned int axis = 0; axis < 2; ++axis)
  {
    const auto pixels = static_cast<itk::SizeValueType>(fullView.GetSize()[axis]);
    preview.ImageSize[axis] = (pixels + factor - 1) / factor;
    preview.PixelSpacing[axis] = factor * fullView.GetSpacing()[axis];
  }
  if (full.Solver == itk::BilateralDepthRelaxSolver::Jacobi)
  {
    preview.Iterations = PreviewIterations(full.Iterations, factor);
  }
  return preview;
}

unsigned int
ChoosePreviewFactor(const std::array<double, 3> & seconds, double budgetSeconds)
{
  const std::size_t count = PreviewFactors.size();
  bool              measured = false;
  for (double time : seconds)
  {
    measured = measured || time >= 0.0;
  }
  if (!measured)
  {
    return 1;
  }
  for (std::size_t index = 0; index < count; ++index)
  {
    double expected = seconds[index];
    if (expected < 0.0)
    {
      // From the measured factors by the pixel count; the smallest prediction, so that an unmeasured finer factor is
      // tried once and then known (its measured time decides from then on).
      for (std::size_t other = 0; other < count; ++other)
      {
        if (seconds[other] >= 0.0)
        {
          const double ratio = static_cast<double>(PreviewFactors[other]) / PreviewFactors[index];
          const double predicted = seconds[other] * ratio * ratio;
          expected = expected < 0.0 ? predicted : std::min(expected, predicted);
        }
      }
    }
    if (expected <= budgetSeconds)
    {
      return PreviewFactors[index];
    }
  }
  return PreviewFactors[count - 1];
}
} // namespace vr
