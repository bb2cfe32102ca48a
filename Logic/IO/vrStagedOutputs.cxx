// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrStagedOutputs.h"

#include "vrInputError.h"

#include <filesystem>

namespace vr
{
std::size_t
StagedOutputs::Add(const std::string & path, const std::string & flag)
{
  namespace fs = std::filesystem;
  const fs::path wanted = fs::absolute(fs::path(path)).lexically_normal();
  for (const auto & entry : m_Entries)
  {
    if (fs::absolute(fs::path(entry.Output->FinalPath())).lexically_normal() == wanted)
    {
      throw InputError(flag + " " + path + ": " + entry.Flag + " already writes this file");
    }
  }
  std::error_code error;
  if (fs::is_directory(wanted, error))
  {
    throw InputError(flag + " " + path + ": is a folder; name a file");
  }
  try
  {
    m_Entries.push_back(Entry{ flag, std::make_unique<AtomicOutput>(path) });
  }
  catch (const InputError & problem)
  {
    throw InputError(flag + " " + problem.what());
  }
  return m_Entries.size() - 1;
}

void
StagedOutputs::Write(std::size_t handle, const std::function<void(const std::string & temporaryPath)> & writer)
{
  const Entry &       entry = m_Entries.at(handle);
  const std::string & temporary = entry.Output->TemporaryPath();
  try
  {
    writer(temporary);
  }
  catch (const InputError & problem)
  {
    // The user never named the temporary file: speak of the file they asked for.
    std::string message = problem.what();
    for (auto at = message.find(temporary); at != std::string::npos; at = message.find(temporary, at))
    {
      message.replace(at, temporary.size(), entry.Output->FinalPath());
      at += entry.Output->FinalPath().size();
    }
    throw InputError(entry.Flag + ": " + message);
  }
}

void
StagedOutputs::CommitAll()
{
  for (auto & entry : m_Entries)
  {
    entry.Output->Commit();
  }
}
} // namespace vr
