// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrVesselStenosis.h"

#include "itkMacro.h"

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

int
CADRADSClass(double diameterStenosisPercent)
{
  if (std::isnan(diameterStenosisPercent))
  {
    return -1;
  }
  if (diameterStenosisPercent >= 100.0)
  {
    return 5;
  }
  // Halves up; some lumen left is never an occlusion.
  const double percent = std::min(99.0, std::floor(diameterStenosisPercent + 0.5));
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

namespace
{
constexpr double Pi = 3.14159265358979323846;

struct Sample
{
  double S;
  double D;
};

/** The measured (arc length, diameter) pairs of the profile, in its order. */
std::vector<Sample>
MeasuredSamples(const itk::VesselLumenProfile & profile)
{
  std::vector<Sample> samples;
  for (const auto & section : profile.Sections)
  {
    if (section.IsMeasured())
    {
      samples.push_back({ section.ArcLength, section.Diameter });
    }
  }
  return samples;
}

/** The profile's diameter at \a s: linear between the measured sections on either side, the nearest one where
 * there is a side without. */
double
DiameterAt(const std::vector<Sample> & samples, double s)
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

/** Piecewise linear through \a points (ascending S), constant beyond the first and the last. */
double
PiecewiseLinear(const std::vector<Sample> & points, double s)
{
  return DiameterAt(points, s);
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

void
CheckPath(const itk::VesselLumenProfile & profile)
{
  const auto & sections = profile.Sections;
  if (sections.size() < 2)
  {
    itkGenericExceptionMacro(<< "stenosis: the path has " << sections.size()
                             << " section(s); a profile needs at least two");
  }
  for (std::size_t k = 0; k < sections.size(); ++k)
  {
    if (!std::isfinite(sections[k].ArcLength) || (k > 0 && sections[k].ArcLength < sections[k - 1].ArcLength))
    {
      itkGenericExceptionMacro(<< "stenosis: section " << k << "'s arc length " << sections[k].ArcLength
                               << " mm is not finite or decreases along the path");
    }
  }
  if (!(sections.back().ArcLength > sections.front().ArcLength))
  {
    itkGenericExceptionMacro(<< "stenosis: the path has length 0");
  }
}

std::vector<double>
ReferencePoints(const itk::VesselLumenProfile & profile, const VesselStenosisOptions & options)
{
  const double        first = profile.Sections.front().ArcLength;
  const double        last = profile.Sections.back().ArcLength;
  std::vector<double> points = options.ReferenceArcLengths;
  if (points.empty())
  {
    points = { first + 0.05 * (last - first), first + 0.95 * (last - first) };
  }
  std::ostringstream outside;
  std::size_t        bad = 0;
  for (const double s : points)
  {
    if (!std::isfinite(s) || s < first || s > last)
    {
      outside << (bad++ ? ", " : "") << s << " mm";
    }
  }
  if (bad > 0)
  {
    itkGenericExceptionMacro(<< "stenosis: reference point" << (bad > 1 ? "s " : " ") << outside.str()
                             << (bad > 1 ? " lie" : " lies") << " outside the path (arc length " << first << " to "
                             << last << " mm)");
  }
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (options.Method == VesselReferenceMethod::RobustFit && points.size() < 2)
  {
    itkGenericExceptionMacro(<< "stenosis: the robust fit needs two distinct reference points (the span it fits), "
                             << "got " << points.size());
  }
  return points;
}
} // namespace

VesselStenosisSummary
AnalyseVesselStenosis(itk::VesselLumenProfile & profile, const VesselStenosisOptions & options)
{
  CheckPath(profile);
  VesselStenosisSummary summary;
  summary.Source = profile.Source;
  summary.Method = options.Method;
  summary.PathLength = profile.Sections.back().ArcLength - profile.Sections.front().ArcLength;
  summary.ReferenceArcLengths = ReferencePoints(profile, options);
  const double spanFirst = summary.ReferenceArcLengths.front();
  const double spanLast = summary.ReferenceArcLengths.back();

  // The area profile: measured areas, or the circle of the diameter for the centerline-radius source.
  const bool segmentation = profile.Source == itk::VesselLumenSource::Segmentation;
  const auto areaOf = [segmentation](const itk::VesselLumenSection & section)
  { return segmentation ? section.Area : 0.25 * Pi * section.Diameter * section.Diameter; };
  std::vector<Sample> diameters;
  std::vector<Sample> areas;
  std::size_t         inSpan = 0;
  for (const auto & section : profile.Sections)
  {
    if (section.IsMeasured())
    {
      diameters.push_back({ section.ArcLength, section.Diameter });
      areas.push_back({ section.ArcLength, areaOf(section) });
      inSpan += section.ArcLength >= spanFirst && section.ArcLength <= spanLast ? 1 : 0;
    }
  }
  summary.MeasuredSections = diameters.size();
  summary.MeasuredSectionsInSpan = inSpan;
  if (diameters.empty() || (options.Method == VesselReferenceMethod::RobustFit && inSpan == 0))
  {
    itkGenericExceptionMacro(<< "stenosis: no section "
                             << (diameters.empty() ? "of the path" : "between the reference points")
                             << " has a measured diameter");
  }

  // The same reference method on the diameters and on the areas, over the whole path.
  const auto reference = [&](const std::vector<Sample> & samples, auto assign)
  {
    if (options.Method == VesselReferenceMethod::Interpolated)
    {
      std::vector<Sample> points;
      for (const double s : summary.ReferenceArcLengths)
      {
        points.push_back({ s, DiameterAt(samples, s) });
      }
      for (auto & section : profile.Sections)
      {
        assign(section, PiecewiseLinear(points, section.ArcLength));
      }
    }
    else
    {
      std::vector<Sample> span;
      std::copy_if(samples.begin(),
                   samples.end(),
                   std::back_inserter(span),
                   [&](const Sample & sample) { return sample.S >= spanFirst && sample.S <= spanLast; });
      const Line line = RobustLine(span, spanFirst);
      for (auto & section : profile.Sections)
      {
        assign(section, line.At(section.ArcLength, spanFirst));
      }
    }
  };
  reference(diameters, [](itk::VesselLumenSection & section, double value) { section.ReferenceDiameter = value; });
  reference(areas, [](itk::VesselLumenSection & section, double value) { section.ReferenceArea = value; });

  // MLD and MLA over the whole path (docs/lumen-measurement.md).
  const itk::VesselLumenSection * narrowest = nullptr;
  const itk::VesselLumenSection * smallest = nullptr;
  for (const auto & section : profile.Sections)
  {
    if (!section.IsMeasured())
    {
      continue;
    }
    if (narrowest == nullptr || section.Diameter < narrowest->Diameter)
    {
      narrowest = &section;
    }
    if (smallest == nullptr || areaOf(section) < areaOf(*smallest))
    {
      smallest = &section;
    }
  }
  summary.MinimalLumenDiameter = narrowest->Diameter;
  summary.MinimalLumenDiameterArcLength = narrowest->ArcLength;
  summary.MinimalLumenDiameterCenter = narrowest->Center;
  summary.ReferenceDiameter = narrowest->ReferenceDiameter;
  summary.MinimalLumenArea = areaOf(*smallest);
  summary.MinimalLumenAreaArcLength = smallest->ArcLength;
  summary.ReferenceArea = smallest->ReferenceArea;
  if (summary.ReferenceDiameter > 0.0)
  {
    summary.DiameterStenosisPercent = 100.0 * (1.0 - summary.MinimalLumenDiameter / summary.ReferenceDiameter);
  }
  if (summary.ReferenceArea > 0.0)
  {
    summary.AreaStenosisPercent = 100.0 * (1.0 - summary.MinimalLumenArea / summary.ReferenceArea);
  }
  summary.CADRADS = CADRADSClass(summary.DiameterStenosisPercent);
  return summary;
}

} // namespace vr
