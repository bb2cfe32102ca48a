// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrFilterSettingsText.h"

#include <sstream>

namespace vr
{
std::string
DescribeFilterSettings(const ReformationParameters & parameters, const std::string & breakBefore)
{
  // Numbers in the stream's shortest form ("3", "0.5"), as the user typed them.
  std::ostringstream text;
  if (parameters.Anisotropy)
  {
    text << "a = " << *parameters.Anisotropy << " mm^-2";
  }
  else
  {
    text << "J = " << parameters.JumpThreshold.value_or(ReformationParameters::DefaultJumpThreshold) << " mm";
  }
  if (parameters.Solver == itk::BilateralDepthRelaxSolver::Steady)
  {
    text << breakBefore << "steady solver";
  }
  else
  {
    text << ", w = " << parameters.Relaxation << breakBefore << parameters.Iterations << " iterations";
  }
  return text.str();
}
} // namespace vr
