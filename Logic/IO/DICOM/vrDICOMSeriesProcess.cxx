// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrDICOMSeriesProcess.h"

#include "itkMetaDataObject.h"

#include "vrDICOMMappedVolume.h"
#include "vrDICOMReaderReport.h"
#include "vrDICOMSeriesChoice.h"
#include "vrDICOMVolumeHandOver.h"
#include "vrInputError.h"

#include <dlfcn.h>
#include <fcntl.h>
#include <spawn.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <thread>
#include <vector>

extern char ** environ;

namespace vr::detail
{
namespace fs = std::filesystem;

namespace
{
constexpr const char * HelperName = "vrReadDICOMSeries";

bool
IsExecutable(const fs::path & path)
{
  std::error_code error;
  return fs::is_regular_file(path, error) && ::access(path.c_str(), X_OK) == 0;
}

/** A private folder under the system's temporary folder, removed with everything in it. */
class TemporaryFolder
{
public:
  TemporaryFolder()
  {
    std::error_code error;
    std::string     pattern = (fs::temp_directory_path(error) / "vr-dicom-XXXXXX").string();
    if (::mkdtemp(pattern.data()) != nullptr)
    {
      m_Path = pattern;
    }
  }
  ~TemporaryFolder()
  {
    if (!m_Path.empty())
    {
      std::error_code error;
      fs::remove_all(m_Path, error);
    }
  }
  TemporaryFolder(const TemporaryFolder &) = delete;
  TemporaryFolder &
  operator=(const TemporaryFolder &) = delete;

