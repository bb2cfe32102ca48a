// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrStagedOutputs.h"

#include "vrInputError.h"
#include "vrText.h"
#include "vrURINames.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace vr
{
namespace
{
namespace fs = std::filesystem;

/** The on-disk layout of one staging folder. */
constexpr const char * StagingPrefix = ".vr-staging-";
constexpr const char * LockName = "lock";
constexpr const char * FilesName = "files";
constexpr const char * JournalName = "journal";
constexpr const char * CommittedName = "committed";
constexpr const char * JournalHeader = "vr-staging 1";
/** A staging folder without a lock file is one a run is creating or removing this very moment, or one whose run died
 * doing so: its name carries the creator's process id, ".vr-staging-<pid>-XXXXXX", to tell the two apart. */
bool
CreatorIsDead(const fs::path & staging)
{
  const std::string name = staging.filename().string().substr(std::strlen(StagingPrefix));
  long long         pid = 0;
  if (!ParseWholeInteger(name.substr(0, name.find('-')), pid) || pid <= 0)
  {
    return false;
  }
  return ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH;
}

std::string
ErrnoText()
{
  return std::strerror(errno);
}

/** Flushes a file or folder to disk; false (errno set) on failure. */
bool
SyncPath(const std::string & path, bool folder)
{
  const int descriptor = ::open(path.c_str(), (folder ? O_RDONLY | O_DIRECTORY : O_RDONLY) | O_CLOEXEC);
  if (descriptor < 0)
  {
    return false;
  }
  const bool synced = ::fsync(descriptor) == 0 || errno == EINVAL; // EINVAL: a file system without fsync
  ::close(descriptor);
  return synced;
}

/** Writes \a text to \a path atomically: a temporary beside it, flushed, renamed onto it, the folder flushed. */
bool
WriteFileAtomically(const std::string & path, const std::string & text)
{
  const std::string temporary = path + ".tmp";
  {
    std::ofstream output(temporary, std::ios::binary | std::ios::trunc);
    output << text;
    output.close();
    if (!output)
    {
      return false;
    }
  }
  return SyncPath(temporary, false) && std::rename(temporary.c_str(), path.c_str()) == 0 &&
         SyncPath(fs::path(path).parent_path().string(), true);
}

/** Takes the staging folder's lock without waiting. \return the descriptor, or -1 when a live run holds it (or it
 * cannot be opened). */
int
TryLock(const fs::path & staging)
{
  const int descriptor = ::open((staging / LockName).c_str(), O_RDWR | O_CLOEXEC);
  if (descriptor < 0)
  {
    return -1;
  }
  if (::flock(descriptor, LOCK_EX | LOCK_NB) != 0)
  {
    ::close(descriptor);
    return -1;
  }
  return descriptor;
}

struct Journal
{
  std::string              Primary;
  std::vector<std::string> Members;
  std::vector<std::string> Files;
};

std::string
JournalText(const Journal & journal)
{
  std::ostringstream text;
  text << JournalHeader << '\n' << "primary " << journal.Primary << '\n';
  for (const auto & member : journal.Members)
  {
    text << "member " << member << '\n';
  }
  for (const auto & file : journal.Files)
  {
    text << "file " << file << '\n';
  }
  text << "end\n";
  return text.str();
}

/** Reads a staging folder's journal; false when it is missing or incomplete (the run died before its commit). */
bool
ReadJournal(const fs::path & staging, Journal & journal)
{
  std::ifstream input(staging / JournalName, std::ios::binary);
  std::string   line;
  if (!input || !std::getline(input, line) || line != JournalHeader)
  {
    return false;
  }
  bool ended = false;
  while (std::getline(input, line))
  {
    if (line == "end")
    {
      ended = true;
      break;
    }
    const auto space = line.find(' ');
    if (space == std::string::npos)
    {
      return false;
    }
    const std::string key = line.substr(0, space);
    const std::string value = line.substr(space + 1);
    if (key == "primary")
    {
      journal.Primary = value;
    }
    else if (key == "member")
    {
      journal.Members.push_back(value);
    }
    else if (key == "file" && value.find('/') == std::string::npos && value != "." && value != "..")
    {
      journal.Files.push_back(value);
    }
    else
    {
      return false;
    }
  }
  return ended && !journal.Primary.empty();
}

/** Moves the staged files still in \a staging onto their final names in its output folder, then removes it.
 * Files already moved (an interrupted earlier publish) are skipped. \return false (errno set) on a failed rename. */
bool
PublishStaging(const fs::path & staging, const std::vector<std::string> & files)
{
  const fs::path folder = staging.parent_path();
  for (const auto & name : files)
  {
    const fs::path  staged = staging / FilesName / name;
    std::error_code error;
    if (!fs::exists(fs::symlink_status(staged, error)))
    {
      continue;
    }
    if (std::rename(staged.c_str(), (folder / name).c_str()) != 0)
    {
      return false;
    }
  }
  SyncPath(folder.string(), true);
  std::error_code ignored;
  fs::remove_all(staging, ignored);
  return true;
}

/** Whether \a path names a file in a staging folder's files/ folder: a writer called by StagedOutputs::Write that
 * stages its own output (vr::WriteImage2D and friends use AtomicOutput) then writes it directly, the enclosing
 * staging making it atomic already. */
bool
IsInsideStaging(const std::string & path)
{
  const fs::path folder = fs::absolute(fs::path(path)).lexically_normal().parent_path();
  return folder.filename() == FilesName && folder.parent_path().filename().string().rfind(StagingPrefix, 0) == 0;
}

void
RemoveStaging(const fs::path & staging)
{
  std::error_code ignored;
  fs::remove_all(staging, ignored);
}

/** Recovers the committed or abandoned run whose primary staging folder is \a primary, locked by the caller, as is
 * \a lockedMember when not empty (a member whose recovery led here: a second flock on it would fail). */
void
RecoverRun(const fs::path & primary, const Journal & journal, bool committed, const fs::path & lockedMember = {})
{
  for (const auto & member : journal.Members)
  {
    const fs::path memberPath(member);
    if (memberPath == primary)
    {
      continue;
    }
    const int lock = memberPath == lockedMember ? -2 : TryLock(memberPath);
    if (lock == -1)
    {
      continue; // gone already, or another run is recovering it
    }
    Journal memberJournal;
    if (committed && ReadJournal(memberPath, memberJournal))
    {
      PublishStaging(memberPath, memberJournal.Files);
    }
    else
    {
      RemoveStaging(memberPath);
    }
    if (lock >= 0)
    {
      ::close(lock);
    }
  }
  if (committed)
  {
    PublishStaging(primary, journal.Files);
  }
  else
  {
    RemoveStaging(primary);
  }
}

/** Recovers one stale staging folder, already locked by the caller. */
void
RecoverLockedStaging(const fs::path & staging)
{
  Journal journal;
  if (!ReadJournal(staging, journal))
  {
    RemoveStaging(staging); // died before its commit: nothing of it was published
    return;
  }
  const fs::path primary(journal.Primary);
  if (primary == staging)
  {
    std::error_code error;
    RecoverRun(staging, journal, fs::exists(staging / CommittedName, error));
    return;
  }
  // A member: its run's fate is decided by the primary staging folder.
  std::error_code error;
  if (!fs::exists(primary, error))
  {
    // A primary is removed only after all its members were published, or when it was never committed.
    RemoveStaging(staging);
    return;
  }
  const int primaryLock = TryLock(primary);
  if (primaryLock < 0)
  {
    return; // another run is recovering it (and this member with it)
  }
  Journal primaryJournal;
  if (ReadJournal(primary, primaryJournal) && fs::exists(primary / CommittedName, error))
  {
    RecoverRun(primary, primaryJournal, true, staging);
  }
  else
  {
    RemoveStaging(staging);
    Journal uncommitted;
    uncommitted.Members = primaryJournal.Members;
    RecoverRun(primary, uncommitted, false, staging);
  }
  ::close(primaryLock);
  if (fs::exists(staging, error))
  {
    RemoveStaging(staging); // not listed by its primary: it cannot be published
  }
}
} // namespace

std::size_t
StagedOutputs::RecoverStaleStaging(const std::string & folder)
{
  std::size_t            handled = 0;
  std::error_code        error;
  fs::directory_iterator entries(folder, error);
  if (error)
  {
    return 0;
  }
  std::vector<fs::path> candidates;
  for (const auto & entry : entries)
  {
    if (entry.path().filename().string().rfind(StagingPrefix, 0) == 0 && entry.is_directory(error))
    {
      candidates.push_back(fs::absolute(entry.path()).lexically_normal());
    }
  }
  for (const auto & staging : candidates)
  {
    if (!fs::exists(staging, error))
    {
      continue; // recovered with its primary a moment ago
    }
    const int lock = TryLock(staging);
    if (lock < 0)
    {
      if (fs::exists(staging / LockName, error) || !fs::exists(staging, error))
      {
        continue; // a live run's
      }
      // No lock file: killed while it created or removed the folder (never while it held outputs to publish).
      if (CreatorIsDead(staging))
      {
        RemoveStaging(staging);
        ++handled;
      }
      continue;
    }
    RecoverLockedStaging(staging);
    ::close(lock);
    ++handled;
  }
  return handled;
}

StagedOutputs::StagedOutputs() = default;

StagedOutputs::~StagedOutputs()
{
  if (!m_Committed)
  {
    Discard();
  }
  for (auto & folder : m_Folders)
  {
    if (folder.LockDescriptor >= 0)
    {
      ::close(folder.LockDescriptor);
    }
  }
}

void
StagedOutputs::Discard()
{
  for (auto & folder : m_Folders)
  {
    RemoveStaging(folder.Staging);
  }
}

std::size_t
StagedOutputs::FolderFor(const std::string & outputFolder, const std::string & what)
{
  for (std::size_t k = 0; k < m_Folders.size(); ++k)
  {
    if (m_Folders[k].OutputFolder == outputFolder)
    {
      return k;
    }
  }
  RecoverStaleStaging(outputFolder);
  std::string pattern =
    (fs::path(outputFolder) / (std::string(StagingPrefix) + std::to_string(::getpid()) + "-XXXXXX")).string();
  if (::mkdtemp(pattern.data()) == nullptr)
  {
    throw InputError(what + ": the folder " + outputFolder + " cannot be written (" + ErrnoText() + ")");
  }
  Folder folder;
  folder.OutputFolder = outputFolder;
  folder.Staging = pattern;
  folder.LockDescriptor = ::open((fs::path(pattern) / LockName).c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  const bool locked = folder.LockDescriptor >= 0 && ::flock(folder.LockDescriptor, LOCK_EX | LOCK_NB) == 0;
  const bool made = locked && ::mkdir((fs::path(pattern) / FilesName).c_str(), 0700) == 0;
  if (!made)
  {
    const std::string reason = ErrnoText();
    if (folder.LockDescriptor >= 0)
    {
      ::close(folder.LockDescriptor);
    }
    RemoveStaging(pattern);
    throw InputError(what + ": the folder " + outputFolder + " cannot be written (" + reason + ")");
  }
  m_Folders.push_back(folder);
  return m_Folders.size() - 1;
}

std::size_t
StagedOutputs::Add(const std::string & path, const std::string & flag)
{
  if (m_Committed)
  {
    throw std::logic_error("StagedOutputs::Add after CommitAll");
  }
  const std::string what = flag + " " + path;
  if (path.empty())
  {
    throw InputError(flag + ": the file name is empty");
  }
  Entry entry;
  entry.Flag = flag;
  if (IsURIName(path) || IsInsideStaging(path))
  {
    entry.FinalPath = path;
    entry.StagedPath = path;
  }
  else
  {
    const fs::path wanted = fs::absolute(fs::path(path)).lexically_normal();
    if (wanted.filename().empty() || wanted.filename() == "." || wanted.filename() == "..")
    {
      throw InputError(what + ": names no file");
    }
    entry.FinalPath = wanted.string();
    std::error_code       error;
    const fs::path        folder = wanted.parent_path();
    const fs::file_status status = fs::status(wanted, error);
    if (fs::is_directory(status))
    {
      throw InputError(what + ": is a folder; name a file");
    }
    if (fs::exists(status) && !fs::is_regular_file(status))
    {
      throw InputError(what + ": exists and is not a regular file (a device, pipe or socket); name a file");
    }
    if (!fs::is_directory(folder, error))
    {
      throw InputError(what + ": the folder " + folder.string() + " does not exist");
    }
    entry.Folder = static_cast<long>(FolderFor(folder.string(), what));
    entry.StagedPath = (fs::path(m_Folders[entry.Folder].Staging) / FilesName / wanted.filename()).string();
  }
  for (const auto & other : m_Entries)
  {
    if (other.FinalPath == entry.FinalPath)
    {
      throw InputError(what + ": " + other.Flag + " already writes this file");
    }
  }
  if (entry.Folder >= 0)
  {
    m_Folders[entry.Folder].FileNames.push_back(fs::path(entry.FinalPath).filename().string());
  }
  m_Entries.push_back(entry);
  return m_Entries.size() - 1;
}

const std::string &
StagedOutputs::StagedPath(std::size_t handle) const
{
  return m_Entries.at(handle).StagedPath;
}

void
StagedOutputs::Write(std::size_t handle, const std::function<void(const std::string & stagedPath)> & writer)
{
  const Entry &       entry = m_Entries.at(handle);
  const std::string & staged = entry.StagedPath;
  try
  {
    writer(staged);
  }
  catch (const InputError & problem)
  {
    // The user never named the staged file: speak of the file they asked for.
    std::string message = problem.what();
    if (staged != entry.FinalPath)
    {
      for (auto at = message.find(staged); at != std::string::npos; at = message.find(staged, at))
      {
        message.replace(at, staged.size(), entry.FinalPath);
        at += entry.FinalPath.size();
      }
    }
    throw InputError(entry.Flag + ": " + message);
  }
}

void
StagedOutputs::CommitAll()
{
  if (m_Committed || m_Folders.empty())
  {
    m_Committed = true;
    return;
  }
  // 1. Every staged file on disk, and a journal in every staging folder.
  Journal journal;
  journal.Primary = m_Folders.front().Staging;
  for (const auto & folder : m_Folders)
  {
    journal.Members.push_back(folder.Staging);
  }
  for (const auto & entry : m_Entries)
  {
    if (entry.Folder < 0)
    {
      continue;
    }
    std::error_code error;
    if (!fs::is_regular_file(entry.StagedPath, error))
    {
      throw InputError(entry.Flag + " " + entry.FinalPath + ": was not written");
    }
    if (!SyncPath(entry.StagedPath, false))
    {
      throw InputError(entry.Flag + " " + entry.FinalPath + ": could not be written to disk (" + ErrnoText() + ")");
    }
  }
  for (const auto & folder : m_Folders)
  {
    journal.Files = folder.FileNames;
    if (!SyncPath((fs::path(folder.Staging) / FilesName).string(), true) ||
        !WriteFileAtomically((fs::path(folder.Staging) / JournalName).string(), JournalText(journal)))
    {
      throw InputError("outputs in " + folder.OutputFolder + ": could not be written (" + ErrnoText() + ")");
    }
  }
  // 2. The commit point.
  if (!WriteFileAtomically((fs::path(m_Folders.front().Staging) / CommittedName).string(), "committed\n"))
  {
    throw InputError("outputs in " + m_Folders.front().OutputFolder + ": could not be written (" + ErrnoText() + ")");
  }
  m_Committed = true;
  // 3. Publish, the primary last: until it is gone, its marker says the run is to be rolled forward.
  for (std::size_t k = 1; k <= m_Folders.size(); ++k)
  {
    const Folder & folder = m_Folders[k % m_Folders.size()]; // members 1..n-1 first, then the primary, 0
    if (!PublishStaging(folder.Staging, folder.FileNames))
    {
      throw InputError("outputs in " + folder.OutputFolder + ": could not be moved into place (" + ErrnoText() +
                       "); the next run that writes there completes it");
    }
  }
}
} // namespace vr
