// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrText.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace vr
{
namespace
{
bool
IsSpace(char c)
{
  return std::isspace(static_cast<unsigned char>(c)) != 0;
}
} // namespace

bool
ParseWholeDouble(const std::string & text, double & value)
{
  if (text.empty() || IsSpace(text.front()))
  {
    return false;
  }
  char * end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && std::isfinite(value);
}

bool
ParseWholeInteger(const std::string & text, long long & value)
{
  if (text.empty() || IsSpace(text.front()))
  {
    return false;
  }
  char * end = nullptr;
  errno = 0;
  value = std::strtoll(text.c_str(), &end, 10);
  return end == text.c_str() + text.size() && errno == 0;
}

std::string
ToLower(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

std::string
ToUpper(std::string text)
{
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::toupper(c); });
  return text;
}

std::string
Trim(const std::string & text)
{
  const auto first = std::find_if_not(text.begin(), text.end(), IsSpace);
  const auto last = std::find_if_not(text.rbegin(), text.rend(), IsSpace).base();
  return first < last ? std::string(first, last) : std::string();
}

bool
EndsWith(const std::string & text, const std::string & suffix)
{
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool
HasExtension(const std::string & path, const std::string & extension)
{
  return EndsWith(ToLower(path), extension);
}

std::vector<std::string>
SplitAndTrim(const std::string & text, char separator)
{
  std::vector<std::string> items;
  std::istringstream       stream(text);
  std::string              item;
  while (std::getline(stream, item, separator))
  {
    items.push_back(Trim(item));
  }
  if (!text.empty() && text.back() == separator)
  {
    items.emplace_back();
  }
  return items;
}
} // namespace vr
