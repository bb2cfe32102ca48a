// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrSecondaryCaptureIO_h
#define vrSecondaryCaptureIO_h

#include "vrDICOMIdentity.h"
#include "vrImageTypes.h"

#include <string>

namespace vr
{
/** The DICOM SOP Class UID of Secondary Capture Image Storage. */
constexpr const char * SecondaryCaptureSOPClassUID = "1.2.840.10008.5.1.4.1.1.7";

/** One Secondary Capture picture of a series: what its file says besides the pixels. */
struct SecondaryCaptureFields
{
  DICOMIdentity Identity;
  std::string   SeriesInstanceUID;
  long long     SeriesNumber{ 0 };
  /** Series Description (0008,103E), at most 64 characters (LO). */
  std::string SeriesDescription;
  /** Series and content date (YYYYMMDD) and time (HHMMSS). */
  std::string SeriesDate;
  std::string SeriesTime;
  std::string SOPInstanceUID;
  long long   InstanceNumber{ 1 };
  /** Image Comments (0020,4000). */
  std::string ImageComments;
};

/** \return a new, globally unique DICOM UID (GDCM's generator, under GDCM's root 1.2.826.0.1.3680043.2.1143). */
std::string
NewDICOMUID();

/** \return the current local date as DICOM writes it (YYYYMMDD); \a time receives HHMMSS. */
std::string
DICOMDateNow(std::string & time);

/** Writes \a grey as one DICOM Secondary Capture file (ITK's GDCMImageIO, uncompressed, explicit VR little endian):
 * SOP Class 1.2.840.10008.5.1.4.1.1.7, Modality OT, Conversion Type WSD (workstation), 8-bit MONOCHROME2, the
 * UIDs given (GDCMImageIO's KeepOriginalUID), and no Image Position or Orientation (Patient): a reformatted
 * picture is not a slice of the patient, and the Secondary Capture IOD leaves the Image Plane module out.
 * Written atomically (vr::AtomicOutput).
 * \param grey the picture; row 0 is the top.
 * \param fields patient, study, series and instance attributes.
 * \param path the file. Throws vr::InputError naming the path, or the field (a UID, the description) when it is not
 * valid DICOM. */
void
WriteSecondaryCapture(const MaskImageType * grey, const SecondaryCaptureFields & fields, const std::string & path);
} // namespace vr

#endif
