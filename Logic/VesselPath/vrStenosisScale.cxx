// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrStenosisScale.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <vector>

namespace vr
{
namespace
{
std::string
Lower(std::string text)
{
  std::transform(
    text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

/** The name's words: runs of letters and digits, in lower case ("LAD_proximal" -> "lad", "proximal"). */
std::vector<std::string>
Tokens(const std::string & name)
{
  std::vector<std::string> tokens;
  std::string              token;
  for (const char c : name)
  {
    if (std::isalnum(static_cast<unsigned char>(c)))
    {
      token += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    else if (!token.empty())
    {
      tokens.push_back(token);
      token.clear();
    }
  }
  if (!token.empty())
  {
    tokens.push_back(token);
  }
  return tokens;
}

bool
Contains(const std::string & text, const char * word)
{
  return text.find(word) != std::string::npos;
}
} // namespace

const char *
ToString(StenosisScale scale)
{
  switch (scale)
  {
    case StenosisScale::Automatic:
      return "automatic";
    case StenosisScale::CADRADS:
      return "CAD-RADS";
    case StenosisScale::Peripheral:
      return "peripheral";
    case StenosisScale::Carotid:
      return "carotid (NASCET)";
    case StenosisScale::Aorta:
      return "aorta";
  }
  return "automatic";
}

bool
ParseStenosisScale(const std::string & text, StenosisScale & scale)
{
  const std::string word = Lower(text);
  if (word == "automatic" || word == "auto")
  {
    scale = StenosisScale::Automatic;
  }
  else if (word == "cad-rads" || word == "cadrads")
  {
    scale = StenosisScale::CADRADS;
  }
  else if (word == "peripheral")
  {
    scale = StenosisScale::Peripheral;
  }
  else if (word == "carotid" || word == "nascet")
  {
    scale = StenosisScale::Carotid;
  }
  else if (word == "aorta")
  {
    scale = StenosisScale::Aorta;
  }
  else
  {
    return false;
  }
  return true;
}

double
RoundedStenosisPercent(double diameterStenosisPercent)
{
  if (std::isnan(diameterStenosisPercent))
  {
    return diameterStenosisPercent;
  }
  if (diameterStenosisPercent >= 100.0)
  {
    return 100.0;
  }
  // Halves up; some lumen left is never an occlusion.
  return std::min(99.0, std::floor(diameterStenosisPercent + 0.5));
}

int
CADRADSClass(double diameterStenosisPercent)
{
  const double percent = RoundedStenosisPercent(diameterStenosisPercent);
  if (std::isnan(percent))
  {
    return -1;
  }
  if (percent >= 100.0)
  {
    return 5;
  }
  if (percent <= 0.0)
  {
    return 0;
  }
  if (percent < 25.0)
  {
    return 1;
  }
  if (percent < 50.0)
  {
    return 2;
  }
  if (percent < 70.0)
  {
    return 3;
  }
  return 4;
}

int
StenosisCategory(StenosisScale scale, double diameterStenosisPercent)
{
  const double percent = RoundedStenosisPercent(diameterStenosisPercent);
  if (std::isnan(percent))
  {
    return -1;
  }
  switch (scale)
  {
    case StenosisScale::CADRADS:
      return CADRADSClass(diameterStenosisPercent);
    case StenosisScale::Peripheral:
      if (percent >= 100.0)
      {
        return 4;
      }
      return percent <= 0.0 ? 0 : percent < 20.0 ? 1 : percent < 50.0 ? 2 : 3;
    case StenosisScale::Carotid:
      if (percent >= 100.0)
      {
        return 3;
      }
      return percent < 50.0 ? 0 : percent < 70.0 ? 1 : 2;
    case StenosisScale::Aorta:
    case StenosisScale::Automatic:
      break;
  }
  return -1;
}

std::string
StenosisCategoryText(StenosisScale scale, int category)
{
  static const char * const cadRads[] = { "0 %", "1–24 %", "25–49 %", "50–69 %", "70–99 %", "100 %, occlusion" };
  static const char * const peripheral[] = { "normal", "1–19 %", "20–49 %", "50–99 %", "occlusion" };
  static const char * const carotid[] = { "< 50 %", "50–69 %", "70–99 %", "occlusion" };
  if (category < 0)
  {
    return std::string();
  }
  switch (scale)
  {
    case StenosisScale::CADRADS:
      return category <= 5 ? "CAD-RADS " + std::to_string(category) + " (" + cadRads[category] + ")" : std::string();
    case StenosisScale::Peripheral:
      return category <= 4 ? std::string(peripheral[category]) + " (peripheral)" : std::string();
    case StenosisScale::Carotid:
      return category <= 3 ? std::string(carotid[category]) + " (NASCET)" : std::string();
    case StenosisScale::Aorta:
    case StenosisScale::Automatic:
      break;
  }
  return std::string();
}

StenosisScale
ScaleOfVesselName(const std::string & name)
{
  const std::string lower = Lower(name);
  if (Contains(lower, "aorta") || Contains(lower, "aortic"))
  {
    return StenosisScale::Aorta;
  }
  if (Contains(lower, "coronary") || Contains(lower, "left main") || Contains(lower, "circumflex") ||
      Contains(lower, "anterior descending") || Contains(lower, "posterior descending") ||
      Contains(lower, "obtuse marginal") || Contains(lower, "diagonal") || Contains(lower, "ramus"))
  {
    return StenosisScale::CADRADS;
  }
  static const char * const coronaryTokens[] = { "lad", "lcx", "rca", "lm", "pda", "plb",
                                                 "om1", "om2", "om3", "d1", "d2",  "d3" };
  for (const std::string & token : Tokens(name))
  {
    for (const char * coronary : coronaryTokens)
    {
      if (token == coronary)
      {
        return StenosisScale::CADRADS;
      }
    }
  }
  if (Contains(lower, "carotid"))
  {
    return StenosisScale::Carotid;
  }
  return StenosisScale::Automatic;
}
} // namespace vr
