// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrInputError_h
#define vrInputError_h

#include <stdexcept>
#include <string>

namespace vr
{
/** Bad input from a user: a file, a field, a flag or a parameter. The message names what is wrong and where,
 * ready to show as it is.
 * \ingroup VesselReformation
 */
class InputError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};
} // namespace vr

#endif
