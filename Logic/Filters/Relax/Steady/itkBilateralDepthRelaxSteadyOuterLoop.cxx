// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkBilateralDepthRelaxSteadyOuterLoop.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace itk::detail::BilateralDepthRelaxSteady
{
OuterLoop::Report
OuterLoop::Run(double                   tolerance,
               const ProgressCallback & progress,
               unsigned int             maximumOuterIterations,
               const Start &            start,
               bool                     stopWhenSlowed)
{
  m_Report = Report();
  m_Signature = m_Field.ComputeWeights();
  bool changed = false;
  m_Report.FloatingPixels = m_Field.ClassifyRegions(changed);
  if (m_Report.FloatingPixels > 0)
  {
    m_Signature = m_Field.ComputeWeights();
  }
  if (start.Values)
  {
    // Floating regions took their mean input depth above; the active pixels start from the coarser solution, whose
    // weights may join or split regions again.
    m_Field.StartFrom(start.Values, start.Width, start.Height);
    if (start.Lent)
    {
      start.Lent->ZeroTaken();
    }
    m_Signature = m_Field.ComputeWeights();
    m_Report.FloatingPixels = m_Field.ClassifyRegions(changed);
    if (changed)
    {
      m_Signature = m_Field.ComputeWeights();
    }
  }
  m_Rebuild = true;
  m_Newton = false;
  double previous = std::numeric_limits<double>::infinity();
  for (unsigned int outer = 0;; ++outer)
  {
    if (outer > 0)
    {
      UpdateWeightsAndRegions();
    }
    // The Hessian while Newton steps go on; an outer iteration that turns to them below assembles it then. Where only
    // a few pixels are left above the tolerance, they are settled on their own, not in another outer iteration.
    const double residual = SettleStragglers(m_Field, m_Stragglers, m_Field.Assemble(m_Newton), tolerance, m_Newton);
    m_Report.Residual = residual;
    m_Report.OuterIterations = outer;
    if (outer == 0)
    {
      m_First = residual;
      m_Done = 0.0;
    }
    if (progress)
    {
      progress(Progress(residual, tolerance));
    }
    if (residual <= tolerance)
    {
      break;
    }
    if (outer >= maximumOuterIterations)
    {
      m_Report.Converged = false;
      break;
    }
    if (m_Rebuild)
    {
      m_Multigrid.Build();
      ++m_Report.HierarchyBuilds;
      m_Rebuild = false;
    }
    // Newton steps once lagged weights have slowed down, for as long as they are taken.
    const bool hessianAssembled = m_Newton;
    const bool wasNewton = m_Newton;
    m_Newton = !m_Field.Isotropic && (m_Newton || residual > NewtonAfterReduction * previous);
    previous = residual;
    if (stopWhenSlowed && m_Newton && !wasNewton && residual > NestedBeforeReduction * m_First)
    {
      m_Report.Slowed = true;
      m_Report.Converged = false;
      break;
    }
    if (m_Newton && !hessianAssembled)
    {
      m_Field.Assemble(true);
    }
    Step(std::max(InnerReduction * residual, 0.5 * tolerance));

    m_Rebuild = m_Correction.GetLastCycles() > RebuildAfterCycles;
  }
  m_Report.Cycles = m_Correction.GetCycles();
  return m_Report;
}

void
OuterLoop::UpdateWeightsAndRegions()
{
  const std::uint64_t next = m_Field.ComputeWeights();
  if (next == m_Signature)
  {
    return;
  }
  m_Signature = next;
  bool changed = false;
  m_Report.FloatingPixels = m_Field.ClassifyRegions(changed);
  if (changed)
  {
    // Floating regions took their mean, or former ones joined anchored regions: new weights, new hierarchy.
    m_Signature = m_Field.ComputeWeights();
    m_Rebuild = true;
  }
}

double
OuterLoop::Progress(double residual, double tolerance)
{
  // The residual need not fall at every outer iteration; the progress never goes back.
  const double fraction =
    residual <= tolerance ? 1.0 : std::clamp(std::log(m_First / residual) / std::log(m_First / tolerance), 0.0, 1.0);
  m_Done = std::max(m_Done, fraction);
  return m_Done;
}

void
OuterLoop::Step(double target)
{
  if (!m_Newton)
  {
    m_Correction.Solve(target, false);
    m_Field.ApplyCorrection(1.0f);
    return;
  }
  if (m_Correction.Solve(target, true))
  {
    if (m_Field.EnergyChange(1.0f) <= 0.0)
    {
      m_Field.ApplyCorrection(1.0f);
      return;
    }
    // The whole Newton step overshoots. The conjugate gradients met only positive curvature, so it points downhill:
    // a shorter step along it costs one energy evaluation, where the search below costs a lagged-weights solve and
    // several.
    if (m_Field.EnergyChange(NewtonBacktrack) < 0.0)
    {
      m_Field.ApplyCorrection(NewtonBacktrack);
      return;
    }
  }
  m_Newton = false;
  SearchStep(target);
}

void
OuterLoop::SearchStep(double target)
{
  float        curvatureStep = 0.0f;
  const double curvatureChange =
    m_Correction.MetNegativeCurvature() ? m_Correction.SearchNegativeCurvature(curvatureStep) : 0.0;
  if (curvatureStep != 0.0f)
  {
    m_Field.CopyRows(m_Field.Delta, m_Field.Saved);
  }
  m_Field.Assemble(false);
  m_Correction.Solve(target, false);
  float        laggedStep = 1.0f;
  const double laggedChange = m_Correction.SearchLaggedStep(laggedStep);
  if (curvatureStep != 0.0f && curvatureChange < laggedChange)
  {
    m_Field.CopyRows(m_Field.Saved, m_Field.Delta);
    m_Field.ApplyCorrection(curvatureStep);
  }
  else
  {
    m_Field.ApplyCorrection(laggedStep);
  }
}
} // namespace itk::detail::BilateralDepthRelaxSteady
