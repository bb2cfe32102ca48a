// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrDICOMFaults.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <functional>
#include <map>
#include <sstream>
#include <stdexcept>

namespace vr::test
{
namespace
{
using Files = std::vector<DICOMTestFile>;

/** The series' own files (not added by a fault), in their names' order, which is their positions' order. */
std::vector<std::size_t>
SeriesFiles(const Files & files)
{
  std::vector<std::size_t> series;
  for (std::size_t k = 0; k < files.size(); ++k)
  {
    if (!files[k].Added)
    {
      series.push_back(k);
    }
  }
  std::sort(series.begin(), series.end(), [&](std::size_t a, std::size_t b) { return files[a].Name < files[b].Name; });
  return series;
}

/** An interior run of \a length of the series' files (positions in SeriesFiles) none of which, nor their neighbours,
 * an earlier fault touched; marks the run and its neighbours touched. None when there is no room. */
std::optional<std::size_t>
PickRun(const Files & files, CampaignRandom & random, std::set<std::string> & touched, std::size_t length = 1)
{
  const std::vector<std::size_t> series = SeriesFiles(files);
  if (series.size() < length + 4)
  {
    return std::nullopt;
  }
  for (int attempt = 0; attempt < 64; ++attempt)
  {
    const std::size_t start = 1 + random.Below(series.size() - length - 1);
    bool              free = true;
    for (std::size_t k = start - 1; k <= start + length && free; ++k)
    {
      free = touched.count(files[series[k]].Name) == 0;
    }
    if (free)
    {
      for (std::size_t k = start - 1; k <= start + length; ++k)
      {
        touched.insert(files[series[k]].Name);
      }
      return start;
    }
  }
  return std::nullopt;
}

std::string
Decimal(double value, const char * format = "%.10g")
{
  char text[40];
  std::snprintf(text, sizeof(text), format, value);
  return text;
}

std::array<double, 3>
PositionOf(const DICOMTestFile & file)
{
  std::array<double, 3> position{};
  std::istringstream    text(file.Data.Text(0x0020, 0x0032));
  for (double & value : position)
  {
    text >> value;
    text.ignore(1);
  }
  return position;
}

void
SetPosition(DICOMTestFile & file, const std::array<double, 3> & position)
{
  file.Data.SetText(
    0x0020, 0x0032, "DS", Decimal(position[0]) + "\\" + Decimal(position[1]) + "\\" + Decimal(position[2]));
}

double
SliceSpacing(const Files & files)
{
  const std::vector<std::size_t> series = SeriesFiles(files);
  return std::abs(PositionOf(files[series[1]])[2] - PositionOf(files[series[0]])[2]);
}

/** A fault that changes one attribute of one interior file: refused, naming it. */
DICOMFault
OneFile(Files &                                             files,
        CampaignRandom &                                    random,
        std::set<std::string> &                             touched,
        const std::string &                                 kind,
        DICOMOutcome                                        expected,
        const std::function<std::string(DICOMTestFile &)> & change)
{
  const auto run = PickRun(files, random, touched);
  if (!run)
  {
    return {};
  }
  DICOMTestFile &   file = files[SeriesFiles(files)[*run]];
  const std::string detail = change(file);
  return { kind, file.Name + ": " + detail, expected, { file.Name } };
}

/** \a choices[random]. */
template<typename T>
const T &
Pick(CampaignRandom & random, const std::vector<T> & choices)
{
  return choices[random.Below(choices.size())];
}

DICOMFault
RemoveRun(Files & files, CampaignRandom & random, std::set<std::string> & touched, std::size_t length, bool refused)
{
  const auto run = PickRun(files, random, touched, length);
  if (!run)
  {
    return {};
  }
  const std::vector<std::size_t> series = SeriesFiles(files);
  const std::string              before = files[series[*run - 1]].Name;
  const std::string              after = files[series[*run + length]].Name;
  std::string                    removed;
  std::vector<std::size_t>       gone(series.begin() + static_cast<std::ptrdiff_t>(*run),
                                series.begin() + static_cast<std::ptrdiff_t>(*run + length));
  std::sort(gone.rbegin(), gone.rend());
  for (const std::size_t k : gone)
  {
    removed = files[k].Name + (removed.empty() ? "" : " ") + removed;
    files.erase(files.begin() + static_cast<std::ptrdiff_t>(k));
  }
  const std::string kind = refused ? "gap too large" : length == 1 ? "missing slice" : "missing slices";
  return { kind, removed + " removed", refused ? DICOMOutcome::Refused : DICOMOutcome::Warning, { before, after } };
}

/** A copy of an interior file under another name, changed by \a change. */
DICOMFault
Copy(Files &                                      files,
     CampaignRandom &                             random,
     std::set<std::string> &                      touched,
     const std::string &                          kind,
     DICOMOutcome                                 expected,
     const std::function<void(DICOMTestFile &)> & change,
     bool                                         nameBoth)
{
  const auto run = PickRun(files, random, touched);
  if (!run)
  {
    return {};
  }
  DICOMTestFile     copy = files[SeriesFiles(files)[*run]];
  const std::string original = copy.Name;
  copy.Name = "copy-" + original;
  copy.Added = true;
  change(copy);
  files.push_back(copy);
  std::vector<std::string> named{ copy.Name };
  if (nameBoth)
  {
    named.push_back(original);
  }
  return { kind, copy.Name + " beside " + original, expected, named };
}

DICOMFault
Stray(Files & files, const std::string & kind, DICOMTestFile stray)
{
  stray.Added = true;
  const std::string name = stray.Name;
  files.push_back(std::move(stray));
  return { kind, name + " added", DICOMOutcome::Identical, {} };
}

using FaultMaker = std::function<DICOMFault(Files &, CampaignRandom &, std::set<std::string> &)>;

const std::vector<std::pair<DICOMFaultKind, FaultMaker>> &
Catalogue()
{
  using O = DICOMOutcome;
  static const std::vector<std::pair<DICOMFaultKind, FaultMaker>> catalogue = {
    // Read as acquired, and the same image: what the reader must not mind.
    { { "slice thickness changed", O::Identical },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t)
      {
        return OneFile(f,
                       r,
                       t,
                       "slice thickness changed",
                       O::Identical,
                       [&r](DICOMTestFile & file)
                       {
                         const std::string value = Pick<std::string>(r, { "0", "-1", "NaN", "", "25", "removed" });
                         if (value == "removed")
                         {
                           file.Data.Remove(0x0018, 0x0050);
                         }
                         else
                         {
                           file.Data.SetText(0x0018, 0x0050, "DS", value);
                         }
                         return "Slice Thickness " + value;
                       });
      } },
    { { "instance number changed", O::Identical },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t)
      {
        return OneFile(f,
                       r,
                       t,
                       "instance number changed",
                       O::Identical,
                       [&r](DICOMTestFile & file)
                       {
                         const std::string value = Pick<std::string>(r, { "removed", "1", "999", "-5" });
                         if (value == "removed")
                         {
                           file.Data.Remove(0x0020, 0x0013);
                         }
                         else
                         {
                           file.Data.SetText(0x0020, 0x0013, "IS", value);
                         }
                         return "Instance Number " + value;
                       });
      } },
    { { "description, modality or patient changed", O::Identical },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t)
      {
        return OneFile(f,
                       r,
                       t,
                       "description, modality or patient changed",
                       O::Identical,
                       [&r](DICOMTestFile & file)
                       {
                         switch (r.Below(4))
                         {
                           case 0:
                             file.Data.SetText(0x0008, 0x103E, "LO", "other description");
                             return std::string("Series Description");
                           case 1:
                             file.Data.SetText(0x0008, 0x0060, "CS", "MR");
                             return std::string("Modality MR");
                           case 2:
                             file.Data.SetText(0x0018, 0x1120, "DS", "12");
                             return std::string("Gantry/Detector Tilt 12 (the positions untilted)");
                           default:
                             file.Data.SetText(0x0010, 0x0010, "PN", "Other^Name");
                             return std::string("Patient's Name");
                         }
                       });
      } },
    { { "position written another way", O::Identical },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t)
      {
        return OneFile(f,
                       r,
                       t,
                       "position written another way",
                       O::Identical,
                       [](DICOMTestFile & file)
                       {
                         const auto p = PositionOf(file);
                         file.Data.SetText(0x0020,
                                           0x0032,
                                           "DS",
                                           " " + Decimal(p[0], "%+.9E") + "\\" + Decimal(p[1], "%+.9E") + "\\" +
                                             Decimal(p[2], "%+.9E"));
                         return std::string("Image Position in exponent notation");
                       });
      } },
    { { "one file in the other little-endian VR", O::Identical },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t)
      {
        // Implicit and explicit VR little-endian are one family (a big-endian series has no such variation).
        if (f.front().Encoding.BigEndian)
        {
          return DICOMFault();
        }
        return OneFile(f,
                       r,
                       t,
                       "one file in the other little-endian VR",
                       O::Identical,
                       [](DICOMTestFile & file)
                       {
                         const bool wasExplicit = file.Encoding.ExplicitVR;
                         file.Encoding = DICOMTestEncoding();
                         file.Encoding.ExplicitVR = !wasExplicit;
                         return std::string(wasExplicit ? "implicit" : "explicit") + " VR little-endian, claimed so";
                       });
      } },
    { { "rescale changed, values kept", O::Identical },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t)
      {
        return OneFile(f,
                       r,
                       t,
                       "rescale changed, values kept",
                       O::Identical,
                       [&r](DICOMTestFile & file)
                       {
                         // Another intercept (and, where the stored values have room, slope), the stored values
                         // following: the same image.
                         const double largest = *std::max_element(file.Values.begin(), file.Values.end());
                         const double room = file.SignedPixels ? 32767.0 : std::ldexp(1.0, file.StoredBits) - 1.0;
                         const double low = file.SignedPixels ? -32768.0 : 0.0;
                         const double smallest = *std::min_element(file.Values.begin(), file.Values.end());
                         for (const double slope : { 0.25, 0.5, 1.0 })
                         {
                           const double shift = std::floor(r.Between(1.0, 40.0));
                           const double intercept = file.Intercept - shift;
                           if ((largest - intercept) / slope <= room && (smallest - intercept) / slope >= low &&
                               (slope == 1.0 || r.Below(2) == 0))
                           {
                             file.Slope = slope;
                             file.Intercept = intercept;
                             break;
                           }
                         }
                         file.Data.SetText(0x0028, 0x1052, "DS", Decimal(file.Intercept));
                         file.Data.SetText(0x0028, 0x1053, "DS", Decimal(file.Slope));
                         return "Rescale Slope " + Decimal(file.Slope) + ", Intercept " + Decimal(file.Intercept);
                       });
      } },
    { { "stray files", O::Identical },
      [](Files & f, CampaignRandom & r, std::set<std::string> &)
      {
        DICOMTestFile stray;
        switch (r.Below(6))
        {
          case 0:
            stray.Name = "notes.txt";
            stray.Raw = "Study notes: contrast 80 ml, late arterial phase.\n";
            break;
          case 1:
            stray.Name = "empty.dcm";
            stray.Raw = "";
            break;
          case 2:
            stray.Name = "thumbnails";
            stray.Folder = true;
            break;
          case 3:
            stray.Name = "thumb.jpg";
            stray.Raw = std::string("\xFF\xD8\xFF\xE0\x00\x10JFIF\x00\x01\x01\x00\x00\x01\x00\x01\x00\x00", 20) +
                        std::string(200, '\x5A');
            break;
          case 4:
          {
            stray = DICOMTestFile();
            stray.Name = "DICOMDIR";
            stray.Data.SetText(0x0002, 0x0002, "UI", "1.2.840.10008.1.3.10");
            stray.Data.SetText(0x0002, 0x0003, "UI", "1.2.826.0.1.3680043.9.7731.37.90");
            stray.Data.SetText(0x0004, 0x1130, "CS", "VR37");
            stray.OmitPixelData = true;
            break;
          }
          default:
          {
            stray = DICOMTestFile();
            stray.Name = "report.dcm";
            stray.Data.SetText(0x0008, 0x0016, "UI", "1.2.840.10008.5.1.4.1.1.88.11");
            stray.Data.SetText(0x0008, 0x0018, "UI", "1.2.826.0.1.3680043.9.7731.37.91");
            stray.Data.SetText(0x0008, 0x0060, "CS", "SR");
            stray.Data.SetText(0x0020, 0x000E, "UI", f.front().Data.Text(0x0020, 0x000E));
            stray.Data.SetText(0x0040, 0xA040, "CS", "CONTAINER");
            stray.OmitPixelData = true;
            break;
          }
        }
        return Stray(f, "stray files", stray);
      } },

    // Read, with a warning that names the files: a gap interpolated, a duplicate left out.
    { { "missing slice", O::Warning },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t) { return RemoveRun(f, r, t, 1, false); } },
    { { "missing slices", O::Warning },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t)
      { return RemoveRun(f, r, t, 2 + r.Below(2), false); } },
    { { "duplicate file", O::Warning },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t)
      {
        return Copy(
          f, r, t, "duplicate file", O::Warning, [](DICOMTestFile &) {}, false);
      } },
    { { "duplicate image, new SOP Instance UID", O::Warning },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t)
      {
        return Copy(
          f,
          r,
          t,
          "duplicate image, new SOP Instance UID",
          O::Warning,
          [](DICOMTestFile & copy) { copy.Data.SetText(0x0008, 0x0018, "UI", copy.Data.Text(0x0008, 0x0018) + ".9"); },
          false);
      } },

    // Refused, naming the file (or files, or the series, or the reason).
    { { "gap too large", O::Refused },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t) { return RemoveRun(f, r, t, 4, true); } },
    { { "another image at one position", O::Refused },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t)
      {
        return Copy(
          f,
          r,
          t,
          "another image at one position",
          O::Refused,
          [](DICOMTestFile & copy)
          {
            copy.Data.SetText(0x0008, 0x0018, "UI", copy.Data.Text(0x0008, 0x0018) + ".8");
            for (double & value : copy.Values)
            {
              value += value + 50.0 <= 3071.0 ? 50.0 : -50.0;
            }
          },
          true);
      } },
    { { "one SOP Instance UID, two images", O::Refused },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t)
      {
        const auto first = PickRun(f, r, t);
        const auto second = PickRun(f, r, t);
        if (!first || !second)
        {
          return DICOMFault();
        }
        const std::vector<std::size_t> series = SeriesFiles(f);
        DICOMTestFile &                a = f[series[*first]];
        DICOMTestFile &                b = f[series[*second]];
        b.Data.SetText(0x0008, 0x0018, "UI", a.Data.Text(0x0008, 0x0018));
        return DICOMFault{ "one SOP Instance UID, two images",
                           b.Name + " given the SOP Instance UID of " + a.Name,
                           O::Refused,
                           { a.Name, b.Name } };
      } },
    { { "second series", O::Refused },
      [](Files & f, CampaignRandom & r, std::set<std::string> &)
      {
        // A scout of three 64 x 64 images of its own series.
        const std::string        uid = "1.2.826.0.1.3680043.9.7731.37.5." + std::to_string(1 + r.Below(1000));
        std::vector<std::string> names;
        for (int k = 1; k <= 3; ++k)
        {
          DICOMTestFile scout = f[SeriesFiles(f).front()];
          scout.Name = "scout-" + std::to_string(k) + ".dcm";
          scout.Added = true;
          scout.Values.assign(64 * 64, 0.0);
          scout.Data.SetUS(0x0028, 0x0010, 64);
          scout.Data.SetUS(0x0028, 0x0011, 64);
          scout.Data.SetText(0x0020, 0x000E, "UI", uid);
          scout.Data.SetText(0x0008, 0x0018, "UI", uid + "." + std::to_string(k));
          scout.Data.SetText(0x0008, 0x103E, "LO", "Topogram");
          scout.Data.SetText(0x0020, 0x0011, "IS", "1");
          scout.Data.SetText(0x0020, 0x0032, "DS", "0\\0\\" + std::to_string(10 * k));
          names.push_back(scout.Name);
          f.push_back(scout);
        }
        return DICOMFault{ "second series", "a 3-file scout, Series Instance UID " + uid, O::Refused, { uid } };
      } },
    { { "Series Instance UID changed", O::Refused },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t)
      {
        return OneFile(f,
                       r,
                       t,
                       "Series Instance UID changed",
                       O::Refused,
                       [](DICOMTestFile & file)
                       {
                         file.Data.SetText(0x0020, 0x000E, "UI", "1.2.826.0.1.3680043.9.7731.37.6");
                         return std::string("another Series Instance UID");
                       });
      } },
    { { "pixel format attribute changed", O::Refused },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t)
      {
        return OneFile(
          f,
          r,
          t,
          "pixel format attribute changed",
          O::Refused,
          [&r](DICOMTestFile & file)
          {
            const auto         rows = file.Data.Find(0x0028, 0x0010)->Value;
            const unsigned int height =
              static_cast<unsigned char>(rows[0]) | (static_cast<unsigned char>(rows[1]) << 8);
            switch (r.Below(9))
            {
              case 0:
              {
                const unsigned int value = Pick<unsigned int>(r, { 0, 1, height + 1, height / 2, 65535 });
                file.Data.SetUS(0x0028, 0x0010, static_cast<std::uint16_t>(value));
                return "Rows " + std::to_string(value);
              }
              case 1:
              {
                const unsigned int value = Pick<unsigned int>(r, { 0, 1, 2, 65535 });
                file.Data.SetUS(0x0028, 0x0011, static_cast<std::uint16_t>(value));
                return "Columns " + std::to_string(value);
              }
              case 2:
              {
                const unsigned int value = Pick<unsigned int>(r, { 8, 32, 12, 0, 64 });
                file.Data.SetUS(0x0028, 0x0100, static_cast<std::uint16_t>(value));
                return "Bits Allocated " + std::to_string(value);
              }
              case 3:
              {
                const unsigned int value = file.StoredBits == 16 ? 12 : 16;
                file.Data.SetUS(0x0028, 0x0101, static_cast<std::uint16_t>(value));
                file.Data.SetUS(0x0028, 0x0102, static_cast<std::uint16_t>(value - 1));
                return "Bits Stored " + std::to_string(value);
              }
              case 4:
                file.Data.SetUS(0x0028, 0x0102, static_cast<std::uint16_t>(file.StoredBits));
                return std::string("High Bit at Bits Stored");
              case 5:
                file.Data.SetUS(0x0028, 0x0103, file.SignedPixels ? 0 : 1);
                return std::string("Pixel Representation flipped");
              case 6:
              {
                const std::string value = Pick<std::string>(r, { "MONOCHROME1", "RGB", "PALETTE COLOR", "YBR_FULL" });
                file.Data.SetText(0x0028, 0x0004, "CS", value);
                return "Photometric Interpretation " + value;
              }
              case 7:
                file.Data.SetUS(0x0028, 0x0002, 3);
                return std::string("Samples per Pixel 3");
              default:
              {
                const std::string value = Pick<std::string>(r, { "2", "0", "x" });
                file.Data.SetText(0x0028, 0x0008, "IS", value);
                return "Number of Frames " + value;
              }
            }
          });
      } },
    { { "pixel data of the wrong length", O::Refused },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t)
      {
        return OneFile(
          f,
          r,
          t,
          "pixel data of the wrong length",
          O::Refused,
          [&r](DICOMTestFile & file)
          {
            const long bytes = static_cast<long>(file.Values.size() * 2);
            switch (r.Below(4))
            {
              case 0:
                file.PixelDataChange = -2 * static_cast<long>(1 + r.Below(static_cast<std::size_t>(bytes / 4)));
                return "Pixel Data " + std::to_string(-file.PixelDataChange) + " bytes short";
              case 1:
                file.PixelDataChange = 2 * static_cast<long>(1 + r.Below(64));
                return "Pixel Data " + std::to_string(file.PixelDataChange) + " bytes long";
              case 2:
                file.OmitPixelData = true;
                return std::string("no Pixel Data");
              default:
              {
                const std::size_t size = EncodeDICOMFile(file).size();
                file.TruncateTo = 200 + r.Below(size - 201);
                return "file cut to " + std::to_string(*file.TruncateTo) + " of " + std::to_string(size) + " bytes";
              }
            }
          });
      } },
    { { "transfer syntax", O::Refused },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t)
      {
        // Explicit VR claimed over implicit little-endian data is the one false claim GDCM reads through (it parses
        // the data set again with implicit VR): read, with a warning naming the file.
        bool       readThrough = false;
        DICOMFault fault =
          OneFile(f,
                  r,
                  t,
                  "transfer syntax",
                  O::Refused,
                  [&r, &readThrough](DICOMTestFile & file)
                  {
                    // Claims the data do not match, and one true encoding that differs from the series'.
                    const std::vector<std::pair<std::string, std::string>> claims = {
                      { "1.2.840.10008.1.2", "implicit VR claimed" },
                      { "1.2.840.10008.1.2.1", "explicit VR claimed" },
                      { "1.2.840.10008.1.2.2", "big-endian claimed" },
                      { "1.2.840.10008.1.2.4.50", "JPEG baseline claimed" },
                      { "1.2.840.10008.1.2.4.70", "JPEG lossless claimed" },
                      { "1.2.840.10008.1.2.4.80", "JPEG-LS claimed" },
                      { "1.2.840.10008.1.2.4.90", "JPEG 2000 claimed" },
                      { "1.2.840.10008.1.2.5", "RLE claimed" },
                      { "1.2.840.10008.1.2.1.99", "deflate claimed" },
                      { "1.2.3.4.5", "an unknown syntax claimed" },
                      { "", "written big-endian, claimed so" },
                    };
                    const auto & [uid, what] = Pick(r, claims);
                    readThrough = uid == "1.2.840.10008.1.2.1" && !file.Encoding.ExplicitVR && !file.Encoding.BigEndian;
                    const bool trueClaim = uid == (file.Encoding.BigEndian    ? "1.2.840.10008.1.2.2"
                                                   : file.Encoding.ExplicitVR ? "1.2.840.10008.1.2.1"
                                                                              : "1.2.840.10008.1.2");
                    if (uid.empty())
                    {
                      const bool big = !file.Encoding.BigEndian;
                      file.Encoding = DICOMTestEncoding();
                      file.Encoding.BigEndian = big;
                      return std::string(big ? "written big-endian, claimed so" : "written little-endian");
                    }
                    file.Encoding.ClaimedTransferSyntax = trueClaim ? "1.2.840.10008.1.2.4.50" : uid;
                    return trueClaim ? std::string("JPEG baseline claimed") : what;
                  });
        if (readThrough)
        {
          fault.Expected = O::Warning;
        }
        return fault;
      } },
    { { "rescale broken", O::Refused },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t)
      {
        return OneFile(
          f,
          r,
          t,
          "rescale broken",
          O::Refused,
          [&r](DICOMTestFile & file)
          {
            const bool        slope = r.Below(2) == 0;
            const std::string value = Pick<std::string>(
              r,
              slope ? std::vector<std::string>{ "inf", "-inf", "nan", "1e308", "0", "abc", "", "1e10", "removed" }
                    : std::vector<std::string>{ "1e308", "-inf", "nan", "x", "2e9", "removed" });
            const std::uint16_t element = slope ? 0x1053 : 0x1052;
            if (value == "removed")
            {
              file.Data.Remove(0x0028, element);
            }
            else
            {
              file.Data.SetText(0x0028, element, "DS", value);
            }
            return std::string(slope ? "Rescale Slope " : "Rescale Intercept ") + value;
          });
      } },
    { { "geometry attribute missing or corrupt", O::Refused },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t)
      {
        return OneFile(f,
                       r,
                       t,
                       "geometry attribute missing or corrupt",
                       O::Refused,
                       [&r](DICOMTestFile & file)
                       {
                         switch (r.Below(5))
                         {
                           case 0:
                             file.Data.Remove(0x0020, 0x0032);
                             return std::string("no Image Position");
                           case 1:
                             file.Data.Remove(0x0020, 0x0037);
                             return std::string("no Image Orientation");
                           case 2:
                             file.Data.Remove(0x0028, 0x0030);
                             return std::string("no Pixel Spacing");
                           case 3:
                           {
                             const std::string value = Pick<std::string>(r, { "1\\2", "abc\\0\\0", "1e999\\0\\0", "" });
                             file.Data.SetText(0x0020, 0x0032, "DS", value);
                             return "Image Position \"" + value + "\"";
                           }
                           default:
                           {
                             const std::string value = Pick<std::string>(r, { "0\\0", "-1\\1", "abc\\1", "0.7" });
                             file.Data.SetText(0x0028, 0x0030, "DS", value);
                             return "Pixel Spacing \"" + value + "\"";
                           }
                         }
                       });
      } },
    { { "position off the line", O::Refused },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t)
      {
        return OneFile(f,
                       r,
                       t,
                       "position off the line",
                       O::Refused,
                       [&r](DICOMTestFile & file)
                       {
                         auto         p = PositionOf(file);
                         const double shift = r.Between(0.3, 5.0) * (r.Below(2) ? 1.0 : -1.0);
                         p[r.Below(2)] += shift;
                         SetPosition(file, p);
                         return "moved " + Decimal(shift, "%.2f") + " mm in the slice plane";
                       });
      } },
    { { "position moved along the normal", O::Refused },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t)
      {
        const double spacing = SliceSpacing(f);
        return OneFile(f,
                       r,
                       t,
                       "position moved along the normal",
                       O::Refused,
                       [&r, spacing](DICOMTestFile & file)
                       {
                         auto         p = PositionOf(file);
                         const double shift = r.Between(0.2, 0.8) * spacing * (r.Below(2) ? 1.0 : -1.0);
                         p[2] += shift;
                         SetPosition(file, p);
                         return "moved " + Decimal(shift, "%.2f") + " mm along the normal";
                       });
      } },
    { { "orientation changed", O::Refused },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t)
      {
        return OneFile(
          f,
          r,
          t,
          "orientation changed",
          O::Refused,
          [&r](DICOMTestFile & file)
          {
            if (r.Below(3) == 0)
            {
              file.Data.SetText(0x0020, 0x0037, "DS", "1\\0\\0\\0\\0.8\\0");
              return std::string("Image Orientation not unit vectors");
            }
            const double angle = r.Between(0.5, 5.0) * 3.14159265358979 / 180.0;
            const double sign = file.Data.Text(0x0020, 0x0037)[0] == '-' ? -1.0 : 1.0;
            file.Data.SetText(0x0020,
                              0x0037,
                              "DS",
                              Decimal(sign * std::cos(angle)) + "\\" + Decimal(std::sin(angle)) + "\\0\\" +
                                Decimal(-sign * std::sin(angle)) + "\\" + Decimal(std::cos(angle)) + "\\0");
            return "Image Orientation turned " + Decimal(angle * 180.0 / 3.14159265358979, "%.2f") + " degrees";
          });
      } },
    { { "pixel spacing changed", O::Refused },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t)
      {
        return OneFile(f,
                       r,
                       t,
                       "pixel spacing changed",
                       O::Refused,
                       [&r](DICOMTestFile & file)
                       {
                         std::istringstream text(file.Data.Text(0x0028, 0x0030));
                         double             rows = 0.0;
                         double             columns = 0.0;
                         text >> rows;
                         text.ignore(1);
                         text >> columns;
                         const double factor = r.Between(1.01, 1.3);
                         file.Data.SetText(0x0028, 0x0030, "DS", Decimal(rows * factor) + "\\" + Decimal(columns));
                         return "Pixel Spacing times " + Decimal(factor, "%.3f");
                       });
      } },
    { { "frame of reference changed", O::Refused },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t)
      {
        return OneFile(f,
                       r,
                       t,
                       "frame of reference changed",
                       O::Refused,
                       [](DICOMTestFile & file)
                       {
                         file.Data.SetText(0x0020, 0x0052, "UI", "1.2.826.0.1.3680043.9.7731.37.7");
                         return std::string("another Frame of Reference UID");
                       });
      } },
    { { "gantry tilt", O::Refused },
      [](Files & f, CampaignRandom & r, std::set<std::string> & t)
      {
        // The whole series, positions stepping aside as a tilted gantry's do; alone, so that no other fault moves a
        // position of it.
        if (!t.empty())
        {
          return DICOMFault();
        }
        const double                   degrees = r.Between(3.0, 30.0);
        const std::vector<std::size_t> series = SeriesFiles(f);
        const double                   z0 = PositionOf(f[series.front()])[2];
        for (const std::size_t k : series)
        {
          auto p = PositionOf(f[k]);
          p[1] += std::tan(degrees * 3.14159265358979 / 180.0) * (p[2] - z0);
          SetPosition(f[k], p);
          f[k].Data.SetText(0x0018, 0x1120, "DS", Decimal(degrees, "%.1f"));
          t.insert(f[k].Name);
        }
        return DICOMFault{ "gantry tilt", Decimal(degrees, "%.1f") + " degrees", O::Refused, { "tilt" } };
      } },
  };
  return catalogue;
}
} // namespace

