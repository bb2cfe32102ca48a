// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCLIProgress.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <sstream>

namespace vr
{
CLIProgress::CLIProgress(std::string                  name,
                         std::string                  comment,
                         vrModuleProcessInformation * information,
                         std::ostream &               out,
                         bool                         terminal)
  : m_Name(std::move(name))
  , m_Comment(std::move(comment))
  , m_Information(information)
  , m_Out(out)
  , m_Terminal(terminal)
  , m_Start(std::chrono::steady_clock::now())
{
}

double
CLIProgress::ElapsedSeconds() const
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_Start).count();
}

void
CLIProgress::Start()
{
  m_Start = std::chrono::steady_clock::now();
  m_Reported = -1.0;
  if (m_Information != nullptr)
  {
    m_Information->Progress = 0.0f;
    m_Information->StageProgress = 0.0f;
    std::strncpy(m_Information->ProgressMessage, m_Comment.c_str(), sizeof(m_Information->ProgressMessage) - 1);
    m_Information->ProgressMessage[sizeof(m_Information->ProgressMessage) - 1] = '\0';
    m_Information->ElapsedTime = 0.0;
    if (m_Information->ProgressCallbackFunction != nullptr)
    {
      m_Information->ProgressCallbackFunction(m_Information->ProgressCallbackClientData);
    }
    return;
  }
  if (!m_Terminal)
  {
    m_Out << "<filter-start>\n<filter-name>" << m_Name << "</filter-name>\n<filter-comment> \"" << m_Comment
          << "\" </filter-comment>\n</filter-start>" << std::endl;
  }
}

void
CLIProgress::Update(double fraction, const std::string & stage)
{
  fraction = std::clamp(fraction, 0.0, 1.0);
  if (fraction < m_Reported + 0.01 && !(fraction == 1.0 && m_Reported < 1.0))
  {
    return;
  }
  m_Reported = fraction;
  if (m_Information != nullptr)
  {
    m_Information->Progress = static_cast<float>(fraction);
    m_Information->StageProgress = static_cast<float>(fraction);
    std::strncpy(m_Information->ProgressMessage, stage.c_str(), sizeof(m_Information->ProgressMessage) - 1);
    m_Information->ProgressMessage[sizeof(m_Information->ProgressMessage) - 1] = '\0';
    m_Information->ElapsedTime = ElapsedSeconds();
    if (m_Information->ProgressCallbackFunction != nullptr)
    {
      m_Information->ProgressCallbackFunction(m_Information->ProgressCallbackClientData);
    }
    return;
  }
  if (m_Terminal)
  {
    constexpr int width = 40;
    m_BarOpen = true;
    const int filled = static_cast<int>(std::lround(fraction * width));
    m_Out << "\r" << m_Name << " [" << std::string(filled, '#') << std::string(width - filled, '.') << "] "
          << std::setw(3) << static_cast<int>(std::lround(100.0 * fraction)) << "% " << std::left << std::setw(10)
          << stage << std::right << std::flush;
    m_BarOpen = true;
    return;
  }
  std::ostringstream line;
  line << "<filter-progress>" << std::setprecision(4) << fraction << "</filter-progress>";
  m_Out << line.str() << std::endl;
}

void
CLIProgress::End()
{
  Update(1.0, "done");
  if (m_Information != nullptr)
  {
    m_Information->ElapsedTime = ElapsedSeconds();
    return;
  }
  if (m_Terminal)
  {
    if (m_BarOpen)
    {
      m_Out << std::endl;
      m_BarOpen = false;
    }
    return;
  }
  for (const auto & [name, value] : m_ReturnValues)
  {
    // CTK reads these lines as XML: a value in words (a backend's reason) may hold &, < or >.
    std::string escaped;
    for (const char c : value)
    {
      escaped += c == '&' ? "&amp;" : c == '<' ? "&lt;" : c == '>' ? "&gt;" : std::string(1, c);
    }
    m_Out << "<filter-result name=\"" << name << "\">" << escaped << "</filter-result>\n";
  }
  m_Out << "<filter-end>\n<filter-name>" << m_Name << "</filter-name>\n<filter-time>" << ElapsedSeconds()
        << "</filter-time>\n</filter-end>" << std::endl;
}

void
CLIProgress::Print(std::ostream & stream, const std::string & text)
{
  if (m_BarOpen)
  {
    m_Out << std::endl;
    m_BarOpen = false;
  }
  stream << text << std::endl;
}

void
CLIProgress::SetReturnValue(const std::string & name, const std::string & value)
{
  for (auto & entry : m_ReturnValues)
  {
    if (entry.first == name)
    {
      entry.second = value;
      return;
    }
  }
  m_ReturnValues.emplace_back(name, value);
}

bool
CLIProgress::AbortRequested() const
{
  return m_Information != nullptr && m_Information->Abort != 0;
}
} // namespace vr
