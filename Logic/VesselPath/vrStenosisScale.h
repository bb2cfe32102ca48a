// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrStenosisScale_h
#define vrStenosisScale_h

#include <string>

namespace vr
{
/** The clinical scale a segment of a vessel path is graded on (docs/lumen-measurement.md, "Grading scales"). Each
 * scale is defined for one kind of vessel: a % diameter stenosis means something only on the scale of its vessel. */
enum class StenosisScale
{
  /** Chosen per segment from the vessel's name (and, for a vessel without a name, its size): ScaleOfVessel. */
  Automatic,
  /** CAD-RADS (coronary arteries): 0, 1-24, 25-49, 50-69, 70-99 %, occlusion. */
  CADRADS,
  /** Peripheral and visceral arteries: the duplex categories of Jager et al. (1985) that CTA reports share: normal,
   * 1-19, 20-49, 50-99 %, occlusion. */
  Peripheral,
  /** Carotid arteries: NASCET's categories, < 50, 50-69, 70-99 %, occlusion. */
  Carotid,
  /** The aorta: no stenosis grade; its headline is the maximum diameter and its position (aneurysm sizing). */
  Aorta
};

/** "automatic", "CAD-RADS", "peripheral", "carotid (NASCET)" or "aorta". */
const char *
ToString(StenosisScale scale);

/** Reads a scale as the command line and the settings spell it: "automatic", "cad-rads", "peripheral", "carotid",
 * "aorta" (any case; "cadrads" too). \return false for anything else. */
bool
ParseStenosisScale(const std::string & text, StenosisScale & scale);

/** The % diameter stenosis rounded as every scale's categories are defined: to the nearest whole percent, halves up;
 * 100 only for a lumen of diameter 0 (some lumen left rounds to at most 99). NaN stays NaN. */
double
RoundedStenosisPercent(double diameterStenosisPercent);

/** The CAD-RADS stenosis class of a % diameter stenosis (docs/lumen-measurement.md, the scales table's "CAD-RADS" row): rounded as
 * RoundedStenosisPercent, then 0 % or less: 0; 1-24: 1; 25-49: 2; 50-69: 3; 70-99: 4; 5 only for a lumen of
 * diameter 0 (exactly 100 %). \return the class, or -1 for NaN. */
int
CADRADSClass(double diameterStenosisPercent);

/** The category of a % diameter stenosis on \a scale (rounded as RoundedStenosisPercent): CAD-RADS its class 0-5;
 * peripheral 0 normal (0 % or less), 1 (1-19 %), 2 (20-49 %), 3 (50-99 %), 4 occlusion; carotid 0 (< 50 %),
 * 1 (50-69 %), 2 (70-99 %), 3 occlusion. \return -1 for NaN, for the aorta and for Automatic (no scale). */
int
StenosisCategory(StenosisScale scale, double diameterStenosisPercent);

/** The category as a reader sees it: "CAD-RADS 3 (50–69 %)", "20–49 % (peripheral)", "70–99 % (NASCET)",
 * "occlusion (peripheral)". Empty for -1. */
std::string
StenosisCategoryText(StenosisScale scale, int category);

/** What the name of a vessel says of its scale: Aorta for a name with "aorta" or "aortic"; CADRADS for a coronary
 * artery ("coronary", "left main", "circumflex", "anterior descending", "posterior descending", "obtuse marginal",
 * "diagonal", "ramus", or the tokens LAD, LCX, RCA, LM, PDA, PLB, OM1-3, D1-3); Carotid for "carotid"; Automatic when
 * the name says none of these (the caller decides: a peripheral artery, or by size when there is no name). */
StenosisScale
ScaleOfVesselName(const std::string & name);

/** The smallest median lumen diameter (mm) at which a vessel without a name is taken for the aorta: larger than any
 * healthy peripheral, visceral, carotid or coronary artery (a common iliac artery is 8-12 mm), smaller than a healthy
 * adult's infrarenal aorta (15-20 mm). An unnamed aneurysm of another artery reaches it too, where the maximum
 * diameter is what a reader wants anyway. */
constexpr double AortaSizedDiameter = 14.0;
} // namespace vr

#endif
