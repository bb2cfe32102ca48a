// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Both features' logics run on the viewer's worker (issue 42, docs/viewer.md "Threads"): while the viewer opens the
// phantom, turns the tree view, opens a vessel path, rolls it, stretches it and widens it, every ITK filter start of
// either logic is recorded with the thread it ran on (vr::SetFilterStartObserver, on each filter's StartEvent), and
// none is the GUI thread's. And the worker's task lanes themselves: a newer task replaces the one waiting in its lane,
// tasks run on the worker and their answers come on the GUI thread.
#include "vrWidgetsTestSupport.h"

#include "vrReformationController.h"
#include "vrStageMonitor.h"
#include "vrVesselPathPanel.h"

#include <QTest>

#include <gtest/gtest.h>

#include <condition_variable>
#include <iostream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace vr::test
{
namespace
{
/** The filter starts of both logics, by filter class, with their threads. */
class FilterStartRecord
{
public:
  FilterStartRecord()
  {
    SetFilterStartObserver(
      [this](const itk::ProcessObject & filter)
      {
        const std::lock_guard<std::mutex> lock(m_Mutex);
        m_Starts.emplace_back(filter.GetNameOfClass(), std::this_thread::get_id());
      });
  }
  ~FilterStartRecord() { SetFilterStartObserver(nullptr); }
  FilterStartRecord(const FilterStartRecord &) = delete;
  FilterStartRecord &
  operator=(const FilterStartRecord &) = delete;

  /** \return how many starts each filter class had on \a thread (or on any other thread when \a on is false). */
  std::map<std::string, int>
  Count(std::thread::id thread, bool on) const
  {
    const std::lock_guard<std::mutex> lock(m_Mutex);
    std::map<std::string, int>        counts;
    for (const auto & [name, id] : m_Starts)
    {
      if ((id == thread) == on)
      {
        ++counts[name];
      }
    }
    return counts;
  }

private:
  mutable std::mutex                                   m_Mutex;
  std::vector<std::pair<std::string, std::thread::id>> m_Starts;
};

/** \return the starts of the filter classes whose name contains \a part (the CPU's or an OpenCL device's filter). */
int
Starts(const std::map<std::string, int> & counts, const std::string & part)
{
  int sum = 0;
  for (const auto & [name, count] : counts)
  {
    sum += name.find(part) != std::string::npos ? count : 0;
  }
  return sum;
}

std::string
Describe(const std::map<std::string, int> & counts)
{
  std::ostringstream text;
  for (const auto & [name, count] : counts)
  {
    text << " " << name << " x" << count;
  }
  return text.str();
}
} // namespace

TEST(LogicThreads, NoFilterOfEitherLogicRunsOnTheGUIThread)
{
  const std::thread::id   gui = std::this_thread::get_id();
  const FilterStartRecord record;

  // The tree: the phantom opened and reformed, then the view turned.
  std::unique_ptr<ViewerWindow> window = MakeWindowOnSmallPhantom(30.0);
  ASSERT_TRUE(window->GetCPRView()->GetResult()) << window->GetLastError().toStdString();
  window->GetPanel()->SetAngle(75.0, RequestKind::Final);
  ASSERT_TRUE(WaitUntilSettled(*window));

  // One vessel: opened, rolled, stretched, widened.
  VesselPathPanel & panel = *window->GetPathPanel();
  ASSERT_TRUE(window->OpenVesselPath(0)) << window->GetLastError().toStdString();
  ASSERT_TRUE(WaitUntilSettled(*window));
  ASSERT_TRUE(panel.HasPath()) << panel.GetLastError().toStdString();
  panel.SetRoll(40.0);
  ASSERT_TRUE(WaitUntilSettled(*window));
  panel.SetStretched(true);
  ASSERT_TRUE(WaitUntilSettled(*window));
  panel.SetWidth(panel.GetParameters().Width + 10.0);
  ASSERT_TRUE(WaitUntilSettled(*window));
  EXPECT_EQ(panel.GetResult()->Parameters.RollInDegrees, 40.0);
  EXPECT_TRUE(panel.IsStretched());
  EXPECT_EQ(panel.GetResult()->Parameters.Reformation, PathReformation::Stretched);
  window.reset();

  const auto onGUI = record.Count(gui, true);
  const auto elsewhere = record.Count(gui, false);
  std::cout << "filter starts off the GUI thread:" << Describe(elsewhere) << "\n";
  EXPECT_TRUE(onGUI.empty()) << "filters started on the GUI thread:" << Describe(onGUI);
  // Both logics ran (the record would be empty, and the test pass, with no observer reached): the tree's depth,
  // relaxation and resampling, the path's straightened CPR (an open, a roll, the stretched mode and a width: four runs)
  // and its cross-sections.
  EXPECT_GE(Starts(elsewhere, "CPRDepthImageFilter"), 2);
  EXPECT_GE(Starts(elsewhere, "BilateralDepthRelaxFilter"), 1);
  EXPECT_GE(Starts(elsewhere, "CPRResampleImageFilter"), 2);
  EXPECT_GE(Starts(elsewhere, "StraightenedCPRImageFilter"), 4);
  EXPECT_GE(Starts(elsewhere, "CrossSectionStackImageFilter"), 1);
}

TEST(LogicThreads, ANewerTaskReplacesTheOneWaitingInItsLaneAndAnswersComeOnTheGUIThread)
{
  const std::thread::id    gui = std::this_thread::get_id();
  ReformationController    worker;
  std::mutex               mutex;
  std::condition_variable  released;
  bool                     release = false;
  std::vector<std::string> ran;
  std::vector<std::string> answered;
  bool                     ranOnGUI = false;
  bool                     answeredElsewhere = false;
  const auto               task = [&](const std::string & name, bool block)
  {
    LogicWorker::Task made;
    made.Run = [&, name, block]
    {
      std::unique_lock<std::mutex> lock(mutex);
      ran.push_back(name);
      ranOnGUI = ranOnGUI || std::this_thread::get_id() == gui;
      released.wait(lock, [&] { return release || !block; });
    };
    made.Done = [&, name]
    {
      answered.push_back(name);
      answeredElsewhere = answeredElsewhere || std::this_thread::get_id() != gui;
    };
    return made;
  };
  worker.RunTask("path", task("first", true));
  ASSERT_TRUE(WaitUntil(
    [&]
    {
      const std::lock_guard<std::mutex> lock(mutex);
      return !ran.empty();
    },
    10.0));
  // While the first runs: two more in its lane (the second never runs) and one in another lane.
  worker.RunTask("path", task("second", false));
  worker.RunTask("path", task("third", false));
  worker.RunTask("probe", task("probe", false));
  EXPECT_FALSE(worker.IsIdle());
  {
    const std::lock_guard<std::mutex> lock(mutex);
    release = true;
  }
  released.notify_all();
  ASSERT_TRUE(WaitUntil([&] { return worker.IsIdle(); }, 10.0));
  const std::lock_guard<std::mutex> lock(mutex);
  EXPECT_EQ(ran, (std::vector<std::string>{ "first", "third", "probe" }));
  EXPECT_EQ(answered, ran) << "each task that ran is answered, in order, before the worker says it is idle";
  EXPECT_FALSE(ranOnGUI);
  EXPECT_FALSE(answeredElsewhere);
}
} // namespace vr::test
