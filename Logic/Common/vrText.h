// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrText_h
#define vrText_h

#include <string>
#include <vector>

/** \file vrText.h
 * \brief The text helpers every layer of the platform side shares: strict number parsing for parameters, command
 * lines and files, and the few string operations their parsers need.
 * \ingroup VesselReformation
 */
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

/** \param text any text.
 * \return \a text with ASCII letters in lower case. */
std::string
ToLower(std::string text);

/** \param text any text.
 * \return \a text with ASCII letters in upper case. */
std::string
ToUpper(std::string text);

/** \param text any text.
 * \return \a text without leading and trailing white space. */
std::string
Trim(const std::string & text);

/** \param text any text.
 * \param suffix the ending looked for.
 * \return whether \a text ends with \a suffix, exactly. */
bool
EndsWith(const std::string & text, const std::string & suffix);

/** \param path a file path.
 * \param extension an extension with its dot, in lower case (".vtp", ".mrk.json").
 * \return whether \a path ends with \a extension, ignoring case. */
bool
HasExtension(const std::string & path, const std::string & extension);

/** \param text a list such as "1, 2,3".
 * \param separator the character between items.
 * \return the items, each trimmed; an empty text gives none, a trailing separator a last empty item. */
std::vector<std::string>
SplitAndTrim(const std::string & text, char separator);
} // namespace vr

#endif
