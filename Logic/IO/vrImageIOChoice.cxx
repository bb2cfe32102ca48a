// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrImageIOChoice.h"

#include "itkObjectFactoryBase.h"

namespace vr::detail
{
itk::ImageIOBase::Pointer
CreateImageIOWithoutDICOM(const std::string & path)
{
  for (const itk::LightObject::Pointer & object : itk::ObjectFactoryBase::CreateAllInstance("itkImageIOBase"))
  {
    auto * io = dynamic_cast<itk::ImageIOBase *>(object.GetPointer());
    if (io == nullptr || std::string(io->GetNameOfClass()) == "GDCMImageIO")
    {
      continue;
    }
    if (io->CanReadFile(path.c_str()))
    {
      return io;
    }
  }
  return nullptr;
}
} // namespace vr::detail
