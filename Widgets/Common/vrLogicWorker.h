// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrLogicWorker_h
#define vrLogicWorker_h

#include <functional>
#include <string>

namespace vr
{
/** \class LogicWorker
 * \brief The thread a host runs the features' logics on (docs/viewer.md, "Threads"): the whole-tree reformation's
 * requests and the other features' tasks (the one-vessel reading's) take turns on it, so that no logic runs on the GUI
 * thread and the two never compete for the processor. The host says which worker a feature's widgets use
 * (vr::ReformationController is the viewer's).
 *
 * A task's Run runs on the worker; its Done then runs on the thread that owns the worker (the GUI thread), unless the
 * worker was destroyed first. Each lane (a feature's name) holds at most one waiting task: a newer one replaces it
 * (latest wins; the replaced task never runs, nor its Done), and a running one finishes. Tasks go before the tree's
 * requests, which they are short beside. Run must catch what it throws: the worker drops an exception it lets out.
 * \ingroup VesselReformation
 */
class LogicWorker
{
public:
  struct Task
  {
    /** On the worker thread: the only place the feature's logic object is touched while a task runs. */
    std::function<void()> Run;
    /** Afterwards on the worker owner's thread, e.g. to show the results Run left; may be empty. */
    std::function<void()> Done;
  };

  virtual ~LogicWorker() = default;

  /** Queues \a task in lane \a lane, replacing the task waiting there. Worker owner's thread. */
  virtual void
  RunTask(const std::string & lane, Task task) = 0;
  /** From a running task (worker thread): its progress in [0, 1] and stage, shown as the tree's is. */
  virtual void
  ReportTaskProgress(double fraction, const std::string & stage) = 0;
};
} // namespace vr

#endif
