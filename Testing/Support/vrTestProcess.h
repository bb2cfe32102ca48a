// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrTestProcess_h
#define vrTestProcess_h

#include <cstddef>
#include <cstdint>
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

/** One mapping of this process's address space, as /proc/self/maps lists it. */
struct ProcessMapping
{
  std::uintptr_t Start{ 0 };
  std::uintptr_t End{ 0 };
  std::string    Name;

  std::size_t
  Bytes() const
  {
    return End - Start;
  }
};

/** This process's mappings whose name holds \a part (a memfd's is "/memfd:<its name> (deleted)"). */
std::vector<ProcessMapping>
MappingsNamed(const std::string & part);

/** The targets of this process's open file descriptors that hold \a part ("/memfd:..." for a memfd). */
std::vector<std::string>
OpenFilesNamed(const std::string & part);
} // namespace vr::test

#endif
