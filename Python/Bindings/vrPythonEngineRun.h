// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrPythonEngineRun_h
#define vrPythonEngineRun_h

#include <pybind11/pybind11.h>

#include <atomic>
#include <condition_variable>
#include <functional>
#include <mutex>
#include <string>

namespace vr::python
{
namespace py = pybind11;

/** \class ProgressSink
 * \brief What the engine's work reports to while it runs on its own thread, without the GIL: the latest progress,
 * which the calling thread hands to Python, and whether Python asked it to stop.
 */
class ProgressSink
{
public:
  /** Records \a fraction in [0, 1] of the whole run, in stage \a stage (any thread). */
  void
  Report(double fraction, const std::string & stage);
  /** \return whether the run is to stop (Ctrl-C, the callback raised or returned False). */
  bool
  StopRequested() const
  {
    return m_Stop.load();
  }

private:
  friend class EngineRun;
  std::mutex              m_Mutex;
  std::condition_variable m_Changed;
  bool                    m_Fresh{ false };
  bool                    m_Done{ false };
  double                  m_Fraction{ 0.0 };
  std::string             m_Stage;
  std::atomic<bool>       m_Stop{ false };
};

/** Runs \a work (the engine) on a worker thread while the calling thread waits with the GIL released; it wakes when
 * the engine reports progress, which it hands to \a callback (a Python callable (fraction, stage), or None) on the
 * calling thread, and at least every 0.1 s to check for Ctrl-C. When the callback raises (KeyboardInterrupt among
 * others) or returns False, or a signal handler raises, \a abort is called (the logic's AbortUpdate; any thread) and
 * the run waits for \a work to return. Throws, in this order: the Python exception raised; vr::Cancelled when the
 * callback returned False; what \a work threw. \a work must not touch Python objects. */
void
RunEngine(const py::object &                          callback,
          const std::function<void(ProgressSink &)> & work,
          const std::function<void()> &               abort);
} // namespace vr::python

#endif
