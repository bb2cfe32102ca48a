// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCoordinateFrames.h"
#include "vrText.h"

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
  const std::string upper = ToUpper(text);
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
