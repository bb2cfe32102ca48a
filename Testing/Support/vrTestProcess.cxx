// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrTestProcess.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

extern char ** environ;

namespace vr::test
{
namespace
{
std::string
ReadWhole(const std::filesystem::path & path)
{
  std::ifstream      file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}
} // namespace

ProcessResult
RunProcess(const std::vector<std::string> & arguments, const std::string & captureFolder)
{
  static int                  counter = 0;
  const std::filesystem::path folder(captureFolder);
  std::filesystem::create_directories(folder);
  const std::string           suffix = std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".txt";
  const std::filesystem::path out = folder / ("out-" + suffix);
  const std::filesystem::path err = folder / ("err-" + suffix);

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
  pid_t         pid = 0;
  ProcessResult result;
  const int     started = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (started != 0)
  {
    ADD_FAILURE() << "could not start " << arguments[0];
    return result;
  }
  int status = 0;
  waitpid(pid, &status, 0);
  result.Crashed = WIFSIGNALED(status);
  result.ExitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.Out = ReadWhole(out);
  result.Err = ReadWhole(err);
  std::filesystem::remove(out);
  std::filesystem::remove(err);
  return result;
}
std::vector<ProcessMapping>
MappingsNamed(const std::string & part)
{
  std::vector<ProcessMapping> found;
  std::ifstream               maps("/proc/self/maps");
  for (std::string line; std::getline(maps, line);)
  {
    // "start-end perms offset dev inode   name"
    std::istringstream fields(line);
    std::string        range, perms, offset, device, inode;
    fields >> range >> perms >> offset >> device >> inode;
    std::string name;
    std::getline(fields >> std::ws, name);
    if (name.find(part) == std::string::npos)
    {
      continue;
    }
    const auto     dash = range.find('-');
    ProcessMapping mapping;
    mapping.Start = std::stoull(range.substr(0, dash), nullptr, 16);
    mapping.End = std::stoull(range.substr(dash + 1), nullptr, 16);
    mapping.Name = name;
    found.push_back(mapping);
  }
  return found;
}

std::vector<std::string>
OpenFilesNamed(const std::string & part)
{
  std::vector<std::string> found;
  std::error_code          error;
  for (const auto & entry : std::filesystem::directory_iterator("/proc/self/fd", error))
  {
    std::error_code linkError;
    const auto      target = std::filesystem::read_symlink(entry.path(), linkError).string();
    if (!linkError && target.find(part) != std::string::npos)
    {
      found.push_back(target);
    }
  }
  return found;
}
} // namespace vr::test
