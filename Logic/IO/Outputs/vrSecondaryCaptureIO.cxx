// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrSecondaryCaptureIO.h"

#include "vrAtomicOutput.h"
#include "vrITKMessages.h"
#include "vrInputError.h"
#include "vrURINames.h"

#include "itkGDCMImageIO.h"
#include "itkImageFileReader.h"
#include "itkImageFileWriter.h"
#include "itkMetaDataObject.h"

#include <gdcmUIDGenerator.h>

#include <algorithm>
#include <ctime>
#include <filesystem>
#include <regex>

#include <sys/statvfs.h>

namespace vr
{
namespace
{
void
Put(itk::MetaDataDictionary & dictionary, const std::string & tag, const std::string & value)
{
  itk::EncapsulateMetaData<std::string>(dictionary, tag, value);
}

void
CheckUID(const std::string & uid, const std::string & field, const std::string & path)
{
  // DICOM PS3.5 9.1: digits and dots, components without leading zeros, at most 64 characters.
  static const std::regex valid("(0|[1-9][0-9]*)(\\.(0|[1-9][0-9]*))*");
  if (uid.empty() || uid.size() > 64 || !std::regex_match(uid, valid))
  {
    throw InputError("DICOM output " + path + ": " + field + " \"" + uid + "\" is not a valid DICOM UID");
  }
}
} // namespace

std::string
NewDICOMUID()
{
  // ITK's GDCMImageIO sets the generator's (global) root to ITK's own when it writes: set GDCM's again, so that
  // every UID of a series has one root.
  gdcm::UIDGenerator::SetRoot(gdcm::UIDGenerator::GetGDCMUID());
  gdcm::UIDGenerator generator;
  return generator.Generate();
}

std::string
DICOMDateNow(std::string & time)
{
  const std::time_t now = std::time(nullptr);
  std::tm           local{};
  localtime_r(&now, &local);
  char date[16];
  char clock[16];
  std::strftime(date, sizeof(date), "%Y%m%d", &local);
  std::strftime(clock, sizeof(clock), "%H%M%S", &local);
  time = clock;
  return date;
}

void
WriteSecondaryCapture(const MaskImageType * grey, const SecondaryCaptureFields & fields, const std::string & path)
{
  if (grey == nullptr)
  {
    throw InputError("DICOM output " + path + ": no image to write");
  }
  CheckUID(fields.SOPInstanceUID, "SOP Instance UID", path);
  CheckUID(fields.SeriesInstanceUID, "Series Instance UID", path);
  CheckUID(fields.Identity.StudyInstanceUID, "Study Instance UID", path);
  if (fields.SeriesDescription.size() > 64)
  {
    throw InputError("DICOM output " + path + ": Series Description \"" + fields.SeriesDescription +
                     "\" is longer than DICOM's 64 characters");
  }

  // The picture alone: no origin or direction of the patient's space.
  auto picture = MaskImageType::New();
  picture->SetRegions(grey->GetLargestPossibleRegion().GetSize());
  picture->SetSpacing(grey->GetSpacing());
  picture->Allocate();
  std::copy(grey->GetBufferPointer(),
            grey->GetBufferPointer() + grey->GetLargestPossibleRegion().GetNumberOfPixels(),
            picture->GetBufferPointer());

  itk::MetaDataDictionary & dictionary = picture->GetMetaDataDictionary();
  const DICOMIdentity &     who = fields.Identity;
  Put(dictionary, "0008|0016", SecondaryCaptureSOPClassUID);
  Put(dictionary, "0008|0018", fields.SOPInstanceUID);
  Put(dictionary, "0008|0060", "OT");
  Put(dictionary, "0008|0064", "WSD");
  Put(dictionary, "0008|0020", who.StudyDate);
  Put(dictionary, "0008|0030", who.StudyTime);
  Put(dictionary, "0008|0021", fields.SeriesDate);
  Put(dictionary, "0008|0031", fields.SeriesTime);
  Put(dictionary, "0008|0023", fields.SeriesDate);
  Put(dictionary, "0008|0033", fields.SeriesTime);
  Put(dictionary, "0008|0050", who.AccessionNumber);
  Put(dictionary, "0008|1030", who.StudyDescription);
  Put(dictionary, "0008|103e", fields.SeriesDescription);
  Put(dictionary, "0010|0010", who.PatientName);
  Put(dictionary, "0010|0020", who.PatientID);
  Put(dictionary, "0010|0030", who.PatientBirthDate);
  Put(dictionary, "0010|0040", who.PatientSex);
  if (!who.PatientComments.empty())
  {
    Put(dictionary, "0010|4000", who.PatientComments);
  }
  Put(dictionary, "0020|000d", who.StudyInstanceUID);
  Put(dictionary, "0020|000e", fields.SeriesInstanceUID);
  Put(dictionary, "0020|0010", who.StudyID);
  Put(dictionary, "0020|0011", std::to_string(fields.SeriesNumber));
  Put(dictionary, "0020|0013", std::to_string(fields.InstanceNumber));
  Put(dictionary, "0020|4000", fields.ImageComments);
  Put(dictionary, "0028|0301", "NO"); // Burned In Annotation: the picture holds no text

  AtomicOutput output(path);
  // GDCM asserts (aborts the process) when its stream fails mid-write, as on a full disk: make sure the file fits
  // first. The pixels and a header of a few kilobytes, with a margin.
  struct statvfs disk
  {
  };
  const double needed = static_cast<double>(picture->GetLargestPossibleRegion().GetNumberOfPixels()) + 64.0 * 1024.0;
  if (!IsURIName(path) && ::statvfs(std::filesystem::path(output.TemporaryPath()).parent_path().c_str(), &disk) == 0 &&
      static_cast<double>(disk.f_bavail) * static_cast<double>(disk.f_frsize) < needed)
  {
    throw InputError("DICOM output " + path + ": could not be written: the disk is full");
  }
  auto io = itk::GDCMImageIO::New();
  io->KeepOriginalUIDOn(); // the series' UIDs, not new ones per file
  auto writer = itk::ImageFileWriter<MaskImageType>::New();
  writer->SetInput(picture);
  writer->SetImageIO(io);
  writer->SetFileName(output.TemporaryPath());
  writer->UseCompressionOff();
  try
  {
    writer->Update();
  }
  catch (const itk::ExceptionObject & exception)
  {
    throw InputError("DICOM output " + path +
                     ": could not be written: " + detail::CondenseITKMessage(exception, output.TemporaryPath(), path));
  }
  // As for PNGs: a full disk may go unnoticed by the writer, so read the file back and compare before it is published.
  bool same = false;
  try
  {
    const detail::ScopedConsoleCapture console; // GDCM's warnings about a truncated file
    auto                               reader = itk::ImageFileReader<MaskImageType>::New();
    reader->SetImageIO(itk::GDCMImageIO::New());
    reader->SetFileName(output.TemporaryPath());
    reader->Update();
    const MaskImageType * back = reader->GetOutput();
    same = back->GetLargestPossibleRegion().GetSize() == picture->GetLargestPossibleRegion().GetSize() &&
           std::equal(picture->GetBufferPointer(),
                      picture->GetBufferPointer() + picture->GetLargestPossibleRegion().GetNumberOfPixels(),
                      back->GetBufferPointer());
  }
  catch (const itk::ExceptionObject &)
  {
    same = false;
  }
  if (!same)
  {
    throw InputError("DICOM output " + path + ": could not be written (the file reads back incomplete: disk full?)");
  }
  output.Commit();
}
} // namespace vr
