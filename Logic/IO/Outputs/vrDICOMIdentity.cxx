// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrDICOMIdentity.h"

#include "itkMetaDataObject.h"

#include <utility>

namespace vr
{
std::map<std::string, std::string>
DICOMAttributesOf(const itk::MetaDataDictionary & dictionary)
{
  static const std::pair<const char *, const char *> Tags[] = {
    { "0010|0010", DICOMAttribute::PatientName },      { "0010|0020", DICOMAttribute::PatientID },
    { "0010|0030", DICOMAttribute::PatientBirthDate }, { "0010|0040", DICOMAttribute::PatientSex },
    { "0020|000d", DICOMAttribute::StudyInstanceUID }, { "0020|0010", DICOMAttribute::StudyID },
    { "0008|0020", DICOMAttribute::StudyDate },        { "0008|0030", DICOMAttribute::StudyTime },
    { "0008|0050", DICOMAttribute::AccessionNumber },  { "0008|1030", DICOMAttribute::StudyDescription },
  };
  std::map<std::string, std::string> attributes;
  for (const auto & [tag, key] : Tags)
  {
    std::string value;
    if (!itk::ExposeMetaData<std::string>(dictionary, tag, value))
    {
      continue;
    }
    // DICOM pads values to an even length: text with a space, UIDs with a NUL.
    while (!value.empty() && (value.back() == ' ' || value.back() == '\0'))
    {
      value.pop_back();
    }
    if (!value.empty())
    {
      attributes[key] = value;
    }
  }
  return attributes;
}
} // namespace vr
