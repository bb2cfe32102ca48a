// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrDICOMFolderExamination.h"

#include "vrDICOMIdentity.h"

#include "itkMetaDataObject.h"

#include <gdcmReader.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace vr::detail
{
namespace
{
namespace fs = std::filesystem;

const gdcm::Tag        PixelDataTag(0x7fe0, 0x0010);
constexpr const char * DICOMDIRClass = "1.2.840.10008.1.3.10";

/** A string attribute's text without the padding DICOM adds (trailing spaces and NULs) or a writer left in front. */
std::string
Unpadded(std::string text)
{
  const auto last = text.find_last_not_of(std::string(" \0", 2));
  text.erase(last == std::string::npos ? 0 : last + 1);
  text.erase(0, std::min(text.find_first_not_of(' '), text.size()));
  return text;
}

/** The attribute's text as DICOMFileAttributes keeps it; none when \a elements lack it. GDCM holds a parsed data set's
 * binary values little-endian whatever the file's byte order. */
std::optional<std::string>
TextOf(const gdcm::DataSet & elements, const DICOMAttributeTag & tag)
{
  const gdcm::Tag key(tag.Group, tag.Element);
  if (!elements.FindDataElement(key))
  {
    return std::nullopt;
  }
  const gdcm::ByteValue * bytes = elements.GetDataElement(key).GetByteValue();
  if (tag.Binary)
  {
    if (bytes == nullptr || bytes->GetLength() != 2)
    {
      return "not a 2-byte value";
    }
    const auto * value = reinterpret_cast<const unsigned char *>(bytes->GetPointer());
    return std::to_string(value[0] | (value[1] << 8));
  }
  return Unpadded(bytes != nullptr ? std::string(bytes->GetPointer(), bytes->GetLength()) : std::string());
}

/** What the first 132 bytes say: the "DICM" marker of DICOM Part 10, or a preamble of zeros without it (a damaged
 * marker, or a writer that left it out). */
bool
LooksLikeDICOM(const std::string & path)
{
  std::ifstream file(path, std::ios::binary);
  char          start[132] = {};
  file.read(start, sizeof(start));
  if (file.gcount() < static_cast<std::streamsize>(sizeof(start)))
  {
    return false;
  }
  return std::string(start + 128, 4) == "DICM" || std::all_of(start, start + 128, [](char c) { return c == 0; });
}

/** Whether \a uid is a storage SOP class of images (CT, MR, PET, NM, US, X-ray, secondary capture, visible light, RT
 * image; DICOM PS3.4 Annex B), as opposed to reports, presentation states, structures, waveforms and documents. */
bool
IsImageStorageClass(const std::string & uid)
{
  const std::string storage = "1.2.840.10008.5.1.4.1.1.";
  if (uid.rfind(storage, 0) != 0)
  {
    return false;
  }
  const std::string rest = uid.substr(storage.size());
  for (const char * image : { "1",    "2",      "2.1",  "2.2", "3.1", "4",     "4.1", "4.2",  "4.3",  "4.4",
                              "6",    "6.1",    "6.2",  "7",   "7.1", "7.2",   "7.3", "7.4",  "12.1", "12.1.1",
                              "12.2", "12.2.1", "12.3", "20",  "128", "128.1", "130", "481.1" })
  {
    if (rest == image)
    {
      return true;
    }
  }
  // Digital X-ray, mammography, intra-oral and visible light families.
  for (const char * family : { "1.1", "1.2", "1.3", "77.1." })
  {
    if (rest.rfind(family, 0) == 0)
    {
      return true;
    }
  }
  return false;
}

/** Whether GDCM read \a file's data set with implicit VR although its Transfer Syntax UID declares explicit VR: where
 * an explicit-VR parse fails, GDCM parses the data set again with implicit VR, and the elements read so carry no VR of
 * their own (gdcm::VR::INVALID; their dictionary's VR applies). */
bool
ReadAsImplicitUnderExplicitClaim(const gdcm::File & file)
{
  const gdcm::DataSet & elements = file.GetDataSet();
  if (!file.GetHeader().GetDataSetTransferSyntax().IsExplicit() || elements.IsEmpty())
  {
    return false;
  }
  return std::all_of(elements.Begin(),
                     elements.End(),
                     [](const gdcm::DataElement & element) { return element.GetVR() == gdcm::VR::INVALID; });
}

std::string
Names(const std::vector<std::string> & paths)
{
  std::string text;
  for (std::size_t k = 0; k < paths.size() && k < 3; ++k)
  {
    text += (k ? ", " : "") + fs::path(paths[k]).filename().string();
  }
  return text + (paths.size() > 3 ? ", ..." : "");
}
} // namespace

DICOMFolderExamination
ExamineDICOMFolder(const std::string & folder, const std::function<void(const std::string &)> & beforeReading)
{
  DICOMFolderExamination examination;
  std::vector<fs::path>  entries;
  std::error_code        error;
  for (const auto & entry : fs::directory_iterator(folder, error))
  {
    entries.push_back(entry.path());
  }
  std::sort(entries.begin(), entries.end());
  for (const fs::path & entry : entries)
  {
    const std::string path = entry.string();
    if (fs::is_directory(entry, error))
    {
      examination.SubFolders.push_back(path);
      continue;
    }
    if (!fs::is_regular_file(entry, error))
    {
      examination.NotDICOM.push_back(path);
      continue;
    }
    if (fs::file_size(entry, error) == 0)
    {
      examination.EmptyFiles.push_back(path);
      continue;
    }
    beforeReading(path);
    gdcm::Reader reader;
    reader.SetFileName(path.c_str());
    if (!reader.ReadUpToTag(PixelDataTag))
    {
      if (LooksLikeDICOM(path))
      {
        examination.Refusal = "the DICOM file " + path +
                              " cannot be read: GDCM's parser stops in its header (truncated or corrupt?); it may "
                              "belong to the series: remove or replace it";
        return examination;
      }
      examination.NotDICOM.push_back(path);
      continue;
    }
    const gdcm::DataSet & header = reader.GetFile().GetHeader();
    const gdcm::DataSet & elements = reader.GetFile().GetDataSet();
    if (TextOf(header, DICOMTag::MediaStorageSOPClassUID).value_or("") == DICOMDIRClass)
    {
      examination.DICOMDIRs.push_back(path);
      continue;
    }
    if (!elements.FindDataElement(gdcm::Tag(0x0028, 0x0010)) && !elements.FindDataElement(gdcm::Tag(0x0028, 0x0011)))
    {
      // No image: a report, a presentation state... skipped. But a file of an image class (or of none) without one is
      // an image GDCM could not make out (a data set it parsed as something else: a false transfer syntax).
      const std::string sopClass = TextOf(elements, DICOMTag::SOPClassUID)
                                     .value_or(TextOf(header, DICOMTag::MediaStorageSOPClassUID).value_or(""));
      if (sopClass.empty() || IsImageStorageClass(sopClass))
      {
        examination.Refusal =
          "the DICOM file " + path + " holds no Rows or Columns although " +
          (sopClass.empty() ? std::string("it names no other kind of object (no SOP Class UID)")
                            : "its SOP Class UID " + sopClass + " is an image's") +
          ": GDCM's parser found no image in it (corrupt, or a transfer syntax its data do not match?); it may "
          "belong to the series: remove or replace it";
        return examination;
      }
      examination.NotImages.push_back(path);
      continue;
    }
    DICOMFileAttributes file;
    file.File = path;
    if (const auto syntax = TextOf(header, DICOMTag::TransferSyntaxUID))
    {
      file.Values[DICOMTag::TransferSyntaxUID.Key()] = *syntax;
    }
    file.ImplicitUnderExplicitClaim = ReadAsImplicitUnderExplicitClaim(reader.GetFile());
    for (const DICOMAttributeTag & tag : DICOMTag::DataSetAttributes())
    {
      if (const auto text = TextOf(elements, tag))
      {
        file.Values[tag.Key()] = *text;
      }
    }
    // The patient and study as the node keeps them (vr::DICOMAttributesOf reads ITK's "gggg|eeee" keys).
    itk::MetaDataDictionary identity;
    for (const char * key : { "0010|0010",
                              "0010|0020",
                              "0010|0030",
                              "0010|0040",
                              "0020|000d",
                              "0020|0010",
                              "0008|0020",
                              "0008|0030",
                              "0008|0050",
                              "0008|1030" })
    {
      unsigned int group = 0;
      unsigned int element = 0;
      std::sscanf(key, "%x|%x", &group, &element);
      const DICOMAttributeTag tag{ static_cast<std::uint16_t>(group), static_cast<std::uint16_t>(element), key, false };
      if (const auto text = TextOf(elements, tag))
      {
        itk::EncapsulateMetaData<std::string>(identity, key, *text);
      }
    }
    file.Identity = DICOMAttributesOf(identity);
    examination.Images.push_back(std::move(file));
  }
  return examination;
}

std::string
SkippedEntriesNote(const DICOMFolderExamination & examination)
{
  std::string text;
  std::size_t count = 0;
  const struct
  {
    const std::vector<std::string> & Paths;
    const char *                     One;
    const char *                     Several;
  } kinds[] = {
    { examination.SubFolders, "sub-folder", "sub-folders" },
    { examination.EmptyFiles, "empty file", "empty files" },
    { examination.NotDICOM, "file that is not DICOM", "files that are not DICOM" },
    { examination.DICOMDIRs, "DICOMDIR", "DICOMDIRs" },
    { examination.NotImages, "DICOM file that holds no image", "DICOM files that hold no image" },
  };
  for (const auto & kind : kinds)
  {
    if (kind.Paths.empty())
    {
      continue;
    }
    count += kind.Paths.size();
    text += (text.empty() ? "" : ", ") + std::to_string(kind.Paths.size()) + " " +
            (kind.Paths.size() == 1 ? kind.One : kind.Several) + " (" + Names(kind.Paths) + ")";
  }
  if (count == 0)
  {
    return std::string();
  }
  return std::to_string(count) + (count == 1 ? " entry" : " entries") + " of the folder " +
         (count == 1 ? "was" : "were") + " skipped, not read: " + text;
}
} // namespace vr::detail
