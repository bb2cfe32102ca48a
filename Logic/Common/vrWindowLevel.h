// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrWindowLevel_h
#define vrWindowLevel_h

#include <cstddef>

/** \file vrWindowLevel.h
 * \brief The one window/level -> grey mapping: what the views show and what every PNG holds, so that a saved picture
 * and the screen agree to the grey level.
 * \ingroup VesselReformation
 */
namespace vr
{
/** Maps an intensity through window/level to 0..255: grey = round(255 (value - level + window/2) / window), clamped
 * to [0, 255], so that level - window/2 -> 0 and level + window/2 -> 255 (halves round away from zero); NaN -> 0.
 * \param value the intensity.
 * \param window the window width (> 0).
 * \param level the window's centre.
 * \return the grey value. */
unsigned char
WindowLevelToByte(double value, double window, double level);

/** WindowLevelToByte() of \a count values into \a grey. */
void
WindowLevelToBytes(const float * values, std::size_t count, double window, double level, unsigned char * grey);
} // namespace vr

#endif