std::uint64_t
CampaignRandom::Next()
{
  std::uint64_t z = (m_State += 0x9E3779B97F4A7C15ULL);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

std::size_t
CampaignRandom::Below(std::size_t count)
{
  return count == 0 ? 0 : static_cast<std::size_t>(Next() % count);
}

double
CampaignRandom::Between(double low, double high)
{
  return low + (high - low) * static_cast<double>(Next() >> 11) * 0x1.0p-53;
}

std::string
ToString(DICOMOutcome outcome)
{
  switch (outcome)
  {
    case DICOMOutcome::Identical:
      return "read-identical";
    case DICOMOutcome::Warning:
      return "read-with-warning";
    default:
      return "refused-naming-the-file";
  }
}

const std::vector<DICOMFaultKind> &
DICOMFaultKinds()
{
  static const std::vector<DICOMFaultKind> kinds = []
  {
    std::vector<DICOMFaultKind> names;
    for (const auto & [kind, maker] : Catalogue())
    {
      names.push_back(kind);
    }
    return names;
  }();
  return kinds;
}

DICOMFault
ApplyDICOMFault(const std::string &          kind,
                std::vector<DICOMTestFile> & files,
                CampaignRandom &             random,
                std::set<std::string> &      touched)
{
  for (const auto & [entry, maker] : Catalogue())
  {
    if (entry.Name == kind)
    {
      return maker(files, random, touched);
    }
  }
  throw std::logic_error("no DICOM fault of kind \"" + kind + "\"");
}

DICOMOutcome
ExpectedOutcome(const std::vector<DICOMFault> & faults)
{
  DICOMOutcome outcome = DICOMOutcome::Identical;
  for (const DICOMFault & fault : faults)
  {
    if (fault.Expected == DICOMOutcome::Refused)
    {
      return DICOMOutcome::Refused;
    }
    if (fault.Expected == DICOMOutcome::Warning)
    {
      outcome = DICOMOutcome::Warning;
    }
  }
  return outcome;
}
} // namespace vr::test
