// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrTestProcess_h
#define vrTestProcess_h

#include <string>
#include <vector>

/** Running a built program from a test. */
namespace vr::test
{
/** How a program ended and what it printed. */
struct ProcessResult
{
  int         ExitCode{ -1 };
  bool        Crashed{ false };
  std::string Out;
  std::string Err;
};

/** Runs \a arguments[0] with the rest as its arguments and this process's environment (so a virtual X server's
 * DISPLAY carries over); stdout and stderr are captured through files in \a captureFolder. */
ProcessResult
RunProcess(const std::vector<std::string> & arguments, const std::string & captureFolder);
} // namespace vr::test

#endif
