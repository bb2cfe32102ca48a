// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrDICOMSeriesGroups.h"

#include "vrDICOMSliceGeometry.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <numeric>
#include <sstream>

namespace vr::detail
{
namespace
{
using namespace DICOMTag;

/** The attributes whose text must be equal within a set, beside the transfer syntax family and the orientation. */
const DICOMAttributeTag * const SetAttributes[] = {
  &SeriesInstanceUID, &Rows,       &Columns, &SamplesPerPixel,     &PhotometricInterpretation,
  &BitsAllocated,     &BitsStored, &HighBit, &PixelRepresentation, &FrameOfReferenceUID
};
/** Two orientations within this of each other, cosine by cosine, are one. */
constexpr double SameOrientation = 1e-4;
/** No rescaled value may be larger than this in size. */
constexpr double LargestRescaledValue = 1e9;

std::string
ValueOf(const DICOMFileAttributes & file, const DICOMAttributeTag & tag)
{
  return file.Get(tag).value_or("(none)");
}

struct SetKey
{
  std::vector<std::string>           Values;
  std::string                        Family;
  std::string                        OrientationText;
  std::optional<std::vector<double>> Orientation;
};

SetKey
KeyOf(const DICOMFileAttributes & file)
{
  SetKey key;
  for (const DICOMAttributeTag * tag : SetAttributes)
  {
    key.Values.push_back(ValueOf(file, *tag));
  }
  key.Family = TransferSyntaxFamily(file.Get(TransferSyntaxUID));
  key.OrientationText = ValueOf(file, ImageOrientation);
  if (const auto text = file.Get(ImageOrientation))
  {
    key.Orientation = ParseDecimalStrings(*text, 6);
  }
  return key;
}

bool
SameOrientations(const SetKey & a, const SetKey & b)
{
  if (a.Orientation && b.Orientation)
  {
    for (std::size_t c = 0; c < 6; ++c)
    {
      if (std::abs((*a.Orientation)[c] - (*b.Orientation)[c]) > SameOrientation)
      {
        return false;
      }
    }
    return true;
  }
  return !a.Orientation && !b.Orientation && a.OrientationText == b.OrientationText;
}

bool
SameSet(const SetKey & a, const SetKey & b)
{
  return a.Values == b.Values && a.Family == b.Family && SameOrientations(a, b);
}

/** "Rows 256, not 512; ..." for what \a key has that \a reference has not. */
std::string
Differences(const SetKey & key, const SetKey & reference)
{
  std::string text;
  auto        add = [&](const std::string & name, const std::string & value, const std::string & other)
  { text += (text.empty() ? "" : "; ") + name + " " + value + ", not " + other; };
  for (std::size_t k = 1; k < key.Values.size(); ++k) // the first is the UID they share
  {
    if (key.Values[k] != reference.Values[k])
    {
      add(SetAttributes[k]->Label(), key.Values[k], reference.Values[k]);
    }
  }
  if (key.Family != reference.Family)
  {
    add("transfer syntax", key.Family, reference.Family);
  }
  if (!SameOrientations(key, reference))
  {
    add(ImageOrientation.Label(), key.OrientationText, reference.OrientationText);
  }
  return text;
}

long
SeriesNumberOf(const DICOMFileAttributes & file)
{
  const auto text = file.Get(SeriesNumber);
  if (!text)
  {
    return LONG_MAX;
  }
  char *     end = nullptr;
  const long number = std::strtol(text->c_str(), &end, 10);
  return end != text->c_str() ? number : LONG_MAX;
}

/** The unsigned number \a text holds (a Binary attribute's decimal value, an Integer String), or none. */
std::optional<unsigned long>
Unsigned(const std::optional<std::string> & text)
{
  if (!text)
  {
    return std::nullopt;
  }
  const auto first = text->find_first_not_of(' ');
  const auto last = text->find_last_not_of(' ');
  if (first == std::string::npos)
  {
    return std::nullopt;
  }
  const std::string digits = text->substr(first, last - first + 1);
  if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos)
  {
    return std::nullopt;
  }
  return std::stoul(digits);
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

std::string
FileSays(const DICOMFileAttributes & file, const DICOMAttributeTag & tag)
{
  return "the DICOM file " + file.File + ": its " + tag.Label() + " is " + file.Shown(tag);
}
} // namespace

std::vector<DICOMImageSet>
GroupDICOMImages(const std::vector<DICOMFileAttributes> & files)
{
  std::vector<DICOMImageSet> sets;
  std::vector<SetKey>        keys;
  for (std::size_t k = 0; k < files.size(); ++k)
  {
    const SetKey key = KeyOf(files[k]);
    auto same = std::find_if(keys.begin(), keys.end(), [&](const SetKey & other) { return SameSet(key, other); });
    if (same == keys.end())
    {
      keys.push_back(key);
      sets.push_back({ { k }, std::string() });
    }
    else
    {
      sets[static_cast<std::size_t>(same - keys.begin())].Files.push_back(k);
    }
  }
  // Each set that shares its UID with a larger one says how it differs from the largest.
  for (std::size_t s = 0; s < sets.size(); ++s)
  {
    std::size_t largest = s;
    for (std::size_t t = 0; t < sets.size(); ++t)
    {
      const bool larger = sets[t].Files.size() > sets[largest].Files.size() ||
                          (sets[t].Files.size() == sets[largest].Files.size() && t < largest);
      if (keys[t].Values.front() == keys[s].Values.front() && larger)
      {
        largest = t;
      }
    }
    if (largest != s)
    {
      const std::size_t others = sets[largest].Files.size();
      sets[s].Difference = Differences(keys[s], keys[largest]) + " (the other " +
                           (others == 1 ? std::string("file") : std::to_string(others) + " files") +
                           " of this Series Instance UID)";
    }
  }
  std::vector<std::size_t> order(sets.size());
  std::iota(order.begin(), order.end(), std::size_t{ 0 });
  std::stable_sort(order.begin(),
                   order.end(),
                   [&](std::size_t a, std::size_t b)
                   {
                     const DICOMFileAttributes & first = files[sets[a].Files.front()];
                     const DICOMFileAttributes & second = files[sets[b].Files.front()];
                     if (SeriesNumberOf(first) != SeriesNumberOf(second))
                     {
                       return SeriesNumberOf(first) < SeriesNumberOf(second);
                     }
                     if (keys[a].Values.front() != keys[b].Values.front())
                     {
                       return keys[a].Values.front() < keys[b].Values.front();
                     }
                     return sets[a].Files.size() > sets[b].Files.size();
                   });
  std::vector<DICOMImageSet> sorted;
  for (const std::size_t s : order)
  {
    sorted.push_back(sets[s]);
  }
  return sorted;
}

std::vector<DICOMSeriesSummary>
SummarizeDICOMImageSets(const std::vector<DICOMFileAttributes> & files, const std::vector<DICOMImageSet> & sets)
{
  std::vector<DICOMSeriesSummary> summaries;
  for (std::size_t s = 0; s < sets.size(); ++s)
  {
    const DICOMFileAttributes & first = files[sets[s].Files.front()];
    DICOMSeriesSummary          summary;
    summary.Number = static_cast<unsigned int>(s + 1);
    summary.SeriesInstanceUID = first.Get(SeriesInstanceUID).value_or("");
    summary.SeriesNumber = first.Get(SeriesNumber).value_or("");
    summary.SeriesDescription = first.Get(SeriesDescription).value_or("");
    summary.Modality = first.Get(Modality).value_or("");
    summary.Files = sets[s].Files.size();
    summary.Columns = static_cast<unsigned int>(Unsigned(first.Get(Columns)).value_or(0));
    summary.Rows = static_cast<unsigned int>(Unsigned(first.Get(Rows)).value_or(0));
    summary.Detail = sets[s].Difference;
    if (sets[s].Files.size() <= 3)
    {
      std::string names;
      for (const std::size_t k : sets[s].Files)
      {
        names += (names.empty() ? "" : ", ") + files[k].File;
      }
      summary.Detail +=
        (summary.Detail.empty() ? "" : "; ") + std::string(sets[s].Files.size() == 1 ? "file " : "files ") + names;
    }
    summaries.push_back(summary);
  }
  return summaries;
}

std::string
ChooseDICOMImageSet(const std::vector<DICOMFileAttributes> & files,
                    const std::vector<DICOMImageSet> &       sets,
                    const std::string &                      choice,
                    std::size_t &                            chosen)
{
  const std::string count =
    "the folder holds " + std::to_string(sets.size()) + (sets.size() == 1 ? " series" : " series");
  if (const auto number = Unsigned(choice))
  {
    if (*number >= 1 && *number <= sets.size())
    {
      chosen = static_cast<std::size_t>(*number - 1);
      return std::string();
    }
    return "the DICOM series chosen, " + choice + ", is no series of the folder: " + count +
           ", numbered from 1; choose one by its number or its Series Instance UID";
  }
  std::vector<std::size_t> matching;
  for (std::size_t s = 0; s < sets.size(); ++s)
  {
    if (files[sets[s].Files.front()].Get(SeriesInstanceUID).value_or("") == choice)
    {
      matching.push_back(s);
    }
  }
  if (matching.size() == 1)
  {
    chosen = matching.front();
    return std::string();
  }
  if (matching.empty())
  {
    return "the DICOM series chosen, \"" + choice +
           "\", is no series of the folder: no file has that Series Instance " + "UID; " + count +
           ", choose one by its number or its Series Instance UID";
  }
  return "the DICOM series chosen, Series Instance UID " + choice + ", holds " + std::to_string(matching.size()) +
         " sets of images that differ in size, pixel format, orientation or frame of reference: choose one of them " +
         "by its number";
}

std::string
CheckDICOMImageSet(const std::vector<DICOMFileAttributes> & files, const DICOMImageSet & set, DICOMImageLayout & layout)
{
  layout = DICOMImageLayout();
  const DICOMFileAttributes & first = files[set.Files.front()];
  // The pixel format, which every file of the set shares: said of the first.
  const auto samples = Unsigned(first.Get(SamplesPerPixel));
  if (!samples || *samples != 1)
  {
    return FileSays(first, SamplesPerPixel) +
           ": a volume must be scalar, one sample a pixel (colour images are not read as volumes)";
  }
  const std::string photometric = first.Get(PhotometricInterpretation).value_or("");
  if (photometric != "MONOCHROME1" && photometric != "MONOCHROME2")
  {
    return FileSays(first, PhotometricInterpretation) + ": a volume must be greyscale (MONOCHROME1 or MONOCHROME2)";
  }
  const auto rows = Unsigned(first.Get(Rows));
  const auto columns = Unsigned(first.Get(Columns));
  if (!rows || *rows == 0 || *rows > 65535)
  {
    return FileSays(first, Rows) + ": a number of rows from 1 to 65535 is expected";
  }
  if (!columns || *columns == 0 || *columns > 65535)
  {
    return FileSays(first, Columns) + ": a number of columns from 1 to 65535 is expected";
  }
  const auto allocated = Unsigned(first.Get(BitsAllocated));
  if (!allocated || (*allocated != 8 && *allocated != 16 && *allocated != 32))
  {
    return FileSays(first, BitsAllocated) + ": 8, 16 or 32 is expected";
  }
  const auto stored = Unsigned(first.Get(BitsStored));
  if (!stored || *stored == 0 || *stored > *allocated)
  {
    return FileSays(first, BitsStored) + ": from 1 to the " + std::to_string(*allocated) +
           " bits allocated is expected";
  }
  const auto high = Unsigned(first.Get(HighBit));
  if (!high || *high + 1 != *stored)
  {
    return FileSays(first, HighBit) + ": one below the " + std::to_string(*stored) +
           " bits stored is expected (the pixel data's low bits)";
  }
  const auto representation = Unsigned(first.Get(PixelRepresentation));
  if (!representation || *representation > 1)
  {
    return FileSays(first, PixelRepresentation) + ": 0 (unsigned) or 1 (signed) is expected";
  }
  const std::string family = TransferSyntaxFamily(first.Get(TransferSyntaxUID));
  if (family.rfind("unknown", 0) == 0)
  {
    return FileSays(first, TransferSyntaxUID) + ": a transfer syntax the reader does not decode";
  }
  layout.Rows = static_cast<unsigned int>(*rows);
  layout.Columns = static_cast<unsigned int>(*columns);
  layout.BitsAllocated = static_cast<unsigned int>(*allocated);
  layout.BitsStored = static_cast<unsigned int>(*stored);
  layout.PixelRepresentation = static_cast<unsigned int>(*representation);
  layout.TransferSyntaxFamily = family;

  // The pixel spacing's attribute: Pixel Spacing; where no file has it, what GDCM and ITK take then.
  const DICOMAttributeTag * spacingTag = &PixelSpacing;
  for (const DICOMAttributeTag * other : { &PixelSpacing, &ImagerPixelSpacing, &NominalScannedPixelSpacing })
  {
    if (std::any_of(set.Files.begin(), set.Files.end(), [&](std::size_t k) { return bool(files[k].Get(*other)); }))
    {
      spacingTag = other;
      break;
    }
  }
  if (spacingTag != &PixelSpacing)
  {
    layout.PixelSpacingSource = spacingTag->Label();
  }

  // File by file: frames, the geometry attributes, the rescale.
  std::vector<std::vector<double>> spacings;
  const bool                       rescaled =
    std::any_of(set.Files.begin(),
                set.Files.end(),
                [&](std::size_t k) { return files[k].Get(RescaleSlope) || files[k].Get(RescaleIntercept); });
  for (const std::size_t k : set.Files)
  {
    const DICOMFileAttributes & file = files[k];
    if (const auto frames = file.Get(NumberOfFrames))
    {
      const auto count = Unsigned(frames);
      if (!count || *count != 1)
      {
        return FileSays(file, NumberOfFrames) +
               ": the reader reads series of single-frame images, not multi-frame files (export the series as one "
               "file a slice)";
      }
    }
    std::vector<double> position, orientation, spacing;
    for (const auto & [tag, count, values] :
         { std::tuple<const DICOMAttributeTag &, std::size_t, std::vector<double> &>{ ImagePosition, 3, position },
           { ImageOrientation, 6, orientation },
           { *spacingTag, 2, spacing } })
    {
      const auto text = file.Get(tag);
      if (!text)
      {
        return "the DICOM file " + file.File + " lacks the " + tag.Label() + " that places its pixels in space";
      }
      const auto parsed = ParseDecimalStrings(*text, count);
      if (!parsed)
      {
        return FileSays(file, tag) + ", not " + std::to_string(count) + " decimal numbers";
      }
      values = *parsed;
    }
    layout.Positions.push_back({ position[0], position[1], position[2] });
    spacings.push_back(spacing);
    if (k == set.Files.front())
    {
      std::copy(orientation.begin(), orientation.end(), layout.Orientation.begin());
    }
    double slope = 1.0;
    double intercept = 0.0;
    if (rescaled)
    {
      for (const auto & [tag, value] :
           { std::pair<const DICOMAttributeTag &, double &>{ RescaleSlope, slope }, { RescaleIntercept, intercept } })
      {
        const auto text = file.Get(tag);
        if (!text)
        {
          const DICOMAttributeTag & other = &tag == &RescaleSlope ? RescaleIntercept : RescaleSlope;
          return "the DICOM file " + file.File +
                 (file.Get(other) ? " has a " + other.Label() + " but no " + tag.Label()
                                  : " lacks the " + tag.Label() + " that the series' other files have") +
                 ": its values cannot be told";
        }
        const auto parsed = ParseDecimalStrings(*text, 1);
        if (!parsed)
        {
          return FileSays(file, tag) + ", not a finite decimal number";
        }
        value = parsed->front();
      }
      if (slope == 0.0 || std::abs(slope) > LargestRescaledValue)
      {
        return FileSays(file, RescaleSlope) + ": a slope of 0 or larger than 1e9 in size makes no image";
      }
      if (std::abs(intercept) > LargestRescaledValue)
      {
        return FileSays(file, RescaleIntercept) + ": an intercept larger than 1e9 in size makes no image";
      }
    }
    layout.Slopes.push_back(slope);
    layout.Intercepts.push_back(intercept);
  }

  // The orientation: two orthogonal unit vectors.
  const auto & o = layout.Orientation;
  const double rowLength = std::sqrt(o[0] * o[0] + o[1] * o[1] + o[2] * o[2]);
  const double columnLength = std::sqrt(o[3] * o[3] + o[4] * o[4] + o[5] * o[5]);
  const double dot = o[0] * o[3] + o[1] * o[4] + o[2] * o[5];
  if (std::abs(rowLength - 1.0) > SameOrientation || std::abs(columnLength - 1.0) > SameOrientation ||
      std::abs(dot) > SameOrientation)
  {
    return FileSays(first, ImageOrientation) + ": two orthogonal unit vectors (the row and column directions) are " +
           "expected";
  }
  // The pixel spacing: positive, and the same in every file.
  std::vector<double> median(2);
  for (std::size_t c = 0; c < 2; ++c)
  {
    std::vector<double> column;
    for (const auto & spacing : spacings)
    {
      column.push_back(spacing[c]);
    }
    std::nth_element(
      column.begin(), column.begin() + static_cast<std::ptrdiff_t>((column.size() - 1) / 2), column.end());
    median[c] = column[(column.size() - 1) / 2];
  }
  for (std::size_t j = 0; j < spacings.size(); ++j)
  {
    const DICOMFileAttributes & file = files[set.Files[j]];
    if (!(spacings[j][0] > 0.0 && spacings[j][1] > 0.0))
    {
      return FileSays(file, *spacingTag) + ": two spacings above 0 mm are expected";
    }
    for (std::size_t c = 0; c < 2; ++c)
    {
      if (std::abs(spacings[j][c] - median[c]) > 1e-4 * median[c])
      {
        return "the DICOM file " + file.File + ": its " + spacingTag->Label() + " " + Listed(spacings[j]) +
               " mm differs from the series' " + Listed(median) + " mm";
      }
    }
  }
  layout.PixelSpacing = { median[0], median[1] };
  return std::string();
}
} // namespace vr::detail
