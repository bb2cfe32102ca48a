// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkBilateralDepthRelaxSteadyField.h"

#include "itkBilateralDepthRelaxSteadyNested.h"
#include "itkBilateralDepthRelaxSteadyRows.h"

#include <algorithm>
#include <cmath>

namespace itk::detail::BilateralDepthRelaxSteady
{
Field::Field(FieldBuffers & buffers,
             Bands &        bands,
             Level &        finest,
             long           width,
             long           height,
             double         anisotropy,
             Lender *       lender)
  : Width(width)
  , Height(height)
  , Stride(PaddedStride(width))
  , Scale(static_cast<float>(anisotropy > 0.0 ? std::sqrt(anisotropy / std::log(2.0)) : 0.0))
  , Isotropic(anisotropy == 0.0)
  , TwiceAnisotropy(static_cast<float>(2.0 * anisotropy))
  , Finest(finest)
  , m_Buffers(buffers)
  , m_Bands(bands)
{
  const std::size_t size = PaddedSize(width, height);
  bool              fresh = false;
  Depth = buffers.Depth.Reserve(size, fresh, lender);
  WeightRight = buffers.WeightRight.Reserve(size, fresh, lender);
  WeightDown = buffers.WeightDown.Reserve(size, fresh, lender);
  Fixed = buffers.Fixed.Reserve(size, fresh, lender);
  Active = buffers.Active.Reserve(size, fresh, lender);
  Residual = buffers.Residual.Reserve(size, fresh, lender);
  Z = buffers.Z.Reserve(size, fresh, lender);
  Delta = buffers.Delta.Reserve(size, fresh, lender);
  Direction = buffers.Direction.Reserve(size, fresh, lender);
  HessianC = buffers.HessianC.Reserve(size, fresh, lender);
  HessianE = buffers.HessianE.Reserve(size, fresh, lender);
  HessianN = buffers.HessianN.Reserve(size, fresh, lender);
  Saved = buffers.Saved.Reserve(size, fresh, lender);
  const std::size_t rows = static_cast<std::size_t>(height);
  buffers.RowLowest.assign(rows, 0.0);
  buffers.RowHighest.assign(rows, 0.0);
  buffers.RowMaxima.assign(rows, 0.0);
  buffers.RowSignatures.assign(rows, 0);
  // The finest level's right-hand side and correction are the conjugate gradients' residual and preconditioned
  // residual.
  finest.B = Residual;
  finest.X = Z;
}

void
Field::LendScratchTo(Lender & lender)
{
  const std::size_t bytes = PaddedSize(Width, Height) * sizeof(float);
  for (float * array : { Residual, Z, Delta, Direction, HessianC, HessianE, HessianN, Saved })
  {
    lender.Add(array, bytes);
  }
}

std::size_t
Field::ClassifyRegions(bool & changed)
{
  const RegionGrid grid{ Width, Height, Stride, WeightRight, WeightDown, Fixed, Active, Depth };
  return ClassifyFloatingRegions(m_Buffers.Regions, m_Bands, grid, changed);
}

void
Field::Load(const float * depth, const unsigned char * fixed)
{
  // The input's range, per row in the same pass.
  std::vector<double> & lowest = m_Buffers.RowLowest;
  std::vector<double> & highest = m_Buffers.RowHighest;
  m_Bands.ForRows(Height,
                  true,
                  [&](long y0, long y1)
                  {
                    for (long y = y0; y < y1; ++y)
                    {
                      const float * in = depth + y * Width;
                      const long    row = At(0, y);
                      for (long x = 0; x < Width; ++x)
                      {
                        Depth[row + x] = in[x];
                        Fixed[row + x] = fixed && fixed[y * Width + x] ? 1.0f : 0.0f;
                      }
                      const auto range = std::minmax_element(in, in + Width);
                      lowest[static_cast<std::size_t>(y)] = *range.first;
                      highest[static_cast<std::size_t>(y)] = *range.second;
                    }
                  });
  Lowest = *std::min_element(lowest.begin(), lowest.end());
  Highest = *std::max_element(highest.begin(), highest.end());
}

void
Field::StartFrom(const float * coarse, long coarseWidth, long coarseHeight)
{
  ProlongStart(m_Bands, coarse, coarseWidth, coarseHeight, Scale, Active, Depth, Width, Height, Stride);
}

double
Field::Energy()
{
  // In double with expm1: 1 - R in float loses the small differences' share to cancellation.
  const double anisotropy = 0.5 * static_cast<double>(TwiceAnisotropy);
  auto         edge = [&](double difference)
  {
    return Isotropic ? 0.5 * difference * difference
                     : -std::expm1(-anisotropy * difference * difference) / (2.0 * anisotropy);
  };
  return m_Bands.SumRows(
    [&](long y, float *)
    {
      const double * d = Depth + At(0, y);
      const double * above = y + 1 < Height ? d + Stride : nullptr;
      double         sum = 0.0;
      for (long x = 0; x < Width; ++x)
      {
        sum += (x + 1 < Width ? edge(d[x + 1] - d[x]) : 0.0) + (above ? edge(above[x] - d[x]) : 0.0);
      }
      return sum;
    });
}

void
Field::Store(const float * depth, const unsigned char * fixed, float * relaxed) const
{
  m_Bands.ForRows(Height,
                  true,
                  [&](long y0, long y1)
                  {
                    for (long y = y0; y < y1; ++y)
                    {
                      const long row = At(0, y);
                      for (long x = 0; x < Width; ++x)
                      {
                        const long k = y * Width + x;
                        relaxed[k] = fixed && fixed[k] ? depth[k] : static_cast<float>(Depth[row + x]);
                      }
                    }
                  });
}

std::uint64_t
Field::WeightRowSignature(long y)
{
  const long row = At(0, y);
  return Rows().WeightRow(WeightRight + row,
                          WeightDown + row,
                          Depth + row,
                          y + 1 < Height ? Depth + row + Stride : nullptr,
                          Scale,
                          Isotropic,
                          Width);
}

void
Field::AssembleRow(long y, bool hessian)
{
  const long row = At(0, y);
  const long s = Stride;
  Level &    l = Finest;
  (hessian ? Rows().AssembleOperatorAndHessianRow : Rows().AssembleOperatorRow)(l.C + row,
                                                                                l.E + row,
                                                                                l.N + row,
                                                                                HessianC + row,
                                                                                HessianE + row,
                                                                                HessianN + row,
                                                                                Residual + row,
                                                                                Depth + row,
                                                                                Depth + row + s,
                                                                                Depth + row - s,
                                                                                Active + row,
                                                                                Active + row + s,
                                                                                WeightRight + row,
                                                                                WeightDown + row,
                                                                                WeightDown + row - s,
                                                                                TwiceAnisotropy,
                                                                                Width);
  m_Buffers.RowMaxima[static_cast<std::size_t>(y)] = Rows().RowMaximumOverDiagonal(Residual + row, l.C + row, Width);
}

std::uint64_t
Field::ComputeWeights()
{
  std::vector<std::uint64_t> & signatures = m_Buffers.RowSignatures;
  m_Bands.ForRows(Height,
                  true,
                  [&](long y0, long y1)
                  {
                    for (long y = y0; y < y1; ++y)
                    {
                      signatures[static_cast<std::size_t>(y)] = WeightRowSignature(y);
                    }
                  });
  std::uint64_t signature = 0;
  for (const std::uint64_t value : signatures)
  {
    signature = signature * 0x9E3779B97F4A7C15ull + value;
  }
  return signature;
}

double
Field::Assemble(bool hessian)
{
  m_Bands.ForRows(Height,
                  true,
                  [&](long y0, long y1)
                  {
                    for (long y = y0; y < y1; ++y)
                    {
                      AssembleRow(y, hessian);
                    }
                  });
  return *std::max_element(m_Buffers.RowMaxima.begin(), m_Buffers.RowMaxima.end());
}

bool
Field::ReassembleRows(long first, long last, bool hessian)
{
  bool samePattern = true;
  for (long y = std::max(first - 1, 0L); y <= std::min(last, Height - 1); ++y)
  {
    samePattern = WeightRowSignature(y) == m_Buffers.RowSignatures[static_cast<std::size_t>(y)] && samePattern;
  }
  for (long y = std::max(first - 1, 0L); y <= std::min(last + 1, Height - 1); ++y)
  {
    AssembleRow(y, hessian);
  }
  return samePattern;
}

double
Field::EnergyChange(float step)
{
  const float anisotropy = 0.5f * TwiceAnisotropy;
  return m_Bands.SumRows(
    [&](long y, float * scratch)
    {
      const long row = At(0, y);
      const bool last = y + 1 == Height;
      return Rows().EnergyChangeRow(Depth + row,
                                    last ? nullptr : Depth + row + Stride,
                                    WeightRight + row,
                                    WeightDown + row,
                                    Delta + row,
                                    Delta + row + Stride,
                                    step,
                                    anisotropy,
                                    Scale,
                                    scratch,
                                    Width);
    });
}

void
Field::CopyRows(const float * from, float * to)
{
  m_Bands.ForRows(
    Height, true, [&](long y0, long y1) { std::copy(from + At(0, y0), from + At(0, y1), to + At(0, y0)); });
}

void
Field::ApplyCorrection(float step)
{
  m_Bands.ForRows(Height,
                  true,
                  [&](long y0, long y1)
                  {
                    for (long y = y0; y < y1; ++y)
                    {
                      Rows().AddRow(Depth + At(0, y), Delta + At(0, y), step, Lowest, Highest, Width);
                    }
                  });
}

} // namespace itk::detail::BilateralDepthRelaxSteady
