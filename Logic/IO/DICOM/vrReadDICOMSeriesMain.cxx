// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// vrReadDICOMSeries <folder> <output.mha> <progress file>: reads the DICOM series with the most files in <folder>
// (ITK's GDCMSeriesFileNames and ImageSeriesReader, as float) and writes it to <output.mha>. It runs as a child
// process of the volume reader (vrDICOMSeriesProcess.cxx) because Debian's GDCM asserts, i.e. aborts the process, on
// some corrupt files: here an abort ends this process only. Before GDCM opens a file, "file <path>" is appended to
// the progress file, so the parent can name the file that a crash or a failure happened in. Its last line is "done"
// on success, or "error <scan|none|read N|message|write>" followed by ITK's description (or the message) on the
// lines after it. Each file is also sorted into series alone before the folder is, since GDCM asserts in the sort too,
// and the series' geometry attributes are checked file by file before the volume is handed over
// (vrDICOMSliceGeometry.h).
// Exit status: 0 done, 1 error, 2 wrong arguments.
#include "itkGDCMImageIO.h"
#include "itkGDCMSeriesFileNames.h"
#include "itkImageFileWriter.h"
#include "vrDICOMIdentity.h"
#include "vrDICOMSliceGeometry.h"
#include "itkImageSeriesReader.h"
#include "itkMetaImageIO.h"
#include "itkObject.h"

#include <gdcmImageReader.h>
#include <gdcmSerieHelper.h>
#include <gdcmTrace.h>

#include <fcntl.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <fstream>
#include <string>
#include <vector>

namespace
{
int ProgressFile = -1;

/** Appends \a line to the progress file at once (no buffer a crash could lose). */
void
Report(const std::string & line)
{
  const std::string text = line + "\n";
  std::size_t       written = 0;
  while (written < text.size())
  {
    const ssize_t count = ::write(ProgressFile, text.data() + written, text.size() - written);
    if (count <= 0)
    {
      return;
    }
    written += static_cast<std::size_t>(count);
  }
}

/** GDCM's ImageIO, saying which file it is about to read before each header and each slice it reads. */
class TracingGDCMImageIO : public itk::GDCMImageIO
{
public:
  ITK_DISALLOW_COPY_AND_MOVE(TracingGDCMImageIO);
  using Self = TracingGDCMImageIO;
  using Superclass = itk::GDCMImageIO;
  using Pointer = itk::SmartPointer<Self>;
  itkNewMacro(Self);
  itkTypeMacro(TracingGDCMImageIO, GDCMImageIO);

  void
  ReadImageInformation() override
  {
    Report("file " + std::string(this->GetFileName()));
    Superclass::ReadImageInformation();
  }
  void
  Read(void * buffer) override
  {
    Report("file " + std::string(this->GetFileName()));
    Superclass::Read(buffer);
  }

protected:
  TracingGDCMImageIO() = default;
  ~TracingGDCMImageIO() override = default;
};

/** gdcm::SerieHelper given one file: SetDirectory adds a folder's files one by one with this protected call. */
class OneFileSerieHelper : public gdcm::SerieHelper
{
public:
  using gdcm::SerieHelper::AddFileName;
};

/** Runs GDCM's series sort (gdcm::SerieHelper, called as itk::GDCMSeriesFileNames calls it below) on \a file alone.
 * The sort reads attributes of its own (position, orientation, series details), and GDCM asserts on some of them
 * (a value whose VR differs from the one the attribute expects): a file that kills the sort dies here, named. */
void
SortAlone(const std::string & file)
{
  OneFileSerieHelper helper;
  helper.SetUseSeriesDetails(true);
  helper.SetLoadMode(gdcm::LD_NOSEQ | gdcm::LD_NOSHADOW);
  helper.AddFileName(file);
  for (gdcm::FileList * files = helper.GetFirstSingleSerieUIDFileSet(); files != nullptr;
       files = helper.GetNextSingleSerieUIDFileSet())
  {
    if (!files->empty())
    {
      helper.CreateUniqueSeriesIdentifier(files->front().GetPointer());
      helper.OrderFileList(files);
    }
  }
}

/** \a text without the NUL bytes a writer may pad an odd-length value with. */
std::string
Unpadded(std::string text)
{
  text.erase(text.find_last_not_of('\0') + 1);
  return text;
}

/** Ends with "error <what failed>" and ITK's description (or our message) on the lines after it. */
int
Fail(const std::string & what, const std::string & description)
{
  Report("error " + what);
  Report(description);
  return 1;
}
} // namespace

