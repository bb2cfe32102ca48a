// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrVesselPathReport.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <limits>

namespace vr
{
namespace
{
QString
Tr(const char * text)
{
  return QCoreApplication::translate("vr::VesselPathReport", text);
}

QString
Number(double value, int decimals)
{
  if (!std::isfinite(value))
  {
    return QStringLiteral("–");
  }
  if (std::abs(value) < 0.5 * std::pow(10.0, -decimals))
  {
    value = 0.0; // no "-0"
  }
  return QString::number(value, 'f', decimals);
}

QString
Escaped(const std::string & text)
{
  return QString::fromStdString(text).toHtmlEscaped();
}

QString
SegmentName(const SegmentGrading & grading, std::size_t index)
{
  return grading.Segment.Name.empty() ? Tr("segment %1").arg(index + 1) : Escaped(grading.Segment.Name);
}

/** One segment in a line: its vessel, arc lengths, scale, and its values or why none. */
QString
SegmentLine(const SegmentGrading & grading, std::size_t index)
{
  QString line = QStringLiteral("%1. %2, %3–%4 mm, %5: ")
                   .arg(index + 1)
                   .arg(SegmentName(grading, index))
                   .arg(Number(grading.Segment.Begin, 1), Number(grading.Segment.End, 1))
                   .arg(QString::fromUtf8(ToString(grading.Scale)).toHtmlEscaped());
  QStringList parts;
  if (grading.Scale == StenosisScale::Aorta && std::isfinite(grading.MaximumDiameter))
  {
    parts
      << Tr("max %1 mm at %2 mm").arg(Number(grading.MaximumDiameter, 1), Number(grading.MaximumDiameterArcLength, 1));
  }
  if (std::isfinite(grading.DiameterStenosisPercent))
  {
    parts << Tr("%1 % (MLD %2 mm)")
                 .arg(Number(grading.DiameterStenosisPercent, 0), Number(grading.MinimalLumenDiameter, 2)) +
               (grading.IsGraded() ? QStringLiteral(", ") + QString::fromStdString(grading.Grade).toHtmlEscaped()
                                   : QString());
  }
  if (!grading.NotGradedBecause.empty() && grading.Scale != StenosisScale::Aorta)
  {
    parts << Tr("not graded: %1").arg(Escaped(grading.NotGradedBecause));
  }
  else if (grading.Scale == StenosisScale::Aorta && !std::isfinite(grading.MaximumDiameter))
  {
    parts << Tr("not sized: %1").arg(Escaped(grading.NotGradedBecause));
  }
  return line + parts.join(QStringLiteral("; "));
}

/** The widest lumen along the path (mm): what a fold-free width is compared with. */
double
VesselDiameter(const VesselPathOutputs & results)
{
  double widest = std::numeric_limits<double>::quiet_NaN();
  for (const auto & section : results.Lumen.Sections)
  {
    if (section.IsMeasured() && !(section.Diameter <= widest))
    {
      widest = section.Diameter;
    }
  }
  return widest;
}
} // namespace

QString
VesselPathReportHTML(const VesselPathOutputs & results, std::size_t section, double width)
{
  const auto & stenosis = results.Stenosis;
  QString      text = Tr("<b>Path</b> %1 mm: %2").arg(Number(results.Path.GetLength(), 1), Escaped(results.PathName));
  if (!results.HasLumen)
  {
    text += Tr("<br>lumen not measured (no segmentation, no radii)");
  }
  else
  {
    text += Tr("<br>lumen from the %1").arg(QString::fromUtf8(itk::ToString(results.Lumen.Source)));
    // The headline a reader signs.
    if (stenosis.HeadlineSegment >= 0)
    {
      const auto &  headline = stenosis.Segments[static_cast<std::size_t>(stenosis.HeadlineSegment)];
      const QString where = SegmentName(headline, static_cast<std::size_t>(stenosis.HeadlineSegment));
      if (headline.IsGraded())
      {
        text += Tr("<br><b>Stenosis %1 %</b> diameter, %2 % area: <b>%3</b>, in %4")
                  .arg(Number(stenosis.DiameterStenosisPercent, 0), Number(stenosis.AreaStenosisPercent, 0))
                  .arg(QString::fromStdString(stenosis.Grade).toHtmlEscaped(), where);
        text += Tr("<br><b>MLD</b> %1 mm at %2 mm, reference %3 mm; <b>MLA</b> %4 mm² at %5 mm")
                  .arg(Number(stenosis.MinimalLumenDiameter, 2), Number(stenosis.MinimalLumenDiameterArcLength, 1))
                  .arg(Number(stenosis.ReferenceDiameter, 2))
                  .arg(Number(stenosis.MinimalLumenArea, 1), Number(stenosis.MinimalLumenAreaArcLength, 1));
        if (std::isfinite(stenosis.MaximumDiameter))
        {
          text += Tr("<br>aorta: maximum diameter %1 mm at %2 mm")
                    .arg(Number(stenosis.MaximumDiameter, 1), Number(stenosis.MaximumDiameterArcLength, 1));
        }
      }
      else
      {
        text += Tr("<br><b>Maximum diameter %1 mm</b> at %2 mm, in %3 (aorta: sized, not graded for stenosis; "
                   "%4 % diameter stenosis)")
                  .arg(Number(stenosis.MaximumDiameter, 1), Number(stenosis.MaximumDiameterArcLength, 1), where)
                  .arg(Number(stenosis.DiameterStenosisPercent, 0));
      }
    }
    else
    {
      text += Tr("<br><b>Not graded</b>: %1").arg(Escaped(stenosis.NotGradedBecause));
    }
    text += Tr("<br>reference: %1 %2")
              .arg(QString::fromUtf8(ToString(stenosis.Method)),
                   stenosis.UserReferencePoints ? Tr("through your points, over the whole path")
                                                : Tr("within each segment (never across a junction)"));
    text += QStringLiteral("<br>");
    for (std::size_t g = 0; g < stenosis.Segments.size(); ++g)
    {
      text += QStringLiteral("<br>") + SegmentLine(stenosis.Segments[g], g);
    }
    text += Tr("<br>%1 sections within the margins of the path's ends and branch origins: not candidates for the MLD "
               "(shaded in the plot)")
              .arg(stenosis.ExcludedSections);
    if (section < results.Lumen.Sections.size())
    {
      const auto & here = results.Lumen.Sections[section];
      text += Tr("<br><br>here, %1 mm: %2 mm, area %3 mm², min %4 / max %5 mm")
                .arg(Number(here.ArcLength, 1), Number(here.Diameter, 2), Number(here.Area, 1))
                .arg(Number(here.MinimumDiameter, 2), Number(here.MaximumDiameter, 2));
      if (section < stenosis.Sections.size() && !stenosis.Sections[section].Candidate)
      {
        text += Tr(" (excluded: %1)").arg(Escaped(stenosis.Sections[section].ExcludedBecause));
      }
    }
  }
  if (results.FoldedPixels > 0)
  {
    // A width that does not fold, offered through the width setting; where it is narrower than the vessel, the
    // stretched CPR (which never folds) is offered too.
    const double foldFree = std::floor(20.0 * results.FoldFreeHalfWidth) / 10.0;
    const double vessel = VesselDiameter(results);
    text += Tr("<br><span style='color:#b00000'>%1 pixels fold over at a width of %2 mm: "
               "<a href='%3%4'>use a width of %4 mm</a>, which does not fold")
              .arg(results.FoldedPixels)
              .arg(Number(width, 1), QString::fromLatin1(ReportLink::Width), Number(foldFree, 1));
    if (std::isfinite(vessel) && foldFree < vessel)
    {
      text += Tr(", but is narrower than the vessel (%1 mm): its edges would fall outside; or "
                 "<a href='%2'>use the stretched CPR</a>, which does not fold")
                .arg(Number(vessel, 1), QString::fromLatin1(ReportLink::Stretched));
    }
    text += QStringLiteral("</span>");
  }
  return text;
}
} // namespace vr
