// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrPreviewPolicy_h
#define vrPreviewPolicy_h

#include "itkCPRViewGeometry.h"
#include "vrProgressiveRefinement.h"
#include "vrReformationParameters.h"

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

namespace vr
{
/** \class PreviewPolicy
 * \brief What a host decides while the user moves the view (docs/progressive-refinement.md): the preview factor k of
 * the next step of an interaction, forced or chosen from the measured times of recent updates and a frame budget
 * (vr::ChoosePreviewFactor), and that step's parameters, a preview of the latest full-resolution view of the same
 * view up to the angle (vr::PreviewParameters).
 *
 * It holds no thread and no lock: its owner (the viewer's reformation controller) serialises the calls.
 * \ingroup VesselReformation
 */
class PreviewPolicy
{
public:
  /** How many recent update times per factor the choice looks at (their median). */
  static constexpr std::size_t RecentTimes = 5;

  /** \a factor 0 (the default) chooses k from the measured times and the frame budget; 1 turns previews off (every
   * step at full resolution); 2 or 4 preview every step at that factor; another value is taken as 1. */
  void
  SetForcedFactor(unsigned int factor);
  /** The time a step's update should take, in seconds (default 0.05: 20 images a second); negative counts as 0. */
  void
  SetFrameBudget(double seconds);
  /** \return the factor the next step of an interaction would be computed at. */
  unsigned int
  ChooseFactor() const;
  /** Keeps the time, in seconds, of an update at \a factor whose view changed (the newest RecentTimes per factor). */
  void
  RecordTime(unsigned int factor, double seconds);
  /** Keeps the full-resolution view \a view resolved from \a parameters: a later preview of the same view (up to the
   * angle) keeps its centre, size and spacing. */
  void
  RememberFullView(const ReformationParameters & parameters, const itk::CPRViewGeometry & view);
  /** New data: its views and update times are still to be measured. */
  void
  Forget();

  /** One step of an interaction as it is to be computed. */
  struct Step
  {
    ReformationParameters Parameters;
    /** 1 for full resolution, else the preview factor. */
    unsigned int Factor{ 1 };
  };
  /** The step \a parameters at ChooseFactor() when that is above 1 and the full view of the same view up to the angle
   * is known; else \a parameters at full resolution. */
  Step
  PlanStep(const ReformationParameters & parameters) const;
  /** The full-resolution view a preview computed as \a previewView stands for: the remembered full view turned to the
   * preview's angle. Requires a remembered full view. */
  itk::CPRViewGeometry
  FullViewOf(const itk::CPRViewGeometry & previewView) const;

private:
  unsigned int                                           m_ForcedFactor{ 0 };
  double                                                 m_FrameBudget{ 0.05 };
  std::array<std::vector<double>, PreviewFactors.size()> m_Times;
  std::optional<itk::CPRViewGeometry>                    m_FullView;
  ReformationParameters                                  m_FullViewParameters;
};
} // namespace vr

#endif
