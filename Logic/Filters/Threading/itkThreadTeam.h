// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef itkThreadTeam_h
#define itkThreadTeam_h

#include "itkThreadTeamBarrier.h"

#include <atomic>
#include <cstddef>
#include <functional>
#include <memory>
#include <thread>
#include <vector>

namespace itk::detail
{

/** \class ThreadTeam
 * \brief A fixed team of threads for many short parallel steps: fork-join without creating threads per step.
 *
 * The team is created once (the calling thread is member 0, the others are helpers) and then runs job after job:
 * Run() hands the same job to every member and returns when all have finished it. Helpers wait between jobs on a
 * ThreadTeamBarrier (a brief spin, then sleep). When the system refuses a helper thread, the team simply has fewer
 * members. Jobs must not throw.
 *
 * \sa ThreadTeamBarrier, BilateralDepthRelaxSteadySolver
 * \ingroup VesselReformation
 */
class ThreadTeam
{
public:
  using Job = std::function<void(unsigned int member)>;

  /** A team of up to \a size threads (at least 1: the caller). */
  explicit ThreadTeam(unsigned int size);
  ~ThreadTeam();
  ThreadTeam(const ThreadTeam &) = delete;
  ThreadTeam &
  operator=(const ThreadTeam &) = delete;

  unsigned int
  GetSize() const
  {
    return m_Size;
  }

  /** Runs \a job(member) on every member, member 0 on the calling thread, and waits for all. */
  void
  Run(const Job & job);

  /** Splits [0, count) into GetSize() contiguous bands, member m taking [count m / size, count (m + 1) / size),
   * and runs \a job(begin, end) on each; with \a parallel false the caller does all of it. */
  void
  ForBands(std::size_t count, const std::function<void(std::size_t, std::size_t)> & job, bool parallel = true);

  /** ForBands, with the member that works each band as \a job's first argument (0 for the whole range when not
   * \a parallel), for jobs that keep scratch space per member. */
  void
  ForMemberBands(std::size_t                                                         count,
                 const std::function<void(unsigned int, std::size_t, std::size_t)> & job,
                 bool                                                                parallel = true);

private:
  void
  Serve(unsigned int member);

  unsigned int                       m_Size{ 1 };
  std::unique_ptr<ThreadTeamBarrier> m_Barrier;
  const Job *                        m_Job{ nullptr };
  std::atomic<bool>                  m_Stop{ false };
  std::vector<std::thread>           m_Helpers;
};

} // namespace itk::detail

#endif
