// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrInputFileChecks.h"

#include "vrInputError.h"
#include "vrText.h"

#include <filesystem>
#include <fstream>

namespace vr::detail
{
namespace fs = std::filesystem;

InputKind
CheckInputPath(const std::string & path, const std::string & role, bool folderAllowed)
{
  const std::string     where = role + " " + path;
  std::error_code       error;
  const fs::file_status status = fs::status(path, error);
  if (!fs::exists(status))
  {
    throw InputError(where + ": no such file" + (folderAllowed ? std::string(" or folder") : std::string()));
  }
  if (fs::is_directory(status))
  {
    if (folderAllowed)
    {
      return InputKind::Folder;
    }
    throw InputError(where + ": is a folder, not a file");
  }
  if (!fs::is_regular_file(status))
  {
    const char * kind = fs::is_fifo(status)                                          ? "a named pipe (FIFO)"
                        : fs::is_character_file(status) || fs::is_block_file(status) ? "a device"
                        : fs::is_socket(status)                                      ? "a socket"
                                                                                     : "not a regular file";
    throw InputError(where + ": is " + std::string(kind) + "; give a regular file");
  }
  if (fs::file_size(path, error) == 0 && !error)
  {
    throw InputError(where + ": is empty");
  }
  return InputKind::RegularFile;
}

std::uintmax_t
InputFileSize(const std::string & path)
{
  std::error_code error;
  const auto      size = fs::file_size(path, error);
  return error ? 0 : size;
}

std::vector<std::string>
DetachedDataFiles(const std::string & headerPath)
{
  std::vector<std::string> files;
  std::ifstream            input(headerPath, std::ios::binary);
  std::string              header(64 * 1024, '\0');
  input.read(header.data(), static_cast<std::streamsize>(header.size()));
  header.resize(static_cast<std::size_t>(input.gcount()));
  const fs::path folder = fs::path(headerPath).parent_path();
  std::size_t    start = 0;
  while (start < header.size())
  {
    auto end = header.find('\n', start);
    if (end == std::string::npos)
    {
      end = header.size();
    }
    const std::string line = Trim(header.substr(start, end - start));
    start = end + 1;
    std::string name;
    const auto  equals = line.find('=');
    const auto  colon = line.find(':');
    if (equals != std::string::npos && Trim(line.substr(0, equals)) == "ElementDataFile")
    {
      name = Trim(line.substr(equals + 1));
      if (name == "LOCAL" || name == "Local" || name == "local")
      {
        name.clear();
      }
    }
    else if (colon != std::string::npos)
    {
      const std::string key = ToLower(Trim(line.substr(0, colon)));
      if (key == "data file" || key == "datafile")
      {
        name = Trim(line.substr(colon + 1));
      }
    }
    if (name.empty() || name.rfind("LIST", 0) == 0 || name.find('%') != std::string::npos ||
        name.find(' ') != std::string::npos)
    {
      continue;
    }
    const fs::path file(name);
    files.push_back((file.is_absolute() ? file : folder / file).string());
  }
  return files;
}

std::size_t
JSONNestingDepth(const std::string & path, const std::string & role)
{
  std::ifstream input(path, std::ios::binary);
  if (!input)
  {
    throw InputError(role + " " + path + ": cannot be opened");
  }
  std::size_t depth = 0;
  std::size_t deepest = 0;
  bool        inString = false;
  bool        escaped = false;
  char        buffer[1 << 16];
  while (input)
  {
    input.read(buffer, sizeof(buffer));
    const auto count = static_cast<std::size_t>(input.gcount());
    for (std::size_t k = 0; k < count; ++k)
    {
      const char c = buffer[k];
      if (inString)
      {
        if (escaped)
        {
          escaped = false;
        }
        else if (c == '\\')
        {
          escaped = true;
        }
        else if (c == '"')
        {
          inString = false;
        }
        continue;
      }
      if (c == '"')
      {
        inString = true;
      }
      else if (c == '[' || c == '{')
      {
        ++depth;
        deepest = depth > deepest ? depth : deepest;
      }
      else if ((c == ']' || c == '}') && depth > 0)
      {
        --depth;
      }
    }
  }
  return deepest;
}
void
CheckImageIOIsOneWeRead(const std::string & ioClassName, const std::string & where, bool dicomAllowed)
{
  if (ioClassName == "NrrdImageIO" || ioClassName == "NiftiImageIO" || ioClassName == "MetaImageIO" ||
      (dicomAllowed && ioClassName == "GDCMImageIO"))
  {
    return;
  }
  std::string format = ioClassName;
  const auto  suffix = format.rfind("ImageIO");
  if (suffix != std::string::npos)
  {
    format.erase(suffix);
  }
  throw InputError(where + ": holds a " + format + " image; NRRD, NIfTI or MetaImage" +
                   (dicomAllowed ? std::string(" (or a DICOM series as a folder)") : std::string()) + " is expected");
}
} // namespace vr::detail
