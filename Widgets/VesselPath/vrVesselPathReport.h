// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrVesselPathReport_h
#define vrVesselPathReport_h

#include "vrVesselPathLogic.h"

#include <QString>

namespace vr
{
/** The links the report's fold warning offers (the panel acts on them). */
namespace ReportLink
{
/** "Use the fold-free width": vr:width=<mm>. */
constexpr const char * Width = "vr:width=";
/** "Use the stretched CPR". */
constexpr const char * Stretched = "vr:stretched";
} // namespace ReportLink

/** The vessel path panel's report as HTML (docs/viewer.md, "Reading one vessel"): the path and its names, where the
 * lumen comes from, the headline (the most severe graded stenosis with its scale, or the aorta's maximum diameter, or
 * why nothing is graded), the reference and where it was taken, each segment in a line, the sections the margins
 * excluded, the section at \a section (its diameters, and why it is excluded when it is), and, where the CPR folds,
 * the warning with links to a width that does not fold (ReportLink::Width) and to the stretched CPR
 * (ReportLink::Stretched) when that width is narrower than the vessel. Every value is the logic's. */
QString
VesselPathReportHTML(const VesselPathOutputs & results, std::size_t section, double width);
} // namespace vr

#endif
