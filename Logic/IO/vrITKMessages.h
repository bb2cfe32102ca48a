// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrITKMessages_h
#define vrITKMessages_h

#include "itkMacro.h"
#include "itkObjectFactory.h"
#include "itkOutputWindow.h"

#include <sstream>
#include <string>

/** Turning ITK's error and warning text into the one-line messages vr::InputError carries. Not installed: an
 * implementation detail of the IO library. */
namespace vr::detail
{
/** The description of \a exception on one line: without ITK's "ITK ERROR: Class(0x...): " prefix, with the
 * NRRD library's chain of "trouble" lines reduced to the ones that say what is wrong, and \a temporaryPath
 * (an AtomicOutput name the user never sees) replaced by \a finalPath. */
std::string
CondenseITKMessage(const itk::ExceptionObject & exception,
                   const std::string &          temporaryPath = std::string(),
                   const std::string &          finalPath = std::string());

/** While alive, ITK warnings (itkWarningMacro, e.g. GDCMSeriesFileNames' "No Series were found") go nowhere
 * instead of to the terminal: the caller reports what went wrong itself.
 * \ingroup VesselReformation
 */
class ScopedSilentITKOutput
{
public:
  ScopedSilentITKOutput();
  ~ScopedSilentITKOutput();
  ScopedSilentITKOutput(const ScopedSilentITKOutput &) = delete;
  ScopedSilentITKOutput &
  operator=(const ScopedSilentITKOutput &) = delete;

private:
  itk::OutputWindow::Pointer m_Previous;
};

/** While alive, what is printed on std::cout and std::cerr is kept instead of shown: MetaIO (MetaImage, the .tre
 * reader) reports trouble there besides (or instead of) failing, e.g. "data not read completely" for a truncated
 * file that it otherwise accepts. */
class ScopedConsoleCapture
{
public:
  ScopedConsoleCapture();
  ~ScopedConsoleCapture();
  ScopedConsoleCapture(const ScopedConsoleCapture &) = delete;
  ScopedConsoleCapture &
  operator=(const ScopedConsoleCapture &) = delete;

  /** The first line printed (MetaIO repeats itself line by line), trimmed; empty when nothing was printed. */
  std::string
  FirstLine() const;
  /** The first line printed that starts with \a prefix ("Meta": MetaIO's complaints, not ITK's warnings), trimmed;
   * empty when none. */
  std::string
  FirstLineStartingWith(const std::string & prefix) const;

private:
  std::ostringstream m_Text;
  std::streambuf *   m_PreviousError;
  std::streambuf *   m_PreviousOutput;
};
} // namespace vr::detail

#endif
