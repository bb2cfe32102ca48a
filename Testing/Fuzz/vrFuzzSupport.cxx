// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrFuzzSupport.h"

#include "vrInputError.h"
#include "vrVolumeIO.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace vr::fuzz
{
namespace
{
class InputFolder
{
public:
  InputFolder()
  {
    const char * base = std::getenv("TMPDIR");
    m_Path = std::filesystem::path(base != nullptr && *base != '\0' ? base : "/tmp") /
             ("vr-fuzz-" + std::to_string(::getpid()));
    std::filesystem::create_directories(m_Path);
  }
  ~InputFolder()
  {
    std::error_code ignored;
    std::filesystem::remove_all(m_Path, ignored);
  }
  InputFolder(const InputFolder &) = delete;
  InputFolder &
  operator=(const InputFolder &) = delete;

  const std::filesystem::path &
  Path() const
  {
    return m_Path;
  }

private:
  std::filesystem::path m_Path;
};

const InputFolder &
TheInputFolder()
{
  static const InputFolder folder;
  return folder;
}
} // namespace

std::string
InputFolder()
{
  return TheInputFolder().Path().string();
}

std::string
WriteInput(const std::uint8_t * data, std::size_t size, const std::string & extension)
{
  const std::string path = (TheInputFolder().Path() / ("input" + extension)).string();
  std::ofstream     output(path, std::ios::binary | std::ios::trunc);
  output.write(reinterpret_cast<const char *>(data), static_cast<std::streamsize>(size));
  output.close();
  return path;
}

void
ReadVolumeOfBoundedSize(const std::string & path)
{
  try
  {
    const itk::ImageIOBase::Pointer io = InspectVolumeFile(path);
    std::uint64_t                   voxels = 1;
    for (unsigned int d = 0; d < io->GetNumberOfDimensions(); ++d)
    {
      voxels *= io->GetDimensions(d); // each at most MaximumVolumeVoxels in all, checked above: no overflow
    }
    if (voxels <= (std::uint64_t{ 1 } << 22))
    {
      ReadVolume(path);
    }
  }
  catch (const InputError &)
  {
  }
}
} // namespace vr::fuzz
