// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// WriteDICOMSeries <volume> <folder> [slices] [--time-read]: writes a volume (any format vr::ReadVolume reads) as a
// CT DICOM series of 16-bit slices with ITK's GDCM IO, one file per slice, as ITK's DICOM examples do; with
// [slices], resampled (linearly) to that many slices along its third axis first. Used by
// scripts/dicom-mutation-campaign.sh (the series it mutates) and to measure the DICOM reader on a long series:
// --time-read then reads the written folder back through vr::ReadVolume (a child process) and in this process
// with ITK's series reader, and prints both times.
#include "vrVolumeIO.h"

#include "itkCastImageFilter.h"
#include "itkGDCMImageIO.h"
#include "itkGDCMSeriesFileNames.h"
#include "itkImageSeriesReader.h"
#include "itkImageSeriesWriter.h"
#include "itkLinearInterpolateImageFunction.h"
#include "itkMetaDataObject.h"
#include "itkResampleImageFilter.h"

#include <gdcmTrace.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using Volume = vr::VolumeImageType;
using ShortVolume = itk::Image<short, 3>;
using Slice = itk::Image<short, 2>;

Volume::Pointer
Resampled(const Volume * volume, unsigned int slices)
{
  auto size = volume->GetLargestPossibleRegion().GetSize();
  auto spacing = volume->GetSpacing();
  spacing[2] = spacing[2] * static_cast<double>(size[2] - 1) / static_cast<double>(slices - 1);
  size[2] = slices;
  auto resample = itk::ResampleImageFilter<Volume, Volume>::New();
  resample->SetInput(volume);
  resample->SetInterpolator(itk::LinearInterpolateImageFunction<Volume, double>::New());
  resample->SetSize(size);
  resample->SetOutputSpacing(spacing);
  resample->SetOutputOrigin(volume->GetOrigin());
  resample->SetOutputDirection(volume->GetDirection());
  resample->Update();
  return resample->GetOutput();
}

void
Write(const Volume * volume, const std::string & folder)
{
  auto cast = itk::CastImageFilter<Volume, ShortVolume>::New();
  cast->SetInput(volume);
  cast->Update();
  const ShortVolume *                                   shorts = cast->GetOutput();
  const unsigned int                                    slices = shorts->GetLargestPossibleRegion().GetSize()[2];
  std::vector<std::unique_ptr<itk::MetaDataDictionary>> owned;
  std::vector<itk::MetaDataDictionary *>                dictionaries;
  std::vector<std::string>                              names;
  const auto &                                          d = shorts->GetDirection();
  std::ostringstream                                    orientation;
  orientation << d(0, 0) << "\\" << d(1, 0) << "\\" << d(2, 0) << "\\" << d(0, 1) << "\\" << d(1, 1) << "\\" << d(2, 1);
  for (unsigned int z = 0; z < slices; ++z)
  {
    auto dictionary = std::make_unique<itk::MetaDataDictionary>();
    auto put = [&](const char * tag, const std::string & value)
    { itk::EncapsulateMetaData<std::string>(*dictionary, tag, value); };
    itk::Point<double, 3> position;
    shorts->TransformIndexToPhysicalPoint({ { 0, 0, static_cast<itk::IndexValueType>(z) } }, position);
    std::ostringstream positionText;
    positionText.precision(10);
    positionText << position[0] << "\\" << position[1] << "\\" << position[2];
    put("0008|0060", "CT");
    put("0008|0016", "1.2.840.10008.5.1.4.1.1.2");
    put("0020|000d", "1.2.826.0.1.3680043.2.1125.7.1");
    put("0020|000e", "1.2.826.0.1.3680043.2.1125.7.2");
    put("0020|0052", "1.2.826.0.1.3680043.2.1125.7.3");
    put("0008|0018", "1.2.826.0.1.3680043.2.1125.7.2." + std::to_string(z + 1));
    put("0020|0013", std::to_string(z + 1));
    put("0020|0032", positionText.str());
    put("0020|0037", orientation.str());
    put("0018|0050", std::to_string(shorts->GetSpacing()[2]));
    dictionaries.push_back(dictionary.get());
    owned.push_back(std::move(dictionary));
    char name[32];
    std::snprintf(name, sizeof(name), "IM%04u.dcm", z + 1);
    names.push_back(folder + "/" + name);
  }
  auto io = itk::GDCMImageIO::New();
  io->KeepOriginalUIDOn();
  auto writer = itk::ImageSeriesWriter<ShortVolume, Slice>::New();
  writer->SetInput(shorts);
  writer->SetImageIO(io);
  writer->SetFileNames(names);
  writer->SetMetaDataDictionaryArray(&dictionaries);
  writer->Update();
}

double
Seconds(const std::chrono::steady_clock::time_point & start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/** The series read in this process, as the volume reader did before it used a child process. */
void
ReadInProcess(const std::string & folder)
{
  auto names = itk::GDCMSeriesFileNames::New();
  names->SetUseSeriesDetails(true);
  names->SetDirectory(folder);
  const std::vector<std::string> files = names->GetFileNames(names->GetSeriesUIDs().front());
  auto                           reader = itk::ImageSeriesReader<Volume>::New();
  reader->SetImageIO(itk::GDCMImageIO::New());
  reader->SetFileNames(files);
  reader->Update();
}
} // namespace

int
main(int argc, char * argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: WriteDICOMSeries <volume> <folder> [slices] [--time-read]\n";
    return 2;
  }
  gdcm::Trace::SetWarning(false);
  gdcm::Trace::SetDebug(false);
  try
  {
    Volume::Pointer volume = vr::ReadVolume(argv[1]);
    if (argc > 3 && std::string(argv[3]) != "--time-read")
    {
      volume = Resampled(volume, static_cast<unsigned int>(std::stoul(argv[3])));
    }
    std::filesystem::create_directories(argv[2]);
    Write(volume, argv[2]);
    if (std::string(argv[argc - 1]) == "--time-read")
    {
      for (int round = 0; round < 3; ++round)
      {
        auto start = std::chrono::steady_clock::now();
        ReadInProcess(argv[2]);
        const double inProcess = Seconds(start);
        start = std::chrono::steady_clock::now();
        const auto   read = vr::ReadVolume(argv[2]);
        const double child = Seconds(start);
        std::cout << "slices " << read->GetLargestPossibleRegion().GetSize()[2] << "  in-process " << inProcess
                  << " s  child process " << child << " s  ratio " << child / inProcess << "\n";
      }
    }
  }
  catch (const std::exception & error)
  {
    std::cerr << "WriteDICOMSeries: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
