// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrPythonImages_h
#define vrPythonImages_h

#include "itkImage.h"
#include "itkImageBase.h"

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <algorithm>

/** \file vrPythonImages.h
 * \brief The engine's images as numpy sees them: grids as tuples and matrices (LPS, and the affine in RAS through the
 * one RAS <-> LPS conversion), the 2D and 3D results as arrays indexed (row, column) and (k, j, i), copied out of the
 * engine's buffers so that they outlive the run.
 */
namespace vr::python
{
namespace py = pybind11;

/** (k, j, i) */
py::tuple
ShapeOf(const itk::ImageBase<3> * image);
/** (si, sj, sk) mm */
py::tuple
SpacingOf(const itk::ImageBase<3> * image);
/** LPS mm */
py::tuple
OriginOf(const itk::ImageBase<3> * image);
/** 3 x 3, column c the LPS direction of axis c */
py::array_t<double>
DirectionOf(const itk::ImageBase<3> * image);
/** 4 x 4, (i, j, k, 1) -> RAS mm, as nibabel's affine */
py::array_t<double>
AffineOf(const itk::ImageBase<3> * image);

/** A copy of a scalar image's buffer as a numpy array: 2D (row, column), 3D (k, j, i); None for a null image. */
template<typename TImage>
py::object
ArrayOf(const TImage * image)
{
  if (image == nullptr)
  {
    return py::none();
  }
  const auto               size = image->GetBufferedRegion().GetSize();
  std::vector<py::ssize_t> shape;
  for (int axis = static_cast<int>(TImage::ImageDimension) - 1; axis >= 0; --axis)
  {
    shape.push_back(static_cast<py::ssize_t>(size[axis]));
  }
  py::array_t<typename TImage::PixelType> array(shape);
  std::copy(image->GetBufferPointer(),
            image->GetBufferPointer() + image->GetBufferedRegion().GetNumberOfPixels(),
            array.mutable_data());
  return std::move(array);
}

/** A copy of a 2D image of 3-vectors (the CPR's LPS points) as a (row, column, 3) float array; None for null. */
py::object
ArrayOfPoints(const itk::Image<itk::Vector<float, 3>, 2> * image);
} // namespace vr::python

#endif
