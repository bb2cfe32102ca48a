// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkThreadTeamBarrier_h
#define itkThreadTeamBarrier_h

#include <atomic>
#include <condition_variable>
#include <mutex>

namespace itk::detail
{

/** \class ThreadTeamBarrier
 * \brief A reusable barrier for a fixed team of threads that meet many times per second.
 *
 * Wait() returns once all \a parties threads of the team have called it; the barrier is then ready for the next
 * round. A waiting thread first spins briefly (the other threads usually arrive within microseconds when the
 * work is balanced), then sleeps on a condition variable, so an oversubscribed machine is not burnt by spinning.
 * Everything a thread wrote before its Wait() is visible to every thread after theirs.
 *
 * \sa BilateralDepthRelaxKernel
 * \ingroup VesselReformation
 */
class ThreadTeamBarrier
{
public:
  explicit ThreadTeamBarrier(unsigned int parties);

  ThreadTeamBarrier(const ThreadTeamBarrier &) = delete;
  ThreadTeamBarrier &
  operator=(const ThreadTeamBarrier &) = delete;

  void
  Wait();

  unsigned int
  GetNumberOfParties() const
  {
    return m_Parties;
  }

private:
  const unsigned int        m_Parties;
  std::atomic<unsigned int> m_Arrived{ 0 };
  std::atomic<unsigned int> m_Generation{ 0 };
  std::mutex                m_Mutex;
  std::condition_variable   m_Condition;
};

} // namespace itk::detail

#endif
