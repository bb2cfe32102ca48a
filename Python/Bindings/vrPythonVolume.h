// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrPythonVolume_h
#define vrPythonVolume_h

#include "vrCenterlineExtraction.h"
#include "vrImageTypes.h"
#include "vrSegmentationIO.h"
#include "vrVolumeNode.h"

#include <vtkSmartPointer.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

namespace vr::python
{
namespace py = pybind11;

/** The grid of a volume in LPS, as ITK and SimpleITK give it: spacing (i, j, k), origin, direction columns. */
struct VolumeGeometry
{
  VolumeImageType::SpacingType   Spacing;
  VolumeImageType::PointType     Origin;
  VolumeImageType::DirectionType Direction;
};

/** \class Volume
 * \brief vesselreformation.Volume: a scalar volume on an LPS grid as the engine reads it (vr::VolumeImageType), and
 * the numpy array (k, j, i) holding its voxels. The image views the array's memory: no copy of a float32
 * C-contiguous array; one copy (to float32, C order) of any other (VolumeFromArray).
 */
struct Volume
{
  VolumeImageType::Pointer Image;
  /** The float32 C-contiguous array the image's voxels live in (the caller's, or the one copy). */
  py::array_t<float> Array;
  /** Whether Array is a copy of what the caller gave. */
  bool        Copied{ false };
  std::string Name;
};

/** The one conversion of a numpy array to an engine volume. \a array is indexed (k, j, i) as ITK's and SimpleITK's
 * arrays are, i the fastest: a float32, C-contiguous, aligned array is viewed as it is (the engine reads its memory);
 * any other (another dtype, a transposed or strided view) is copied once into a new float32 C-order array. The
 * engine's volumes are float today; when they keep their stored type, int16 will be viewed here too.
 * Throws ValueError naming the argument \a what: not 3-D, an empty axis, a dtype that is no real number, a NaN or
 * infinite voxel. */
Volume
VolumeFromArray(const py::array & array, const VolumeGeometry & geometry, const std::string & name, const char * what);

/** \return the grid given by ITK-style arguments: spacing (3, finite, > 0), origin (3, finite), direction (3 x 3,
 * finite, orthonormal columns; None: identity). Throws ValueError naming the argument. */
VolumeGeometry
GeometryFromITK(const py::object & spacing, const py::object & origin, const py::object & direction);
/** \return the grid given by a nibabel-style affine: 4 x 4, voxel (i, j, k) -> RAS mm, last row 0 0 0 1, columns of
 * non-zero length and orthogonal. Throws ValueError naming "affine". */
VolumeGeometry
GeometryFromAffine(const py::object & affine);

/** \return \a image (the caller keeps it alive through the capsule) as a Volume whose array views its voxels. */
Volume
VolumeFromImage(VolumeImageType::Pointer image, const std::string & name);

/** A volume node over the voxels \a volume's image holds (no copy; the image outlives the node, which lives in one
 * call of reform() or vessel_path()), on the image's grid: what a platform hands the logics. */
vtkSmartPointer<VolumeNode>
NodeOver(const Volume & volume);

/** \return a mask (0/1, unsigned char) as a numpy array (k, j, i) viewing its voxels; the array keeps it alive. */
py::array
ArrayOfMask(SegmentationMaskType::Pointer mask);

/** \class SegmentationObject
 * \brief vesselreformation.Segmentation: a vessel segmentation as the engine reads it (vr::Segmentation) and what
 * reading it warned about.
 */
struct SegmentationObject
{
  Segmentation             Value;
  std::vector<std::string> Warnings;
};

/** \return the engine's segmentation of \a value (a Segmentation); ValueError naming \a what otherwise. */
const Segmentation &
SegmentationOf(const py::object & value, const char * what);

/** Defines Volume, Segmentation, read_volume, write_volume, read_segmentation. */
void
RegisterVolumes(py::module_ & module);
} // namespace vr::python

#endif
