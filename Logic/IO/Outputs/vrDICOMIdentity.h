// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrDICOMIdentity_h
#define vrDICOMIdentity_h

#include "itkMetaDataDictionary.h"

#include <map>
#include <string>

namespace vr
{
/** The attributes of a volume node read from DICOM (vr::VolumeNode::SetAttribute) that name its patient and study,
 * as 3D Slicer's DICOM module keeps them; a rotation series (vr::RotationSeriesExport) copies them into its files. A
 * node with a non-empty StudyInstanceUID counts as DICOM input. */
namespace DICOMAttribute
{
constexpr const char * PatientName = "DICOM.PatientName";
constexpr const char * PatientID = "DICOM.PatientID";
constexpr const char * PatientBirthDate = "DICOM.PatientBirthDate";
constexpr const char * PatientSex = "DICOM.PatientSex";
constexpr const char * StudyInstanceUID = "DICOM.StudyInstanceUID";
constexpr const char * StudyID = "DICOM.StudyID";
constexpr const char * StudyDate = "DICOM.StudyDate";
constexpr const char * StudyTime = "DICOM.StudyTime";
constexpr const char * AccessionNumber = "DICOM.AccessionNumber";
constexpr const char * StudyDescription = "DICOM.StudyDescription";
} // namespace DICOMAttribute

/** The patient and study a DICOM file belongs to (DICOM's Patient and General Study modules). Empty fields are
 * written empty (the type 2 attributes) or left out. */
struct DICOMIdentity
{
  std::string PatientName;
  std::string PatientID;
  std::string PatientBirthDate;
  std::string PatientSex;
  /** Patient Comments (0010,4000); says so when the identity was made up. */
  std::string PatientComments;
  std::string StudyInstanceUID;
  std::string StudyID;
  std::string StudyDate;
  std::string StudyTime;
  std::string AccessionNumber;
  std::string StudyDescription;
};

/** The patient and study of a DICOM file as volume node attributes (DICOMAttribute keys), for a DICOM reader to set
 * on the node it makes.
 * \param dictionary the file's header as ITK's GDCMImageIO reads it ("gggg|eeee" -> value).
 * \return the attributes present and non-empty, values without DICOM's trailing padding. */
std::map<std::string, std::string>
DICOMAttributesOf(const itk::MetaDataDictionary & dictionary);
} // namespace vr

#endif
