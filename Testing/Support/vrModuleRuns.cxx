// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrModuleRuns.h"

#include <dlfcn.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
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
  ModuleRun           result;
  const CaptureFiles  capture;
  std::vector<char *> argv;
  for (const auto & argument : arguments)
  {
    argv.push_back(const_cast<char *>(argument.c_str()));
  }
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, capture.Out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, capture.Err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (!workingDirectory.empty())
  {
    posix_spawn_file_actions_addchdir_np(&actions, workingDirectory.c_str()); // glibc 2.29 and later
  }
  pid_t     pid = 0;
  const int spawned = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0)
  {
    result.Err = "could not start " + arguments.at(0);
    return result;
  }
  const auto start = std::chrono::steady_clock::now();
  int        status = 0;
  while (true)
  {
    const pid_t done = ::waitpid(pid, &status, limitSeconds > 0.0 ? WNOHANG : 0);
    if (done == pid)
    {
      break;
    }
    if (std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() > limitSeconds)
    {
      result.TimedOut = true;
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
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
