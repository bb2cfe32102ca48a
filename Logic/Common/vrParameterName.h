// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrParameterName_h
#define vrParameterName_h

namespace vr
{
/** The reformation's parameters by their meaning, as vr::InputError::Parameter() and the logic's warnings name
 * them. Front ends map these to their own controls (the command-line modules to flags, the widgets to fields). */
namespace ParameterName
{
constexpr const char * UpAxis = "up axis";
constexpr const char * Angle = "angle";
constexpr const char * ViewCenter = "view centre";
constexpr const char * ViewSize = "view size";
constexpr const char * PixelSpacing = "pixel spacing";
constexpr const char * DepthMode = "depth mode";
constexpr const char * FixLumen = "lumen fixing";
constexpr const char * Relaxation = "relaxation";
constexpr const char * Anisotropy = "anisotropy";
constexpr const char * JumpThreshold = "jump threshold";
constexpr const char * Solver = "relax solver";
constexpr const char * Iterations = "iterations";
constexpr const char * Backend = "relax backend";
constexpr const char * OpenCLDevice = "OpenCL device";
constexpr const char * Interpolation = "interpolation";
constexpr const char * SlabThickness = "slab thickness";
constexpr const char * SlabMode = "slab mode";
constexpr const char * Window = "window";
constexpr const char * Level = "level";
/** Which series of a DICOM folder that holds several is read as the volume (vr::VolumeReadOptions). */
constexpr const char * DICOMSeries = "DICOM series";
/** The coordinate system (RAS or LPS) the centerlines were read in. */
constexpr const char * CenterlineSpace = "centerline coordinate system";
/** Centerline extraction from a segmentation (vr::CenterlineExtractionParameters). */
constexpr const char * VesselLabels = "vessel labels";
constexpr const char * RootPoint = "root point";
constexpr const char * RootPointTolerance = "root point tolerance";
constexpr const char * MinimumBranchLength = "minimum branch length";
/** The lumen measurement along a vessel path (vr::LumenMeasurementParameters). */
constexpr const char * ReferencePoints = "reference points";
constexpr const char * ReferenceMethod = "reference method";
constexpr const char * GradingScale = "grading scale";
constexpr const char * LumenSampling = "lumen sampling";
/** The single-vessel reading (vr::VesselPathParameters). */
constexpr const char * Branch = "branch";
constexpr const char * PathRange = "path range";
constexpr const char * Roll = "roll";
constexpr const char * Width = "width";
constexpr const char * SectionSpacing = "section spacing";
} // namespace ParameterName

} // namespace vr

#endif
