// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrMetaIOWords_h
#define vrMetaIOWords_h

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

/** Word lists in MetaIO headers. Not installed: an implementation detail of the IO library. */
namespace vr::detail
{
/** The longest word MetaIO 5.2's MET_StringToWordArray copies safely: it copies each word into 80 bytes. */
constexpr std::size_t MaximumMetaIOWordLength = 79;

/** The words of \a text as MetaIO 5.2's MET_StringToWordArray splits them (a tube's PointDim, a MetaImage's
 * ElementDataFile list or pattern), or an empty vector where that function goes wrong: it counts a run of spaces as
 * more than one separator and then leaves the last entries of its array unset (fuzzing: MetaTube read a wild pointer
 * for a PointDim with a run of spaces), splits on spaces only (a tab stays inside a word), and copies each word into
 * 80 bytes. So only words of 1 to MaximumMetaIOWordLength characters with no tab, separated by single spaces and
 * with no space at either end, are given back. */
inline std::vector<std::string>
MetaIOWords(const std::string & text)
{
  std::vector<std::string> words;
  std::size_t              start = 0;
  while (start <= text.size())
  {
    const std::size_t end = std::min(text.find(' ', start), text.size());
    const std::string word = text.substr(start, end - start);
    if (word.empty() || word.size() > MaximumMetaIOWordLength || word.find('\t') != std::string::npos)
    {
      return {};
    }
    words.push_back(word);
    start = end + 1;
  }
  return words;
}
} // namespace vr::detail

#endif
