// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkBilateralDepthRelaxSteadyCorrection.h"

#include "itkBilateralDepthRelaxSteadyRows.h"

#include <algorithm>
#include <cmath>

namespace itk::detail::BilateralDepthRelaxSteady
{
bool
Correction::Solve(double target, bool newton)
{
  const float * opC = newton ? m_Field.HessianC : m_Field.Finest.C;
  const float * opE = newton ? m_Field.HessianE : m_Field.Finest.E;
  const float * opN = newton ? m_Field.HessianN : m_Field.Finest.N;
  m_NegativeCurvature = false;
  const Level &         l = m_Field.Finest;
  const long            s = m_Field.Stride;
  const long            width = m_Field.Width;
  const unsigned int    cyclesBefore = m_Cycles;
  std::vector<double> & maxima = m_Field.RowMaxima();
  double                rz = Precondition();
  m_Bands.ForRows(m_Field.Height,
                  true,
                  [&](long y0, long y1)
                  {
                    for (long y = y0; y < y1; ++y)
                    {
                      const long row = m_Field.At(0, y);
                      std::copy(m_Field.Z + row, m_Field.Z + row + width, m_Field.Direction + row);
                      std::fill(m_Field.Delta + row, m_Field.Delta + row + width, 0.0f);
                    }
                  });
  for (unsigned int iteration = 0; iteration < MaximumInnerIterations; ++iteration)
  {
    // A v row by row into Z, here for its dot product and again in the update below. Z holds nothing between the
    // direction update and the next V-cycle, which writes it from zero: A v there costs no array of its own, and
    // the update reads one row of it instead of v's three and the operator's (fewer bytes from memory where the
    // arrays exceed the cache).
    const double curvature = m_Bands.SumRows(
      [&](long y, float *)
      {
        const long row = m_Field.At(0, y);
        Rows().ApplyRow5(m_Field.Z + row,
                         m_Field.Direction + row,
                         m_Field.Direction + row + s,
                         m_Field.Direction + row - s,
                         opC + row,
                         opE + row,
                         opN + row,
                         opN + row - s,
                         width);
        return Rows().RowDot(m_Field.Direction + row, m_Field.Z + row, width);
      });
    m_NegativeCurvature = newton && !(curvature > 0.0) && rz > 0.0;
    if (m_NegativeCurvature)
    {
      return false;
    }
    if (!(curvature > 0.0) || !(rz > 0.0))
    {
      break;
    }
    const float alpha = static_cast<float>(rz / curvature);
    m_Bands.ForRows(
      m_Field.Height,
      true,
      [&](long y0, long y1)
      {
        for (long y = y0; y < y1; ++y)
        {
          const long row = m_Field.At(0, y);
          Rows().UpdateRow(
            m_Field.Delta + row, m_Field.Residual + row, m_Field.Direction + row, m_Field.Z + row, alpha, width);
          maxima[static_cast<std::size_t>(y)] = Rows().RowMaximumOverDiagonal(m_Field.Residual + row, l.C + row, width);
        }
      });
    if (*std::max_element(maxima.begin(), maxima.end()) <= target)
    {
      break;
    }
    const double rzNext = Precondition();
    const float  beta = static_cast<float>(rzNext / rz);
    rz = rzNext;
    m_Bands.ForRows(m_Field.Height,
                    true,
                    [&](long y0, long y1)
                    {
                      for (long y = y0; y < y1; ++y)
                      {
                        Rows().DirectionRow(
                          m_Field.Direction + m_Field.At(0, y), m_Field.Z + m_Field.At(0, y), beta, width);
                      }
                    });
  }
  m_LastCycles = m_Cycles - cyclesBefore;
  return true;
}

double
Correction::SearchNegativeCurvature(float & step)
{
  std::vector<double> & maxima = m_Field.RowMaxima();
  m_Bands.ForRows(m_Field.Height,
                  true,
                  [&](long y0, long y1)
                  {
                    for (long y = y0; y < y1; ++y)
                    {
                      const long row = m_Field.At(0, y);
                      std::copy(m_Field.Direction + row, m_Field.Direction + row + m_Field.Width, m_Field.Delta + row);
                      maxima[static_cast<std::size_t>(y)] =
                        Rows().RowMaximum(m_Field.Delta + row, m_Field.Active + row, m_Field.Width);
                    }
                  });
  step = 0.0f;
  const double largest = *std::max_element(maxima.begin(), maxima.end());
  if (!(largest > 0.0))
  {
    return 0.0;
  }
  const float  unit = static_cast<float>(1.0 / (32.0 * largest * std::sqrt(0.5 * m_Field.TwiceAnisotropy)));
  const double forward = m_Field.EnergyChange(unit);
  const double backward = m_Field.EnergyChange(-unit);
  double       change = std::min(forward, backward);
  if (!(change < 0.0))
  {
    return 0.0;
  }
  step = forward <= backward ? unit : -unit;
  while (std::abs(step) < 64.0f * unit)
  {
    const double further = m_Field.EnergyChange(2.0f * step);
    if (!(further < change))
    {
      break;
    }
    change = further;
    step *= 2.0f;
  }
  return change;
}

double
Correction::SearchLaggedStep(float & step)
{
  step = 1.0f;
  double change = m_Field.EnergyChange(step);
  while (step < MaximumStep)
  {
    const double further = m_Field.EnergyChange(2.0f * step);
    if (!(further < change))
    {
      break;
    }
    change = further;
    step *= 2.0f;
  }
  return change;
}

} // namespace itk::detail::BilateralDepthRelaxSteady
