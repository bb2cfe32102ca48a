// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrDICOMSliceGeometry.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace vr::detail
{
namespace
{
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

/** \a text as a user can read it in a message: printable ASCII, at most 64 characters. */
std::string
Shown(const std::string & text)
{
  std::string shown;
  for (const char c : text.substr(0, 64))
  {
    shown += std::isprint(static_cast<unsigned char>(c)) ? c : '?';
  }
  return "\"" + shown + (text.size() > 64 ? "...\"" : "\"");
}

std::string
Listed(const std::vector<double> & values)
{
  std::ostringstream text;
  text << "(";
  for (std::size_t k = 0; k < values.size(); ++k)
  {
    text << (k ? ", " : "") << values[k];
  }
  text << ")";
  return text.str();
}

/** The median of each coordinate over \a rows (the lower middle for an even count). */
std::vector<double>
Medians(const std::vector<std::vector<double>> & rows)
{
  std::vector<double> medians(rows.front().size());
  for (std::size_t c = 0; c < medians.size(); ++c)
  {
    std::vector<double> column;
    for (const auto & row : rows)
    {
      column.push_back(row[c]);
    }
    std::nth_element(column.begin(), column.begin() + (column.size() - 1) / 2, column.end());
    medians[c] = column[(column.size() - 1) / 2];
  }
  return medians;
}

double
Distance(const std::vector<double> & a, const std::vector<double> & b)
{
  double sum = 0.0;
  for (std::size_t c = 0; c < a.size(); ++c)
  {
    sum += (a[c] - b[c]) * (a[c] - b[c]);
  }
  return std::sqrt(sum);
}

struct Attribute
{
  const char *               Name;
  std::size_t                Count;
  std::optional<std::string> DICOMSliceAttributes::*Member;
};

constexpr Attribute Position{ "Image Position (Patient) (0020,0032)", 3, &DICOMSliceAttributes::Position };
constexpr Attribute Orientation{ "Image Orientation (Patient) (0020,0037)", 6, &DICOMSliceAttributes::Orientation };
constexpr Attribute PixelSpacing{ "Pixel Spacing (0028,0030)", 2, &DICOMSliceAttributes::PixelSpacing };

/** \a slice's values of \a attribute (none when it lacks it), or a message naming the file. */
std::string
ValueOf(const DICOMSliceAttributes & slice, const Attribute & attribute, std::optional<std::vector<double>> & values)
{
  values.reset();
  const auto & text = slice.*attribute.Member;
  if (!text)
  {
    return std::string();
  }
  values = ParseDecimalStrings(*text, attribute.Count);
  if (!values)
  {
    return "the DICOM file " + slice.File + ": its " + attribute.Name + " is " + Shown(*text) + ", not " +
           std::to_string(attribute.Count) + " decimal numbers";
  }
  return std::string();
}

/** Each file's values of \a attribute, or a message; no rows when no file has it. */
std::string
ValuesOf(const std::vector<DICOMSliceAttributes> & slices,
         const Attribute &                         attribute,
         std::vector<std::vector<double>> &        values)
{
  values.clear();
  const auto having =
    std::find_if(slices.begin(), slices.end(), [&](const auto & slice) { return bool(slice.*attribute.Member); });
  if (having == slices.end())
  {
    return std::string();
  }
  for (const auto & slice : slices)
  {
    if (!(slice.*attribute.Member))
    {
      return "the DICOM file " + slice.File + " lacks the " + attribute.Name + " that the series' other files have";
    }
    std::optional<std::vector<double>> parsed;
    if (std::string message = ValueOf(slice, attribute, parsed); !message.empty())
    {
      return message;
    }
    values.push_back(*parsed);
  }
  return std::string();
}

/** The file whose values of \a attribute differ from the series' (the medians) by more than \a tolerance (times the
 * median's size with \a relative), or a message naming it. */
std::string
AllAlike(const std::vector<DICOMSliceAttributes> & slices,
         const Attribute &                         attribute,
         const std::vector<std::vector<double>> &  values,
         double                                    tolerance,
         bool                                      relative)
{
  if (values.empty())
  {
    return std::string();
  }
  const std::vector<double> series = Medians(values);
  const double bound = relative ? tolerance * Distance(series, std::vector<double>(series.size())) : tolerance;
  for (std::size_t k = 0; k < values.size(); ++k)
  {
    for (std::size_t c = 0; c < series.size(); ++c)
    {
      if (std::abs(values[k][c] - series[c]) > bound)
      {
        return "the DICOM file " + slices[k].File + ": its " + attribute.Name + " " + Listed(values[k]) +
               " differs from the series' " + Listed(series);
      }
    }
  }
  return std::string();
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
CheckDICOMSliceAttributes(const DICOMSliceAttributes & slice)
{
  std::optional<std::vector<double>> values;
  for (const Attribute * attribute : { &Position, &Orientation, &PixelSpacing })
  {
    if (std::string message = ValueOf(slice, *attribute, values); !message.empty())
    {
      return message;
    }
  }
  return std::string();
}

std::string
CheckDICOMSliceGeometry(const std::vector<DICOMSliceAttributes> & slices)
{
  if (slices.empty())
  {
    return std::string();
  }
  std::vector<std::vector<double>> positions, orientations, spacings;
  for (std::string message : { ValuesOf(slices, Position, positions),
                               ValuesOf(slices, Orientation, orientations),
                               ValuesOf(slices, PixelSpacing, spacings) })
  {
    if (!message.empty())
    {
      return message;
    }
  }
  if (std::string message = AllAlike(slices, Orientation, orientations, 1e-4, false); !message.empty())
  {
    return message;
  }
  if (std::string message = AllAlike(slices, PixelSpacing, spacings, 1e-4, true); !message.empty())
  {
    return message;
  }
  if (positions.size() < 4)
  {
    return std::string();
  }
  std::vector<std::vector<double>> steps;
  for (std::size_t k = 0; k + 1 < positions.size(); ++k)
  {
    steps.push_back({ positions[k + 1][0] - positions[k][0],
                      positions[k + 1][1] - positions[k][1],
                      positions[k + 1][2] - positions[k][2] });
  }
  const std::vector<double> step = Medians(steps);
  const double              tolerance = std::max(0.25 * Distance(step, { 0.0, 0.0, 0.0 }), 0.01);
  // A step is regular when it is a whole number of the series' steps (more than one where slices are missing).
  auto regular = [&](const std::vector<double> & s)
  {
    const double length = Distance(step, { 0.0, 0.0, 0.0 });
    const double along = length > 0.0 ? (s[0] * step[0] + s[1] * step[1] + s[2] * step[2]) / (length * length) : 1.0;
    const double whole = std::max(1.0, std::round(along));
    return Distance(s, { whole * step[0], whole * step[1], whole * step[2] }) <= tolerance;
  };
  for (std::size_t k = 0; k < positions.size(); ++k)
  {
    const bool before = k == 0 || !regular(steps[k - 1]);
    const bool after = k + 1 == positions.size() || !regular(steps[k]);
    if (before && after)
    {
      std::ostringstream text;
      text << "the DICOM file " << slices[k].File << " lies off the series' line of slices: its " << Position.Name
           << " is " << Listed(positions[k]) << " mm, where the series steps by " << Listed(step)
           << " mm from slice to slice";
      return text.str();
    }
  }
  return std::string();
}
} // namespace vr::detail
