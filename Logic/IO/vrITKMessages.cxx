// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrITKMessages.h"
#include "vrText.h"

#include <iostream>
#include <mutex>
#include <sstream>
#include <vector>

namespace vr::detail
{
namespace
{
void
ReplaceAll(std::string & text, const std::string & from, const std::string & to)
{
  if (from.empty())
  {
    return;
  }
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
  {
    text.replace(at, from.size(), to);
  }
}

/** "itk::ERROR: NrrdImageIO(0x55d0): Read: ..." -> "Read: ...". */
std::string
WithoutITKPrefix(std::string line)
{
  for (const std::string prefix : { "ITK ERROR: ", "itk::ERROR: ", "itk::ERROR " })
  {
    if (line.rfind(prefix, 0) == 0)
    {
      line = line.substr(prefix.size());
      const auto object = line.find("(0x");
      const auto objectEnd = line.find("): ");
      if (object != std::string::npos && objectEnd != std::string::npos && object < objectEnd)
      {
        line = line.substr(objectEnd + 3);
      }
    }
  }
  return line;
}

class SilentOutputWindow : public itk::OutputWindow
{
public:
  ITK_DISALLOW_COPY_AND_MOVE(SilentOutputWindow);
  using Self = SilentOutputWindow;
  using Pointer = itk::SmartPointer<Self>;
  itkNewMacro(Self);

  void
  DisplayText(const char *) override
  {
  }

protected:
  SilentOutputWindow() = default;
  ~SilentOutputWindow() override = default;
};

std::recursive_mutex &
OutputWindowMutex()
{
  static std::recursive_mutex mutex;
  return mutex;
}
} // namespace

std::string
CondenseITKMessage(const itk::ExceptionObject & exception,
                   const std::string &          temporaryPath,
                   const std::string &          finalPath)
{
  std::string description = exception.GetDescription();
  ReplaceAll(description, temporaryPath, finalPath);
  if (description.find("Could not create IO object") != std::string::npos)
  {
    return "ITK has no reader or writer for this file name's extension";
  }
  std::vector<std::string> kept;
  std::istringstream       lines(description);
  std::string              line;
  while (std::getline(lines, line))
  {
    line = Trim(line);
    if (line.rfind("[nrrd] ", 0) == 0)
    {
      // Teem's error chain: "[nrrd] function: text". Keep the texts that say more than "trouble".
      line = line.substr(7);
      if (!line.empty() && line.back() == ':' && line.find(": ") == std::string::npos)
      {
        continue; // "[nrrd] function:" with nothing after it
      }
      const auto colon = line.find(": ");
      line = colon == std::string::npos ? line : line.substr(colon + 2);
      if (line.empty() || line == "trouble" || line.rfind("trouble reading", 0) == 0)
      {
        continue;
      }
    }
    else
    {
      line = WithoutITKPrefix(line);
    }
    // "Read: Error reading /path:" only repeats the file the caller names already.
    if (line.empty() || (line.back() == ':' && line.find("Error reading") != std::string::npos))
    {
      continue;
    }
    kept.push_back(line);
  }
  std::string condensed;
  for (const auto & part : kept)
  {
    condensed += (condensed.empty() ? "" : "; ") + part;
  }
  return condensed.empty() ? Trim(WithoutITKPrefix(description)) : condensed;
}

ScopedSilentITKOutput::ScopedSilentITKOutput()
{
  OutputWindowMutex().lock();
  m_Previous = itk::OutputWindow::GetInstance();
  itk::OutputWindow::SetInstance(SilentOutputWindow::New());
}

ScopedConsoleCapture::ScopedConsoleCapture()
  : m_PreviousError(std::cerr.rdbuf(m_Text.rdbuf()))
  , m_PreviousOutput(std::cout.rdbuf(m_Text.rdbuf()))
{
}

ScopedConsoleCapture::~ScopedConsoleCapture()
{
  std::cerr.rdbuf(m_PreviousError);
  std::cout.rdbuf(m_PreviousOutput);
}

std::string
ScopedConsoleCapture::FirstLine() const
{
  const std::string text = m_Text.str();
  const auto        first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos)
  {
    return std::string();
  }
  return Trim(text.substr(first, text.find('\n', first) - first));
}

std::string
ScopedConsoleCapture::FirstLineStartingWith(const std::string & prefix) const
{
  std::istringstream lines(m_Text.str());
  std::string        line;
  while (std::getline(lines, line))
  {
    line = Trim(line);
    if (line.rfind(prefix, 0) == 0)
    {
      return line;
    }
  }
  return std::string();
}

ScopedSilentITKOutput::~ScopedSilentITKOutput()
{
  itk::OutputWindow::SetInstance(m_Previous);
  OutputWindowMutex().unlock();
}
} // namespace vr::detail
