// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrNrrdRawVoxels.h"

#include "vrInputError.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <sstream>

namespace vr::detail
{
namespace
{
/** Closes a descriptor with its scope. */
class Descriptor
{
public:
  explicit Descriptor(int descriptor)
    : m_Descriptor(descriptor)
  {
  }
  ~Descriptor()
  {
    if (m_Descriptor >= 0)
    {
      ::close(m_Descriptor);
    }
  }
  Descriptor(const Descriptor &) = delete;
  Descriptor &
  operator=(const Descriptor &) = delete;
  int
  Get() const
  {
    return m_Descriptor;
  }

private:
  int m_Descriptor;
};

/** The header's text up to and including the blank line that ends it; empty when there is none within the first
 * \a limit bytes (or the file cannot be read). */
std::string
HeaderText(int descriptor, std::size_t limit)
{
  std::string text;
  char        chunk[8192];
  while (text.size() < limit)
  {
    const ssize_t count = ::pread(descriptor, chunk, sizeof(chunk), static_cast<off_t>(text.size()));
    if (count <= 0)
    {
      return std::string();
    }
    const std::size_t searchFrom = text.size() > 0 ? text.size() - 1 : 0;
    text.append(chunk, static_cast<std::size_t>(count));
    const auto end = text.find("\n\n", searchFrom);
    if (end != std::string::npos)
    {
      return text.substr(0, end + 2);
    }
  }
  return std::string();
}
} // namespace

std::optional<std::uint64_t>
RawNrrdVoxelOffset(const std::string & path, std::uint64_t voxelBytes, std::size_t pixelBytes)
{
  const Descriptor file(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
  struct stat      status
  {
  };
  if (file.Get() < 0 || ::fstat(file.Get(), &status) != 0 || !S_ISREG(status.st_mode))
  {
    return std::nullopt;
  }
  // Headers are a few hundred bytes; one with a megabyte of comments is left to ITK.
  const std::string header = HeaderText(file.Get(), std::size_t{ 1 } << 20);
  if (header.rfind("NRRD000", 0) != 0 || header.find('\r') != std::string::npos)
  {
    return std::nullopt;
  }
  std::istringstream lines(header);
  std::string        line;
  std::getline(lines, line); // the magic
  bool        raw = false;
  std::string endian;
  while (std::getline(lines, line) && !line.empty())
  {
    if (line[0] == '#' || line.find(":=") != std::string::npos)
    {
      continue; // a comment, a key/value pair
    }
    const auto colon = line.find(": ");
    if (colon == std::string::npos)
    {
      return std::nullopt;
    }
    const std::string field = line.substr(0, colon);
    std::string       value = line.substr(colon + 2);
    value.erase(value.find_last_not_of(" \t") + 1);
    if (field == "encoding")
    {
      raw = value == "raw";
    }
    else if (field == "endian")
    {
      endian = value;
    }
    else if (field == "data file" || field == "datafile" || field == "line skip" || field == "lineskip" ||
             field == "byte skip" || field == "byteskip")
    {
      return std::nullopt;
    }
  }
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
  const bool machineOrder = pixelBytes == 1 || endian == "little";
#else
  const bool machineOrder = pixelBytes == 1 || endian == "big";
#endif
  const std::uint64_t offset = header.size();
  if (!raw || !machineOrder || static_cast<std::uint64_t>(status.st_size) != offset + voxelBytes)
  {
    return std::nullopt;
  }
  return offset;
}

void
ReadRawVoxels(const std::string & path,
              std::uint64_t       offset,
              void *              buffer,
              std::uint64_t       bytes,
              const std::string & where)
{
  const Descriptor file(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
  if (file.Get() < 0)
  {
    throw InputError(where + ": the voxel data cannot be read: " + std::strerror(errno));
  }
  auto *        target = static_cast<char *>(buffer);
  std::uint64_t done = 0;
  while (done < bytes)
  {
    // Pieces of at most 1 GiB: one read returns at most about 2 GiB on Linux.
    const std::size_t piece = static_cast<std::size_t>(std::min<std::uint64_t>(bytes - done, std::uint64_t{ 1 } << 30));
    const ssize_t     count = ::pread(file.Get(), target + done, piece, static_cast<off_t>(offset + done));
    if (count < 0 && errno == EINTR)
    {
      continue;
    }
    if (count <= 0)
    {
      throw InputError(where + ": the voxel data cannot be read (truncated?): " + std::to_string(done) + " of " +
                       std::to_string(bytes) + " bytes read" +
                       (count < 0 ? std::string(": ") + std::strerror(errno) : std::string()));
    }
    done += static_cast<std::uint64_t>(count);
  }
}
} // namespace vr::detail
