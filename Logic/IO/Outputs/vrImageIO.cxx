// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrImageIO.h"

#include "vrAtomicOutput.h"
#include "vrITKMessages.h"
#include "vrInputError.h"
#include "vrImageIOChoice.h"
#include "vrInputFileChecks.h"
#include "vrURINames.h"
#include "vrWindowLevel.h"

// Including the reader and writer here pulls in the IO factory registration that ITK_USE_FILE sets up.
#include "itkImageFileReader.h"
#include "itkImageFileWriter.h"
#include "itkImageIOFactory.h"
#include "itkImageRegionConstIterator.h"
#include "itkPNGImageIO.h"

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <filesystem>
#include <functional>
#include <sstream>

namespace vr
{
namespace
{
/** The most pixels a 2D input may declare (2^31): more means a corrupt or hostile header. */
constexpr std::uintmax_t MaximumImagePixels = std::uintmax_t{ 1 } << 31;

template<typename TImage>
void
WriteImageAtomically(const TImage *                                   image,
                     const std::string &                              path,
                     itk::ImageIOBase *                               io = nullptr,
                     const std::function<void(const std::string &)> & verify = {})
{
  if (image == nullptr)
  {
    throw InputError("output " + path + ": no image to write");
  }
  AtomicOutput output(path);
  auto         writer = itk::ImageFileWriter<TImage>::New();
  writer->SetInput(image);
  writer->SetFileName(output.TemporaryPath());
  if (io != nullptr)
  {
    writer->SetImageIO(io);
  }
  writer->UseCompressionOn();
  try
  {
    writer->Update();
  }
  catch (const itk::ExceptionObject & exception)
  {
    throw InputError("output " + path +
                     ": could not be written: " + detail::CondenseITKMessage(exception, output.TemporaryPath(), path));
  }
  if (verify)
  {
    verify(output.TemporaryPath());
  }
  output.Commit();
}

/** Opens \a path and checks that it holds a 2D scalar image (a 3D one with a single slice is accepted). */
itk::ImageIOBase::Pointer
Open2DImage(const std::string & path, const std::string & role)
{
  const std::string where = role + " " + path;
  if (!IsURIName(path))
  {
    detail::CheckInputPath(path, role);
    for (const std::string & dataFile : detail::DetachedDataFiles(path))
    {
      detail::CheckInputPath(dataFile, where + ": the data file");
    }
  }
  itk::ImageIOBase::Pointer io = detail::CreateImageIOWithoutDICOM(path);
  if (io.IsNull())
  {
    throw InputError(where + ": no ITK reader recognises this file (is the header corrupt?)");
  }
  {
    const detail::ScopedConsoleCapture console;
    try
    {
      if (!IsURIName(path))
      {
        detail::CheckImageIOIsOneWeRead(io->GetNameOfClass(), where, false);
      }
      if (!IsURIName(path))
      {
        detail::CheckHeaderBeforeITKReads(*io, path, where);
      }
      io->SetFileName(path);
      io->ReadImageInformation();
    }
    catch (const itk::ExceptionObject & exception)
    {
      throw InputError(where + ": the header cannot be read: " + detail::CondenseITKMessage(exception));
    }
  }
  const unsigned int dimensions = io->GetNumberOfDimensions();
  if (!(dimensions == 2 || (dimensions == 3 && io->GetDimensions(2) == 1)))
  {
    throw InputError(where + ": the image has " + std::to_string(dimensions) + " dimensions; it must be 2D");
  }
  if (io->GetNumberOfComponents() != 1)
  {
    throw InputError(where + ": the image has " + std::to_string(io->GetNumberOfComponents()) +
                     " components per pixel; it must be scalar");
  }
  std::uintmax_t pixels = 1;
  for (unsigned int d = 0; d < dimensions; ++d)
  {
    const auto size = io->GetDimensions(d);
    if (size == 0 || pixels > MaximumImagePixels / size)
    {
      throw InputError(where + ": the image is " + std::to_string(io->GetDimensions(0)) + " x " +
                       std::to_string(io->GetDimensions(1)) + " pixels; an axis is empty or there are more than " +
                       std::to_string(MaximumImagePixels) + " in all (is the header corrupt?)");
    }
    pixels *= size;
  }
  return io;
}

template<typename TImage>
typename TImage::Pointer
Read2DImage(const std::string & path, const std::string & role)
{
  itk::ImageIOBase::Pointer io = Open2DImage(path, role);
  auto                      reader = itk::ImageFileReader<TImage>::New();
  reader->SetImageIO(io);
  reader->SetFileName(path);
  {
    const detail::ScopedConsoleCapture console; // MetaIO says "data not read completely" there, and carries on
    try
    {
      reader->Update();
    }
    catch (const itk::ExceptionObject & exception)
    {
      throw InputError(role + " " + path +
                       ": the pixel data cannot be read (truncated?): " + detail::CondenseITKMessage(exception));
    }
    const std::string metaIO = console.FirstLineStartingWith("Meta"); // not ITK's warnings about valid files
    if (!metaIO.empty())
    {
      throw InputError(role + " " + path + ": the pixel data cannot be read (truncated?): " + metaIO);
    }
  }
  typename TImage::Pointer image = reader->GetOutput();
  image->DisconnectPipeline();
  return image;
}
} // namespace

void
WriteImage2D(const DepthImageType * image, const std::string & path)
{
  WriteImageAtomically(image, path);
}

void
WriteImage2D(const MaskImageType * image, const std::string & path)
{
  WriteImageAtomically(image, path);
}

void
WriteImage2D(const LabelImageType * image, const std::string & path)
{
  WriteImageAtomically(image, path);
}

void
WriteImage2D(const itk::Image<itk::Vector<float, 3>, 2> * image, const std::string & path)
{
  WriteImageAtomically(image, path);
}

DepthImageType::Pointer
ReadDepthImage(const std::string & path)
{
  return Read2DImage<DepthImageType>(path, "depth image");
}

MaskImageType::Pointer
ReadMaskImage(const std::string & path)
{
  // Read the stored values as they are, so that no integer type wraps and no fraction truncates on the way to
  // unsigned char: any non-zero pixel is fixed, as BilateralDepthRelaxFilter reads its mask.
  using StoredImageType = itk::Image<double, 2>;
  StoredImageType::Pointer stored = Read2DImage<StoredImageType>(path, "mask image");

  auto mask = MaskImageType::New();
  mask->CopyInformation(stored);
  mask->SetRegions(stored->GetLargestPossibleRegion());
  mask->SetMetaDataDictionary(stored->GetMetaDataDictionary());
  mask->Allocate();
  const std::size_t count = stored->GetLargestPossibleRegion().GetNumberOfPixels();
  const double *    values = stored->GetBufferPointer();
  unsigned char *   fixed = mask->GetBufferPointer();
  for (std::size_t k = 0; k < count; ++k)
  {
    if (!std::isfinite(values[k]))
    {
      const auto         index = stored->ComputeIndex(static_cast<StoredImageType::OffsetValueType>(k));
      std::ostringstream what;
      what << "mask image " << path << ": pixel (" << index[0] << ", " << index[1] << ") is " << values[k]
           << "; a mask holds 0 (free) or non-zero (fixed)";
      throw InputError(what.str());
    }
    fixed[k] = values[k] != 0.0 ? 1 : 0;
  }
  return mask;
}

void
WriteWindowedPNG(const DepthImageType * image, double window, double level, const std::string & path)
{
  if (!(window > 0.0) || !std::isfinite(window))
  {
    std::ostringstream what;
    what << "PNG output " << path << ": window " << window << " must be a finite number > 0";
    throw InputError(what.str());
  }
  if (!std::isfinite(level))
  {
    std::ostringstream what;
    what << "PNG output " << path << ": level " << level << " must be a finite number";
    throw InputError(what.str());
  }
  if (image == nullptr)
  {
    throw InputError("PNG output " + path + ": no image to write");
  }
  // A plain loop rather than itk::IntensityWindowingImageFilter, whose functor casts NaN to unsigned char.
  auto bytes = MaskImageType::New();
  bytes->CopyInformation(image);
  bytes->SetRegions(image->GetLargestPossibleRegion());
  bytes->Allocate();
  const std::size_t count = image->GetLargestPossibleRegion().GetNumberOfPixels();
  const float *     values = image->GetBufferPointer();
  unsigned char *   grey = bytes->GetBufferPointer();
  WindowLevelToBytes(values, count, window, level, grey);
  WriteGreyPNG(bytes, path);
}

void
WriteGreyPNG(const MaskImageType * bytes, const std::string & path)
{
  if (bytes == nullptr)
  {
    throw InputError("PNG output " + path + ": no image to write");
  }
  const std::size_t     count = bytes->GetLargestPossibleRegion().GetNumberOfPixels();
  const unsigned char * grey = bytes->GetBufferPointer();
  // ITK's PNG writer ignores a failed fclose, so a full disk can leave a truncated PNG behind a successful write:
  // read the file back and compare before it is published.
  const auto verify = [&](const std::string & written)
  {
    bool same = false;
    try
    {
      auto reader = itk::ImageFileReader<MaskImageType>::New();
      reader->SetImageIO(itk::PNGImageIO::New());
      reader->SetFileName(written);
      const detail::ScopedConsoleCapture console; // libpng's warnings about the truncation
      reader->Update();
      const MaskImageType * back = reader->GetOutput();
      same = back->GetLargestPossibleRegion().GetSize() == bytes->GetLargestPossibleRegion().GetSize() &&
             std::equal(grey, grey + count, back->GetBufferPointer());
    }
    catch (const itk::ExceptionObject &)
    {
      same = false;
    }
    if (!same)
    {
      throw InputError("PNG output " + path + ": could not be written (the file reads back incomplete: disk full?)");
    }
  };
  WriteImageAtomically<MaskImageType>(bytes, path, itk::PNGImageIO::New(), verify);
}
} // namespace vr
