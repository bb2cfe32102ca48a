// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrModuleRuns_h
#define vrModuleRuns_h

#include <string>
#include <vector>

/** Running command-line modules as platforms run them: an executable in a process of its own (as 3D Slicer and
 * MITK do), a shared library's ModuleEntryPoint in this process (as 3D Slicer does). */
namespace vr::test
{
struct ModuleRun
{
  int  ExitCode{ -1 };
  bool Crashed{ false };
  /** It was still running at the time limit (and was killed, for a program). */
  bool        TimedOut{ false };
  double      Seconds{ 0.0 };
  std::string Out;
  std::string Err;
};

/** How RunProgram runs a program besides its arguments. */
struct RunLimits
{
  /** Kill it with SIGKILL after this many seconds and report TimedOut (0: wait as long as it runs). */
  double KillAfterSeconds{ 0.0 };
  /** RLIMIT_FSIZE in bytes (0: none): writes past it fail with EFBIG, as on a full disk; SIGXFSZ is ignored. */
  long long FileSizeLimit{ 0 };
  /** Where it runs ("" = here). */
  std::string WorkingDirectory;
};

/** Runs a program, \a arguments[0] its path, with stdout and stderr captured through files in a folder of their own
 * (under the system's temporary folder), so that tests can check which files appear beside the outputs. */
ModuleRun
RunProgram(const std::vector<std::string> & arguments, const RunLimits & limits);

/** RunProgram with a time limit and a working directory only.
 * \param arguments the command line.
 * \param limitSeconds kill it after this long and report TimedOut (0: wait as long as it runs).
 * \param workingDirectory where it runs ("" = here). */
ModuleRun
RunProgram(const std::vector<std::string> & arguments,
           double                           limitSeconds = 0.0,
           const std::string &              workingDirectory = "");

/** Calls the ModuleEntryPoint of a shared-library module in this process with \a arguments (argv[0] first, as 3D
 * Slicer passes its target), capturing what it prints on stdout and stderr.
 * \param library the shared library.
 * \param arguments the command line.
 * \param limitSeconds wait at most this long for it (0: as long as it runs); a call still running then is reported
 * TimedOut and left to finish on its thread.
 * \param workingDirectory the working directory during the call ("" = unchanged). */
ModuleRun
RunEntryPointInProcess(const std::string &              library,
                       const std::vector<std::string> & arguments,
                       double                           limitSeconds = 0.0,
                       const std::string &              workingDirectory = "");

/** \return the address of a symbol of \a library (loaded once, kept loaded), or null. */
void *
LibrarySymbol(const std::string & library, const char * name);

/** SlicerExecutionModel's ModuleProcessInformation (ModuleDescriptionParser/ModuleProcessInformation.h), written here
 * from Slicer's header independently of the module's own copy, so that a layout mismatch shows. */
struct SlicerModuleProcessInformation
{
  unsigned char Abort{ 0 };
  float         Progress{ 0.0f };
  float         StageProgress{ 0.0f };
  char          ProgressMessage[1024]{};
  void (*ProgressCallbackFunction)(void *){ nullptr };
  void * ProgressCallbackClientData{ nullptr };
  double ElapsedTime{ 0.0 };
};

/** \return \a pointer as 3D Slicer prints it for --processinformationaddress (sprintf "%p"). */
std::string
AddressText(const void * pointer);
} // namespace vr::test

#endif
