#include "vrStagedOutputs.h"

#include "vrInputError.h"

#include <filesystem>

namespace vr
{
const std::string &
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
  return m_Entries.back().Output->TemporaryPath();
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
