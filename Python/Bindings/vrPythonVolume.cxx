// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrPythonVolume.h"

#include "vrCenterlineExtraction.h"
#include "vrCoordinateFrames.h"
#include "vrNodeConversion.h"
#include "vrPythonErrors.h"
#include "vrPythonImages.h"
#include "vrVolumeIO.h"

#include <pybind11/stl.h>

#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>

#include <cmath>
#include <sstream>

namespace vr::python
{
namespace
{
/** \a value as \a count finite numbers; ValueError naming \a what otherwise. */
std::vector<double>
FiniteNumbers(const py::object & value, std::size_t count, const char * what)
{
  py::array_t<double, py::array::c_style | py::array::forcecast> numbers;
  try
  {
    numbers = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
  }
  catch (const py::error_already_set &)
  {
  }
  if (!numbers || static_cast<std::size_t>(numbers.size()) != count)
  {
    RaiseValueError(std::string(what) + ": expected " + std::to_string(count) + " numbers, got " +
                    py::repr(value).cast<std::string>());
  }
  std::vector<double> result(numbers.data(), numbers.data() + count);
  for (const double number : result)
  {
    if (!std::isfinite(number))
    {
      RaiseValueError(std::string(what) + ": " + py::repr(value).cast<std::string>() + " is not finite");
    }
  }
  return result;
}

/** Throws ValueError naming \a what unless the columns of \a direction are orthonormal (to 1e-4). */
void
CheckOrthonormal(const VolumeImageType::DirectionType & direction, const char * what, const char * hint)
{
  for (unsigned int a = 0; a < 3; ++a)
  {
    for (unsigned int b = a; b < 3; ++b)
    {
      double dot = 0.0;
      for (unsigned int r = 0; r < 3; ++r)
      {
        dot += direction[r][a] * direction[r][b];
      }
      if (std::abs(dot - (a == b ? 1.0 : 0.0)) > 1e-4)
      {
        std::ostringstream message;
        message << what << ": "
                << (a == b ? "column " + std::to_string(a) + " is not of unit length"
                           : "columns " + std::to_string(a) + " and " + std::to_string(b) +
                               " are not orthogonal (a sheared grid)")
                << " (" << dot << "); " << hint;
        RaiseValueError(message.str());
      }
    }
  }
}

/** The index (i, j, k) of the first voxel of \a data that is not finite, if any. */
bool
FindNonFinite(const float * data, const std::size_t size[3], std::size_t index[3])
{
  const std::size_t count = size[0] * size[1] * size[2];
  for (std::size_t n = 0; n < count; ++n)
  {
    if (!std::isfinite(data[n]))
    {
      index[0] = n % size[0];
      index[1] = (n / size[0]) % size[1];
      index[2] = n / (size[0] * size[1]);
      return true;
    }
  }
  return false;
}
} // namespace

VolumeGeometry
GeometryFromITK(const py::object & spacing, const py::object & origin, const py::object & direction)
{
  VolumeGeometry geometry;
  const auto     s = spacing.is_none() ? std::vector<double>{ 1.0, 1.0, 1.0 } : FiniteNumbers(spacing, 3, "spacing");
  const auto     o = origin.is_none() ? std::vector<double>{ 0.0, 0.0, 0.0 } : FiniteNumbers(origin, 3, "origin");
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    if (!(s[axis] > 0.0))
    {
      RaiseValueError("spacing: " + py::repr(spacing).cast<std::string>() + ": every spacing must be > 0 mm");
    }
    geometry.Spacing[axis] = s[axis];
    geometry.Origin[axis] = o[axis];
  }
  geometry.Direction.SetIdentity();
  if (!direction.is_none())
  {
    // Row-major 3 x 3, as numpy and SimpleITK's GetDirection() give it: column c is axis c's direction in LPS.
    const auto d = FiniteNumbers(direction, 9, "direction");
    for (unsigned int r = 0; r < 3; ++r)
    {
      for (unsigned int c = 0; c < 3; ++c)
      {
        geometry.Direction[r][c] = d[3 * r + c];
      }
    }
    CheckOrthonormal(geometry.Direction, "direction", "give the direction cosines of the voxel axes (LPS)");
  }
  return geometry;
}

