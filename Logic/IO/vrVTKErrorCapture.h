// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrVTKErrorCapture_h
#define vrVTKErrorCapture_h

#include <memory>
#include <string>
#include <vector>

class vtkObject;

namespace vr::detail
{
/** \class VTKErrorCapture
 * \brief Collects the errors and warnings VTK readers and writers report, instead of letting VTK print them.
 *
 * Warnings count as errors: a reader that warns (a short array, a value it could not parse) has left its output
 * partly uninitialised, so HasErrors() is true after one.
 *
 * VTK reports file errors through vtkErrorMacro (an ErrorEvent on the object, else text on the global
 * vtkOutputWindow), never through exceptions. While a capture lives, the output window is replaced by a silent
 * one that records what it is given, and Observe() adds ErrorEvent/WarningEvent observers to an algorithm (and,
 * for XML readers, to their parser), so a caller can turn the first message into a vr::InputError that names
 * the file. VTK 9.1 also hands an error without an observer to vtkLogger, which prints to stderr itself: while a
 * capture lives, vtkLogger prints nothing and its warnings and errors are recorded too. Captures are serialised by a
 * process-wide lock because the output window and the logger are global.
 * \ingroup VesselReformation
 */
class VTKErrorCapture
{
public:
  VTKErrorCapture();
  ~VTKErrorCapture();
  VTKErrorCapture(const VTKErrorCapture &) = delete;
  VTKErrorCapture &
  operator=(const VTKErrorCapture &) = delete;

  /** Routes the errors and warnings of \a object (and of its executive) to this capture. */
  void
  Observe(vtkObject * object);

  bool
  HasErrors() const;
  /** The first error without VTK's "ERROR: In file, line" preamble; empty when none. */
  std::string
  FirstError() const;
  const std::vector<std::string> &
  Errors() const;

  class Implementation;

private:
  std::unique_ptr<Implementation> m_Implementation;
};
} // namespace vr::detail

#endif
