// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// glibc's allocator under a count: each replacement calls glibc's own entry point (__libc_malloc and its relatives,
// which glibc exports for this) and adds or takes away the block's malloc_usable_size (for a block aligned to a page
// or more, the pages asked for: see AlignedBlock). Linux with glibc only.
#include "vrAllocationCounter.h"

#include <atomic>
#include <cerrno>
#include <cstdint>
#include <malloc.h>
#include <unistd.h>

extern "C"
{
  void *
  __libc_malloc(std::size_t size);
  void
  __libc_free(void * pointer);
  void *
  __libc_calloc(std::size_t count, std::size_t size);
  void *
  __libc_realloc(void * pointer, std::size_t size);
  void *
  __libc_memalign(std::size_t alignment, std::size_t size);
}

namespace
{
std::atomic<long long> Live{ 0 };
std::atomic<long long> Peak{ 0 };
// The blocks of at least LargeThreshold bytes (0: not counted) allocated since the threshold was set.
std::atomic<long long> LargeThreshold{ 0 };
std::atomic<long long> LargeCount{ 0 };
std::atomic<long long> LargeBytes{ 0 };

/** Blocks aligned to a page or more whose usable size exceeds the pages asked for by more than a page: glibc maps an
 * aligned block of that size with room to align it, and leaves the room after the block as part of it, mapped but
 * never touched (the 2 MiB-aligned arrays of itkBilateralDepthRelaxArrays.h). They count as the pages asked for; the
 * table remembers what each counted until it is freed. */
struct AlignedBlock
{
  void *    Block{ nullptr };
  long long Bytes{ 0 };
};
constexpr std::size_t    MaximumAlignedBlocks = 4096;
AlignedBlock             AlignedBlocks[MaximumAlignedBlocks];
std::atomic<std::size_t> AlignedBlockCount{ 0 };
std::atomic_flag         AlignedBlocksLock = ATOMIC_FLAG_INIT;

struct AlignedBlocksGuard
{
  AlignedBlocksGuard()
  {
    while (AlignedBlocksLock.test_and_set(std::memory_order_acquire))
    {
    }
  }
  ~AlignedBlocksGuard() { AlignedBlocksLock.clear(std::memory_order_release); }
};

std::size_t
PageSize()
{
  static const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  return page;
}

void
Add(long long bytes)
{
  const long long threshold = LargeThreshold.load(std::memory_order_relaxed);
  if (threshold > 0 && bytes >= threshold)
  {
    LargeCount.fetch_add(1, std::memory_order_relaxed);
    LargeBytes.fetch_add(bytes, std::memory_order_relaxed);
  }
  const long long live = Live.fetch_add(bytes, std::memory_order_relaxed) + bytes;
  long long       peak = Peak.load(std::memory_order_relaxed);
  while (live > peak && !Peak.compare_exchange_weak(peak, live, std::memory_order_relaxed))
  {
  }
}

/** The bytes a block counts, for a block just allocated with \a alignment and \a size. */
void *
CountedAligned(void * block, std::size_t alignment, std::size_t size)
{
  if (!block)
  {
    return block;
  }
  const std::size_t page = PageSize();
  const std::size_t asked = (size + page - 1) / page * page;
  const std::size_t usable = malloc_usable_size(block);
  if (alignment < page || usable <= asked + page)
  {
    Add(static_cast<long long>(usable));
    return block;
  }
  {
    const AlignedBlocksGuard guard;
    const std::size_t        count = AlignedBlockCount.load(std::memory_order_relaxed);
    if (count == MaximumAlignedBlocks)
    {
      // Never expected: counted as usable, as any other block.
      Add(static_cast<long long>(usable));
      return block;
    }
    AlignedBlocks[count] = { block, static_cast<long long>(asked) };
    AlignedBlockCount.store(count + 1, std::memory_order_relaxed);
  }
  Add(static_cast<long long>(asked));
  return block;
}

/** The bytes \a block counted (its usable size, unless the table has it), forgotten by the table. */
long long
CountedBytes(void * block)
{
  if (AlignedBlockCount.load(std::memory_order_relaxed) > 0 &&
      reinterpret_cast<std::uintptr_t>(block) % PageSize() == 0)
  {
    const AlignedBlocksGuard guard;
    const std::size_t        count = AlignedBlockCount.load(std::memory_order_relaxed);
    for (std::size_t i = 0; i < count; ++i)
    {
      if (AlignedBlocks[i].Block == block)
      {
        const long long bytes = AlignedBlocks[i].Bytes;
        AlignedBlocks[i] = AlignedBlocks[count - 1];
        AlignedBlockCount.store(count - 1, std::memory_order_relaxed);
        return bytes;
      }
    }
  }
  return static_cast<long long>(malloc_usable_size(block));
}

void *
Counted(void * block)
{
  if (block)
  {
    Add(static_cast<long long>(malloc_usable_size(block)));
  }
  return block;
}

void
Uncounted(void * block)
{
  if (block)
  {
    Live.fetch_sub(CountedBytes(block), std::memory_order_relaxed);
  }
}
} // namespace

extern "C"
{
  void *
  malloc(std::size_t size)
  {
    return Counted(__libc_malloc(size));
  }

  void
  free(void * block)
  {
    Uncounted(block);
    __libc_free(block);
  }

  void *
  calloc(std::size_t count, std::size_t size)
  {
    return Counted(__libc_calloc(count, size));
  }

  void *
  realloc(void * block, std::size_t size)
  {
    const long long before = block ? CountedBytes(block) : 0;
    void *          moved = __libc_realloc(block, size);
    if (moved || size == 0) // else it failed and the block stays as it was
    {
      Live.fetch_sub(before, std::memory_order_relaxed);
      Counted(moved);
    }
    return moved;
  }

  void *
  memalign(std::size_t alignment, std::size_t size)
  {
    return CountedAligned(__libc_memalign(alignment, size), alignment, size);
  }

  void *
  aligned_alloc(std::size_t alignment, std::size_t size)
  {
    return CountedAligned(__libc_memalign(alignment, size), alignment, size);
  }

  int
  posix_memalign(void ** result, std::size_t alignment, std::size_t size)
  {
    void * block = __libc_memalign(alignment, size);
    if (!block)
    {
      return ENOMEM;
    }
    *result = CountedAligned(block, alignment, size);
    return 0;
  }

  void *
  valloc(std::size_t size)
  {
    return Counted(__libc_memalign(static_cast<std::size_t>(sysconf(_SC_PAGESIZE)), size));
  }

  void *
  pvalloc(std::size_t size)
  {
    const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
    return Counted(__libc_memalign(page, (size + page - 1) / page * page));
  }
}

namespace vr::test
{
long long
AllocatedBytes()
{
  return Live.load();
}

long long
AllocationPeak()
{
  return Peak.load();
}

void
ResetAllocationPeak()
{
  Peak.store(Live.load());
}

void
CountAllocationsOfAtLeast(long long bytes)
{
  LargeCount.store(0);
  LargeBytes.store(0);
  LargeThreshold.store(bytes);
}

long long
LargeAllocations()
{
  return LargeCount.load();
}

long long
LargeAllocationBytes()
{
  return LargeBytes.load();
}
} // namespace vr::test
