// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrStoredVolume.h"

#include "itkCPRVolumeSampler.h"
#include "vrInputError.h"

#include <type_traits>

namespace vr
{
namespace
{
template<typename TPixel>
constexpr itk::IOComponentEnum
PixelTypeOf()
{
  if constexpr (std::is_same_v<TPixel, signed char>)
  {
    return itk::IOComponentEnum::CHAR;
  }
  else if constexpr (std::is_same_v<TPixel, unsigned char>)
  {
    return itk::IOComponentEnum::UCHAR;
  }
  else if constexpr (std::is_same_v<TPixel, short>)
  {
    return itk::IOComponentEnum::SHORT;
  }
  else if constexpr (std::is_same_v<TPixel, unsigned short>)
  {
    return itk::IOComponentEnum::USHORT;
  }
  else if constexpr (std::is_same_v<TPixel, float>)
  {
    return itk::IOComponentEnum::FLOAT;
  }
  else
  {
    static_assert(std::is_same_v<TPixel, double>, "a stored pixel type");
    return itk::IOComponentEnum::DOUBLE;
  }
}

/** Whether \a image is an image of a stored pixel type (VisitStoredVolume would not throw). */
bool
IsStored(const itk::ImageBase<3> * image)
{
  return dynamic_cast<const itk::Image<short, 3> *>(image) || dynamic_cast<const itk::Image<float, 3> *>(image) ||
         dynamic_cast<const itk::Image<unsigned short, 3> *>(image) ||
         dynamic_cast<const itk::Image<unsigned char, 3> *>(image) ||
         dynamic_cast<const itk::Image<signed char, 3> *>(image) || dynamic_cast<const itk::Image<double, 3> *>(image);
}
} // namespace

itk::IOComponentEnum
StoredVolume::GetPixelType() const
{
  if (!IsStored(Image.GetPointer()))
  {
    return itk::IOComponentEnum::UNKNOWNCOMPONENTTYPE;
  }
  return itk::VisitStoredVolume(static_cast<const itk::ImageBase<3> *>(Image.GetPointer()),
                                        [](const auto * image)
                                        {
                                          using ImageType = std::remove_pointer_t<decltype(image)>;
                                          return PixelTypeOf<typename ImageType::PixelType>();
                                        });
}

std::size_t
StoredVolume::GetVoxelBytes() const
{
  return Image ? StoredPixelBytes(GetPixelType()) * Image->GetBufferedRegion().GetNumberOfPixels() : 0;
}

const void *
StoredVolume::GetBufferPointer() const
{
  if (!IsStored(Image.GetPointer()))
  {
    return nullptr;
  }
  return itk::VisitStoredVolume(static_cast<const itk::ImageBase<3> *>(Image.GetPointer()),
                                        [](const auto * image)
                                        { return static_cast<const void *>(image->GetBufferPointer()); });
}

std::size_t
StoredPixelBytes(itk::IOComponentEnum pixelType)
{
  switch (pixelType)
  {
    case itk::IOComponentEnum::CHAR:
    case itk::IOComponentEnum::UCHAR:
      return 1;
    case itk::IOComponentEnum::SHORT:
    case itk::IOComponentEnum::USHORT:
      return 2;
    case itk::IOComponentEnum::FLOAT:
      return 4;
    case itk::IOComponentEnum::DOUBLE:
      return 8;
    default:
      return 0;
  }
}

std::string
StoredPixelTypeName(itk::IOComponentEnum pixelType)
{
  switch (pixelType)
  {
    case itk::IOComponentEnum::CHAR:
      return "int8";
    case itk::IOComponentEnum::UCHAR:
      return "uint8";
    case itk::IOComponentEnum::SHORT:
      return "int16";
    case itk::IOComponentEnum::USHORT:
      return "uint16";
    case itk::IOComponentEnum::FLOAT:
      return "float32";
    case itk::IOComponentEnum::DOUBLE:
      return "float64";
    default:
      return "unknown";
  }
}

VolumeImageType::Pointer
ConvertStoredVolumeToFloat(const StoredVolume & volume)
{
  if (!IsStored(volume.Image.GetPointer()))
  {
    throw InputError(std::string("volume: ") + (volume.Image ? "its pixel type is not one a volume is kept in (" +
                                                                 std::string(itk::CPRStoredPixelTypes) + ")"
                                                             : "no image given"));
  }
  if (auto * image = dynamic_cast<VolumeImageType *>(volume.Image.GetPointer()); image && volume.Rescale.IsIdentity())
  {
    return image;
  }
  return itk::VisitStoredVolume(static_cast<const itk::ImageBase<3> *>(volume.Image.GetPointer()),
                                        [&volume](const auto * image)
                                        {
                                          auto copy = VolumeImageType::New();
                                          copy->CopyInformation(image);
                                          copy->SetRegions(image->GetBufferedRegion());
                                          copy->SetMetaDataDictionary(image->GetMetaDataDictionary());
                                          copy->Allocate();
                                          const std::size_t count = image->GetBufferedRegion().GetNumberOfPixels();
                                          const auto *      source = image->GetBufferPointer();
                                          float *           target = copy->GetBufferPointer();
                                          for (std::size_t k = 0; k < count; ++k)
                                          {
                                            target[k] =
                                              static_cast<float>(volume.Rescale.Apply(static_cast<double>(source[k])));
                                          }
                                          return copy;
                                        });
}
} // namespace vr
