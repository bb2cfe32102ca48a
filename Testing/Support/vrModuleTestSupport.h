// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrModuleTestSupport_h
#define vrModuleTestSupport_h

#include <filesystem>
#include <set>
#include <string>
#include <vector>

/** Running the command-line modules as 3D Slicer and a shell do, for their tests: as a program (its own process) and
 * through a shared library's ModuleEntryPoint (in this process), with stdout and stderr captured. */
namespace vr::test
{
struct ProgramRun
{
  int         ExitCode{ -1 };
  bool        Crashed{ false };
  std::string Out;
  std::string Err;
};

/** Runs \a arguments[0] with the rest as its arguments; stdout and stderr go through files in \a captureFolder. */
ProgramRun
RunProgram(const std::vector<std::string> & arguments, const std::filesystem::path & captureFolder);

/** Loads \a library and calls its ModuleEntryPoint with \a arguments (arguments[0] the module's name), as 3D Slicer
 * runs a module in-process; stdout and stderr are captured through files in \a captureFolder. */
ProgramRun
RunEntryPoint(const std::string &              library,
              const std::vector<std::string> & arguments,
              const std::filesystem::path &    captureFolder);

/** The address of a symbol of \a library (dlopen, dlsym), or null. */
void *
LibrarySymbol(const std::string & library, const char * name);

/** The whole content of a file ("" when it cannot be read). */
std::string
ReadWholeFile(const std::filesystem::path & path);

/** The names of the entries of a folder. */
std::set<std::string>
FolderEntries(const std::filesystem::path & folder);
} // namespace vr::test

#endif
