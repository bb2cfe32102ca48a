// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrVolumeIO.h"

#include "vrAtomicOutput.h"
#include "vrITKMessages.h"
#include "vrInputError.h"
#include "vrURINames.h"

// Including the reader and writer here pulls in the IO factory registration that ITK_USE_FILE sets up
// (ITK_IO_FACTORY_REGISTER_MANAGER): NRRD, NIfTI, MetaImage, PNG and GDCM are known to this translation unit.
#include "itkGDCMImageIO.h"
#include "itkGDCMSeriesFileNames.h"
#include "itkImageFileReader.h"
#include "itkImageFileWriter.h"
#include "itkImageIOFactory.h"
#include "itkImageSeriesReader.h"

#include <filesystem>
#include <sstream>

namespace vr
{
namespace
{
VolumeImageType::Pointer
ReadDicomSeries(const std::string & folder)
{
  const std::string        where = "volume folder " + folder;
  auto                     names = itk::GDCMSeriesFileNames::New();
  std::vector<std::string> files;
  try
  {
    const detail::ScopedSilentITKOutput quiet; // "No Series were found": said below, in our words
    names->SetUseSeriesDetails(true);
    names->SetDirectory(folder);
    // Several series in one folder: take the one with the most files (the volume, not a scout).
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
    throw InputError(where + ": cannot scan for DICOM files: " + detail::CondenseITKMessage(exception));
  }
  if (files.empty())
  {
    throw InputError(where + ": holds no DICOM series");
  }
  auto dicom = itk::GDCMImageIO::New();
  auto reader = itk::ImageSeriesReader<VolumeImageType>::New();
  reader->SetImageIO(dicom);
  reader->SetFileNames(files);
  try
  {
    reader->Update();
  }
  catch (const itk::ExceptionObject & exception)
  {
    throw InputError(where + ": the DICOM series (" + std::to_string(files.size()) +
                     " files) cannot be read: " + detail::CondenseITKMessage(exception));
  }
  if (dicom->GetNumberOfComponents() != 1)
  {
    throw InputError(where + ": the DICOM series has " + std::to_string(dicom->GetNumberOfComponents()) +
                     " components per pixel (colour?); a volume must be scalar");
  }
  VolumeImageType::Pointer volume = reader->GetOutput();
  const auto               size = volume->GetLargestPossibleRegion().GetSize();
  if (size[2] < 2)
  {
    throw InputError(where + ": the DICOM series is a single 2D slice; a volume must be 3D");
  }
  volume->DisconnectPipeline();
  return volume;
}

VolumeImageType::Pointer
ReadVolumeFile(const std::string & path)
{
  const std::string         where = "volume " + path;
  itk::ImageIOBase::Pointer io =
    itk::ImageIOFactory::CreateImageIO(path.c_str(), itk::ImageIOFactory::IOFileModeEnum::ReadMode);
  if (io.IsNull())
  {
    throw InputError(where + ": no ITK reader recognises this file (NRRD, NIfTI, MetaImage or a DICOM folder are "
                             "expected); is the header corrupt?");
  }
  try
  {
    io->SetFileName(path);
    io->ReadImageInformation();
  }
  catch (const itk::ExceptionObject & exception)
  {
    throw InputError(where + ": the header cannot be read: " + detail::CondenseITKMessage(exception));
  }
  if (io->GetNumberOfDimensions() != 3)
  {
    throw InputError(where + ": the image has " + std::to_string(io->GetNumberOfDimensions()) +
                     " dimensions; a volume must be 3D");
  }
  if (io->GetNumberOfComponents() != 1)
  {
    throw InputError(where + ": the image has " + std::to_string(io->GetNumberOfComponents()) + " " +
                     itk::ImageIOBase::GetPixelTypeAsString(io->GetPixelType()) +
                     " components per voxel; a volume must be scalar");
  }
  auto reader = itk::ImageFileReader<VolumeImageType>::New();
  reader->SetImageIO(io);
  reader->SetFileName(path);
  try
  {
    reader->Update();
  }
  catch (const itk::ExceptionObject & exception)
  {
    throw InputError(where + ": the voxel data cannot be read (truncated?): " + detail::CondenseITKMessage(exception));
  }
  VolumeImageType::Pointer volume = reader->GetOutput();
  volume->DisconnectPipeline();
  return volume;
}
} // namespace

VolumeImageType::Pointer
ReadVolume(const std::string & path)
{
  namespace fs = std::filesystem;
  if (IsURIName(path))
  {
    // No file: a name for an ImageIO of the host process (3D Slicer's "slicer:0x...#node"), handed to ITK as it is.
    return ReadVolumeFile(path);
  }
  std::error_code error;
  if (!fs::exists(path, error))
  {
    throw InputError("volume " + path + ": no such file or folder");
  }
  if (fs::is_directory(path, error))
  {
    return ReadDicomSeries(path);
  }
  if (fs::file_size(path, error) == 0 && !error)
  {
    throw InputError("volume " + path + ": is empty");
  }
  return ReadVolumeFile(path);
}

void
WriteVolume(const VolumeImageType * volume, const std::string & path)
{
  if (volume == nullptr)
  {
    throw InputError("volume output " + path + ": no volume to write");
  }
  AtomicOutput output(path);
  auto         writer = itk::ImageFileWriter<VolumeImageType>::New();
  writer->SetInput(volume);
  writer->SetFileName(output.TemporaryPath());
  writer->UseCompressionOn();
  try
  {
    writer->Update();
  }
  catch (const itk::ExceptionObject & exception)
  {
    throw InputError("volume output " + path +
                     ": could not be written: " + detail::CondenseITKMessage(exception, output.TemporaryPath(), path));
  }
  output.Commit();
}
} // namespace vr
