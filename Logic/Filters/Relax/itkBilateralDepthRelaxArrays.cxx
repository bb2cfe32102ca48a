// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkBilateralDepthRelaxArrays.h"

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <new>

#if defined(__linux__)
#include <stdlib.h> // posix_memalign
#include <sys/mman.h>
#endif

namespace itk::detail
{
void *
AllocateLarge(std::size_t bytes)
{
#if defined(__linux__)
  // posix_memalign, not aligned operator new: that rounds the size up to a multiple of the alignment (2 MiB more for
  // an array of just over 2 MiB). Through the C allocator, so that whoever counts the program's allocations sees it.
  void * memory = nullptr;
  if (posix_memalign(&memory, LargeArrayBytes, bytes) != 0)
  {
    throw std::bad_alloc();
  }
#if defined(MADV_HUGEPAGE)
  const std::size_t whole = bytes / LargeArrayBytes * LargeArrayBytes;
  if (whole > 0)
  {
    // Advice only: a system without transparent huge pages refuses it, and the pages stay the usual ones. Memory the
    // allocator hands out again may already be backed by small pages, which the advice does not replace: dropped
    // (MADV_DONTNEED: they read as zero again, and the zero-filling that follows touches them afresh). The blocks lie
    // inside the allocation, clear of the allocator's own bookkeeping before it.
    if (madvise(memory, whole, MADV_HUGEPAGE) == 0)
    {
      static_cast<void>(madvise(memory, whole, MADV_DONTNEED));
    }
  }
#endif
  return memory;
#else
  // clang-format off (its alignment reaches across the #else)
  return ::operator new[](bytes, std::align_val_t{ LargeArrayBytes });
  // clang-format on
#endif
}

void
FreeLarge(void * memory) noexcept
{
#if defined(__linux__)
  std::free(memory);
#else
  // clang-format off (its alignment reaches across the #else)
  ::operator delete[](memory, std::align_val_t{ LargeArrayBytes });
  // clang-format on
#endif
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
} // namespace itk::detail