VolumeGeometry
GeometryFromAffine(const py::object & affine)
{
  const auto m = FiniteNumbers(affine, 16, "affine");
  if (m[12] != 0.0 || m[13] != 0.0 || m[14] != 0.0 || m[15] != 1.0)
  {
    RaiseValueError("affine: the last row must be 0 0 0 1 (a 4 x 4 voxel-to-RAS matrix, as nibabel's)");
  }
  VolumeGeometry geometry;
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    // Columns and translation go through the one RAS <-> LPS conversion (vrCoordinateFrames.h).
    itk::Point<double, 3> column;
    for (unsigned int r = 0; r < 3; ++r)
    {
      column[r] = m[4 * r + axis];
    }
    const auto   lps = RASToLPS(column);
    const double length = lps.GetVectorFromOrigin().GetNorm();
    if (!(length > 0.0))
    {
      RaiseValueError("affine: column " + std::to_string(axis) + " is zero, so the voxel spacing is 0");
    }
    geometry.Spacing[axis] = length;
    for (unsigned int r = 0; r < 3; ++r)
    {
      geometry.Direction[r][axis] = lps[r] / length;
    }
  }
  itk::Point<double, 3> translation;
  for (unsigned int r = 0; r < 3; ++r)
  {
    translation[r] = m[4 * r + 3];
  }
  geometry.Origin = RASToLPS(translation);
  CheckOrthonormal(geometry.Direction, "affine", "the engine reads grids whose voxel axes are orthogonal");
  return geometry;
}

Volume
VolumeFromArray(const py::array & array, const VolumeGeometry & geometry, const std::string & name, const char * what)
{
  if (array.ndim() != 3)
  {
    RaiseValueError(std::string(what) +
                    ": a volume is a 3-D array indexed (k, j, i); got ndim=" + std::to_string(array.ndim()) +
                    ", shape " + py::repr(py::getattr(array, "shape")).cast<std::string>());
  }
  const char kind = array.dtype().kind();
  if (kind != 'b' && kind != 'i' && kind != 'u' && kind != 'f')
  {
    RaiseValueError(std::string(what) + ": dtype " + py::str(array.dtype()).cast<std::string>() +
                    " holds no intensities (give a boolean, integer or real array)");
  }
  for (py::ssize_t axis = 0; axis < 3; ++axis)
  {
    if (array.shape(axis) == 0)
    {
      RaiseValueError(std::string(what) + ": axis " + std::to_string(axis) + " is empty (shape " +
                      py::repr(py::getattr(array, "shape")).cast<std::string>() + ")");
    }
  }
  Volume volume;
  volume.Name = name;
  const bool viewable = array.dtype().is(py::dtype::of<float>()) && (array.flags() & py::array::c_style) != 0 &&
                        (array.flags() & py::detail::npy_api::NPY_ARRAY_ALIGNED_) != 0;
  if (viewable)
  {
    volume.Array = py::reinterpret_borrow<py::array_t<float>>(array);
  }
  else
  {
    // The one copy: numpy casts and reorders into a new float32 C-order array.
    volume.Array = py::array_t<float, py::array::c_style | py::array::forcecast>::ensure(array);
    volume.Copied = true;
    if (!volume.Array)
    {
      throw py::error_already_set();
    }
  }
  const std::size_t size[3] = { static_cast<std::size_t>(array.shape(2)),
                                static_cast<std::size_t>(array.shape(1)),
                                static_cast<std::size_t>(array.shape(0)) };
  std::size_t       bad[3];
  if (kind == 'f' && FindNonFinite(volume.Array.data(), size, bad))
  {
    RaiseValueError(std::string(what) + ": voxel (i, j, k) = (" + std::to_string(bad[0]) + ", " +
                    std::to_string(bad[1]) + ", " + std::to_string(bad[2]) +
                    ") is not finite; the engine needs finite intensities (array index [" + std::to_string(bad[2]) +
                    ", " + std::to_string(bad[1]) + ", " + std::to_string(bad[0]) + "])");
  }

  VolumeImageType::RegionType region;
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    region.SetSize(axis, size[axis]);
  }
  auto image = VolumeImageType::New();
  image->SetRegions(region);
  image->SetSpacing(geometry.Spacing);
  image->SetOrigin(geometry.Origin);
  image->SetDirection(geometry.Direction);
  // The image reads the array's memory and never frees it: the Volume holds the array as long as the image lives.
  auto container = VolumeImageType::PixelContainer::New();
  container->SetImportPointer(
    const_cast<float *>(volume.Array.data()), static_cast<itk::SizeValueType>(region.GetNumberOfPixels()), false);
  image->SetPixelContainer(container);
  volume.Image = image;
  return volume;
}

