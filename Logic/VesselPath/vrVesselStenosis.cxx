// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrVesselStenosis.h"

#include "vrInputError.h"
#include "vrParameterName.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <sstream>

namespace vr
{
const char *
ToString(VesselReferenceMethod method)
{
  return method == VesselReferenceMethod::Interpolated ? "interpolated" : "robust fit";
}

namespace
{
constexpr double Pi = 3.14159265358979323846;

struct Sample
{
  double S;
  double D;
};

/** The samples' value at \a s: linear between the samples on either side, the nearest one where there is a side
 * without (so: constant beyond the first and the last). */
double
ValueAt(const std::vector<Sample> & samples, double s)
{
  const auto after = std::lower_bound(
    samples.begin(), samples.end(), s, [](const Sample & sample, double value) { return sample.S < value; });
  if (after == samples.begin())
  {
    return after->D;
  }
  if (after == samples.end())
  {
    return samples.back().D;
  }
  const Sample & b = *after;
  const Sample & a = *(after - 1);
  if (b.S == a.S)
  {
    return 0.5 * (a.D + b.D);
  }
  const double t = (s - a.S) / (b.S - a.S);
  return a.D + t * (b.D - a.D);
}

double
Median(std::vector<double> values)
{
  const std::size_t middle = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<long>(middle), values.end());
  double median = values[middle];
  if (values.size() % 2 == 0)
  {
    median = 0.5 * (median + *std::max_element(values.begin(), values.begin() + static_cast<long>(middle)));
  }
  return median;
}

struct Line
{
  double Intercept; // at the span's first arc length
  double Slope;

  double
  At(double s, double s0) const
  {
    return Intercept + Slope * (s - s0);
  }
};

/** Theil-Sen: the median of the pairwise slopes (of at most 600 evenly chosen samples), then the median
 * intercept. Robust to about 29 % of outliers: the start of the reweighting. */
Line
TheilSen(const std::vector<Sample> & samples, double s0)
{
  const std::size_t   stride = std::max<std::size_t>(1, samples.size() / 600);
  std::vector<Sample> chosen;
  for (std::size_t k = 0; k < samples.size(); k += stride)
  {
    chosen.push_back(samples[k]);
  }
  std::vector<double> slopes;
  for (std::size_t i = 0; i < chosen.size(); ++i)
  {
    for (std::size_t j = i + 1; j < chosen.size(); ++j)
    {
      if (chosen[j].S != chosen[i].S)
      {
        slopes.push_back((chosen[j].D - chosen[i].D) / (chosen[j].S - chosen[i].S));
      }
    }
  }
  Line                line{ 0.0, slopes.empty() ? 0.0 : Median(slopes) };
  std::vector<double> intercepts;
  for (const auto & sample : samples)
  {
    intercepts.push_back(sample.D - line.Slope * (sample.S - s0));
  }
  line.Intercept = Median(intercepts);
  return line;
}

/** Tukey's biweight by iteratively reweighted least squares from the Theil-Sen line. The scale is the residuals'
 * median absolute deviation (x 1.4826), floored at 0.5 % of the median diameter so that an exact profile (a
 * synthetic tube) still gives a finite weight to what lies on the line. */
Line
RobustLine(const std::vector<Sample> & samples, double s0)
{
  constexpr double TukeyC = 4.685;
  Line             line = TheilSen(samples, s0);
  if (samples.size() < 2)
  {
    return line;
  }
  std::vector<double> diameters;
  for (const auto & sample : samples)
  {
    diameters.push_back(sample.D);
  }
  const double        floor = 0.005 * std::abs(Median(diameters));
  std::vector<double> residuals(samples.size());
  for (int iteration = 0; iteration < 100; ++iteration)
  {
    for (std::size_t k = 0; k < samples.size(); ++k)
    {
      residuals[k] = samples[k].D - line.At(samples[k].S, s0);
    }
    std::vector<double> absolute(residuals.size());
    std::transform(residuals.begin(), residuals.end(), absolute.begin(), [](double r) { return std::abs(r); });
    const double scale = std::max(1.4826 * Median(absolute), std::max(floor, 1e-9));
    double       sw = 0.0;
    double       sws = 0.0;
    double       swd = 0.0;
    double       swss = 0.0;
    double       swsd = 0.0;
    for (std::size_t k = 0; k < samples.size(); ++k)
    {
      const double u = residuals[k] / (TukeyC * scale);
      const double w = std::abs(u) < 1.0 ? (1.0 - u * u) * (1.0 - u * u) : 0.0;
      const double s = samples[k].S - s0;
      sw += w;
      sws += w * s;
      swd += w * samples[k].D;
      swss += w * s * s;
      swsd += w * s * samples[k].D;
    }
    const double determinant = sw * swss - sws * sws;
    if (!(sw > 0.0) || !(std::abs(determinant) > 1e-12 * std::max(1.0, sw * swss)))
    {
      break;
    }
    const Line next{ (swss * swd - sws * swsd) / determinant, (sw * swsd - sws * swd) / determinant };
    const bool converged =
      std::abs(next.Intercept - line.Intercept) < 1e-9 && std::abs(next.Slope - line.Slope) < 1e-12;
    line = next;
    if (converged)
    {
      break;
    }
  }
  return line;
}

/** A reference along part of the path: interpolated between points, or a robust line. */
struct Reference
{
  bool                  Valid{ false };
  VesselReferenceMethod Method{ VesselReferenceMethod::Interpolated };
  std::vector<Sample>   Points;
  Line                  Fit{ 0.0, 0.0 };
  double                Start{ 0.0 };

