// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// glibc's allocator under a count: each replacement calls glibc's own entry point (__libc_malloc and its relatives,
// which glibc exports for this) and adds or takes away the block's malloc_usable_size. Linux with glibc only.
#include "vrAllocationCounter.h"

#include <atomic>
#include <cerrno>
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

void *
Counted(void * block)
{
  if (block)
  {
    const auto      bytes = static_cast<long long>(malloc_usable_size(block));
    const long long live = Live.fetch_add(bytes, std::memory_order_relaxed) + bytes;
    long long       peak = Peak.load(std::memory_order_relaxed);
    while (live > peak && !Peak.compare_exchange_weak(peak, live, std::memory_order_relaxed))
    {
    }
  }
  return block;
}

void
Uncounted(void * block)
{
  if (block)
  {
    Live.fetch_sub(static_cast<long long>(malloc_usable_size(block)), std::memory_order_relaxed);
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
    const long long before = block ? static_cast<long long>(malloc_usable_size(block)) : 0;
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
    return Counted(__libc_memalign(alignment, size));
  }

  void *
  aligned_alloc(std::size_t alignment, std::size_t size)
  {
    return Counted(__libc_memalign(alignment, size));
  }

  int
  posix_memalign(void ** result, std::size_t alignment, std::size_t size)
  {
    void * block = __libc_memalign(alignment, size);
    if (!block)
    {
      return ENOMEM;
    }
    *result = Counted(block);
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
} // namespace vr::test
