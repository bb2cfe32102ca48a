// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrImageIOChoice_h
#define vrImageIOChoice_h

#include "itkImageIOBase.h"

#include <string>

/** Which ITK ImageIO reads a file. Not installed: an implementation detail of the IO library. */
namespace vr::detail
{
/** ITK's choice of reader for \a path (itk::ImageIOFactory::CreateImageIO: the first registered ImageIO whose
 * CanReadFile says yes), except that GDCM is never asked: its CanReadFile parses the whole file, and Debian's GDCM
 * aborts the process on some corrupt files. DICOM is read from a folder, in a child process (vrDICOMSeriesProcess.h).
 * Null when no other ImageIO takes the file. */
itk::ImageIOBase::Pointer
CreateImageIOWithoutDICOM(const std::string & path);

/** Our own check of the whole header, for the formats whose ITK reader trusts it, before \a io reads \a path: NIfTI
 * (vrNiftiHeaderCheck.h) and MetaImage (vrMetaImageHeaderCheck.h). Throws vr::InputError "<where>: ..." naming the
 * field at fault. Other formats (NRRD, whose reader checks its fields) are left to ITK. */
void
CheckHeaderBeforeITKReads(const itk::ImageIOBase & io, const std::string & path, const std::string & where);
} // namespace vr::detail

#endif
