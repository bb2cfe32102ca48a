// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrVolumeIO.h"

#include "vrAtomicOutput.h"
#include "vrDICOMSeriesProcess.h"
#include "vrITKMessages.h"
#include "vrInputError.h"
#include "vrImageIOChoice.h"
#include "vrInputFileChecks.h"
#include "vrURINames.h"

// Including the reader and writer here pulls in the IO factory registration that ITK_USE_FILE sets up
// (ITK_IO_FACTORY_REGISTER_MANAGER): NRRD, NIfTI, MetaImage, PNG and GDCM are known to this translation unit.
#include "itkGDCMImageIO.h"
#include "itkImageFileReader.h"
#include "itkImageFileWriter.h"
#include "itkImageIOFactory.h"

#include <cmath>
#include <filesystem>
#include <sstream>

namespace vr
{
namespace
{
/** Rejects a volume holding NaN or an infinity: it would turn the CPR into NaN without a word. */
void
RequireFiniteVoxels(const VolumeImageType & volume, const std::string & where)
{
  const std::size_t count = volume.GetLargestPossibleRegion().GetNumberOfPixels();
  const float *     voxels = volume.GetBufferPointer();
  for (std::size_t k = 0; k < count; ++k)
  {
    if (!std::isfinite(voxels[k]))
    {
      const auto         index = volume.ComputeIndex(static_cast<VolumeImageType::OffsetValueType>(k));
      std::ostringstream what;
      what << where << ": voxel (" << index[0] << ", " << index[1] << ", " << index[2] << ") is " << voxels[k]
           << "; a volume must hold finite values (NaN or infinite voxels would make the CPR meaningless)";
      throw InputError(what.str());
    }
  }
}

VolumeImageType::Pointer
ReadDICOMSeries(const std::string & folder, const VolumeReadOptions & options, VolumeReadReport * report)
{
  const std::string       where = "volume folder " + folder;
  detail::DICOMSeriesRead read = detail::ReadDICOMSeriesInChildProcess(folder, options.DICOMSeries, where);
  RequireFiniteVoxels(*read.Volume, where);
  if (report != nullptr)
  {
    report->Warnings.insert(report->Warnings.end(), read.Warnings.begin(), read.Warnings.end());
    report->Notes.insert(report->Notes.end(), read.Notes.begin(), read.Notes.end());
  }
  return read.Volume;
}

/** "64 x 64 x 32 x 5" */
std::string
SizeText(const itk::ImageIOBase & io)
{
  std::string text;
  for (unsigned int d = 0; d < io.GetNumberOfDimensions(); ++d)
  {
    text += (d == 0 ? "" : " x ") + std::to_string(io.GetDimensions(d));
  }
  return text;
}
} // namespace

itk::ImageIOBase::Pointer
InspectVolumeFile(const std::string & path)
{
  const std::string where = "volume " + path;
  const bool        uri = IsURIName(path);
  if (!uri)
  {
    detail::CheckInputPath(path, "volume");
    // A detached header's data file is opened by ITK as it is: a FIFO there would block the reader for ever.
    for (const std::string & dataFile : detail::DetachedDataFiles(path))
    {
      detail::CheckInputPath(dataFile, "volume " + path + ": the data file");
    }
  }
  itk::ImageIOBase::Pointer io;
  {
    const detail::ScopedConsoleCapture console;
    io = detail::CreateImageIOWithoutDICOM(path);
  }
  if (io.IsNull())
  {
    throw InputError(where + ": no ITK reader recognises this file (NRRD, NIfTI, MetaImage or a DICOM folder are "
                             "expected); is the header corrupt?");
  }
  {
    const detail::ScopedConsoleCapture console;
    try
    {
      if (!uri)
      {
        detail::CheckImageIOIsOneWeRead(io->GetNameOfClass(), where, true);
      }
      if (!uri)
      {
        detail::CheckHeaderBeforeITKReads(*io, path, where);
      }
      io->SetFileName(path);
      io->ReadImageInformation();
    }
    catch (const itk::ExceptionObject & exception)
    {
      throw InputError(where + ": the header cannot be read: " + detail::CondenseITKMessage(exception) +
                       (console.FirstLine().empty() ? std::string() : " (" + console.FirstLine() + ")"));
    }
  }
  const unsigned int dimensions = io->GetNumberOfDimensions();
  // Trailing axes of one voxel (a 4D file of one time point) read as 3D.
  unsigned int used = dimensions;
  while (used > 3 && io->GetDimensions(used - 1) == 1)
  {
    --used;
  }
  if (used > 3)
  {
    throw InputError(where + ": the image is " + std::to_string(dimensions) + "D (" + SizeText(*io) +
                     " voxels), e.g. a time series; a volume must be 3D: save one time point or channel");
  }
  if (used < 3)
  {
    throw InputError(where + ": the image is " + std::to_string(dimensions) + "D (" + SizeText(*io) +
                     " pixels); a volume must be 3D");
  }
  if (io->GetNumberOfComponents() != 1)
  {
    throw InputError(where + ": the image has " + std::to_string(io->GetNumberOfComponents()) + " " +
                     itk::ImageIOBase::GetComponentTypeAsString(io->GetComponentType()) +
                     " components per voxel; a volume must be scalar");
  }
  std::uintmax_t voxels = 1;
  for (unsigned int d = 0; d < dimensions; ++d)
  {
    const auto size = io->GetDimensions(d);
    if (size == 0)
    {
      throw InputError(where + ": the image is " + SizeText(*io) + " voxels; no axis may be empty");
    }
    if (voxels > MaximumVolumeVoxels / size)
    {
      throw InputError(where + ": the image is " + SizeText(*io) + " voxels, more than " +
                       std::to_string(MaximumVolumeVoxels) + " in all; is the header corrupt?");
    }
    voxels *= size;
  }
  for (unsigned int d = 0; d < 3; ++d)
  {
    const double spacing = io->GetSpacing(d);
    if (!std::isfinite(spacing) || !(spacing > 0.0) || !std::isfinite(io->GetOrigin(d)))
    {
      std::ostringstream what;
      what << where << ": axis " << d << " has spacing " << spacing << " mm and origin " << io->GetOrigin(d)
           << " mm; the spacing must be a finite number > 0 and the origin finite";
      throw InputError(what.str());
    }
    for (unsigned int e = 0; e < 3; ++e)
    {
      if (!std::isfinite(io->GetDirection(d)[e]))
      {
        throw InputError(where + ": the direction matrix holds a value that is not a finite number");
      }
    }
  }
  return io;
}

namespace
{
VolumeImageType::Pointer
ReadVolumeFile(const std::string & path)
{
  const std::string         where = "volume " + path;
  itk::ImageIOBase::Pointer io = InspectVolumeFile(path);
  auto                      reader = itk::ImageFileReader<VolumeImageType>::New();
  reader->SetImageIO(io);
  reader->SetFileName(path);
  {
    // MetaIO reports a truncated file on the console and carries on with what it read: that is a failure here.
    const detail::ScopedConsoleCapture console;
    try
    {
      reader->Update();
    }
    catch (const itk::ExceptionObject & exception)
    {
      throw InputError(where +
                       ": the voxel data cannot be read (truncated?): " + detail::CondenseITKMessage(exception) +
                       (console.FirstLine().empty() ? std::string() : " (" + console.FirstLine() + ")"));
    }
    // Only MetaIO's own complaints: an ITK warning about a valid file (printed there too) is no failure.
    const std::string metaIO = console.FirstLineStartingWith("Meta");
    if (!metaIO.empty())
    {
      throw InputError(where + ": the voxel data cannot be read (truncated?): " + metaIO);
    }
  }
  VolumeImageType::Pointer volume = reader->GetOutput();
  volume->DisconnectPipeline();
  RequireFiniteVoxels(*volume, where);
  return volume;
}
} // namespace

VolumeImageType::Pointer
ReadVolume(const std::string & path, const VolumeReadOptions & options, VolumeReadReport * report)
{
  if (!IsURIName(path) && detail::CheckInputPath(path, "volume", true) == detail::InputKind::Folder)
  {
    return ReadDICOMSeries(path, options, report);
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
