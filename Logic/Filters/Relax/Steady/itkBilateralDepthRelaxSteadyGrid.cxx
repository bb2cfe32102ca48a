// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkBilateralDepthRelaxSteadyGrid.h"

#include <algorithm>
#include <atomic>
#include <cstring>

namespace itk::detail::BilateralDepthRelaxSteady
{
void
Level::Allocate(long width, long height, bool coarse, Lender * lender)
{
  Width = width;
  Height = height;
  Stride = PaddedStride(width);
  NinePoint = coarse;
  Storage.resize(CoarseArrays);
  std::size_t next = 0;
  bool        fresh = false;
  auto        take = [&]() { return Storage[next++].Reserve(Size(), fresh, lender); };
  C = take();
  E = take();
  N = take();
  if (coarse)
  {
    NE = take();
    NW = take();
    X = take();
    B = take();
    XA = take();
    XB = take();
    YA = take();
    YB = take();
    Q0 = take();
    Q1 = take();
    Q2 = take();
    Q3 = take();
    Active = take();
  }
}

void
Level::LendTo(Lender & lender)
{
  for (float * array : { C, E, N, NE, NW, X, B, XA, XB, YA, YB, Q0, Q1, Q2, Q3, Active })
  {
    if (array && NinePoint)
    {
      lender.Add(array, Size() * sizeof(float));
    }
  }
}

unsigned int
Bands::TeamSize(unsigned int threads, long height)
{
  return std::max(1u, std::min<unsigned int>(threads, static_cast<unsigned int>(std::max(1L, height / 8))));
}

Bands::Bands(BandBuffers & buffers, unsigned int threads, long height, long stride)
  : m_Buffers(buffers)
  , m_Team(TeamSize(threads, height))
  , m_Height(height)
  , m_Stride(stride)
{
  buffers.RowSums.assign(static_cast<std::size_t>(height), 0.0);
  buffers.ScratchRows.assign(static_cast<std::size_t>(stride) * m_Team.GetSize(), 0.0f);
}
} // namespace itk::detail::BilateralDepthRelaxSteady