  double
  At(double s) const
  {
    if (!Valid)
    {
      return std::numeric_limits<double>::quiet_NaN();
    }
    return Method == VesselReferenceMethod::Interpolated ? ValueAt(Points, s) : Fit.At(s, Start);
  }
};

/** The reference of \a samples (ascending S) through \a points (ascending): the samples' values there
 * (interpolated), or the robust line over the samples between the first and the last point. */
Reference
MakeReference(VesselReferenceMethod method, const std::vector<Sample> & samples, const std::vector<double> & points)
{
  Reference reference;
  reference.Method = method;
  if (samples.empty() || points.empty())
  {
    return reference;
  }
  if (method == VesselReferenceMethod::Interpolated)
  {
    for (const double s : points)
    {
      reference.Points.push_back({ s, ValueAt(samples, s) });
    }
    reference.Valid = true;
    return reference;
  }
  std::vector<Sample> span;
  std::copy_if(samples.begin(),
               samples.end(),
               std::back_inserter(span),
               [&](const Sample & sample) { return sample.S >= points.front() && sample.S <= points.back(); });
  if (span.empty())
  {
    return reference;
  }
  reference.Start = points.front();
  reference.Fit = RobustLine(span, reference.Start);
  reference.Valid = true;
  return reference;
}

void
CheckPath(const itk::VesselLumenProfile & profile)
{
  const auto & sections = profile.Sections;
  if (sections.size() < 2)
  {
    throw InputError("stenosis: the path has " + std::to_string(sections.size()) +
                     " section(s); a profile needs at least two");
  }
  for (std::size_t k = 0; k < sections.size(); ++k)
  {
    if (!std::isfinite(sections[k].ArcLength) || (k > 0 && sections[k].ArcLength < sections[k - 1].ArcLength))
    {
      std::ostringstream message;
      message << "stenosis: section " << k << "'s arc length " << sections[k].ArcLength
              << " mm is not finite or decreases along the path";
      throw InputError(message.str());
    }
  }
  if (!(sections.back().ArcLength > sections.front().ArcLength))
  {
    throw InputError("stenosis: the path has length 0");
  }
}

/** The user's reference points, checked, sorted and without repeats. */
std::vector<double>
UserPoints(const itk::VesselLumenProfile & profile, const VesselStenosisOptions & options)
{
  const double        first = profile.Sections.front().ArcLength;
  const double        last = profile.Sections.back().ArcLength;
  std::vector<double> points = options.ReferenceArcLengths;
  std::ostringstream  outside;
  std::size_t         bad = 0;
  for (const double s : points)
  {
    if (!std::isfinite(s) || s < first || s > last)
    {
      outside << (bad++ ? ", " : "") << s << " mm";
    }
  }
  if (bad > 0)
  {
    std::ostringstream message;
    message << "reference point" << (bad > 1 ? "s " : " ") << outside.str() << (bad > 1 ? " lie" : " lies")
            << " outside the path (arc length " << first << " to " << last << " mm)";
    throw InputError(message.str(), ParameterName::ReferencePoints);
  }
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (options.Method == VesselReferenceMethod::RobustFit && points.size() == 1)
  {
    throw InputError("the robust-fit reference needs two distinct reference points (the span it fits), got 1",
                     ParameterName::ReferencePoints);
  }
  return points;
}

/** The radius to measure a margin with near section \a k: the centerline's, else half the median measured diameter
 * within 5 mm (on the side of \a side: -1 before, +1 after, 0 both), else 0. */
double
LocalRadius(const itk::VesselLumenProfile & profile, double s, int side)
{
  std::vector<double> diameters;
  double              inscribed = std::numeric_limits<double>::quiet_NaN();
  double              nearest = std::numeric_limits<double>::infinity();
  for (const auto & section : profile.Sections)
  {
    const double offset = section.ArcLength - s;
    if (std::abs(offset) < nearest && std::isfinite(section.InscribedDiameter) && offset * side >= 0.0)
    {
      nearest = std::abs(offset);
      inscribed = section.InscribedDiameter;
    }
    if (std::abs(offset) <= 5.0 && offset * side >= 0.0 && section.IsMeasured())
    {
      diameters.push_back(section.Diameter);
    }
  }
  if (std::isfinite(inscribed) && nearest <= 5.0)
  {
    return 0.5 * inscribed;
  }
  return diameters.empty() ? 0.0 : 0.5 * Median(diameters);
}

std::string
Millimetres(double value)
{
  std::ostringstream text;
  text.setf(std::ios::fixed);
  text.precision(1);
  text << value << " mm";
  return text.str();
}

/** Which sections may hold the MLD, and why the others may not. */
std::vector<SectionGrading>
MarkSections(const itk::VesselLumenProfile & profile, const PathLayout & layout, std::size_t & excluded)
{
  const auto & sections = profile.Sections;
  const double first = sections.front().ArcLength;
  const double last = sections.back().ArcLength;
  struct Margin
  {
    double      Begin;
    double      End;
    std::string Why;
  };
  std::vector<Margin> margins;
  if (layout.StartIsVesselEnd)
  {
    margins.push_back({ -std::numeric_limits<double>::infinity(),
                        first + std::max(MinimumExclusionMargin, LocalRadius(profile, first, 1)),
                        "path start" });
  }
  if (layout.EndIsVesselEnd)
  {
    margins.push_back({ last - std::max(MinimumExclusionMargin, LocalRadius(profile, last, -1)),
                        std::numeric_limits<double>::infinity(),
                        "path end" });
  }
  for (const auto & junction : layout.Junctions)
  {
    const double radius = std::isfinite(junction.ParentRadius)
                            ? junction.ParentRadius
                            : LocalRadius(profile, junction.ArcLength, junction.OnPath ? -1 : 0);
    const double margin = std::max(MinimumExclusionMargin, radius);
    margins.push_back({ junction.ArcLength - margin,
                        junction.ArcLength + margin,
                        junction.OnPath ? "junction into branch " + std::to_string(junction.BranchId)
                                        : "origin of branch " + std::to_string(junction.BranchId) });
  }
  std::vector<SectionGrading> marks(sections.size());
  excluded = 0;
  std::size_t segment = 0;
  for (std::size_t k = 0; k < sections.size(); ++k)
  {
    const double s = sections[k].ArcLength;
    while (segment + 1 < layout.Segments.size() && s >= layout.Segments[segment].End)
    {
      ++segment;
    }
    marks[k].Segment = segment;
    for (const Margin & margin : margins)
    {
      if (s >= margin.Begin && s <= margin.End)
      {
        marks[k].ExcludedBecause = margin.Why;
        ++excluded;
        break;
      }
    }
    if (marks[k].ExcludedBecause.empty() && !sections[k].IsMeasured())
    {
      marks[k].ExcludedBecause = "not measured";
    }
    marks[k].Candidate = marks[k].ExcludedBecause.empty();
  }
  return marks;
}

/** The segment's scale and why. */
void
ChooseScale(SegmentGrading & grading, StenosisScale chosen, double medianDiameter)
{
  const std::string & name = grading.Segment.Name;
  if (chosen != StenosisScale::Automatic)
  {
    grading.Scale = chosen;
    grading.ScaleReason = "chosen by the user";
    return;
  }
  const StenosisScale byName = ScaleOfVesselName(name);
  if (byName != StenosisScale::Automatic)
  {
    grading.Scale = byName;
    grading.ScaleReason = "by its name";
    return;
  }
  if (name.empty() && std::isfinite(medianDiameter) && medianDiameter >= AortaSizedDiameter)
  {
    grading.Scale = StenosisScale::Aorta;
    grading.ScaleReason = "by its size: unnamed, median diameter " + Millimetres(medianDiameter) + " (aorta-sized, " +
                          Millimetres(AortaSizedDiameter) + " or more)";
    return;
  }
  grading.Scale = StenosisScale::Peripheral;
  grading.ScaleReason =
    name.empty() ? "unnamed, median diameter " + Millimetres(medianDiameter) + ": taken for a peripheral artery"
                 : "by its name: not an aorta, a coronary or a carotid artery";
}

std::string
DescribeSegment(std::size_t index, const SegmentGrading & grading)
{
  std::ostringstream text;
  text.setf(std::ios::fixed);
  text.precision(1);
  text << "segment " << index + 1 << " (";
  if (!grading.Segment.Name.empty())
  {
    text << grading.Segment.Name << ", ";
  }
  text << grading.Segment.Begin << "–" << grading.Segment.End << " mm)";
  return text.str();
}
} // namespace

