// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkThreadTeamBarrier.h"

#include <stdexcept>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace itk::detail
{
namespace
{
/** About 20-50 microseconds of polling before sleeping: longer than the usual imbalance of one relax iteration,
 * far shorter than a scheduler time slice. */
constexpr unsigned int SpinsBeforeSleeping = 2000;

inline void
PauseCPU()
{
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#endif
}
} // namespace

ThreadTeamBarrier::ThreadTeamBarrier(unsigned int parties)
  : m_Parties(parties)
{
  if (parties == 0)
  {
    throw std::invalid_argument("ThreadTeamBarrier: a team needs at least one thread");
  }
}

void
ThreadTeamBarrier::Wait()
{
  const unsigned int generation = m_Generation.load(std::memory_order_acquire);
  if (m_Arrived.fetch_add(1, std::memory_order_acq_rel) + 1 == m_Parties)
  {
    // Last to arrive: reset the count for the next round before releasing anyone into it.
    m_Arrived.store(0, std::memory_order_relaxed);
    {
      const std::lock_guard<std::mutex> lock(m_Mutex);
      m_Generation.store(generation + 1, std::memory_order_release);
    }
    m_Condition.notify_all();
    return;
  }
  for (unsigned int spin = 0; spin < SpinsBeforeSleeping; ++spin)
  {
    if (m_Generation.load(std::memory_order_acquire) != generation)
    {
      return;
    }
    PauseCPU();
  }
  std::unique_lock<std::mutex> lock(m_Mutex);
  m_Condition.wait(lock, [&] { return m_Generation.load(std::memory_order_acquire) != generation; });
}

} // namespace itk::detail
