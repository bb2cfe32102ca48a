// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrModuleTestSupport.h"

#include <dlfcn.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

extern char ** environ;

namespace vr::test
{
namespace
{
int
NextCaptureNumber()
{
  static int counter = 0;
  return counter++;
}
} // namespace

std::string
ReadWholeFile(const std::filesystem::path & path)
{
  std::ifstream      file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

std::set<std::string>
FolderEntries(const std::filesystem::path & folder)
{
  std::set<std::string> names;
  for (const auto & entry : std::filesystem::directory_iterator(folder))
  {
    names.insert(entry.path().filename().string());
  }
  return names;
}

ProgramRun
RunProgram(const std::vector<std::string> & arguments, const std::filesystem::path & captureFolder)
{
  std::filesystem::create_directories(captureFolder);
  const std::string          tag = std::to_string(::getpid()) + "-" + std::to_string(NextCaptureNumber());
  const auto                 out = captureFolder / ("out-" + tag + ".txt");
  const auto                 err = captureFolder / ("err-" + tag + ".txt");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<char *> argv;
  for (const auto & argument : arguments)
  {
    argv.push_back(const_cast<char *>(argument.c_str()));
  }
  argv.push_back(nullptr);
  ProgramRun run;
  pid_t      pid = 0;
  const int  started = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (started != 0)
  {
    run.Err = "could not start " + arguments[0];
    return run;
  }
  int status = 0;
  waitpid(pid, &status, 0);
  run.Crashed = WIFSIGNALED(status);
  run.ExitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.Out = ReadWholeFile(out);
  run.Err = ReadWholeFile(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return run;
}

void *
LibrarySymbol(const std::string & library, const char * name)
{
  void * handle = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
  return handle == nullptr ? nullptr : dlsym(handle, name);
}

ProgramRun
RunEntryPoint(const std::string &              library,
              const std::vector<std::string> & arguments,
              const std::filesystem::path &    captureFolder)
{
  using EntryPoint = int (*)(int, char **);
  ProgramRun run;
  auto       entry = reinterpret_cast<EntryPoint>(LibrarySymbol(library, "ModuleEntryPoint"));
  if (entry == nullptr)
  {
    run.Err = library + " has no ModuleEntryPoint";
    return run;
  }
  std::filesystem::create_directories(captureFolder);
  const std::string        tag = std::to_string(::getpid()) + "-" + std::to_string(NextCaptureNumber());
  const auto               out = captureFolder / ("in-process-out-" + tag + ".txt");
  const auto               err = captureFolder / ("in-process-err-" + tag + ".txt");
  std::vector<std::string> copies = arguments;
  std::vector<char *>      argv;
  for (auto & argument : copies)
  {
    argv.push_back(argument.data());
  }
  argv.push_back(nullptr);
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  const int savedOut = dup(STDOUT_FILENO);
  const int savedErr = dup(STDERR_FILENO);
  const int outFile = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const int errFile = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  dup2(outFile, STDOUT_FILENO);
  dup2(errFile, STDERR_FILENO);
  run.ExitCode = entry(static_cast<int>(copies.size()), argv.data());
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  dup2(savedOut, STDOUT_FILENO);
  dup2(savedErr, STDERR_FILENO);
  close(outFile);
  close(errFile);
  close(savedOut);
  close(savedErr);
  run.Out = ReadWholeFile(out);
  run.Err = ReadWholeFile(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return run;
}
} // namespace vr::test