int
main(int argc, char * argv[])
{
  if (argc != 4)
  {
    return 2;
  }
  const std::string folder = argv[1];
  const std::string output = argv[2];
  ProgressFile = ::open(argv[3], O_WRONLY | O_CREAT | O_TRUNC | O_APPEND | O_CLOEXEC, 0600);
  if (ProgressFile < 0)
  {
    return 2;
  }
  // A corrupt file is reported by the parent; a core dump of this process would only fill the user's disk.
  const rlimit noCore{ 0, 0 };
  ::setrlimit(RLIMIT_CORE, &noCore);
  // GDCM's and ITK's own messages would reach the terminal (two per slice): the parent reports in its words.
  gdcm::Trace::SetDebug(false);
  gdcm::Trace::SetWarning(false);
  gdcm::Trace::SetError(false);
  itk::Object::GlobalWarningDisplayOff();

  // Every file of the folder parsed and sorted once, alone: a file that makes GDCM abort while the series are
  // sorted out below is named here first.
  std::vector<std::string> entries;
  std::error_code          error;
  for (const auto & entry : std::filesystem::directory_iterator(folder, error))
  {
    if (entry.is_regular_file(error))
    {
      entries.push_back(entry.path().string());
    }
  }
  std::sort(entries.begin(), entries.end());
  for (const std::string & file : entries)
  {
    Report("file " + file);
    gdcm::ImageReader reader; // as the series scan reads it: the header, then the image description
    reader.SetFileName(file.c_str());
    if (reader.Read()) // a file that is not DICOM is simply not read, here and in the scan
    {
      const gdcm::DataSet & elements = reader.GetFile().GetDataSet();
      auto                  text = [&](std::uint16_t group, std::uint16_t element) -> std::optional<std::string>
      {
        const gdcm::Tag tag(group, element);
        if (!elements.FindDataElement(tag))
        {
          return std::nullopt;
        }
        const gdcm::ByteValue * bytes = elements.GetDataElement(tag).GetByteValue();
        return Unpadded(bytes ? std::string(bytes->GetPointer(), bytes->GetLength()) : std::string());
      };
      const std::string message = vr::detail::CheckDICOMSliceAttributes(
        { file, text(0x0020, 0x0032), text(0x0020, 0x0037), text(0x0028, 0x0030) });
      if (!message.empty())
      {
        return Fail("message", message + "; the series is not read: remove or replace that file");
      }
    }
    SortAlone(file);
  }
  Report("scan");

  std::vector<std::string> files;
  try
  {
    auto names = itk::GDCMSeriesFileNames::New();
    names->SetUseSeriesDetails(true);
    names->SetDirectory(folder);
    // Several series in one folder: the one with the most files (the volume, not a scout).
    for (const std::string & uid : names->GetSeriesUIDs())
    {
      const std::vector<std::string> & seriesFiles = names->GetFileNames(uid);
      if (seriesFiles.size() > files.size())
      {
        files = seriesFiles;
      }
    }
  }
  catch (const itk::ExceptionObject & exception)
  {
    return Fail("scan", exception.GetDescription());
  }
  if (files.empty())
  {
    return Fail("none", "holds no DICOM series");
  }

  using VolumeType = itk::Image<float, 3>;
  auto dicom = TracingGDCMImageIO::New();
  auto reader = itk::ImageSeriesReader<VolumeType>::New();
  reader->SetImageIO(dicom);
  reader->SetFileNames(files);
  try
  {
    reader->Update();
  }
  catch (const itk::ExceptionObject & exception)
  {
    return Fail("read " + std::to_string(files.size()), exception.GetDescription());
  }
  if (dicom->GetNumberOfComponents() != 1)
  {
    return Fail("message",
                "the DICOM series has " + std::to_string(dicom->GetNumberOfComponents()) +
                  " components per pixel (colour?); a volume must be scalar");
  }
  // The geometry ITK took from the files: a corrupt position in one file would displace the whole volume unnamed.
  const auto * headers = reader->GetMetaDataDictionaryArray();
  if (headers != nullptr && headers->size() == files.size())
  {
    std::vector<vr::detail::DICOMSliceAttributes> slices;
    for (std::size_t k = 0; k < files.size(); ++k)
    {
      auto text = [&](const char * key) -> std::optional<std::string>
      {
        std::string value;
        if ((*headers)[k] == nullptr || !itk::ExposeMetaData<std::string>(*(*headers)[k], key, value))
        {
          return std::nullopt;
        }
        return Unpadded(value);
      };
      slices.push_back({ files[k], text("0020|0032"), text("0020|0037"), text("0028|0030") });
    }
    if (const std::string message = vr::detail::CheckDICOMSliceGeometry(slices); !message.empty())
    {
      return Fail("message",
                  message + "; the series (" + std::to_string(files.size()) + (files.size() == 1 ? " file" : " files") +
                    ") is not read: remove or replace that file");
    }
  }
  Report("write");
  // The patient and study of the first file, for the node the caller makes (vr::DICOMAttribute): one
  // "key<TAB>value" line each beside the volume.
  if (headers != nullptr && !headers->empty() && headers->front() != nullptr)
  {
    std::ofstream identity(output + ".identity");
    for (auto [key, value] : vr::DICOMAttributesOf(*headers->front()))
    {
      std::replace_if(
        value.begin(), value.end(), [](char c) { return c == '\n' || c == '\r' || c == '\t'; }, ' ');
      identity << key << '\t' << value << '\n';
    }
  }
  auto writer = itk::ImageFileWriter<VolumeType>::New();
  writer->SetImageIO(itk::MetaImageIO::New());
  writer->SetInput(reader->GetOutput());
  writer->SetFileName(output);
  try
  {
    writer->Update();
  }
  catch (const itk::ExceptionObject & exception)
  {
    return Fail("write", exception.GetDescription());
  }
  Report("done " + std::to_string(files.size()));
  return 0;
}
