// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrInputError_h
#define vrInputError_h

#include <stdexcept>
#include <string>

namespace vr
{
/** Bad input from a user: a file, a field, a node or a parameter. The message names what is wrong and where,
 * ready to show as it is. When a parameter is at fault, Parameter() names it by its meaning (vr::ParameterName),
 * so that a front end can point at its own control for it (a command-line flag, a widget) without the logic
 * knowing either.
 * \ingroup VesselReformation
 */
class InputError : public std::runtime_error
{
public:
  /** \param message what is wrong, naming the file, field or parameter. */
  explicit InputError(const std::string & message)
    : std::runtime_error(message)
  {
  }
  /** \param message what is wrong.
   * \param parameter the parameter at fault, by its meaning ("anisotropy", "view size"). */
  InputError(const std::string & message, std::string parameter)
    : std::runtime_error(message)
    , m_Parameter(std::move(parameter))
  {
  }

  /** \return the parameter at fault by its meaning, or empty when the error is not about one parameter. */
  const std::string &
  Parameter() const
  {
    return m_Parameter;
  }

private:
  std::string m_Parameter;
};

/** A computation stopped because its caller asked it to (a new request superseded it, or the user cancelled).
 * Not an error: nothing is wrong with the input, and no output of the stopped run should be used.
 * \ingroup VesselReformation
 */
class Cancelled : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};
} // namespace vr

#endif