Volume
VolumeFromImage(VolumeImageType::Pointer image, const std::string & name)
{
  const auto size = image->GetBufferedRegion().GetSize();
  // The capsule holds a reference to the image: the array keeps its voxels alive, whoever else lets go.
  auto *      held = new VolumeImageType::Pointer(image);
  py::capsule owner(held, [](void * pointer) { delete static_cast<VolumeImageType::Pointer *>(pointer); });
  Volume      volume;
  volume.Image = image;
  volume.Name = name;
  volume.Array = py::array_t<float>(
    { static_cast<py::ssize_t>(size[2]), static_cast<py::ssize_t>(size[1]), static_cast<py::ssize_t>(size[0]) },
    image->GetBufferPointer(),
    owner);
  return volume;
}

py::array
ArrayOfMask(SegmentationMaskType::Pointer mask)
{
  const auto  size = mask->GetBufferedRegion().GetSize();
  auto *      held = new SegmentationMaskType::Pointer(mask);
  py::capsule owner(held, [](void * pointer) { delete static_cast<SegmentationMaskType::Pointer *>(pointer); });
  return py::array_t<unsigned char>(
    { static_cast<py::ssize_t>(size[2]), static_cast<py::ssize_t>(size[1]), static_cast<py::ssize_t>(size[0]) },
    mask->GetBufferPointer(),
    owner);
}

namespace
{
std::vector<std::string>
PathList(const py::object & paths)
{
  if (py::isinstance<py::str>(paths) || py::hasattr(paths, "__fspath__"))
  {
    return { py::str(py::module_::import("os").attr("fspath")(paths)).cast<std::string>() };
  }
  std::vector<std::string> list;
  for (const auto & path : paths)
  {
    list.push_back(py::str(py::module_::import("os").attr("fspath")(path)).cast<std::string>());
  }
  return list;
}
} // namespace

const Segmentation &
SegmentationOf(const py::object & value, const char * what)
{
  if (!py::isinstance<SegmentationObject>(value))
  {
    RaiseValueError(std::string(what) + ": give a Segmentation (read_segmentation, Segmentation.from_volume); got " +
                    py::repr(py::type::of(value)).cast<std::string>());
  }
  return value.cast<const SegmentationObject &>().Value;
}

