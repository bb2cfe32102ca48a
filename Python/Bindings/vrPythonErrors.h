// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrPythonErrors_h
#define vrPythonErrors_h

#include "vrInputError.h"

#include <pybind11/pybind11.h>

#include <functional>
#include <stdexcept>
#include <string>

/** \file vrPythonErrors.h
 * \brief How the engine's errors reach Python: a bad argument raises ValueError, a file that cannot be read or
 * written OSError, each with the engine's message; a parameter the logic names by its meaning (vr::ParameterName) is
 * named by the keyword argument that sets it ("angle: ..."), as the command-line modules name their flags. A cancelled
 * run raises vesselreformation.Cancelled.
 */
namespace vr::python
{
namespace py = pybind11;

/** A file that could not be written, from the engine's thread: the calling thread raises OSError with its message. */
class FileError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/** \return the keyword argument that sets the parameter of meaning \a meaning (vr::ParameterName), or "". */
std::string
KeywordOf(const std::string & meaning);

/** \return the message of \a error, prefixed with the keyword of its parameter when it names one. */
std::string
MessageOf(const InputError & error);

/** Raises ValueError with \a message. */
[[noreturn]] void
RaiseValueError(const std::string & message);
/** Raises OSError with \a message (and the file name, when given). */
[[noreturn]] void
RaiseOSError(const std::string & message, const std::string & path = std::string());

/** Runs \a work, which reads or writes files: vr::InputError becomes OSError naming \a path. */
void
OnFiles(const std::string & path, const std::function<void()> & work);
/** Runs \a work, which checks arguments or computes: vr::InputError becomes ValueError (keyword-named), FileError
 * OSError. */
void
OnArguments(const std::function<void()> & work);

/** Defines vesselreformation.Cancelled and the translation of vr::Cancelled to it. */
void
RegisterErrors(py::module_ & module);
} // namespace vr::python

#endif