  const fs::path &
  Path() const
  {
    return m_Path;
  }

private:
  fs::path m_Path;
};

std::vector<std::string>
Lines(const fs::path & path)
{
  std::ifstream            file(path);
  std::vector<std::string> lines;
  std::string              line;
  while (std::getline(file, line))
  {
    lines.push_back(line);
  }
  return lines;
}

/** glibc's "prog: /build/gdcm/Source/gdcmPixelFormat.h:94: ...: Assertion `spp <= 4' failed." as
 * "gdcmPixelFormat.h:94: assertion `spp <= 4' failed"; empty when the child printed no assertion. */
std::string
AssertionText(const fs::path & messages)
{
  for (const std::string & line : Lines(messages))
  {
    const auto assertion = line.find("Assertion `");
    if (assertion == std::string::npos)
    {
      continue;
    }
    std::string expression = line.substr(assertion + 11);
    expression = expression.substr(0, expression.find("' failed"));
    // The source file and line: the field before the function's, after the program's name.
    std::string where;
    const auto  first = line.find(": ");
    if (first != std::string::npos)
    {
      const auto second = line.find(": ", first + 2);
      if (second != std::string::npos && second < assertion)
      {
        where = fs::path(line.substr(first + 2, second - first - 2)).filename().string() + ": ";
      }
    }
    return where + "assertion `" + expression + "' failed";
  }
  return std::string();
}

std::string
SignalName(int signal)
{
  switch (signal)
  {
    case SIGABRT:
      return "SIGABRT, an assertion or abort";
    case SIGSEGV:
      return "SIGSEGV, a crash";
    case SIGBUS:
      return "SIGBUS, a crash";
    case SIGFPE:
      return "SIGFPE, a crash";
    case SIGILL:
      return "SIGILL, a crash";
    case SIGKILL:
      return "SIGKILL, killed (out of memory?)";
    default:
      return "signal " + std::to_string(signal);
  }
}

/** Runs \a helper with \a arguments, its standard output and error into \a messages and \a handOver at
 * DICOMVolumeHandOverDescriptor; returns waitpid's status, or
 * -1 (errno kept in \a spawnError) when it could not be started. A helper still running after \a timeoutSeconds is
 * killed (SIGKILL) and \a timedOut set. */
int
RunHelper(const std::string &              helper,
          const std::vector<std::string> & arguments,
          const fs::path &                 messages,
          int                              handOver,
          double                           timeoutSeconds,
          int &                            spawnError,
          bool &                           timedOut)
{
  timedOut = false;
  std::vector<char *> argv;
  argv.push_back(const_cast<char *>(helper.c_str()));
  for (const std::string & argument : arguments)
  {
    argv.push_back(const_cast<char *>(argument.c_str()));
  }
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, messages.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_adddup2(&actions, 1, 2);
  // The hand-over file at the descriptor the child expects (dup2 clears close-on-exec on the copy).
  posix_spawn_file_actions_adddup2(&actions, handOver, DICOMVolumeHandOverDescriptor);
  pid_t child = -1;
  spawnError = ::posix_spawn(&child, helper.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawnError != 0)
  {
    return -1;
  }
  // Polled rather than waited for, so that a hang (GDCM in a loop on a corrupt length, a stalled network folder) ends
  // at the bound: after 1 ms at first, doubling to every 50 ms, so that a quick read is not slowed down.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeoutSeconds);
  auto       pause = std::chrono::milliseconds(1);
  int        status = 0;
  for (;;)
  {
    const pid_t done = ::waitpid(child, &status, WNOHANG);
    if (done == child)
    {
      return status;
    }
    if (done < 0 && errno != EINTR)
    {
      spawnError = errno;
      return -1;
    }
    if (std::chrono::steady_clock::now() >= deadline)
    {
      timedOut = true;
      ::kill(child, SIGKILL);
      while (::waitpid(child, &status, 0) < 0 && errno == EINTR)
      {
      }
      return status;
    }
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::milliseconds(50));
  }
}

/** The regular files directly in \a folder, as the helper lists them. */
std::size_t
CountFiles(const std::string & folder)
{
  std::size_t     count = 0;
  std::error_code error;
  for (const auto & entry : fs::directory_iterator(folder, error))
  {
    if (entry.is_regular_file(error))
    {
      ++count;
    }
  }
  return count;
}

/** The file the reader process writes the voxels into, open in this process: a memfd (anonymous memory, gone with
 * its last descriptor and mapping, so that nothing is left behind whatever ends either process), else an unnamed file
 * in the private scratch folder (O_TMPFILE) for a system without memfd. Closed with this object. */
class HandOverFile
{
public:
  explicit HandOverFile(const fs::path & scratch)
  {
    m_Descriptor = ::memfd_create("vrReadDICOMSeries volume", MFD_CLOEXEC | MFD_ALLOW_SEALING);
    if (m_Descriptor < 0)
    {
      m_Descriptor = ::open(scratch.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
    }
  }
  ~HandOverFile()
  {
    if (m_Descriptor >= 0)
    {
      ::close(m_Descriptor);
    }
  }
  HandOverFile(const HandOverFile &) = delete;
  HandOverFile &
  operator=(const HandOverFile &) = delete;

  int
  Descriptor() const
  {
    return m_Descriptor;
  }

private:
  int m_Descriptor{ -1 };
};
} // namespace

double
DICOMSeriesTimeoutSeconds(std::size_t fileCount)
{
  if (const char * configured = std::getenv("VR_DICOM_SERIES_TIMEOUT"))
  {
    char *       end = nullptr;
    const double seconds = std::strtod(configured, &end);
    if (end == configured || *end != '\0' || !std::isfinite(seconds) || seconds <= 0.0)
    {
      throw InputError("VR_DICOM_SERIES_TIMEOUT is \"" + std::string(configured) +
                       "\"; it must be a positive number of seconds (the bound on reading a DICOM series)");
    }
    return seconds;
  }
  return 60.0 + 0.25 * static_cast<double>(fileCount);
}

std::string
DICOMSeriesReaderPath()
{
  if (const char * configured = std::getenv("VR_DICOM_SERIES_READER"))
  {
    return IsExecutable(configured) ? std::string(configured) : std::string();
  }
  std::vector<fs::path> bases;
  Dl_info               info{};
  if (::dladdr(reinterpret_cast<void *>(&DICOMSeriesReaderPath), &info) != 0 && info.dli_fname != nullptr)
  {
    std::error_code error;
    bases.push_back(fs::canonical(info.dli_fname, error).parent_path());
  }
  std::error_code error;
  const fs::path  executable = fs::read_symlink("/proc/self/exe", error);
  if (!error)
  {
    bases.push_back(executable.parent_path());
  }
  for (const fs::path & base : bases)
  {
    for (const fs::path & candidate : { base / HelperName,
                                        base / "../libexec/VesselReformation" / HelperName,
                                        base / "../../../libexec/VesselReformation" / HelperName })
    {
      if (IsExecutable(candidate))
      {
        return candidate.lexically_normal().string();
      }
    }
  }
  for (const char * compiledIn : { VR_DICOM_SERIES_READER_BUILD_PATH, VR_DICOM_SERIES_READER_INSTALL_PATH })
  {
    if (IsExecutable(compiledIn))
    {
      return compiledIn;
    }
  }
  return std::string();
}

DICOMSeriesRead
ReadDICOMSeriesInChildProcess(const std::string & folder, const std::string & series, const std::string & where)
{
  const std::string helper = DICOMSeriesReaderPath();
  if (helper.empty())
  {
    throw InputError(where + ": cannot read DICOM: the reader process " + std::string(HelperName) +
                     " was not found (is the installation complete? VR_DICOM_SERIES_READER may name it)");
  }
  const TemporaryFolder scratch;
  if (scratch.Path().empty())
  {
    throw InputError(where + ": cannot read DICOM: no temporary folder could be made for the reader process");
  }
  const HandOverFile handOver(scratch.Path());
  if (handOver.Descriptor() < 0)
  {
    throw InputError(where +
                     ": cannot read DICOM: no file could be made for the reader process to hand the volume "
                     "over in (" +
                     std::strerror(errno) + ")");
  }
  const fs::path    report = scratch.Path() / "report.txt";
  const fs::path    messages = scratch.Path() / "messages.txt";
  const std::size_t fileCount = CountFiles(folder);
  double            timeout = 0.0;
  try
  {
    timeout = DICOMSeriesTimeoutSeconds(fileCount);
  }
  catch (const InputError & error)
  {
    throw InputError(where + ": " + error.what());
  }
  std::vector<std::string> arguments{ folder, std::to_string(DICOMVolumeHandOverDescriptor), report.string() };
  if (!series.empty())
  {
    arguments.push_back(series);
  }
  int       spawnError = 0;
  bool      timedOut = false;
  const int status = RunHelper(helper, arguments, messages, handOver.Descriptor(), timeout, spawnError, timedOut);
  if (status < 0)
  {
    throw InputError(where + ": cannot start the DICOM reader process " + helper + ": " + std::strerror(spawnError));
  }

  // The report, line by line (vrDICOMReaderReport.h).
  const std::vector<std::string>                   lines = Lines(report);
  DICOMSeriesRead                                  read;
  std::vector<DICOMSeriesSummary>                  listed;
  std::vector<std::pair<std::string, std::string>> identity;
  std::string                                      lastFile;
  std::string step = "starting"; // what the child was doing when it stopped, if not a file
  std::string errorKind;
  std::string errorText;
  auto        after = [](const std::string & line, const char * word) -> std::optional<std::string>
  {
    const std::string prefix = std::string(word) + " ";
    return line.rfind(prefix, 0) == 0 ? std::optional<std::string>(line.substr(prefix.size())) : std::nullopt;
  };
  for (std::size_t k = 0; k < lines.size(); ++k)
  {
    if (const auto file = after(lines[k], "file"))
    {
      lastFile = *file;
      step.clear();
    }
    else if (const auto next = after(lines[k], "step"))
    {
      step = *next == "choose"   ? "sorting the folder's files into series"
             : *next == "write"  ? "handing the series it read over"
             : *next == "decode" ? "placing the series' slices"
                                 : "examining the folder";
    }
    else if (const auto warning = after(lines[k], "warning"))
    {
      read.Warnings.push_back(where + ": " + *warning);
    }
    else if (const auto note = after(lines[k], "note"))
    {
      read.Notes.push_back(where + ": " + *note);
    }
    else if (const auto line = after(lines[k], "series"))
    {
      if (const auto summary = ParseSeriesReportLine(*line))
      {
        listed.push_back(*summary);
      }
    }
    else if (const auto pair = after(lines[k], "identity"))
    {
      const auto tab = pair->find('\t');
      if (tab != std::string::npos)
      {
        identity.emplace_back(pair->substr(0, tab), pair->substr(tab + 1));
      }
    }
    else if (const auto kind = after(lines[k], "error"))
    {
      errorKind = *kind;
      for (std::size_t m = k + 1; m < lines.size(); ++m)
      {
        errorText += (m == k + 1 ? "" : " ") + lines[m];
      }
      break;
    }
  }
  if (timedOut)
  {
    std::ostringstream bound;
    bound << timeout << " s";
    const std::string doing = step.empty() ? "reading the file " + lastFile : step;
    throw InputError(where + ": the DICOM reader process did not finish within " + bound.str() + " (for " +
                     std::to_string(fileCount) + (fileCount == 1 ? " file" : " files") +
                     "; VR_DICOM_SERIES_TIMEOUT may set another bound) and was stopped while " + doing +
                     "; the series is not read");
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 1 && !errorKind.empty())
  {
    if (errorKind == "choose" || errorKind == "choice")
    {
      std::string list;
      for (const DICOMSeriesSummary & summary : listed)
      {
        list += "\n  " + DescribeDICOMSeries(summary);
      }
      const std::string why = errorKind == "choose" ? "holds " + std::to_string(listed.size()) +
                                                        " DICOM series; choose one, by its number or its Series "
                                                        "Instance UID (nothing was read)"
                                                    : errorText;
      throw DICOMSeriesChoiceRequired(where + ": " + why + ":" + list, listed);
    }
    if (errorKind == "write")
    {
      throw InputError(where + ": the DICOM series was read but could not be handed over: " + errorText);
    }
    throw InputError(where + ": " + errorText);
  }
  if (!(WIFEXITED(status) && WEXITSTATUS(status) == 0))
  {
    const std::string assertion = AssertionText(messages);
    const std::string how =
      WIFSIGNALED(status) ? SignalName(WTERMSIG(status)) : "exit status " + std::to_string(WEXITSTATUS(status));
    const std::string detail = " (" + how + (assertion.empty() ? std::string() : "; " + assertion) + ")";
    if (step.empty())
    {
      throw InputError(where + ": the DICOM file " + lastFile + " is corrupt: GDCM's reader died reading it" + detail +
                       "; the series is not read: remove or replace that file");
    }
    // Not at a file: the process itself died (killed, out of memory, a fault outside GDCM's reading of a file).
    throw InputError(where + ": the DICOM reader process died " + step + detail + "; the series is not read");
  }
  read.Volume = ReceiveDICOMVolume(handOver.Descriptor(), where);
  for (const auto & [key, value] : identity)
  {
    if (key.rfind("DICOM.", 0) == 0)
    {
      itk::EncapsulateMetaData<std::string>(read.Volume.Image->GetMetaDataDictionary(), key, value);
    }
  }
  return read;
}
} // namespace vr::detail
