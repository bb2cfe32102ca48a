// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkBilateralDepthRelaxArrays.h"

#include <atomic>
#include <cstring>

namespace itk::detail
{
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
} // namespace itk::detail
