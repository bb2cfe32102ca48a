// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrTestProcesses.h"

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

extern char ** environ;

namespace vr::test
{
namespace
{
namespace fs = std::filesystem;

std::string
ReadWhole(const fs::path & path)
{
  std::ifstream      file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}
} // namespace

/** Runs \a arguments[0] with the rest as its arguments; stdout and stderr are captured through files in a folder of
 * their own, so that tests can check which files appear beside the outputs. */
RunResult
RunProgram(const std::vector<std::string> & arguments, const RunLimits & limits)
{
  static int     counter = 0;
  const fs::path capture = fs::temp_directory_path() / "vr-test-capture";
  fs::create_directories(capture);
  const fs::path out = capture / ("out-" + std::to_string(::getpid()) + "-" + std::to_string(counter) + ".txt");
  const fs::path err = capture / ("err-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".txt");

  std::vector<char *> argv;
  for (const auto & argument : arguments)
  {
    argv.push_back(const_cast<char *>(argument.c_str()));
  }
  argv.push_back(nullptr);
  RunResult   result;
  const auto  start = std::chrono::steady_clock::now();
  const int   outFile = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  const int   errFile = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  const pid_t pid = ::fork();
  if (pid == 0)
  {
    ::dup2(outFile, STDOUT_FILENO);
    ::dup2(errFile, STDERR_FILENO);
    if (limits.FileSizeLimit > 0)
    {
      ::signal(SIGXFSZ, SIG_IGN);
      const struct rlimit limit = { static_cast<rlim_t>(limits.FileSizeLimit),
                                    static_cast<rlim_t>(limits.FileSizeLimit) };
      ::setrlimit(RLIMIT_FSIZE, &limit);
    }
    ::execve(argv[0], argv.data(), environ);
    ::_exit(127);
  }
  ::close(outFile);
  ::close(errFile);
  if (pid < 0)
  {
    ADD_FAILURE() << "could not start " << arguments[0];
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
        result.Killed = true;
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
  result.Crashed = WIFSIGNALED(status) && !result.Killed;
  result.ExitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.Out = ReadWhole(out);
  result.Err = ReadWhole(err);
  fs::remove(out);
  fs::remove(err);
  return result;
}

} // namespace vr::test
