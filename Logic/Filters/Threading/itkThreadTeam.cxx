// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkThreadTeam.h"

#include <future>
#include <system_error>

namespace itk::detail
{

ThreadTeam::ThreadTeam(unsigned int size)
{
  // Helpers wait for the word to start, so that a helper the system refuses to create leaves nobody waiting on a
  // barrier sized for it.
  std::promise<bool>       start;
  std::shared_future<bool> started = start.get_future().share();
  try
  {
    for (unsigned int member = 1; member < size; ++member)
    {
      m_Helpers.emplace_back(
        [this, started, member]
        {
          if (started.get())
          {
            this->Serve(member);
          }
        });
    }
  }
  catch (const std::system_error &)
  {
    start.set_value(false);
    for (auto & helper : m_Helpers)
    {
      helper.join();
    }
    m_Helpers.clear();
    m_Barrier = std::make_unique<ThreadTeamBarrier>(1);
    return;
  }
  m_Size = static_cast<unsigned int>(m_Helpers.size()) + 1;
  m_Barrier = std::make_unique<ThreadTeamBarrier>(m_Size);
  start.set_value(true);
}

ThreadTeam::~ThreadTeam()
{
  if (!m_Helpers.empty())
  {
    m_Stop.store(true, std::memory_order_relaxed);
    m_Barrier->Wait();
    for (auto & helper : m_Helpers)
    {
      helper.join();
    }
  }
}

void
ThreadTeam::Serve(unsigned int member)
{
  for (;;)
  {
    m_Barrier->Wait(); // a job is ready, or the team stops
    if (m_Stop.load(std::memory_order_relaxed))
    {
      return;
    }
    (*m_Job)(member);
    m_Barrier->Wait(); // done
  }
}

void
ThreadTeam::Run(const Job & job)
{
  if (m_Helpers.empty())
  {
    job(0);
    return;
  }
  m_Job = &job;
  m_Barrier->Wait();
  job(0);
  m_Barrier->Wait();
  m_Job = nullptr;
}

void
ThreadTeam::ForBands(std::size_t count, const std::function<void(std::size_t, std::size_t)> & job, bool parallel)
{
  this->ForMemberBands(
    count, [&](unsigned int, std::size_t begin, std::size_t end) { job(begin, end); }, parallel);
}

void
ThreadTeam::ForMemberBands(std::size_t                                                         count,
                           const std::function<void(unsigned int, std::size_t, std::size_t)> & job,
                           bool                                                                parallel)
{
  if (!parallel || m_Size == 1 || count < 2)
  {
    job(0, 0, count);
    return;
  }
  const std::size_t size = m_Size;
  this->Run(
    [&](unsigned int member)
    {
      const std::size_t begin = count * member / size;
      const std::size_t end = count * (member + 1) / size;
      if (begin < end)
      {
        job(member, begin, end);
      }
    });
}

} // namespace itk::detail
