// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrTestProcesses_h
#define vrTestProcesses_h

#include <string>
#include <vector>

/** Running the built programs from tests: exit status, output, time limits, injected write failures. */
namespace vr::test
{
struct RunResult
{
  int  ExitCode{ -1 };
  bool Crashed{ false };
  /** Killed by RunProgram after its time limit. */
  bool        Killed{ false };
  double      Seconds{ 0.0 };
  std::string Out;
  std::string Err;
};

/** How RunProgram runs a program besides its arguments. */
struct RunLimits
{
  /** Kill it with SIGKILL after this many seconds (0: wait for ever). */
  double KillAfterSeconds{ 0.0 };
  /** RLIMIT_FSIZE in bytes (0: none): writes past it fail with EFBIG, as on a full disk; SIGXFSZ is ignored. */
  long long FileSizeLimit{ 0 };
};

/** Runs \a arguments[0] (a path) with the rest as its arguments and waits for it (or kills it, see \a limits);
 * stdout and stderr are captured through files in a folder of their own (under the system's temporary folder), so
 * that tests can check which files appear beside the outputs. */
RunResult
RunProgram(const std::vector<std::string> & arguments, const RunLimits & limits = RunLimits());
} // namespace vr::test

#endif
