// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrVolumeIO.h"

#include "vrAtomicOutput.h"
#include "vrAvailableMemory.h"
#include "vrDICOMSeriesProcess.h"
#include "vrITKMessages.h"
#include "vrInputError.h"
#include "vrImageIOChoice.h"
#include "vrInputFileChecks.h"
#include "vrMetaImageVoxels.h"
#include "vrNiftiVoxels.h"
#include "vrNrrdRawVoxels.h"
#include "vrURINames.h"

// Including the reader and writer here pulls in the IO factory registration that ITK_USE_FILE sets up
// (ITK_IO_FACTORY_REGISTER_MANAGER): NRRD, NIfTI, MetaImage, PNG and GDCM are known to this translation unit.
#include "itkByteSwapper.h"
#include "itkGDCMImageIO.h"
#include "itkImageFileReader.h"
#include "itkImageFileWriter.h"
#include "itkImageIOFactory.h"

#include <cmath>
#include <filesystem>
#include <optional>
#include <sstream>
#include <type_traits>

namespace vr
{
namespace
{
/** Rejects a volume holding NaN or an infinity: it would turn the CPR into NaN without a word. Integers are finite. */
template<typename TImage>
void
RequireFiniteVoxels(const TImage & volume, const std::string & where)
{
  using PixelType = typename TImage::PixelType;
  if constexpr (std::is_floating_point_v<PixelType>)
  {
    const std::size_t count = volume.GetLargestPossibleRegion().GetNumberOfPixels();
    const PixelType * voxels = volume.GetBufferPointer();
    for (std::size_t k = 0; k < count; ++k)
    {
      if (std::isfinite(voxels[k]))
      {
        continue;
      }
      const auto         index = volume.ComputeIndex(static_cast<typename TImage::OffsetValueType>(k));
      std::ostringstream what;
      what << where << ": voxel (" << index[0] << ", " << index[1] << ", " << index[2] << ") is " << voxels[k]
           << "; a volume must hold finite values (NaN or infinite voxels would make the CPR meaningless)";
      throw InputError(what.str());
    }
  }
}

StoredVolume
ReadDICOMSeries(const std::string & folder, const VolumeReadOptions & options, VolumeReadReport * report)
{
  const std::string       where = "volume folder " + folder;
  detail::DICOMSeriesRead read = detail::ReadDICOMSeriesInChildProcess(folder, options.DICOMSeries, where);
  if (const auto * floatVolume = dynamic_cast<const VolumeImageType *>(read.Volume.Image.GetPointer()))
  {
    RequireFiniteVoxels(*floatVolume, where);
  }
  if (report != nullptr)
  {
    report->Warnings.insert(report->Warnings.end(), read.Warnings.begin(), read.Warnings.end());
    report->Notes.insert(report->Notes.end(), read.Notes.begin(), read.Notes.end());
  }
  // In the series' stored type with its rescale, or float intensities (docs/dicom-series.md "Values").
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
/** Refuses, before anything is allocated, voxels that need more memory than this process may still allocate. */
void
RequireMemoryForVoxels(std::uintmax_t      voxels,
                       std::size_t         voxelBytes,
                       const std::string & what,
                       const std::string & where)
{
  const double needed = static_cast<double>(voxels) * static_cast<double>(voxelBytes);
  const double available = AvailableMemoryInBytes();
  if (needed > available)
  {
    throw InputError(where + ": its " + std::to_string(voxels) + " voxels of " + what + " need " +
                     DescribeBytes(needed) + " of memory, more than the " + DescribeBytes(available) + " available");
  }
}

/** The voxel data read by ITK's reader for the pixel type of the volume: straight into the output's buffer when
 * that is the file's type (NRRD, MetaImage), else through ITK's conversion. */
template<typename TPixel>
typename itk::Image<TPixel, 3>::Pointer
ReadWithITK(itk::ImageIOBase * io, const std::string & path, const std::string & where)
{
  auto reader = itk::ImageFileReader<itk::Image<TPixel, 3>>::New();
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
  typename itk::Image<TPixel, 3>::Pointer volume = reader->GetOutput();
  volume->DisconnectPipeline();
  return volume;
}

/** An image of TPixel on the grid ITK's reader gives the file (from its header alone), allocated but not zeroed: the
 * caller reads every voxel into its buffer itself. */
template<typename TPixel>
typename itk::Image<TPixel, 3>::Pointer
AllocateOnTheHeadersGrid(itk::ImageIOBase * io, const std::string & path, const std::string & where)
{
  using ImageType = itk::Image<TPixel, 3>;
  auto reader = itk::ImageFileReader<ImageType>::New();
  reader->SetImageIO(io);
  reader->SetFileName(path);
  {
    const detail::ScopedConsoleCapture console;
    try
    {
      reader->UpdateOutputInformation();
    }
    catch (const itk::ExceptionObject & exception)
    {
      throw InputError(where + ": the header cannot be read: " + detail::CondenseITKMessage(exception));
    }
  }
  auto volume = ImageType::New();
  volume->CopyInformation(reader->GetOutput());
  volume->SetRegions(reader->GetOutput()->GetLargestPossibleRegion());
  volume->SetMetaDataDictionary(io->GetMetaDataDictionary());
  volume->Allocate();
  return volume;
}

/** A NIfTI volume whose voxels our own reader puts straight into the image's buffer (vrNiftiVoxels.h). */
template<typename TPixel>
typename itk::Image<TPixel, 3>::Pointer
ReadNifti(itk::ImageIOBase * io, const std::string & path, const std::string & where)
{
  auto                               volume = AllocateOnTheHeadersGrid<TPixel>(io, path, where);
  const detail::ScopedConsoleCapture console;
  detail::ReadNiftiVoxels(
    path, volume->GetBufferPointer(), volume->GetLargestPossibleRegion().GetNumberOfPixels() * sizeof(TPixel), where);
  return volume;
}

/** A raw NRRD whose voxels are read straight into the image's buffer (vrNrrdRawVoxels.h), at \a offset. */
template<typename TPixel>
typename itk::Image<TPixel, 3>::Pointer
ReadRawNrrd(itk::ImageIOBase * io, const std::string & path, std::uint64_t offset, const std::string & where)
{
  auto volume = AllocateOnTheHeadersGrid<TPixel>(io, path, where);
  detail::ReadRawVoxels(path,
                        offset,
                        volume->GetBufferPointer(),
                        volume->GetLargestPossibleRegion().GetNumberOfPixels() * sizeof(TPixel),
                        where);
  return volume;
}

/** A compressed MetaImage whose voxels are inflated straight into the image's buffer (vrMetaImageVoxels.h). */
template<typename TPixel>
typename itk::Image<TPixel, 3>::Pointer
ReadCompressedMetaImage(itk::ImageIOBase *                        io,
                        const std::string &                       path,
                        const detail::CompressedMetaImageVoxels & compressed,
                        const std::string &                       where)
{
  auto              volume = AllocateOnTheHeadersGrid<TPixel>(io, path, where);
  const std::size_t count = volume->GetLargestPossibleRegion().GetNumberOfPixels();
  detail::InflateMetaImageVoxels(compressed, volume->GetBufferPointer(), count * sizeof(TPixel), where);
  // From the file's byte order to the machine's (nothing to do where they are the same).
  if (compressed.BigEndian)
  {
    itk::ByteSwapper<TPixel>::SwapRangeFromSystemToBigEndian(volume->GetBufferPointer(), count);
  }
  else
  {
    itk::ByteSwapper<TPixel>::SwapRangeFromSystemToLittleEndian(volume->GetBufferPointer(), count);
  }
  return volume;
}

/** Reads the volume as an image of TPixel, checks its voxels are finite and returns it with \a rescale. */
template<typename TPixel>
StoredVolume
ReadAs(itk::ImageIOBase *               io,
       bool                             nifti,
       const itk::CPRIntensityRescale & rescale,
       std::uintmax_t                   voxels,
       const std::string &              path,
       const std::string &              where)
{
  RequireMemoryForVoxels(
    voxels, sizeof(TPixel), StoredPixelTypeName(itk::ImageIOBase::MapPixelType<TPixel>::CType), where);
  std::optional<std::uint64_t>                     rawNrrd;
  std::optional<detail::CompressedMetaImageVoxels> compressedMeta;
  const bool ownReadable = !nifti && !IsURIName(path) && io->GetNumberOfDimensions() == 3 &&
                           io->GetComponentType() == itk::ImageIOBase::MapPixelType<TPixel>::CType &&
                           io->GetNumberOfComponents() == 1;
  if (ownReadable && std::string(io->GetNameOfClass()) == "NrrdImageIO")
  {
    rawNrrd = detail::RawNrrdVoxelOffset(path, voxels * sizeof(TPixel), sizeof(TPixel));
  }
  else if (ownReadable)
  {
    compressedMeta = detail::FindCompressedMetaImageVoxels(*io, path, where);
  }
  typename itk::Image<TPixel, 3>::Pointer volume = nifti     ? ReadNifti<TPixel>(io, path, where)
                                                   : rawNrrd ? ReadRawNrrd<TPixel>(io, path, *rawNrrd, where)
                                                   : compressedMeta
                                                     ? ReadCompressedMetaImage<TPixel>(io, path, *compressedMeta, where)
                                                     : ReadWithITK<TPixel>(io, path, where);
  RequireFiniteVoxels(*volume, where);
  return StoredVolume{ volume.GetPointer(), rescale };
}

StoredVolume
ReadVolumeFile(const std::string & path)
{
  const std::string         where = "volume " + path;
  itk::ImageIOBase::Pointer io = InspectVolumeFile(path);
  std::uintmax_t            voxels = 1;
  for (unsigned int d = 0; d < io->GetNumberOfDimensions(); ++d)
  {
    voxels *= io->GetDimensions(d);
  }
  // ITK's NIfTI reader reports rescaled integers as float: the header says what the file stores.
  const bool               nifti = std::string(io->GetNameOfClass()) == "NiftiImageIO" && !IsURIName(path);
  itk::IOComponentEnum     pixelType = io->GetComponentType();
  itk::CPRIntensityRescale rescale;
  if (nifti)
  {
    const detail::NiftiVoxelLayout layout = detail::InspectNiftiVoxels(path, where);
    if (layout.Voxels != voxels)
    {
      throw InputError(where + ": the NIfTI header describes " + std::to_string(layout.Voxels) +
                       " voxels where its dimensions give " + std::to_string(voxels));
    }
    pixelType = layout.PixelType;
    rescale.Slope = layout.Slope;
    rescale.Intercept = layout.Intercept;
  }
  switch (pixelType)
  {
    case itk::IOComponentEnum::SHORT:
      return ReadAs<short>(io, nifti, rescale, voxels, path, where);
    case itk::IOComponentEnum::USHORT:
      return ReadAs<unsigned short>(io, nifti, rescale, voxels, path, where);
    case itk::IOComponentEnum::UCHAR:
      return ReadAs<unsigned char>(io, nifti, rescale, voxels, path, where);
    case itk::IOComponentEnum::CHAR:
      return ReadAs<signed char>(io, nifti, rescale, voxels, path, where);
    case itk::IOComponentEnum::FLOAT:
      return ReadAs<float>(io, nifti, rescale, voxels, path, where);
    case itk::IOComponentEnum::DOUBLE:
      return ReadAs<double>(io, nifti, rescale, voxels, path, where);
    default:
      // 32- and 64-bit integers (and NIfTI's other datatypes) through ITK's reader, as float intensities: its NIfTI
      // reader applies scl_slope and scl_inter itself.
      return ReadAs<float>(io, false, itk::CPRIntensityRescale(), voxels, path, where);
  }
}
} // namespace

StoredVolume
ReadStoredVolume(const std::string & path, const VolumeReadOptions & options, VolumeReadReport * report)
{
  if (!IsURIName(path) && detail::CheckInputPath(path, "volume", true) == detail::InputKind::Folder)
  {
    return ReadDICOMSeries(path, options, report);
  }
  return ReadVolumeFile(path);
}

VolumeImageType::Pointer
ReadVolume(const std::string & path, const VolumeReadOptions & options, VolumeReadReport * report)
{
  return ConvertStoredVolumeToFloat(ReadStoredVolume(path, options, report));
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
