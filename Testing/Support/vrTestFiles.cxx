// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrTestFiles.h"

#include "vrInputError.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <sys/mount.h>
#include <unistd.h>

namespace vr::test
{
ScopedTemporaryFolder::ScopedTemporaryFolder()
{
  static std::atomic<unsigned> counter{ 0 };
  m_Path = std::filesystem::temp_directory_path() /
           ("vr-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  std::filesystem::remove_all(m_Path);
  std::filesystem::create_directories(m_Path);
}

ScopedTemporaryFolder::~ScopedTemporaryFolder()
{
  std::error_code ignored;
  std::filesystem::remove_all(m_Path, ignored);
}

std::string
ScopedTemporaryFolder::File(const std::string & name) const
{
  return (m_Path / name).string();
}

std::vector<std::string>
ScopedTemporaryFolder::Entries() const
{
  std::vector<std::string> names;
  for (const auto & entry : std::filesystem::directory_iterator(m_Path))
  {
    names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

void
WriteTextFile(const std::string & path, const std::string & text)
{
  std::ofstream output(path, std::ios::binary);
  output << text;
  if (!output)
  {
    throw std::runtime_error("cannot write " + path);
  }
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

bool
Contains(const std::string & text, const std::string & part)
{
  return text.find(part) != std::string::npos;
}

std::filesystem::path
FreshFolderForThisTest(const std::filesystem::path & root, const std::string & prefix)
{
  const auto *  info = ::testing::UnitTest::GetInstance()->current_test_info();
  const auto    folder = root / (prefix + info->test_suite_name() + "." + info->name());
  std::ifstream mounts("/proc/mounts");
  std::string   device;
  std::string   mountPoint;
  std::string   rest;
  while (mounts >> device >> mountPoint && std::getline(mounts, rest))
  {
    if (mountPoint.rfind(folder.string() + "/", 0) == 0)
    {
      ::umount2(mountPoint.c_str(), MNT_DETACH);
    }
  }
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

std::string
ReadTextFile(const std::string & path)
{
  std::ifstream input(path, std::ios::binary);
  if (!input)
  {
    throw std::runtime_error("cannot read " + path);
  }
  std::ostringstream text;
  text << input.rdbuf();
  return text.str();
}

std::string
InputErrorOf(const std::function<void()> & action)
{
  try
  {
    action();
  }
  catch (const vr::InputError & error)
  {
    std::cout << "  vr::InputError: " << error.what() << std::endl; // for reading the messages in the test log
    return error.what();
  }
  catch (const std::exception & other)
  {
    ADD_FAILURE() << "expected vr::InputError, got another exception: " << other.what();
    return std::string();
  }
  ADD_FAILURE() << "expected vr::InputError, nothing was thrown";
  return std::string();
}

std::string
InputErrorAndPrintedTextOf(const std::function<void()> & action, std::string & printed)
{
  testing::internal::CaptureStdout();
  testing::internal::CaptureStderr();
  std::string message;
  bool        thrown = false;
  try
  {
    action();
  }
  catch (const vr::InputError & error)
  {
    message = error.what();
    thrown = true;
  }
  catch (...)
  {
  }
  printed = testing::internal::GetCapturedStderr();
  printed += testing::internal::GetCapturedStdout();
  EXPECT_TRUE(thrown) << "expected vr::InputError";
  std::cout << "  vr::InputError: " << message << std::endl;
  return message;
}

std::string
AortaDataFolder()
{
#ifdef VR_SHARED_DATA_DIR
  const std::filesystem::path folder = std::filesystem::path(VR_SHARED_DATA_DIR) / "vmtk-aorta-mra";
  return std::filesystem::exists(folder / "aorta.mha") ? folder.string() : std::string();
#else
  return std::string();
#endif
}
} // namespace vr::test
