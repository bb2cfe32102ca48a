// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrModuleRuns.h"

#include <dlfcn.h>
#include <fcntl.h>
#include <csignal>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <future>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <thread>

extern char ** environ;

namespace vr::test
{
namespace
{
namespace fs = std::filesystem;

std::string
ReadAll(const fs::path & path)
{
  std::ifstream      file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

/** Two fresh capture files in a folder of their own under the system temporary folder. */
struct CaptureFiles
{
  CaptureFiles()
  {
    static int counter = 0;
    Folder =
      fs::temp_directory_path() / ("vr-module-run-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::remove_all(Folder);
    fs::create_directories(Folder);
    Out = Folder / "out.txt";
    Err = Folder / "err.txt";
  }
  ~CaptureFiles()
  {
    std::error_code ignored;
    fs::remove_all(Folder, ignored);
  }
  fs::path Folder;
  fs::path Out;
  fs::path Err;
};

using EntryPoint = int (*)(int, char **);
} // namespace

ModuleRun
RunProgram(const std::vector<std::string> & arguments, double limitSeconds, const std::string & workingDirectory)
{
  RunLimits limits;
  limits.KillAfterSeconds = limitSeconds;
  limits.WorkingDirectory = workingDirectory;
  return RunProgram(arguments, limits);
}

ModuleRun
RunProgram(const std::vector<std::string> & arguments, const RunLimits & limits)
{
  ModuleRun           result;
  const CaptureFiles  capture;
  std::vector<char *> argv;
  for (const auto & argument : arguments)
  {
    argv.push_back(const_cast<char *>(argument.c_str()));
  }
  argv.push_back(nullptr);
  const auto  start = std::chrono::steady_clock::now();
  const int   outFile = ::open(capture.Out.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  const int   errFile = ::open(capture.Err.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  const pid_t pid = ::fork();
  if (pid == 0)
  {
    // Only async-signal-safe calls between fork and exec.
    ::dup2(outFile, STDOUT_FILENO);
    ::dup2(errFile, STDERR_FILENO);
    if (limits.FileSizeLimit > 0)
    {
      ::signal(SIGXFSZ, SIG_IGN);
      const struct rlimit limit = { static_cast<rlim_t>(limits.FileSizeLimit),
                                    static_cast<rlim_t>(limits.FileSizeLimit) };
      ::setrlimit(RLIMIT_FSIZE, &limit);
    }
    if (!limits.WorkingDirectory.empty() && ::chdir(limits.WorkingDirectory.c_str()) != 0)
    {
      ::_exit(126);
    }
    ::execve(argv[0], argv.data(), environ);
    ::_exit(127);
  }
  ::close(outFile);
  ::close(errFile);
  if (pid < 0)
  {
    result.Err = "could not start " + arguments.at(0);
    return result;
  }
  int status = 0;
  if (limits.KillAfterSeconds > 0.0)
  {
    const auto deadline = start + std::chrono::duration<double>(limits.KillAfterSeconds);
    while (::waitpid(pid, &status, WNOHANG) == 0)
    {
      if (std::chrono::steady_clock::now() >= deadline)
      {
        ::kill(pid, SIGKILL);
        ::waitpid(pid, &status, 0);
        result.TimedOut = true;
        break;
      }
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
  }
  else
  {
    ::waitpid(pid, &status, 0);
  }
  result.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.Crashed = !result.TimedOut && WIFSIGNALED(status);
  result.ExitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.Out = ReadAll(capture.Out);
  result.Err = ReadAll(capture.Err);
  return result;
}

void *
LibrarySymbol(const std::string & library, const char * name)
{
  // RTLD_NOW | RTLD_LOCAL as Slicer's library loader; the handle stays open, as Slicer keeps its modules loaded.
  void * handle = ::dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle == nullptr)
  {
    std::cerr << "dlopen " << library << ": " << ::dlerror() << std::endl;
    return nullptr;
  }
  return ::dlsym(handle, name);
}

ModuleRun
RunEntryPointInProcess(const std::string &              library,
                       const std::vector<std::string> & arguments,
                       double                           limitSeconds,
                       const std::string &              workingDirectory)
{
  ModuleRun result;
  auto      entry = reinterpret_cast<EntryPoint>(LibrarySymbol(library, "ModuleEntryPoint"));
  if (entry == nullptr)
  {
    result.Err = library + " has no ModuleEntryPoint";
    return result;
  }
  const CaptureFiles capture;
  // The strings outlive a call that times out and goes on on its thread.
  auto copies = std::make_shared<std::vector<std::string>>(arguments);
  auto argv = std::make_shared<std::vector<char *>>();
  for (auto & argument : *copies)
  {
    argv->push_back(argument.data());
  }
  argv->push_back(nullptr);

  const fs::path here = fs::current_path();
  if (!workingDirectory.empty())
  {
    fs::current_path(workingDirectory);
  }
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  const int savedOut = ::dup(STDOUT_FILENO);
  const int savedErr = ::dup(STDERR_FILENO);
  const int outFile = ::open(capture.Out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const int errFile = ::open(capture.Err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  ::dup2(outFile, STDOUT_FILENO);
  ::dup2(errFile, STDERR_FILENO);
  auto call = std::async(std::launch::async,
                         [entry, copies, argv] { return entry(static_cast<int>(copies->size()), argv->data()); });
  if (limitSeconds > 0.0 && call.wait_for(std::chrono::duration<double>(limitSeconds)) != std::future_status::ready)
  {
    result.TimedOut = true;
    // Leave it running: a std::async future would wait for it on destruction.
    static std::vector<std::future<int>> abandoned;
    abandoned.push_back(std::move(call));
  }
  else
  {
    result.ExitCode = call.get();
  }
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  ::dup2(savedOut, STDOUT_FILENO);
  ::dup2(savedErr, STDERR_FILENO);
  ::close(outFile);
  ::close(errFile);
  ::close(savedOut);
  ::close(savedErr);
  if (!workingDirectory.empty())
  {
    fs::current_path(here);
  }
  result.Out = ReadAll(capture.Out);
  result.Err = ReadAll(capture.Err);
  return result;
}

std::string
AddressText(const void * pointer)
{
  char text[64];
  std::snprintf(text, sizeof(text), "%p", pointer);
  return text;
}
} // namespace vr::test
