// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Writes a small NRRD by hand (a text header, then raw little-endian floats), reads it with itk::ImageFileReader
// and checks size, spacing, origin and every value. Nothing of VesselReformation's own IO is called: the reader
// works only if the package registered ITK's NRRD factory for this translation unit.
#include "itkImage.h"
#include "itkImageFileReader.h"

#include <fstream>
#include <iostream>

int
main(int argc, char * argv[])
{
  if (argc != 2)
  {
    std::cerr << "usage: NRRDConsumer <file.nrrd to write and read>" << std::endl;
    return 2;
  }
  {
    std::ofstream file(argv[1], std::ios::binary);
    file << "NRRD0004\ntype: float\ndimension: 3\nspace: left-posterior-superior\nsizes: 2 3 4\n"
            "space directions: (0.5,0,0) (0,0.75,0) (0,0,2)\nspace origin: (10,-20,30)\nendian: little\n"
            "encoding: raw\n\n";
    for (int k = 0; k < 24; ++k)
    {
      const float value = 1.5f * static_cast<float>(k);
      file.write(reinterpret_cast<const char *>(&value), sizeof(value));
    }
  }
  using Image = itk::Image<float, 3>;
  auto reader = itk::ImageFileReader<Image>::New();
  reader->SetFileName(argv[1]);
  try
  {
    reader->Update();
  }
  catch (const itk::ExceptionObject & error)
  {
    std::cerr << "reading the NRRD failed: " << error.GetDescription() << std::endl;
    return 1;
  }
  const Image * image = reader->GetOutput();
  const auto    size = image->GetLargestPossibleRegion().GetSize();
  const bool    geometry = size[0] == 2 && size[1] == 3 && size[2] == 4 && image->GetSpacing()[0] == 0.5 &&
                        image->GetSpacing()[1] == 0.75 && image->GetSpacing()[2] == 2.0 &&
                        image->GetOrigin()[0] == 10.0 && image->GetOrigin()[1] == -20.0 &&
                        image->GetOrigin()[2] == 30.0;
  if (!geometry)
  {
    std::cerr << "wrong geometry: size " << size << ", spacing " << image->GetSpacing() << ", origin "
              << image->GetOrigin() << std::endl;
    return 1;
  }
  for (int k = 0; k < 24; ++k)
  {
    if (image->GetBufferPointer()[k] != 1.5f * static_cast<float>(k))
    {
      std::cerr << "voxel " << k << " is " << image->GetBufferPointer()[k] << std::endl;
      return 1;
    }
  }
  std::cout << "read " << size << " voxels through " << reader->GetImageIO()->GetNameOfClass() << std::endl;
  return 0;
}
