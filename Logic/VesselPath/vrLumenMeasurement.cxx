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
  if (parameters.ReferenceMethod == vr::VesselReferenceMethod::RobustFit && parameters.ReferenceArcLengths.size() == 1)
  {
    throw InputError("the robust-fit reference needs two reference points (the span it fits), or none for 5 % and "
                     "95 % of the path",
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

  vr::VesselStenosisOptions options;
  options.Method = parameters.ReferenceMethod;
  options.ReferenceArcLengths = parameters.ReferenceArcLengths;
  try
  {
    result.Summary = vr::AnalyseVesselStenosis(result.Profile, options);
  }
  catch (const itk::ExceptionObject & exception)
  {
    throw InputError(detail::CondenseITKMessage(exception), ParameterName::ReferencePoints);
  }
  return result;
}

std::vector<std::pair<std::string, std::string>>
LumenSummaryValues(const LumenMeasurement & measurement)
{
  const auto & summary = measurement.Summary;
  const auto   number = [](double value)
  {
    if (std::isnan(value))
    {
      return std::string();
    }
    std::ostringstream text;
    text.precision(10);
    text << value;
    return text.str();
  };
  std::string points;
  for (const double s : summary.ReferenceArcLengths)
  {
    points += (points.empty() ? "" : ",") + number(s);
  }
  std::string where;
  if (!std::isnan(summary.MinimalLumenDiameter))
  {
    const auto ras = LPSToRAS(summary.MinimalLumenDiameterCenter);
    where = number(ras[0]) + "," + number(ras[1]) + "," + number(ras[2]);
  }
  return { { "pathLength", number(summary.PathLength) },
           { "lumenSource", itk::ToString(summary.Source) },
           { "referenceMethod", vr::ToString(summary.Method) },
           { "referencePoints", points },
           { "minimalLumenDiameter", number(summary.MinimalLumenDiameter) },
           { "minimalLumenDiameterArcLength", number(summary.MinimalLumenDiameterArcLength) },
           { "minimalLumenDiameterPoint", where },
           { "minimalLumenArea", number(summary.MinimalLumenArea) },
           { "minimalLumenAreaArcLength", number(summary.MinimalLumenAreaArcLength) },
           { "referenceDiameter", number(summary.ReferenceDiameter) },
           { "referenceArea", number(summary.ReferenceArea) },
           { "diameterStenosis", number(summary.DiameterStenosisPercent) },
           { "areaStenosis", number(summary.AreaStenosisPercent) },
           { "cadRads", summary.CADRADS >= 0 ? std::to_string(summary.CADRADS) : std::string() },
           { "sectionsOutsideSegmentation", std::to_string(measurement.Profile.SectionsOutsideSegmentation) } };
}
} // namespace vr
