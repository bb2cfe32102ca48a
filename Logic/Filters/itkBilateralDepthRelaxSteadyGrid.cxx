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

void
Lender::Clear()
{
  // Lendings numbered across all lenders: an array's span is valid for its own lending only.
  static std::atomic<std::uint64_t> lendings{ 0 };
  m_Lending = ++lendings;
  m_Count = 0;
}

void
Lender::Add(void * begin, std::size_t bytes)
{
  if (m_Count < MaximumSpans && begin && bytes > 0)
  {
    m_Spans[m_Count++] = { static_cast<char *>(begin), bytes, 0, 0 };
  }
}

void *
Lender::Take(std::size_t bytes)
{
  constexpr std::size_t Alignment = 64;
  for (std::size_t s = 0; s < m_Count; ++s)
  {
    Span &            span = m_Spans[s];
    const std::size_t address = reinterpret_cast<std::uintptr_t>(span.Begin + span.Used);
    const std::size_t start = span.Used + (Alignment - address % Alignment) % Alignment;
    if (start <= span.Bytes && bytes <= span.Bytes - start)
    {
      span.Used = start + bytes;
      span.Taken = span.Used;
      std::memset(span.Begin + start, 0, bytes);
      return span.Begin + start;
    }
  }
  return nullptr;
}

void
Lender::ZeroTaken()
{
  for (std::size_t s = 0; s < m_Count; ++s)
  {
    std::memset(m_Spans[s].Begin, 0, m_Spans[s].Taken);
    m_Spans[s].Used = 0;
    m_Spans[s].Taken = 0;
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
