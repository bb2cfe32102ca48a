#ifndef vrNumberText_h
#define vrNumberText_h

#include <string>

namespace vr
{
/** The whole of \a text as a finite double: no leading or trailing space, nothing else around it.
 * \param text the text to read.
 * \param value receives the number when the text is one.
 * \return whether the text is exactly one finite number. */
bool
ParseWholeDouble(const std::string & text, double & value);

/** The whole of \a text as a decimal integer that fits a long long, with the same rules.
 * \param text the text to read.
 * \param value receives the number when the text is one.
 * \return whether the text is exactly one such integer. */
bool
ParseWholeInteger(const std::string & text, long long & value);
} // namespace vr

#endif
