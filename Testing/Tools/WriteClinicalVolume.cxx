// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// WriteClinicalVolume <output> [--phantom runoff|thorax] [--size X,Y,Z] [--type int16|uint16|float32|float64]
//                     [--centerlines <file>] [--compress]
// writes a clinical-size CT angiography made from a built-in phantom (vr::test::MakeClinicalVolume: slices of X x Y
// square pixels spanning the phantom's width, Z slices along its length, HU) in the given pixel type, in any format
// ITK writes by the output's extension (.nrrd, .nhdr, .nii, .nii.gz, .mha, .mhd), uncompressed unless --compress; with
// --centerlines, the phantom's exact centerline tree beside it (vr::WriteCenterlines: .vtp in RAS, as VMTK's). uint16
// stores HU + 1024 (the formats here carry no rescale; a CT scanner would put -1024 in its Rescale Intercept).
// Defaults: the run-off phantom, 512,512,1200, int16 (a 630 MB volume, as a clinical run-off CTA). Prints the time it
// took and the voxel bytes. For the measurements of full-size input (docs/benchmarks.md "Full-size volumes").
#include "vrCenterlineIO.h"
#include "vrClinicalVolume.h"
#include "vrText.h"

#include "itkImageFileWriter.h"
#include "itkImageIOFactory.h"

#include <chrono>
#include <iostream>
#include <string>

namespace
{
template<typename TPixel>
std::size_t
Write(itk::CTAPhantomKind kind, const itk::Size<3> & size, double intercept, const std::string & path, bool compress)
{
  auto volume = vr::test::MakeClinicalVolume<TPixel>(
    kind, size, intercept, [](double fraction) { std::cerr << "\rdrawing " << int(100 * fraction) << " %"; });
  std::cerr << "\n";
  auto writer = itk::ImageFileWriter<itk::Image<TPixel, 3>>::New();
  writer->SetInput(volume);
  writer->SetFileName(path);
  writer->SetUseCompression(compress);
  writer->Update();
  return volume->GetLargestPossibleRegion().GetNumberOfPixels() * sizeof(TPixel);
}
} // namespace

int
main(int argc, char ** argv)
{
  const char * const usage = "usage: WriteClinicalVolume <output> [--phantom runoff|thorax] [--size X,Y,Z] "
                             "[--type int16|uint16|float32|float64] [--centerlines <file>] [--compress]\n";
  if (argc >= 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h"))
  {
    std::cout << usage;
    return 0;
  }
  if (argc < 2 || argv[1][0] == '-')
  {
    std::cerr << usage;
    return 2;
  }
  try
  {
    const std::string output = argv[1];
    // Before minutes of drawing: a name no ITK writer takes is refused now.
    if (itk::ImageIOFactory::CreateImageIO(output.c_str(), itk::ImageIOFactory::FileModeEnum::WriteMode).IsNull())
    {
      throw std::invalid_argument(output + ": no ITK writer takes this extension (.nrrd, .nhdr, .nii, .nii.gz, "
                                           ".mha or .mhd)");
    }
    itk::CTAPhantomKind kind = itk::CTAPhantomKind::Runoff;
    itk::Size<3>        size = { { 512, 512, 1200 } };
    std::string         type = "int16";
    std::string         centerlines;
    bool                compress = false;
    for (int k = 2; k < argc; ++k)
    {
      const std::string argument = argv[k];
      const bool        hasValue = k + 1 < argc;
      if (argument == "--phantom" && hasValue)
      {
        kind = itk::ParseCTAPhantomKind(argv[++k]);
      }
      else if (argument == "--size" && hasValue)
      {
        const auto items = vr::SplitAndTrim(argv[++k], ',');
        long long  value = 0;
        if (items.size() != 3)
        {
          throw std::invalid_argument("--size takes X,Y,Z");
        }
        for (unsigned int axis = 0; axis < 3; ++axis)
        {
          if (!vr::ParseWholeInteger(items[axis], value) || value < 2 || value > 65536)
          {
            throw std::invalid_argument("--size: " + items[axis] + " is not a whole number from 2 to 65536");
          }
          size[axis] = static_cast<itk::SizeValueType>(value);
        }
      }
      else if (argument == "--type" && hasValue)
      {
        type = argv[++k];
      }
      else if (argument == "--centerlines" && hasValue)
      {
        centerlines = argv[++k];
      }
      else if (argument == "--compress")
      {
        compress = true;
      }
      else
      {
        throw std::invalid_argument("unknown argument " + argument);
      }
    }
    const auto  start = std::chrono::steady_clock::now();
    std::size_t bytes = 0;
    if (type == "int16")
    {
      bytes = Write<short>(kind, size, 0.0, output, compress);
    }
    else if (type == "uint16")
    {
      bytes = Write<unsigned short>(kind, size, -1024.0, output, compress);
    }
    else if (type == "float32")
    {
      bytes = Write<float>(kind, size, 0.0, output, compress);
    }
    else if (type == "float64")
    {
      bytes = Write<double>(kind, size, 0.0, output, compress);
    }
    else
    {
      throw std::invalid_argument("--type " + type + ": int16, uint16, float32 or float64");
    }
    if (!centerlines.empty())
    {
      vr::WriteCenterlines(itk::MakeCTAPhantom(kind, 1.0).Tree, centerlines);
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << output << ": " << size[0] << " x " << size[1] << " x " << size[2] << " " << type << ", " << bytes
              << " voxel bytes, written in " << seconds << " s\n";
    return 0;
  }
  catch (const std::exception & error)
  {
    std::cerr << "error: " << error.what() << "\n";
    return 1;
  }
}
