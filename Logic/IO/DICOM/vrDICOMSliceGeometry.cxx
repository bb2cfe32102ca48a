// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrDICOMSliceGeometry.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <numeric>
#include <sstream>

namespace vr::detail
{
namespace
{
using Vector = std::array<double, 3>;

/** Two slices closer than this along the normal lie at one position, mm. */
constexpr double SamePosition = 0.01;
/** The absolute floor of the tolerances, mm, and their share of a spacing (docs/dicom-series.md). */
constexpr double ToleranceFloor = 0.01;
constexpr double ToleranceShare = 0.05;
/** The most slices a gap may miss and still be interpolated. */
constexpr long MaximumMissingSlices = 3;

/** One value of a Decimal String: [+-]? (digits [. digits?] | . digits) ([eE] [+-]? digits)?, padded by spaces. Longer
 * than DICOM's 16 characters is accepted: writers exceed it, and ITK reads such values right. */
std::optional<double>
ParseDecimalString(const std::string & text)
{
  const auto first = text.find_first_not_of(' ');
  if (first == std::string::npos)
  {
    return std::nullopt;
  }
  const std::string value = text.substr(first, text.find_last_not_of(' ') - first + 1);
  std::size_t       at = 0;
  if (value[at] == '+' || value[at] == '-')
  {
    ++at;
  }
  std::size_t digits = 0;
  while (at < value.size() && std::isdigit(static_cast<unsigned char>(value[at])))
  {
    ++at;
    ++digits;
  }
  if (at < value.size() && value[at] == '.')
  {
    ++at;
    while (at < value.size() && std::isdigit(static_cast<unsigned char>(value[at])))
    {
      ++at;
      ++digits;
    }
  }
  if (digits == 0)
  {
    return std::nullopt;
  }
  if (at < value.size() && (value[at] == 'e' || value[at] == 'E'))
  {
    ++at;
    if (at < value.size() && (value[at] == '+' || value[at] == '-'))
    {
      ++at;
    }
    const std::size_t exponentStart = at;
    while (at < value.size() && std::isdigit(static_cast<unsigned char>(value[at])))
    {
      ++at;
    }
    if (at == exponentStart)
    {
      return std::nullopt;
    }
  }
  if (at != value.size())
  {
    return std::nullopt;
  }
  const double number = std::strtod(value.c_str(), nullptr);
  return std::isfinite(number) ? std::optional<double>(number) : std::nullopt;
}

double
Dot(const Vector & a, const Vector & b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

Vector
Plus(const Vector & a, const Vector & b, double scale = 1.0)
{
  return { a[0] + scale * b[0], a[1] + scale * b[1], a[2] + scale * b[2] };
}

double
Length(const Vector & a)
{
  return std::sqrt(Dot(a, a));
}

/** The median of \a values (the lower middle for an even count); \a values is reordered. */
double
Median(std::vector<double> values)
{
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>((values.size() - 1) / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

/** "(x, y, z)" with six significant digits. */
std::string
Shown(const Vector & point)
{
  std::ostringstream text;
  text << "(" << point[0] << ", " << point[1] << ", " << point[2] << ")";
  return text.str();
}

std::string
Shown(double value)
{
  std::ostringstream text;
  text << value;
  return text.str();
}
} // namespace

std::optional<std::vector<double>>
ParseDecimalStrings(const std::string & text, std::size_t count)
{
  std::vector<double> values;
  std::size_t         start = 0;
  while (true)
  {
    const std::size_t end = text.find('\\', start);
    const auto        value = ParseDecimalString(text.substr(start, end - start));
    if (!value)
    {
      return std::nullopt;
    }
    values.push_back(*value);
    if (end == std::string::npos)
    {
      break;
    }
    start = end + 1;
  }
  if (values.size() != count)
  {
    return std::nullopt;
  }
  return values;
}

std::string
PlanDICOMSliceGrid(const std::vector<DICOMSlicePosition> &               files,
                   const std::array<double, 6> &                         orientation,
                   double                                                smallestPixelSpacing,
                   const std::function<bool(std::size_t, std::size_t)> & samePixels,
                   const std::optional<std::string> &                    gantryTilt,
                   DICOMSliceGrid &                                      grid)
{
  grid = DICOMSliceGrid();
  if (files.empty())
  {
    return std::string();
  }
  const Vector row{ orientation[0], orientation[1], orientation[2] };
  const Vector column{ orientation[3], orientation[4], orientation[5] };
  Vector       normal{ row[1] * column[2] - row[2] * column[1],
                 row[2] * column[0] - row[0] * column[2],
                 row[0] * column[1] - row[1] * column[0] };
  const double normalLength = Length(normal);
  for (double & component : normal)
  {
    component /= normalLength;
  }
  grid.Normal = normal;

  // Along the normal, in order; files at one position are one slice when they hold the same pixels.
  std::vector<std::size_t> order(files.size());
  std::iota(order.begin(), order.end(), std::size_t{ 0 });
  auto along = [&](std::size_t k) { return Dot(files[k].Position, normal); };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return along(a) < along(b); });
  const double             planeTolerance = std::max(ToleranceFloor, ToleranceShare * smallestPixelSpacing);
  std::vector<std::size_t> kept;
  for (const std::size_t k : order)
  {
    if (!kept.empty() && along(k) - along(kept.back()) <= SamePosition)
    {
      const std::size_t first = kept.back();
      const double      apart = Length(Plus(files[k].Position, files[first].Position, -1.0));
      if (apart <= planeTolerance && samePixels(first, k))
      {
        grid.Duplicates.push_back(k);
        grid.Warnings.push_back("the DICOM file " + files[k].File + " lies at the same position as " +
                                files[first].File + " and holds the same pixels: a duplicate, left out");
        continue;
      }
      return "the DICOM files " + files[first].File + " and " + files[k].File + " both lie in the slice plane at " +
             Shown(along(k)) + " mm along the slice normal (at " + Shown(files[first].Position) + " and " +
             Shown(files[k].Position) + " mm) but hold different images: one of them does not belong to the " +
             "series; remove it";
    }
    kept.push_back(k);
  }
  std::sort(grid.Duplicates.begin(), grid.Duplicates.end());

  // In the slice plane: every file at the series' place (its median), or the series stepping aside steadily (a
  // gantry tilt), or one file off the line.
  std::vector<Vector> offsets;
  for (const std::size_t k : kept)
  {
    offsets.push_back(Plus(files[k].Position, normal, -along(k)));
  }
  Vector median{};
  for (std::size_t c = 0; c < 3; ++c)
  {
    std::vector<double> values;
    for (const Vector & offset : offsets)
    {
      values.push_back(offset[c]);
    }
    median[c] = Median(values);
  }
  std::size_t worst = 0;
  double      worstDistance = 0.0;
  for (std::size_t j = 0; j < offsets.size(); ++j)
  {
    const double distance = Length(Plus(offsets[j], median, -1.0));
    if (distance > worstDistance)
    {
      worst = j;
      worstDistance = distance;
    }
  }
  if (worstDistance > planeTolerance)
  {
    if (kept.size() >= 3)
    {
      // A straight line of positions that is not the normal: offsets grow linearly with the distance along it.
      double meanAlong = 0.0;
      Vector meanOffset{};
      for (std::size_t j = 0; j < kept.size(); ++j)
      {
        meanAlong += along(kept[j]) / static_cast<double>(kept.size());
        meanOffset = Plus(meanOffset, offsets[j], 1.0 / static_cast<double>(kept.size()));
      }
      double sumSquares = 0.0;
      Vector slope{};
      for (std::size_t j = 0; j < kept.size(); ++j)
      {
        const double t = along(kept[j]) - meanAlong;
        sumSquares += t * t;
        slope = Plus(slope, Plus(offsets[j], meanOffset, -1.0), t);
      }
      for (double & component : slope)
      {
        component /= sumSquares;
      }
      double largestResidual = 0.0;
      for (std::size_t j = 0; j < kept.size(); ++j)
      {
        const Vector fitted = Plus(meanOffset, slope, along(kept[j]) - meanAlong);
        largestResidual = std::max(largestResidual, Length(Plus(offsets[j], fitted, -1.0)));
      }
      if (largestResidual <= planeTolerance)
      {
        const double       degrees = std::atan(Length(slope)) * 180.0 / 3.14159265358979323846;
        const double       shear = Length(slope) * (along(kept.back()) - along(kept.front()));
        std::ostringstream text;
        text.precision(3);
        text << "the DICOM series is tilted (a gantry tilt): its slices, from " << files[kept.front()].File << " to "
             << files[kept.back()].File << ", are stacked along a line at " << degrees << " degrees to their normal";
        if (gantryTilt)
        {
          text << " (Gantry/Detector Tilt (0018,1120): \"" << *gantryTilt << "\")";
        }
        text << "; a volume's axes are at right angles, and reading it so would shear the anatomy by up to " << shear
             << " mm (resample it without the tilt first, e.g. with dcm2niix)";
        return text.str();
      }
    }
    std::ostringstream text;
    text << "the DICOM file " << files[kept[worst]].File << " lies off the series' line of slices: its Image Position "
         << "(Patient) " << Shown(files[kept[worst]].Position) << " mm is " << worstDistance
         << " mm aside, in the slice plane, from where the series' other files lie";
    return text.str();
  }

  // Along the normal: a regular grid of the steps' spacing; a step of n spacings (n >= 2) misses n - 1 slices.
  if (kept.size() == 1)
  {
    grid.Origin = files[kept.front()].Position;
    grid.Slices.push_back({ kept.front(), kept.front(), 0.0 });
    return std::string();
  }
  std::vector<double> steps;
  for (std::size_t j = 0; j + 1 < kept.size(); ++j)
  {
    steps.push_back(along(kept[j + 1]) - along(kept[j]));
  }
  const double      typical = Median(steps);
  std::vector<long> index(kept.size(), 0);
  std::vector<long> counts;
  for (std::size_t j = 0; j < steps.size(); ++j)
  {
    counts.push_back(std::max(1L, std::lround(steps[j] / typical)));
    index[j + 1] = index[j] + counts.back();
  }
  std::vector<double> perSlice;
  for (std::size_t j = 0; j < steps.size(); ++j)
  {
    perSlice.push_back(steps[j] / static_cast<double>(counts[j]));
  }
  const double spacing = Median(perSlice);
  const double normalTolerance = std::max(ToleranceFloor, ToleranceShare * spacing);
  auto         irregular = [&](std::size_t s)
  {
    std::ostringstream text;
    text << "the DICOM files " << files[kept[s]].File << " and " << files[kept[s + 1]].File << " lie " << steps[s]
         << " mm apart along the slice normal, where the series steps by " << spacing
         << " mm: the slices are not evenly spaced (no whole number of steps), so they cannot be placed on a volume's "
            "grid";
    return text.str();
  };
  // Each step a whole number of spacings: a file out of place is named with its neighbour.
  for (std::size_t j = 0; j < steps.size(); ++j)
  {
    if (std::abs(steps[j] - spacing * static_cast<double>(counts[j])) > normalTolerance)
    {
      return irregular(j);
    }
  }
  // And every file at its place on the grid: steps each a little off one way would add up.
  std::vector<double> starts;
  for (std::size_t j = 0; j < kept.size(); ++j)
  {
    starts.push_back(along(kept[j]) - spacing * static_cast<double>(index[j]));
  }
  const double start = Median(starts);
  for (std::size_t j = 0; j < kept.size(); ++j)
  {
    if (std::abs(starts[j] - start) > normalTolerance)
    {
      return irregular(j == 0 ? 0 : j - 1);
    }
  }
  for (std::size_t j = 0; j < steps.size(); ++j)
  {
    if (counts[j] - 1 > MaximumMissingSlices)
    {
      std::ostringstream text;
      text << "the DICOM files " << files[kept[j]].File << " and " << files[kept[j + 1]].File << " lie " << steps[j]
           << " mm apart along the slice normal, where the series steps by " << spacing << " mm: " << counts[j] - 1
           << " slices are missing between them, more than the " << MaximumMissingSlices
           << " a gap may miss to be interpolated";
      return text.str();
    }
  }

  grid.SliceSpacing = spacing;
  grid.Origin = Plus(median, normal, start);
  for (std::size_t j = 0; j < kept.size(); ++j)
  {
    grid.Slices.push_back({ kept[j], kept[j], 0.0 });
    if (j + 1 == kept.size() || counts[j] == 1)
    {
      continue;
    }
    std::ostringstream text;
    text << "the DICOM series has a gap of " << steps[j] << " mm between the files " << files[kept[j]].File << " and "
         << files[kept[j + 1]].File << ", where it steps by " << spacing << " mm: "
         << (counts[j] == 2 ? "the missing slice at " : std::to_string(counts[j] - 1) + " missing slices, at ");
    for (long m = 1; m < counts[j]; ++m)
    {
      const double weight = static_cast<double>(m) / static_cast<double>(counts[j]);
      grid.Slices.push_back({ kept[j], kept[j + 1], weight });
      text << (m == 1 ? "" : ", ") << Shown(Plus(grid.Origin, normal, spacing * static_cast<double>(index[j] + m)));
    }
    text << " mm" << (counts[j] == 2 ? " is" : ", are") << " interpolated linearly from those two files";
    grid.Warnings.push_back(text.str());
  }
  return std::string();
}
} // namespace vr::detail
