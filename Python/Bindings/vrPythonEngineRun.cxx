// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrPythonEngineRun.h"

#include "vrInputError.h"

#include <chrono>
#include <exception>
#include <optional>
#include <thread>

namespace vr::python
{
void
ProgressSink::Report(double fraction, const std::string & stage)
{
  {
    const std::lock_guard<std::mutex> lock(m_Mutex);
    m_Fraction = fraction;
    m_Stage = stage;
    m_Fresh = true;
  }
  m_Changed.notify_all();
}

/** The calling thread's side of RunEngine. */
class EngineRun
{
public:
  static void
  Run(const py::object &                          callback,
      const std::function<void(ProgressSink &)> & work,
      const std::function<void()> &               abort)
  {
    ProgressSink       sink;
    std::exception_ptr failure;
    std::thread        worker(
      [&]
      {
        try
        {
          work(sink);
        }
        catch (...)
        {
          failure = std::current_exception();
        }
        {
          const std::lock_guard<std::mutex> lock(sink.m_Mutex);
          sink.m_Done = true;
        }
        sink.m_Changed.notify_all();
      });

    std::optional<py::error_already_set> raised;
    bool                                 cancelled = false;
    for (bool done = false; !done;)
    {
      bool        fresh = false;
      double      fraction = 0.0;
      std::string stage;
      {
        const py::gil_scoped_release release;
        std::unique_lock<std::mutex> lock(sink.m_Mutex);
        sink.m_Changed.wait_for(lock, std::chrono::milliseconds(100), [&] { return sink.m_Done || sink.m_Fresh; });
        done = sink.m_Done;
        fresh = sink.m_Fresh;
        fraction = sink.m_Fraction;
        stage = sink.m_Stage;
        sink.m_Fresh = false;
      }
      if (sink.StopRequested())
      {
        continue;
      }
      try
      {
        if (fresh && !callback.is_none())
        {
          const py::object answer = callback(fraction, stage);
          cancelled = answer.ptr() == Py_False;
        }
        if (PyErr_CheckSignals() != 0)
        {
          throw py::error_already_set();
        }
      }
      catch (py::error_already_set & error)
      {
        raised.emplace(std::move(error));
      }
      if (raised || cancelled)
      {
        sink.m_Stop = true;
        const py::gil_scoped_release release;
        abort();
      }
    }
    {
      const py::gil_scoped_release release;
      worker.join();
    }
    if (raised)
    {
      throw std::move(*raised);
    }
    if (cancelled)
    {
      throw Cancelled("cancelled: the progress callback returned False; nothing was written");
    }
    if (failure)
    {
      std::rethrow_exception(failure);
    }
  }
};

void
RunEngine(const py::object &                          callback,
          const std::function<void(ProgressSink &)> & work,
          const std::function<void()> &               abort)
{
  EngineRun::Run(callback, work, abort);
}
} // namespace vr::python
