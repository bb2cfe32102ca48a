// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrAtomicOutput.h"

#include "vrInputError.h"
#include "vrURINames.h"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <unistd.h>

namespace vr
{
namespace
{
/** The extension to keep: everything from the first dot of the file name (".mrk.json", ".nii.gz"). */
std::string
FullExtension(const std::filesystem::path & path)
{
  const std::string name = path.filename().string();
  const auto        dot = name.find('.', 1);
  return dot == std::string::npos ? std::string() : name.substr(dot);
}
} // namespace

AtomicOutput::AtomicOutput(std::string finalPath)
  : m_FinalPath(std::move(finalPath))
{
  namespace fs = std::filesystem;
  if (IsURIName(m_FinalPath))
  {
    m_TemporaryPath = m_FinalPath;
    m_Direct = true;
    return;
  }
  const fs::path path(m_FinalPath);
  if (path.filename().empty())
  {
    throw InputError("output path \"" + m_FinalPath + "\" names no file");
  }
  const fs::path  folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code error;
  if (!fs::is_directory(folder, error))
  {
    throw InputError("output " + m_FinalPath + ": the folder " + folder.string() + " does not exist");
  }
  static std::atomic<unsigned> counter{ 0 };
  const std::string            stem =
    path.filename().string().substr(0, path.filename().string().size() - FullExtension(path).size());
  m_TemporaryPath = (folder / ("." + stem + ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) +
                               FullExtension(path)))
                      .string();
}

AtomicOutput::~AtomicOutput()
{
  if (!m_Committed && !m_Direct)
  {
    std::remove(m_TemporaryPath.c_str());
  }
}

void
AtomicOutput::Commit()
{
  if (m_Direct)
  {
    m_Committed = true;
    return;
  }
  if (std::rename(m_TemporaryPath.c_str(), m_FinalPath.c_str()) != 0)
  {
    const std::string reason = std::strerror(errno);
    std::remove(m_TemporaryPath.c_str());
    throw InputError("output " + m_FinalPath + ": could not be written (" + reason + ")");
  }
  m_Committed = true;
}
} // namespace vr
