// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrPreviewPolicy.h"

#include <algorithm>

namespace vr
{
namespace
{
/** The median of \a values; -1 (not measured) when there are none. */
double
Median(std::vector<double> values)
{
  if (values.empty())
  {
    return -1.0;
  }
  std::sort(values.begin(), values.end());
  const std::size_t middle = values.size() / 2;
  return values.size() % 2 == 1 ? values[middle] : 0.5 * (values[middle - 1] + values[middle]);
}

/** The index of \a factor in PreviewFactors; 0 (no preview) for a factor not there. */
std::size_t
FactorIndex(unsigned int factor)
{
  const auto found = std::find(PreviewFactors.begin(), PreviewFactors.end(), factor);
  return found == PreviewFactors.end() ? 0 : static_cast<std::size_t>(found - PreviewFactors.begin());
}

/** Whether \a a and \a b ask for the same view up to the angle (then they resolve to the same centre, size and
 * spacing on the same inputs). */
bool
SameViewUpToAngle(const ReformationParameters & a, const ReformationParameters & b)
{
  itk::CPRViewSpecification first = a.ToViewSpecification();
  first.AngleInDegrees = b.AngleInDegrees;
  return first == b.ToViewSpecification();
}
} // namespace

void
PreviewPolicy::SetForcedFactor(unsigned int factor)
{
  m_ForcedFactor = factor == 0 ? 0 : PreviewFactors[FactorIndex(factor)];
}

void
PreviewPolicy::SetFrameBudget(double seconds)
{
  m_FrameBudget = std::max(0.0, seconds);
}

unsigned int
PreviewPolicy::ChooseFactor() const
{
  if (m_ForcedFactor != 0)
  {
    return m_ForcedFactor;
  }
  std::array<double, PreviewFactors.size()> seconds{};
  for (std::size_t index = 0; index < seconds.size(); ++index)
  {
    seconds[index] = Median(m_Times[index]);
  }
  return ChoosePreviewFactor(seconds, m_FrameBudget);
}

void
PreviewPolicy::RecordTime(unsigned int factor, double seconds)
{
  auto & times = m_Times[FactorIndex(factor)];
  times.push_back(seconds);
  if (times.size() > RecentTimes)
  {
    times.erase(times.begin());
  }
}

void
PreviewPolicy::RememberFullView(const ReformationParameters & parameters, const itk::CPRViewGeometry & view)
{
  m_FullView = view;
  m_FullViewParameters = parameters;
}

void
PreviewPolicy::Forget()
{
  m_FullView.reset();
  for (auto & times : m_Times)
  {
    times.clear();
  }
}

PreviewPolicy::Step
PreviewPolicy::PlanStep(const ReformationParameters & parameters) const
{
  const unsigned int factor = ChooseFactor();
  if (factor > 1 && m_FullView && SameViewUpToAngle(parameters, m_FullViewParameters))
  {
    return { PreviewParameters(parameters, *m_FullView, factor), factor };
  }
  return { parameters, 1 };
}

itk::CPRViewGeometry
PreviewPolicy::FullViewOf(const itk::CPRViewGeometry & previewView) const
{
  const itk::CPRViewGeometry & full = *m_FullView;
  return itk::CPRViewGeometry(
    full.GetUp(), previewView.GetAngleInDegrees(), full.GetCenter(), full.GetSize(), full.GetSpacing());
}
} // namespace vr
