#include "vrNumberText.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace vr
{
namespace
{
bool
StartsWithSpace(const std::string & text)
{
  return std::isspace(static_cast<unsigned char>(text.front())) != 0;
}
} // namespace

bool
ParseWholeDouble(const std::string & text, double & value)
{
  if (text.empty() || StartsWithSpace(text))
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
  if (text.empty() || StartsWithSpace(text))
  {
    return false;
  }
  char * end = nullptr;
  errno = 0;
  value = std::strtoll(text.c_str(), &end, 10);
  return end == text.c_str() + text.size() && errno == 0;
}
} // namespace vr