void
RegisterVolumes(py::module_ & module)
{
  py::class_<Volume> volume(module, "Volume", R"doc(
A scalar volume on a grid in LPS millimetres (ITK's and SimpleITK's convention), as the engine reads it.

Volume(array, spacing=None, origin=None, direction=None, name="")
    array      numpy array indexed (k, j, i) like SimpleITK.GetArrayFromImage: i (x) varies fastest.
    spacing    (si, sj, sk) in mm, > 0; default 1 mm.
    origin     LPS position of voxel (0, 0, 0), mm; default 0.
    direction  3 x 3 direction cosines, column c the direction of axis c in LPS (SimpleITK's GetDirection()
               reshaped to 3 x 3); default identity; must be orthonormal.

Volume.from_affine(array, affine) takes nibabel's convention instead: array indexed (i, j, k) and a 4 x 4 affine
mapping (i, j, k, 1) to RAS mm. A NIfTI image from nibabel (Fortran-ordered data) is viewed without a copy.

Memory: a float32, C-contiguous (k, j, i) array is viewed, not copied: the engine reads its memory, and a change to
the array shows in the next run. Any other array (another dtype, such as int16, or a transposed or strided view) is
copied once, to float32 in C order (the engine computes in float32); `copied` says which happened.
)doc");
  volume
    .def(py::init([](const py::array &   array,
                     const py::object &  spacing,
                     const py::object &  origin,
                     const py::object &  direction,
                     const std::string & name)
                  { return VolumeFromArray(array, GeometryFromITK(spacing, origin, direction), name, "array"); }),
         py::arg("array"),
         py::arg("spacing") = py::none(),
         py::arg("origin") = py::none(),
         py::arg("direction") = py::none(),
         py::arg("name") = "")
    .def_static(
      "from_affine",
      [](const py::array & array, const py::object & affine, const std::string & name)
      {
        if (array.ndim() != 3)
        {
          RaiseValueError("array: a volume is a 3-D array indexed (i, j, k) with an affine; got ndim=" +
                          std::to_string(array.ndim()));
        }
        // nibabel's (i, j, k) is the engine's (k, j, i) transposed: a Fortran-ordered array becomes C-ordered.
        const py::array transposed = array.attr("transpose")();
        return VolumeFromArray(transposed, GeometryFromAffine(affine), name, "array");
      },
      py::arg("array"),
      py::arg("affine"),
      py::arg("name") = "",
      "A volume from nibabel's convention: array indexed (i, j, k), affine 4 x 4 voxel -> RAS mm "
      "(nibabel's img.dataobj or get_fdata(), img.affine).")
    .def_property_readonly(
      "array", [](const Volume & v) { return v.Array; }, "The voxels, float32, indexed (k, j, i).")
    .def_property_readonly(
      "copied", [](const Volume & v) { return v.Copied; }, "True when the array given was copied (see the class).")
    .def_property_readonly("name", [](const Volume & v) { return v.Name; })
    .def_property_readonly(
      "shape", [](const Volume & v) { return ShapeOf(v.Image.GetPointer()); }, "(k, j, i).")
    .def_property_readonly(
      "spacing", [](const Volume & v) { return SpacingOf(v.Image.GetPointer()); }, "(si, sj, sk) in mm.")
    .def_property_readonly(
      "origin", [](const Volume & v) { return OriginOf(v.Image.GetPointer()); }, "LPS mm of voxel (0, 0, 0).")
    .def_property_readonly(
      "direction", [](const Volume & v) { return DirectionOf(v.Image.GetPointer()); }, "3 x 3, columns in LPS.")
    .def_property_readonly(
      "affine", [](const Volume & v) { return AffineOf(v.Image.GetPointer()); }, "4 x 4, (i, j, k, 1) -> RAS mm.")
    .def_property_readonly(
      "_buffer_address",
      [](const Volume & v) { return reinterpret_cast<std::uintptr_t>(v.Image->GetBufferPointer()); },
      "The address of the voxels the engine reads (for tests: equals array.ctypes.data when viewed).")
    .def("__repr__",
         [](const Volume & v)
         {
           const auto shape = ShapeOf(v.Image.GetPointer());
           return "<Volume " + (v.Name.empty() ? std::string() : "'" + v.Name + "' ") +
                  py::repr(shape).cast<std::string>() + (v.Copied ? ", copied>" : ">");
         });

  module.def(
    "read_volume",
    [](const py::object & path)
    {
      const std::string        name = PathList(path).front();
      VolumeImageType::Pointer image;
      OnFiles(name,
              [&]
              {
                const py::gil_scoped_release release;
                image = ReadVolume(name);
              });
      return VolumeFromImage(image, py::str(py::module_::import("os.path").attr("basename")(name)));
    },
    py::arg("path"),
    R"doc(Reads a volume as the command-line modules do: NRRD, NIfTI, MetaImage, or a DICOM series folder.
Raises OSError naming the file and what is wrong (missing, unreadable header, not 3-D, NaN voxel, ...).)doc");

  module.def(
    "write_volume",
    [](const Volume & v, const py::object & path)
    {
      const std::string name = PathList(path).front();
      OnFiles(name,
              [&]
              {
                const py::gil_scoped_release release;
                WriteVolume(v.Image, name);
              });
    },
    py::arg("volume"),
    py::arg("path"),
    "Writes a volume (format from the extension: .nrrd, .nii.gz, .mha, ...), whole or not at all.");

  py::class_<SegmentationObject>(module, "Segmentation", R"doc(
A vessel segmentation as the engine reads it: the vessel mask (1 = vessel) on an LPS grid, combined from one or
more files (TotalSegmentator writes one per vessel), and the name of the vessel each region is.
Made by read_segmentation() or Segmentation.from_volume().)doc")
    .def_static(
      "from_volume",
      [](const Volume & values, const std::vector<double> & labels, const std::string & name)
      {
        SegmentationObject segmentation;
        OnArguments(
          [&]
          {
            segmentation.Value.Mask = MakeSegmentationMask(values.Image, labels, name);
            segmentation.Value.Name = name;
          });
        return segmentation;
      },
      py::arg("values"),
      py::arg("labels") = std::vector<double>(),
      py::arg("name") = "segmentation",
      "A segmentation from a label map, mask, level set (inside < 0) or probability map (>= 0.5) given as a Volume; "
      "labels: the label values that are vessel (default: every non-zero voxel).")
    .def_property_readonly(
      "mask", [](const SegmentationObject & s) { return ArrayOfMask(s.Value.Mask); }, "uint8 (k, j, i), 1 = vessel.")
    .def_property_readonly("name", [](const SegmentationObject & s) { return s.Value.Name; })
    .def_property_readonly("region_names", [](const SegmentationObject & s) { return s.Value.RegionNames; })
    .def_property_readonly("descriptions", [](const SegmentationObject & s) { return s.Value.Descriptions; })
    .def_property_readonly("warnings", [](const SegmentationObject & s) { return s.Warnings; })
    .def_property_readonly("spacing", [](const SegmentationObject & s) { return SpacingOf(s.Value.Mask.GetPointer()); })
    .def_property_readonly("origin", [](const SegmentationObject & s) { return OriginOf(s.Value.Mask.GetPointer()); })
    .def_property_readonly("direction",
                           [](const SegmentationObject & s) { return DirectionOf(s.Value.Mask.GetPointer()); })
    .def_property_readonly("affine", [](const SegmentationObject & s) { return AffineOf(s.Value.Mask.GetPointer()); })
    .def("__repr__",
         [](const SegmentationObject & s)
         {
           return "<Segmentation '" + s.Value.Name + "' " +
                  py::repr(ShapeOf(s.Value.Mask.GetPointer())).cast<std::string>() + ">";
         });

  module.def(
    "_read_segmentation",
    [](const py::object & paths, const std::vector<double> & labels)
    {
      const std::vector<std::string> list = PathList(paths);
      SegmentationObject             segmentation;
      OnFiles(list.empty() ? std::string() : list.front(),
              [&]
              {
                const py::gil_scoped_release release;
                segmentation.Value = ReadSegmentation(list, labels, segmentation.Warnings);
              });
      return segmentation;
    },
    py::arg("paths"),
    py::arg("labels") = std::vector<double>());
}

vtkSmartPointer<VolumeNode>
NodeOver(const Volume & volume)
{
  const auto & region = volume.Image->GetBufferedRegion();
  auto         voxels = vtkSmartPointer<vtkFloatArray>::New();
  // save = 1: VTK never frees memory it does not own.
  voxels->SetArray(volume.Image->GetBufferPointer(), static_cast<vtkIdType>(region.GetNumberOfPixels()), 1);
  auto data = vtkSmartPointer<vtkImageData>::New();
  data->SetExtent(0,
                  static_cast<int>(region.GetSize(0)) - 1,
                  0,
                  static_cast<int>(region.GetSize(1)) - 1,
                  0,
                  static_cast<int>(region.GetSize(2)) - 1);
  data->GetPointData()->SetScalars(voxels);
  auto node = vtkSmartPointer<VolumeNode>::New();
  node->SetName(volume.Name);
  node->SetImageData(data);
  node->SetIJKToRASMatrix(IJKToRASMatrixOf(*volume.Image));
  return node;
}

} // namespace vr::python
