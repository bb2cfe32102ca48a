// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrVTKErrorCapture.h"

#include <vtkAlgorithm.h>
#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkLogger.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkSmartPointer.h>
#include <vtkXMLReader.h>

#include <mutex>
#include <string>

namespace vr::detail
{
namespace
{
std::recursive_mutex &
CaptureMutex()
{
  static std::recursive_mutex mutex;
  return mutex;
}

/** How many captures are alive (under CaptureMutex): the outermost one silences vtkLogger's stderr output. */
int &
CaptureDepth()
{
  static int depth = 0;
  return depth;
}

/** "ERROR: In file.cxx, line 12\nvtkClass (0x1234): what went wrong\n\n" -> "what went wrong". */
std::string
CleanMessage(const char * text)
{
  std::string message = text == nullptr ? std::string() : std::string(text);
  const auto  newline = message.find('\n');
  if (message.rfind("ERROR: In ", 0) == 0 || message.rfind("Warning: In ", 0) == 0)
  {
    message = newline == std::string::npos ? std::string() : message.substr(newline + 1);
  }
  const auto objectEnd = message.find("): ");
  if (objectEnd != std::string::npos && message.find('(') < objectEnd)
  {
    message = message.substr(objectEnd + 3);
  }
  const auto last = message.find_last_not_of(" \t\r\n");
  message = last == std::string::npos ? std::string() : message.substr(0, last + 1);
  const auto first = message.find_first_not_of(" \t\r\n");
  return first == std::string::npos ? std::string() : message.substr(first);
}

/** Records ErrorEvent messages; owned by reference counting, so an algorithm that outlives the capture still
 * holds a valid command. */
class ErrorRecorder : public vtkCommand
{
public:
  static ErrorRecorder *
  New()
  {
    return new ErrorRecorder;
  }
  vtkTypeMacro(ErrorRecorder, vtkCommand);

  void
  Execute(vtkObject *, unsigned long event, void * callData) override
  {
    // A reader's warning ("Error reading ascii data", a short array) leaves its output half-filled: a failure too.
    if (event == vtkCommand::ErrorEvent || event == vtkCommand::WarningEvent)
    {
      m_Errors.push_back(CleanMessage(static_cast<const char *>(callData)));
    }
  }

  std::vector<std::string> m_Errors;
};

/** An output window that prints nothing and hands errors to a recorder. */
class RecordingOutputWindow : public vtkOutputWindow
{
public:
  static RecordingOutputWindow *
  New();
  vtkTypeMacro(RecordingOutputWindow, vtkOutputWindow);

  void
  DisplayErrorText(const char * text) override
  {
    if (m_Recorder != nullptr)
    {
      m_Recorder->m_Errors.push_back(CleanMessage(text));
    }
  }
  void
  DisplayText(const char *) override
  {
  }
  void
  DisplayWarningText(const char * text) override
  {
    DisplayErrorText(text);
  }
  void
  DisplayGenericWarningText(const char * text) override
  {
    DisplayErrorText(text);
  }
  void
  DisplayDebugText(const char *) override
  {
  }

  vtkSmartPointer<ErrorRecorder> m_Recorder;
};
vtkStandardNewMacro(RecordingOutputWindow);

/** Records what vtkLogger is given at warning level or worse: VTK 9.1's vtkErrorMacro on an object without an
 * ErrorEvent observer (a data array failing to allocate) logs there as well as on the output window, and vtkLogger
 * prints to stderr itself. */
void
RecordLogMessage(void * recorder, const vtkLogger::Message & message)
{
  if (message.verbosity <= vtkLogger::VERBOSITY_WARNING)
  {
    static_cast<ErrorRecorder *>(recorder)->m_Errors.push_back(CleanMessage(message.message));
  }
}
} // namespace

class VTKErrorCapture::Implementation
{
public:
  std::unique_lock<std::recursive_mutex> m_Lock{ CaptureMutex() };
  vtkSmartPointer<ErrorRecorder>         m_Recorder{ vtkSmartPointer<ErrorRecorder>::New() };
  vtkSmartPointer<vtkOutputWindow>       m_PreviousWindow;
  vtkSmartPointer<RecordingOutputWindow> m_Window{ vtkSmartPointer<RecordingOutputWindow>::New() };
  std::string                            m_LogCallback;
  vtkLogger::Verbosity                   m_PreviousStderrVerbosity{ vtkLogger::VERBOSITY_INFO };
};

VTKErrorCapture::VTKErrorCapture()
  : m_Implementation(std::make_unique<Implementation>())
{
  m_Implementation->m_PreviousWindow = vtkOutputWindow::GetInstance();
  m_Implementation->m_Window->m_Recorder = m_Implementation->m_Recorder;
  vtkOutputWindow::SetInstance(m_Implementation->m_Window);
  if (CaptureDepth()++ == 0)
  {
    // vtkLogger has no getter for its stderr level; with no callback or log file added, the cutoff is that level.
    m_Implementation->m_PreviousStderrVerbosity = vtkLogger::GetCurrentVerbosityCutoff();
    vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  }
  m_Implementation->m_LogCallback = "vr-capture-" + std::to_string(CaptureDepth());
  vtkLogger::AddCallback(m_Implementation->m_LogCallback.c_str(),
                         &RecordLogMessage,
                         m_Implementation->m_Recorder.GetPointer(),
                         vtkLogger::VERBOSITY_WARNING);
}

VTKErrorCapture::~VTKErrorCapture()
{
  vtkLogger::RemoveCallback(m_Implementation->m_LogCallback.c_str());
  if (--CaptureDepth() == 0)
  {
    vtkLogger::SetStderrVerbosity(m_Implementation->m_PreviousStderrVerbosity);
  }
  vtkOutputWindow::SetInstance(m_Implementation->m_PreviousWindow);
}

void
VTKErrorCapture::Observe(vtkObject * object)
{
  if (object == nullptr)
  {
    return;
  }
  object->AddObserver(vtkCommand::ErrorEvent, m_Implementation->m_Recorder);
  object->AddObserver(vtkCommand::WarningEvent, m_Implementation->m_Recorder);
  if (auto * xmlReader = vtkXMLReader::SafeDownCast(object))
  {
    xmlReader->SetReaderErrorObserver(m_Implementation->m_Recorder);
    xmlReader->SetParserErrorObserver(m_Implementation->m_Recorder);
  }
  if (auto * algorithm = vtkAlgorithm::SafeDownCast(object))
  {
    algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, m_Implementation->m_Recorder);
  }
}

bool
VTKErrorCapture::HasErrors() const
{
  return !m_Implementation->m_Recorder->m_Errors.empty();
}

std::string
VTKErrorCapture::FirstError() const
{
  // The executive's "returned failure for request" only repeats that the algorithm failed: prefer the cause.
  for (const auto & error : m_Implementation->m_Recorder->m_Errors)
  {
    if (error.find("returned failure for request") == std::string::npos && !error.empty())
    {
      return error;
    }
  }
  return m_Implementation->m_Recorder->m_Errors.empty() ? std::string()
                                                        : m_Implementation->m_Recorder->m_Errors.front();
}

const std::vector<std::string> &
VTKErrorCapture::Errors() const
{
  return m_Implementation->m_Recorder->m_Errors;
}
} // namespace vr::detail
