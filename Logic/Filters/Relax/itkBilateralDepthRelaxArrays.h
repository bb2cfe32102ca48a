// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The memory both relax kernels keep from one call to the next: ReusableArray, the one kind of array their
// workspaces hold (the Jacobi kernel's depth pairs, self weights and row buffers; the steady solver's grids), and
// Lender, through which the steady solver's finer grid lends its scratch arrays to a coarser grid's solve. Internal
// (namespace itk::detail), not installed.
#ifndef itkBilateralDepthRelaxArrays_h
#define itkBilateralDepthRelaxArrays_h

#include <cstddef>
#include <cstdint>
#include <algorithm>
#include <memory>
#include <new>

namespace itk::detail
{
/** Memory that a finer grid lends a coarser grid's solve of the nested iteration: the finer grid's scratch arrays,
 * whose values it does not need while the coarser grid is solved (it computes them again afterwards). Spans are
 * handed out first fit, 64-byte aligned, zero-filled; ZeroTaken() zeroes what was handed out again, so that the
 * lender's arrays are as freshly sized ones (ghost cells zero) when it takes them back. Holds no allocation. */
class Lender
{
public:
  /** Spans at most: a finer grid lends its eight scratch arrays and its first coarse level's sixteen. */
  static constexpr std::size_t MaximumSpans = 32;

  /** Forgets the spans (a new lending: arrays given spans of an earlier one take new ones). */
  void
  Clear();

  /** Lends \a bytes at \a begin (ignored when MaximumSpans are lent). */
  void
  Add(void * begin, std::size_t bytes);

  /** \a bytes zero-filled from the first span with room, or null when none has. */
  void *
  Take(std::size_t bytes);

  /** Zeroes every byte handed out since Clear() or the last call, and takes it back. */
  void
  ZeroTaken();

  /** Which lending the spans belong to. */
  std::uint64_t
  GetLending() const
  {
    return m_Lending;
  }

private:
  struct Span
  {
    char *      Begin;
    std::size_t Bytes;
    std::size_t Used;
    std::size_t Taken;
  };
  Span          m_Spans[MaximumSpans]{};
  std::size_t   m_Count{ 0 };
  std::uint64_t m_Lending{ 0 };
};

/** Arrays of at least this many bytes start on a 2 MiB boundary, and their whole 2 MiB blocks are offered to the
 * system as transparent huge pages (AllocateLarge). The steady solver's conjugate-gradient iterations
 * stream a dozen arrays of a few MiB at once; with 4 KiB pages their address translations no longer fit the
 * processor's TLB (measured in docs/steady-solver.md, "Cost and memory"). */
constexpr std::size_t LargeArrayBytes = std::size_t{ 2 } << 20;

/** \a bytes (at least LargeArrayBytes), 2 MiB aligned, from the C allocator; on Linux its whole 2 MiB blocks are
 * advised MADV_HUGEPAGE (transparent huge pages are often left to the program's choice, "madvise" mode) and dropped, so
 * that the next touch backs them afresh, by huge pages where the system has them (memory the allocator hands out again
 * may already be backed by small pages, which the advice alone would leave). The contents are undefined until
 * written. Throws std::bad_alloc when there is no memory to give. */
void *
AllocateLarge(std::size_t bytes);

/** Gives back what AllocateLarge returned. */
void
FreeLarge(void * memory) noexcept;

/** Values kept from one call to the next, 64-byte aligned (a cache line, a whole AVX-512 vector; from LargeArrayBytes
 * on, 2 MiB aligned and offered huge pages, see AllocateLarge), with room for a multiple of 16 values. Zero-filled
 * whenever reserved with another count than the last time (ghost cells start at zero); with the same count, the last
 * call's values stay. The memory only grows, so a workspace used at several sizes (a preview, then the full view)
 * allocates once. With a Lender, a span of its memory instead (zero-filled when taken; the same span for the rest of
 * that lending), and the array's own memory is freed; without one, or when the lender has no room, its own. */
template<typename T>
class ReusableArray
{
public:
  /** Values are allocated in multiples of this many. */
  static constexpr std::size_t Granule = 16;

  /** \a count values; \a fresh is set when they were zero-filled. */
  T *
  Reserve(std::size_t count, bool & fresh, Lender * lender = nullptr)
  {
    if (lender)
    {
      if (m_Lent && m_Lending == lender->GetLending() && m_Count == count)
      {
        return m_Lent;
      }
      if (void * lent = lender->Take(count * sizeof(T)))
      {
        m_Own.reset();
        m_Capacity = 0;
        m_Lent = static_cast<T *>(lent);
        m_Count = count;
        m_Lending = lender->GetLending();
        fresh = true;
        return m_Lent;
      }
    }
    if (m_Lent || !m_Own || count != m_Count)
    {
      m_Lent = nullptr;
      if (count > m_Capacity || !m_Own)
      {
        m_Own.reset(); // the old memory goes before the new is taken
        m_Capacity = RoundedUp(count);
        m_Own = Owned(Allocate(m_Capacity), Deleter{ IsLarge(m_Capacity) });
      }
      std::fill_n(m_Own.get(), m_Capacity, T{});
      m_Count = count;
      fresh = true;
    }
    return m_Own.get();
  }

  /** The same, for a caller that needs no word on whether the values were zero-filled. */
  T *
  Reserve(std::size_t count)
  {
    bool fresh = false;
    return Reserve(count, fresh);
  }

  /** Bytes allocated for \a count values (Reserve's own memory). */
  static constexpr std::size_t
  BytesFor(std::size_t count)
  {
    return RoundedUp(count) * sizeof(T);
  }

private:
  static constexpr std::align_val_t Alignment{ 64 };

  static constexpr std::size_t
  RoundedUp(std::size_t count)
  {
    return (count + Granule - 1) / Granule * Granule;
  }
  static T *
  Allocate(std::size_t count)
  {
    if (count > static_cast<std::size_t>(-1) / sizeof(T))
    {
      throw std::bad_alloc();
    }
    const std::size_t bytes = count * sizeof(T);
    return static_cast<T *>(IsLarge(count) ? AllocateLarge(bytes) : ::operator new[](bytes, Alignment));
  }
  static constexpr bool
  IsLarge(std::size_t count)
  {
    return count * sizeof(T) >= LargeArrayBytes;
  }
  struct Deleter
  {
    bool Large{ false };
    void
    operator()(T * data) const
    {
      if (Large)
      {
        FreeLarge(data);
      }
      else
      {
        ::operator delete[](data, Alignment);
      }
    }
  };
  using Owned = std::unique_ptr<T[], Deleter>;

  Owned         m_Own;
  std::size_t   m_Capacity{ 0 };
  std::size_t   m_Count{ 0 };
  T *           m_Lent{ nullptr };
  std::uint64_t m_Lending{ 0 };
};
} // namespace itk::detail

#endif
