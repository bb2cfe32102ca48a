// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCoordinateFrames.h"

#include "vrInputError.h"

#include <algorithm>
#include <cctype>

namespace vr
{
const char *
ToString(CoordinateSpace space)
{
  switch (space)
  {
    case CoordinateSpace::RAS:
      return "RAS";
    case CoordinateSpace::LPS:
      return "LPS";
    default:
      return "auto";
  }
}

CoordinateSpace
ParseCoordinateSpace(const std::string & text, const std::string & what)
{
  std::string upper = text;
  std::transform(upper.begin(), upper.end(), upper.begin(), [](unsigned char c) { return std::toupper(c); });
  if (upper == "RAS")
  {
    return CoordinateSpace::RAS;
  }
  if (upper == "LPS")
  {
    return CoordinateSpace::LPS;
  }
  if (upper == "AUTO")
  {
    return CoordinateSpace::Auto;
  }
  throw InputError(what + ": \"" + text + "\" is not a coordinate system; use RAS, LPS or auto");
}
} // namespace vr
