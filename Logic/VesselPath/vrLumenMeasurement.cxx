// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrLumenMeasurement.h"

#include "vrCoordinateFrames.h"
#include "vrITKMessages.h"
#include "vrInputError.h"
#include "vrParameterName.h"

#include <cmath>
#include <sstream>

namespace vr
{
namespace
{
/** The reference points outside [first, last] named in one message, before any measuring. */
void
CheckReferencePoints(const std::vector<double> & points, double first, double last)
{
  std::ostringstream outside;
  std::size_t        bad = 0;
  for (const double s : points)
  {
    if (!std::isfinite(s) || s < first || s > last)
    {
      outside << (bad++ ? ", " : "") << s;
    }
  }
  if (bad > 0)
  {
    std::ostringstream message;
    message << "reference point" << (bad > 1 ? "s " : " ") << outside.str() << " mm" << (bad > 1 ? " lie" : " lies")
            << " outside the path (arc length " << first << " to " << last << " mm)";
    throw InputError(message.str(), ParameterName::ReferencePoints);
  }
}

/** A number for the returned values: every digit that matters, nothing for NaN. */
std::string
Number(double value)
{
  if (std::isnan(value))
  {
    return std::string();
  }
  std::ostringstream text;
  text.precision(10);
  text << value;
  return text.str();
}

/** A number for a reader: \a decimals after the point, "–" for NaN. */
std::string
Fixed(double value, int decimals)
{
  if (!std::isfinite(value))
  {
    return "–";
  }
  // No "-0": a value that rounds to zero is zero.
  if (std::abs(value) < 0.5 * std::pow(10.0, -decimals))
  {
    value = 0.0;
  }
  std::ostringstream text;
  text.setf(std::ios::fixed);
  text.precision(decimals);
  text << value;
  return text.str();
}

std::string
ReferenceText(const VesselStenosisSummary & summary)
{
  std::string text = ToString(summary.Method);
  if (summary.UserReferencePoints)
  {
    return text + " through the user's reference points, over the whole path";
  }
  return text + (summary.Method == VesselReferenceMethod::Interpolated
                   ? " within each segment, between its first and last candidate section"
                   : " within each segment, fitted to its candidate sections");
}
} // namespace

LumenMeasurement
MeasureLumen(const itk::VesselPathSectionList & sections,
             const SegmentationMaskType *       segmentation,
             const std::string &                segmentationName,
             const LumenMeasurementParameters & parameters)
{
  if (sections.size() < 2)
  {
    throw InputError("lumen measurement: the path has " + std::to_string(sections.size()) +
                     " section(s); it needs at least two");
  }
  CheckReferencePoints(parameters.ReferenceArcLengths, sections.front().ArcLength, sections.back().ArcLength);
  if (parameters.ReferenceMethod == VesselReferenceMethod::RobustFit && parameters.ReferenceArcLengths.size() == 1)
  {
    throw InputError("the robust-fit reference needs two reference points (the span it fits), or none for each "
                     "segment's own",
                     ParameterName::ReferencePoints);
  }

  LumenMeasurement result;
  if (segmentation != nullptr)
  {
    itk::VesselLumenMeasurementOptions options;
    options.SamplingStep = parameters.SamplingStep;
    options.MaximumHalfWidth = parameters.MaximumHalfWidth;
    try
    {
      result.Profile = itk::MeasureVesselLumen(segmentation, sections, options);
    }
    catch (const itk::ExceptionObject & exception)
    {
      throw InputError(detail::CondenseITKMessage(exception), ParameterName::LumenSampling);
    }
    if (result.Profile.SectionsOutsideSegmentation == sections.size())
    {
      throw InputError(segmentationName + ": the path lies wholly outside it (none of its " +
                       std::to_string(sections.size()) +
                       " sections' centres is inside the segmentation); is it the segmentation of this vessel and "
                       "this scan?");
    }
  }
  else
  {
    result.Profile = itk::VesselLumenFromRadii(sections);
    if (result.Profile.SectionsWithoutRadius == sections.size())
    {
      throw InputError("lumen measurement: no segmentation was given and the centerlines carry no radius: nothing to "
                       "measure the lumen from");
    }
  }

  VesselStenosisOptions options;
  options.Method = parameters.ReferenceMethod;
  options.ReferenceArcLengths = parameters.ReferenceArcLengths;
  options.Layout = parameters.Layout;
  options.Scale = parameters.Scale;
  result.Summary = AnalyseVesselStenosis(result.Profile, options);
  return result;
}

std::string
DescribeSegmentGrading(const VesselStenosisSummary & summary, std::size_t segment)
{
  const SegmentGrading & grading = summary.Segments.at(segment);
  std::ostringstream     text;
  text << "segment " << segment + 1 << " (";
  if (!grading.Segment.Name.empty())
  {
    text << grading.Segment.Name << ", ";
  }
  text << Fixed(grading.Segment.Begin, 1) << "–" << Fixed(grading.Segment.End, 1) << " mm), scale "
       << ToString(grading.Scale) << " (" << grading.ScaleReason << "): ";
  bool said = false;
  if (grading.Scale == StenosisScale::Aorta && std::isfinite(grading.MaximumDiameter))
  {
    text << "maximum diameter " << Fixed(grading.MaximumDiameter, 1) << " mm at "
         << Fixed(grading.MaximumDiameterArcLength, 1) << " mm";
    said = true;
  }
  if (std::isfinite(grading.DiameterStenosisPercent))
  {
    text << (said ? "; " : "") << Fixed(grading.DiameterStenosisPercent, 0) << " % diameter stenosis";
    if (grading.IsGraded())
    {
      text << ", " << grading.Grade;
    }
    text << " (MLD " << Fixed(grading.MinimalLumenDiameter, 2) << " mm at "
         << Fixed(grading.MinimalLumenDiameterArcLength, 1) << " mm, reference " << Fixed(grading.ReferenceDiameter, 2)
         << " mm); " << Fixed(grading.AreaStenosisPercent, 0) << " % area stenosis";
    said = true;
  }
  if (!grading.NotGradedBecause.empty())
  {
    // An aortic segment's reason says it already ("the aorta is sized, not graded: ...").
    const bool sized = grading.Scale == StenosisScale::Aorta && std::isfinite(grading.MaximumDiameter);
    text << (said ? "; " : "") << (sized ? "" : "not graded: ") << grading.NotGradedBecause;
  }
  return text.str();
}

std::vector<std::string>
LumenSummaryLines(const LumenMeasurement & measurement, const std::string & pathDescription)
{
  const auto &             summary = measurement.Summary;
  std::vector<std::string> lines;
  if (!pathDescription.empty())
  {
    lines.push_back("path: " + pathDescription);
  }
  lines.push_back(std::string("lumen: from the ") + itk::ToString(summary.Source) + ", " +
                  std::to_string(summary.MeasuredSections) + " of " +
                  std::to_string(measurement.Profile.Sections.size()) + " sections measured");
  lines.push_back("reference: " + ReferenceText(summary));
  lines.push_back("margins: no MLD within max(" + Fixed(MinimumExclusionMargin, 0) +
                  " mm, the radius there) of a vessel end of the path, nor within max(" +
                  Fixed(MinimumExclusionMargin, 0) + " mm, the parent's radius) of a branch origin; " +
                  std::to_string(summary.ExcludedSections) + " sections excluded (column excluded_because)");
  for (std::size_t g = 0; g < summary.Segments.size(); ++g)
  {
    lines.push_back(DescribeSegmentGrading(summary, g));
  }
  std::string headline = "headline: ";
  if (summary.HeadlineSegment >= 0)
  {
    const auto &      grading = summary.Segments[static_cast<std::size_t>(summary.HeadlineSegment)];
    const std::string where = "segment " + std::to_string(summary.HeadlineSegment + 1) +
                              (grading.Segment.Name.empty() ? std::string() : " (" + grading.Segment.Name + ")");
    if (grading.IsGraded())
    {
      headline += Fixed(summary.DiameterStenosisPercent, 0) + " % diameter stenosis, " + summary.Grade + ", in " +
                  where + ": MLD " + Fixed(summary.MinimalLumenDiameter, 2) + " mm at " +
                  Fixed(summary.MinimalLumenDiameterArcLength, 1) + " mm";
    }
    else
    {
      headline += "maximum diameter " + Fixed(summary.MaximumDiameter, 1) + " mm at " +
                  Fixed(summary.MaximumDiameterArcLength, 1) + " mm, in " + where + " (aorta; stenosis not graded)";
    }
  }
  else
  {
    headline += "none: " + summary.NotGradedBecause;
  }
  lines.push_back(headline);
  return lines;
}

LumenTableNotes
LumenTableNotesOf(const LumenMeasurement & measurement, const std::string & pathDescription)
{
  LumenTableNotes notes;
  notes.Comments.push_back("VesselReformation lumen table (docs/lumen-measurement.md); read it with comment lines "
                           "starting with #");
  for (const std::string & line : LumenSummaryLines(measurement, pathDescription))
  {
    notes.Comments.push_back(line);
  }
  for (const auto & section : measurement.Summary.Sections)
  {
    notes.Rows.push_back({ static_cast<int>(section.Segment) + 1, section.Candidate, section.ExcludedBecause });
  }
  return notes;
}

std::vector<std::pair<std::string, std::string>>
LumenSummaryValues(const LumenMeasurement & measurement)
{
  const auto & summary = measurement.Summary;
  std::string  points;
  for (const double s : summary.ReferenceArcLengths)
  {
    points += (points.empty() ? "" : ",") + Number(s);
  }
  std::string where;
  if (!std::isnan(summary.MinimalLumenDiameter))
  {
    const auto ras = LPSToRAS(summary.MinimalLumenDiameterCenter);
    where = Number(ras[0]) + "," + Number(ras[1]) + "," + Number(ras[2]);
  }
  std::string headline;
  std::string scale;
  if (summary.HeadlineSegment >= 0)
  {
    const auto & grading = summary.Segments[static_cast<std::size_t>(summary.HeadlineSegment)];
    headline = std::to_string(summary.HeadlineSegment + 1) + ": " +
               (grading.Segment.Name.empty() ? std::string() : grading.Segment.Name + ", ") +
               Fixed(grading.Segment.Begin, 1) + "–" + Fixed(grading.Segment.End, 1) + " mm";
    scale = ToString(summary.Scale);
  }
  std::string segments;
  for (std::size_t g = 0; g < summary.Segments.size(); ++g)
  {
    segments += (segments.empty() ? "" : "; ") + DescribeSegmentGrading(summary, g);
  }
  return { { "pathLength", Number(summary.PathLength) },
           { "lumenSource", itk::ToString(summary.Source) },
           { "referenceMethod", ToString(summary.Method) },
           { "referencePoints", points },
           { "minimalLumenDiameter", Number(summary.MinimalLumenDiameter) },
           { "minimalLumenDiameterArcLength", Number(summary.MinimalLumenDiameterArcLength) },
           { "minimalLumenDiameterPoint", where },
           { "minimalLumenArea", Number(summary.MinimalLumenArea) },
           { "minimalLumenAreaArcLength", Number(summary.MinimalLumenAreaArcLength) },
           { "referenceDiameter", Number(summary.ReferenceDiameter) },
           { "referenceArea", Number(summary.ReferenceArea) },
           { "diameterStenosis", Number(summary.DiameterStenosisPercent) },
           { "areaStenosis", Number(summary.AreaStenosisPercent) },
           { "cadRads", summary.CADRADS >= 0 ? std::to_string(summary.CADRADS) : std::string() },
           { "sectionsOutsideSegmentation", std::to_string(measurement.Profile.SectionsOutsideSegmentation) },
           { "referenceScope", summary.UserReferencePoints ? "the user's points" : "each segment" },
           { "gradingScale", scale },
           { "grade", summary.Grade },
           { "gradedSegment", headline },
           { "notGradedBecause", summary.NotGradedBecause },
           { "maximumDiameter", Number(summary.MaximumDiameter) },
           { "maximumDiameterArcLength", Number(summary.MaximumDiameterArcLength) },
           { "excludedSections", std::to_string(summary.ExcludedSections) },
           { "segments", segments } };
}
} // namespace vr
