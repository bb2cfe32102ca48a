// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The steady solver's outer loop: lagged-weights (reweighting) steps while they halve the residual, then Newton steps
// on the energy's own curvature while they lower the energy, with line searches where they do not. Internal
// (namespace itk::detail), not installed; see itkBilateralDepthRelaxSteadySolver.h for the method.
#ifndef itkBilateralDepthRelaxSteadyOuterLoop_h
#define itkBilateralDepthRelaxSteadyOuterLoop_h

#include "itkBilateralDepthRelaxSteadyCorrection.h"
#include "itkBilateralDepthRelaxSteadyStragglers.h"

#include <cstddef>
#include <cstdint>
#include <functional>

namespace itk::detail::BilateralDepthRelaxSteady
{
/** Outer iterations on a loaded Field until its residual falls below a tolerance. */
class OuterLoop
{
public:
  /** What the iterations did (BilateralDepthRelaxSteadySolver::Report's fields). */
  struct Report
  {
    unsigned int OuterIterations{ 0 };
    unsigned int Cycles{ 0 };
    unsigned int HierarchyBuilds{ 0 };
    std::size_t  FloatingPixels{ 0 };
    double       Residual{ 0.0 };
    bool         Converged{ true };
    /** Stopped where lagged weights slowed down (see Run's stopWhenSlowed). */
    bool Slowed{ false };
  };

  /** A coarser grid's solution to start from (see Field::StartFrom); none when Values is null. When it lies in
   * memory the field lent (Lent), that is zeroed (given back) once the start is read, before any outer iteration. */
  struct Start
  {
    const float * Values{ nullptr };
    long          Width{ 0 };
    long          Height{ 0 };
    Lender *      Lent{ nullptr };
  };
  using ProgressCallback = std::function<void(double fraction)>;

  /** Each outer iteration's conjugate gradients stop once the residual has fallen this much. */
  static constexpr double InnerReduction = 0.1;

  /** More than this many V-cycles in one outer iteration rebuild the hierarchy from the current weights before the
   * next. */
  static constexpr unsigned int RebuildAfterCycles = 4;

  /** Outer iterations take Newton steps from the first one whose residual has not fallen below this fraction of the
   * previous one. */
  static constexpr double NewtonAfterReduction = 0.5;

  /** With stopWhenSlowed, Run stops where lagged weights slow down only while the residual is still above this
   * fraction of the first: lagged weights that slow down near the end (after a tenfold reduction) leave little for
   * the Newton steps, which then cost less than a restart from the coarser grid (the run-off phantom at 200 x 400:
   * 9 V-cycles, against 101 from the coarser grid; docs/steady-solver.md). */
  static constexpr double NestedBeforeReduction = 0.1;

  /** A Newton step that raises the energy is tried at this fraction of its length before the search (SearchStep). */
  static constexpr float NewtonBacktrack = 0.5f;

  OuterLoop(Field & field, Multigrid & multigrid, Correction & correction, StragglerBuffers & stragglers)
    : m_Field(field)
    , m_Multigrid(multigrid)
    , m_Correction(correction)
    , m_Stragglers(stragglers)
  {
  }

  /** Iterates from \a start (when given; else from the loaded depths) until the residual is at most \a tolerance;
   * calls \a progress (when set) after each outer iteration. Stops after \a maximumOuterIterations with Converged
   * false, the depths those iterations reached left in the field; with \a stopWhenSlowed, also (Slowed) at the first
   * outer iteration that would turn to Newton steps, if lagged weights have not yet brought the residual below
   * NestedBeforeReduction times the first. */
  Report
  Run(double                   tolerance,
      const ProgressCallback & progress,
      unsigned int             maximumOuterIterations,
      const Start &            start,
      bool                     stopWhenSlowed);

private:
  /** The weights at the current depths and, where the pattern of vanishing ones changed, the regions again; sets
   * m_Rebuild when the activity changed. */
  void
  UpdateWeightsAndRegions();

  /** The fraction of the way done, from the logarithm of the residual, never going back. */
  double
  Progress(double residual, double tolerance);

  /** One outer iteration's step towards \a target (max |r| / C): a lagged-weights step, or a Newton step when
   * m_Newton says so and it lowers the energy (else half of it, when that does), else a line search. Updates
   * m_Newton. */
  void
  Step(double target);

  /** The better of a step along the direction of negative curvature the last Newton solve met and a stretched
   * lagged-weights step (the Newton step was not taken). */
  void
  SearchStep(double target);

  Field &            m_Field;
  Multigrid &        m_Multigrid;
  Correction &       m_Correction;
  StragglerBuffers & m_Stragglers;
  Report             m_Report;
  std::uint64_t      m_Signature{ 0 };
  bool               m_Rebuild{ true };
  bool               m_Newton{ false };
  double             m_First{ 0.0 };
  double             m_Done{ 0.0 };
};
} // namespace itk::detail::BilateralDepthRelaxSteady

#endif
