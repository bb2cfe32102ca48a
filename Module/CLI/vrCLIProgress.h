// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrCLIProgress_h
#define vrCLIProgress_h

#include "vrModuleProcessInformation.h"

#include <chrono>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace vr
{
/** \class CLIProgress
 * \brief Reports a command-line module's progress, and the values it returns, the three ways its callers expect.
 *
 * - In-process in 3D Slicer (a ModuleProcessInformation address was given): fills the structure and calls its
 *   callback; prints nothing.
 * - Run by a program (stdout is not a terminal): Slicer Execution Model lines, "<filter-start>" with the
 *   module's name and comment, "<filter-progress>0.42</filter-progress>" at every percent, and "<filter-end>"
 *   with the elapsed time.
 * - Run from a terminal: a progress bar redrawn in place, ended by a newline.
 *
 * The values the module returns (its description's return parameters) are kept by SetReturnValue(); the runner
 * writes them to 3D Slicer's --returnparameterfile, and End() prints them as CTK's
 * "<filter-result name=\"...\">value</filter-result>" lines (before "<filter-end>") when a program runs it.
 * \ingroup VesselReformation
 */
class CLIProgress
{
public:
  /** \param name the module's name (filter-name).
   * \param comment what it does (filter-comment).
   * \param information Slicer's structure, or null.
   * \param out where the lines or the bar go (stdout).
   * \param terminal whether \a out is a terminal. */
  CLIProgress(std::string                  name,
              std::string                  comment,
              vrModuleProcessInformation * information,
              std::ostream &               out,
              bool                         terminal);

  /** Starts the report; call once. */
  void
  Start();
  /** \param fraction overall progress in [0, 1]; reported when it advanced by a percent or more.
   * \param stage the running stage, for the bar and Slicer's message. */
  void
  Update(double fraction, const std::string & stage);
  /** Reports completion; call once after a successful run. */
  void
  End();

  /** Prints a line of text (a warning, a summary) without tearing the progress bar: an open bar is ended first.
   * \param stream where the line goes (stdout or stderr).
   * \param text the line, without its newline. */
  void
  Print(std::ostream & stream, const std::string & text);

  /** \return whether 3D Slicer asked the module to stop. */
  bool
  AbortRequested() const;

  /** Keeps a value the module returns; a second value for the same name replaces the first.
   * \param name the return parameter's name in the module's XML.
   * \param value its value as Slicer's parameter file and CTK write it ("cpu", "512,1024", "12.5"). */
  void
  SetReturnValue(const std::string & name, const std::string & value);
  /** \return the values kept, in the order they were first set. */
  const std::vector<std::pair<std::string, std::string>> &
  GetReturnValues() const
  {
    return m_ReturnValues;
  }

private:
  double
  ElapsedSeconds() const;

  std::string                                      m_Name;
  std::string                                      m_Comment;
  vrModuleProcessInformation *                     m_Information;
  std::ostream &                                   m_Out;
  bool                                             m_Terminal;
  double                                           m_Reported{ -1.0 };
  bool                                             m_BarOpen{ false };
  std::chrono::steady_clock::time_point            m_Start;
  std::vector<std::pair<std::string, std::string>> m_ReturnValues;
};
} // namespace vr

#endif
