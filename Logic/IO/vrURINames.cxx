// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrURINames.h"

#include <cctype>
#include <filesystem>

namespace vr
{
bool
IsURIName(const std::string & name)
{
  const auto colon = name.find(':');
  if (colon == std::string::npos || colon < 2 || !std::isalpha(static_cast<unsigned char>(name[0])))
  {
    return false;
  }
  for (std::size_t k = 1; k < colon; ++k)
  {
    const auto c = static_cast<unsigned char>(name[k]);
    if (!std::isalnum(c) && c != '+' && c != '-' && c != '.')
    {
      return false;
    }
  }
  std::error_code error;
  return !std::filesystem::exists(std::filesystem::path(name), error);
}
} // namespace vr
