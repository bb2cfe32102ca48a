// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The preview policy of progressive refinement (docs/progressive-refinement.md) without a thread or a widget: the
// factor forced or chosen from the medians of recent times, and each step's parameters from the full view.
#include "vrPreviewPolicy.h"

#include <gtest/gtest.h>

#include <array>

namespace
{
using namespace vr;

itk::CPRViewGeometry
FullView(const ReformationParameters & parameters)
{
  return itk::CPRViewGeometry(parameters.Up,
                              parameters.AngleInDegrees,
                              itk::CPRViewGeometry::PointType(std::array<double, 3>{ 1.0, -2.0, 3.0 }.data()),
                              itk::Size<2>{ { 512, 1024 } },
                              itk::CPRViewGeometry::SpacingType(std::array<double, 2>{ 0.5, 0.5 }.data()));
}

TEST(PreviewPolicy, AForcedFactorIsTakenAsItIsAndAnUnknownOneMeansNoPreview)
{
  PreviewPolicy policy;
  policy.SetForcedFactor(4);
  EXPECT_EQ(policy.ChooseFactor(), 4u);
  policy.SetForcedFactor(2);
  EXPECT_EQ(policy.ChooseFactor(), 2u);
  policy.SetForcedFactor(3); // not one of 1, 2, 4
  EXPECT_EQ(policy.ChooseFactor(), 1u);
  policy.SetForcedFactor(0); // adaptive, nothing measured yet: full resolution
  EXPECT_EQ(policy.ChooseFactor(), 1u);
}

TEST(PreviewPolicy, TheAdaptiveChoiceFollowsTheMedianOfTheLastFiveTimes)
{
  PreviewPolicy policy;
  policy.SetFrameBudget(0.05);
  // Full updates of 176 ms: predicted 44 ms at k = 2, within 50 ms.
  for (double seconds : { 0.176, 0.176, 0.176 })
  {
    policy.RecordTime(1, seconds);
  }
  EXPECT_EQ(policy.ChooseFactor(), 2u);
  // Three fast full updates bring the median of the last five (0.176, 0.176, 0.03, 0.03, 0.03) to 30 ms.
  for (double seconds : { 0.03, 0.03, 0.03 })
  {
    policy.RecordTime(1, seconds);
  }
  EXPECT_EQ(policy.ChooseFactor(), 1u);
  // A zero budget: nothing fits, the coarsest factor.
  policy.SetFrameBudget(-1.0);
  EXPECT_EQ(policy.ChooseFactor(), 4u);
  // New data forgets the times.
  policy.SetFrameBudget(0.05);
  policy.Forget();
  EXPECT_EQ(policy.ChooseFactor(), 1u);
}

TEST(PreviewPolicy, AStepIsAPreviewOnlyOfTheRememberedViewUpToTheAngle)
{
  PreviewPolicy         policy;
  ReformationParameters full;
  full.AngleInDegrees = 30.0;
  full.Iterations = 500;
  policy.SetForcedFactor(2);

  // No full view yet: the step at full resolution.
  ReformationParameters step = full;
  step.AngleInDegrees = 35.0;
  PreviewPolicy::Step planned = policy.PlanStep(step);
  EXPECT_EQ(planned.Factor, 1u);
  EXPECT_EQ(planned.Parameters.Iterations, 500);

  // With the full view of the same view: half the pixels each way, ceil(500 / 4) passes, the step's angle.
  const itk::CPRViewGeometry view = FullView(full);
  policy.RememberFullView(full, view);
  planned = policy.PlanStep(step);
  EXPECT_EQ(planned.Factor, 2u);
  EXPECT_EQ(planned.Parameters.Iterations, 125);
  EXPECT_EQ(planned.Parameters.ImageSize[0], 256u);
  EXPECT_EQ(planned.Parameters.ImageSize[1], 512u);
  EXPECT_DOUBLE_EQ(planned.Parameters.AngleInDegrees, 35.0);
  EXPECT_EQ(planned.Parameters.Center, view.GetCenter());

  // Another view (another image size asked): full resolution until its own full view is known.
  ReformationParameters other = step;
  other.ImageSize[0] = 300;
  other.ImageSize[1] = 600;
  EXPECT_EQ(policy.PlanStep(other).Factor, 1u);

  // A preview stands for the full view turned to its angle.
  const itk::CPRViewGeometry preview(full.Up,
                                     35.0,
                                     view.GetCenter(),
                                     itk::Size<2>{ { 256, 512 } },
                                     itk::CPRViewGeometry::SpacingType(std::array<double, 2>{ 1.0, 1.0 }.data()));
  const itk::CPRViewGeometry standsFor = policy.FullViewOf(preview);
  EXPECT_DOUBLE_EQ(standsFor.GetAngleInDegrees(), 35.0);
  EXPECT_EQ(standsFor.GetSize(), view.GetSize());
  EXPECT_EQ(standsFor.GetSpacing(), view.GetSpacing());
  EXPECT_EQ(standsFor.GetCenter(), view.GetCenter());
}
} // namespace