VesselStenosisSummary
AnalyseVesselStenosis(itk::VesselLumenProfile & profile, const VesselStenosisOptions & options)
{
  CheckPath(profile);
  const std::vector<double> userPoints = UserPoints(profile, options);
  auto &                    sections = profile.Sections;

  VesselStenosisSummary summary;
  summary.Source = profile.Source;
  summary.Method = options.Method;
  summary.UserReferencePoints = !userPoints.empty();
  summary.PathLength = sections.back().ArcLength - sections.front().ArcLength;

  // The area profile: measured areas, or the circle of the diameter for the centerline-radius source.
  const bool segmentation = profile.Source == itk::VesselLumenSource::Segmentation;
  const auto areaOf = [segmentation](const itk::VesselLumenSection & section)
  { return segmentation ? section.Area : 0.25 * Pi * section.Diameter * section.Diameter; };
  std::vector<Sample> allDiameters;
  std::vector<Sample> allAreas;
  for (const auto & section : sections)
  {
    if (section.IsMeasured())
    {
      allDiameters.push_back({ section.ArcLength, section.Diameter });
      allAreas.push_back({ section.ArcLength, areaOf(section) });
    }
  }
  summary.MeasuredSections = allDiameters.size();
  if (allDiameters.empty())
  {
    throw InputError("stenosis: no section of the path has a measured diameter");
  }

  PathLayout layout = options.Layout;
  if (layout.Segments.empty())
  {
    layout.Segments.push_back({ sections.front().ArcLength, sections.back().ArcLength, 0, std::string() });
  }
  summary.Sections = MarkSections(profile, layout, summary.ExcludedSections);

  // The user's points give one reference over the whole path, from every measured section.
  const Reference userDiameter = MakeReference(options.Method, allDiameters, userPoints);
  const Reference userArea = MakeReference(options.Method, allAreas, userPoints);

  for (std::size_t g = 0; g < layout.Segments.size(); ++g)
  {
    SegmentGrading grading;
    grading.Segment = layout.Segments[g];
    std::vector<Sample>      diameters;
    std::vector<Sample>      areas;
    std::vector<std::size_t> candidates;
    std::vector<double>      measuredInSegment;
    for (std::size_t k = 0; k < sections.size(); ++k)
    {
      if (summary.Sections[k].Segment != g)
      {
        continue;
      }
      if (sections[k].IsMeasured())
      {
        measuredInSegment.push_back(sections[k].Diameter);
      }
      if (summary.Sections[k].Candidate)
      {
        candidates.push_back(k);
        diameters.push_back({ sections[k].ArcLength, sections[k].Diameter });
        areas.push_back({ sections[k].ArcLength, areaOf(sections[k]) });
      }
    }
    grading.Candidates = candidates.size();
    std::vector<double> sizes;
    for (const auto & sample : diameters)
    {
      sizes.push_back(sample.D);
    }
    const double median = !sizes.empty()               ? Median(sizes)
                          : !measuredInSegment.empty() ? Median(measuredInSegment)
                                                       : std::numeric_limits<double>::quiet_NaN();
    ChooseScale(grading, options.Scale, median);

    // The segment's own reference between the ends of its candidates, or the user's.
    Reference diameterReference = userDiameter;
    Reference areaReference = userArea;
    if (userPoints.empty())
    {
      if (candidates.size() >= MinimumCandidates)
      {
        grading.ReferenceArcLengths = { diameters.front().S, diameters.back().S };
        diameterReference = MakeReference(options.Method, diameters, grading.ReferenceArcLengths);
        areaReference = MakeReference(options.Method, areas, grading.ReferenceArcLengths);
      }
      else
      {
        diameterReference = Reference();
        areaReference = Reference();
        std::ostringstream why;
        why.setf(std::ios::fixed);
        why.precision(1);
        if (measuredInSegment.empty())
        {
          why << "no section measured";
        }
        else if (candidates.empty())
        {
          why << "no section outside the margins of its ends and branch origins ("
              << grading.Segment.End - grading.Segment.Begin << " mm long)";
        }
        else
        {
          why << "too short for two reference points: " << candidates.size()
              << " measured section(s) outside the margins of its ends and branch origins ("
              << grading.Segment.End - grading.Segment.Begin << " mm long)";
        }
        grading.NotGradedBecause = why.str();
      }
    }
    else
    {
      grading.ReferenceArcLengths = userPoints;
      if (candidates.empty())
      {
        grading.NotGradedBecause = measuredInSegment.empty()
                                     ? "no section measured"
                                     : "every measured section lies within a margin of an end or a branch origin";
      }
    }
    for (std::size_t k = 0; k < sections.size(); ++k)
    {
      if (summary.Sections[k].Segment == g)
      {
        sections[k].ReferenceDiameter = diameterReference.At(sections[k].ArcLength);
        sections[k].ReferenceArea = areaReference.At(sections[k].ArcLength);
      }
    }

    // MLD, MLA and the widest section among the candidates.
    const itk::VesselLumenSection * narrowest = nullptr;
    const itk::VesselLumenSection * smallest = nullptr;
    const itk::VesselLumenSection * widest = nullptr;
    for (const std::size_t k : candidates)
    {
      const auto & section = sections[k];
      narrowest = narrowest == nullptr || section.Diameter < narrowest->Diameter ? &section : narrowest;
      smallest = smallest == nullptr || areaOf(section) < areaOf(*smallest) ? &section : smallest;
      widest = widest == nullptr || section.Diameter > widest->Diameter ? &section : widest;
    }
    if (widest != nullptr)
    {
      grading.MaximumDiameter = widest->Diameter;
      grading.MaximumDiameterArcLength = widest->ArcLength;
    }
    if (narrowest != nullptr && diameterReference.Valid)
    {
      grading.MinimalLumenDiameter = narrowest->Diameter;
      grading.MinimalLumenDiameterArcLength = narrowest->ArcLength;
      grading.MinimalLumenDiameterCenter = narrowest->Center;
      grading.ReferenceDiameter = narrowest->ReferenceDiameter;
      grading.MinimalLumenArea = areaOf(*smallest);
      grading.MinimalLumenAreaArcLength = smallest->ArcLength;
      grading.ReferenceArea = smallest->ReferenceArea;
      if (grading.ReferenceDiameter > 0.0)
      {
        grading.DiameterStenosisPercent = 100.0 * (1.0 - grading.MinimalLumenDiameter / grading.ReferenceDiameter);
      }
      if (grading.ReferenceArea > 0.0)
      {
        grading.AreaStenosisPercent = 100.0 * (1.0 - grading.MinimalLumenArea / grading.ReferenceArea);
      }
      if (grading.Scale == StenosisScale::Aorta)
      {
        grading.NotGradedBecause = "the aorta is sized, not graded: its headline is the maximum diameter";
      }
      else
      {
        grading.Category = StenosisCategory(grading.Scale, grading.DiameterStenosisPercent);
        grading.Grade = StenosisCategoryText(grading.Scale, grading.Category);
        if (grading.Category < 0)
        {
          grading.NotGradedBecause = "the reference diameter is not positive";
        }
      }
    }
    summary.Segments.push_back(grading);
  }

  // The headline: the most severe graded stenosis; else the aorta's maximum diameter.
  int worst = -1;
  int widestAorta = -1;
  for (std::size_t g = 0; g < summary.Segments.size(); ++g)
  {
    const SegmentGrading & grading = summary.Segments[g];
    // On a tie the later segment wins: the vessel the path was opened for.
    if (grading.IsGraded() &&
        (worst < 0 ||
         grading.DiameterStenosisPercent >= summary.Segments[static_cast<std::size_t>(worst)].DiameterStenosisPercent))
    {
      worst = static_cast<int>(g);
    }
    if (grading.Scale == StenosisScale::Aorta && std::isfinite(grading.MaximumDiameter) &&
        (widestAorta < 0 ||
         grading.MaximumDiameter > summary.Segments[static_cast<std::size_t>(widestAorta)].MaximumDiameter))
    {
      widestAorta = static_cast<int>(g);
    }
  }
  if (widestAorta >= 0)
  {
    const SegmentGrading & aorta = summary.Segments[static_cast<std::size_t>(widestAorta)];
    summary.MaximumDiameter = aorta.MaximumDiameter;
    summary.MaximumDiameterArcLength = aorta.MaximumDiameterArcLength;
  }
  summary.HeadlineSegment = worst >= 0 ? worst : widestAorta;
  if (summary.HeadlineSegment >= 0)
  {
    const SegmentGrading & headline = summary.Segments[static_cast<std::size_t>(summary.HeadlineSegment)];
    summary.Scale = headline.Scale;
    summary.ReferenceArcLengths = headline.ReferenceArcLengths;
    summary.MinimalLumenDiameter = headline.MinimalLumenDiameter;
    summary.MinimalLumenDiameterArcLength = headline.MinimalLumenDiameterArcLength;
    summary.MinimalLumenDiameterCenter = headline.MinimalLumenDiameterCenter;
    summary.MinimalLumenArea = headline.MinimalLumenArea;
    summary.MinimalLumenAreaArcLength = headline.MinimalLumenAreaArcLength;
    summary.ReferenceDiameter = headline.ReferenceDiameter;
    summary.ReferenceArea = headline.ReferenceArea;
    summary.DiameterStenosisPercent = headline.DiameterStenosisPercent;
    summary.AreaStenosisPercent = headline.AreaStenosisPercent;
    summary.Grade = headline.Grade;
    summary.CADRADS = headline.Scale == StenosisScale::CADRADS ? headline.Category : -1;
  }
  else if (!summary.Segments.empty())
  {
    summary.Scale = summary.Segments.front().Scale;
  }
  if (worst < 0)
  {
    std::string reasons;
    for (std::size_t g = 0; g < summary.Segments.size(); ++g)
    {
      const std::string & why = summary.Segments[g].NotGradedBecause;
      reasons += (reasons.empty() ? "" : "; ") + DescribeSegment(g, summary.Segments[g]) + ": " +
                 (why.empty() ? std::string("not graded") : why);
    }
    summary.NotGradedBecause = reasons;
  }
  return summary;
}
} // namespace vr
