// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrImageIOChoice.h"

#include "vrMetaImageHeaderCheck.h"
#include "vrNiftiHeaderCheck.h"

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

void
CheckHeaderBeforeITKReads(const itk::ImageIOBase & io, const std::string & path, const std::string & where)
{
  const std::string reader = io.GetNameOfClass();
  if (reader == "NiftiImageIO")
  {
    CheckNiftiHeader(path, where);
  }
  else if (reader == "MetaImageIO")
  {
    CheckMetaImageHeader(path, where);
  }
}
} // namespace vr::detail
