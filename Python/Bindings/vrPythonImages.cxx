// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrPythonImages.h"

#include "vrCoordinateFrames.h"

namespace vr::python
{
py::tuple
ShapeOf(const itk::ImageBase<3> * image)
{
  const auto size = image->GetLargestPossibleRegion().GetSize();
  return py::make_tuple(size[2], size[1], size[0]);
}

py::tuple
SpacingOf(const itk::ImageBase<3> * image)
{
  const auto & spacing = image->GetSpacing();
  return py::make_tuple(spacing[0], spacing[1], spacing[2]);
}

py::tuple
OriginOf(const itk::ImageBase<3> * image)
{
  const auto & origin = image->GetOrigin();
  return py::make_tuple(origin[0], origin[1], origin[2]);
}

py::array_t<double>
DirectionOf(const itk::ImageBase<3> * image)
{
  py::array_t<double> direction({ 3, 3 });
  auto                cells = direction.mutable_unchecked<2>();
  for (py::ssize_t r = 0; r < 3; ++r)
  {
    for (py::ssize_t c = 0; c < 3; ++c)
    {
      cells(r, c) = image->GetDirection()[r][c];
    }
  }
  return direction;
}

py::array_t<double>
AffineOf(const itk::ImageBase<3> * image)
{
  py::array_t<double> affine({ 4, 4 });
  auto                cells = affine.mutable_unchecked<2>();
  for (py::ssize_t c = 0; c < 3; ++c)
  {
    itk::Point<double, 3> column;
    for (unsigned int r = 0; r < 3; ++r)
    {
      column[r] = image->GetDirection()[r][c] * image->GetSpacing()[c];
    }
    const auto ras = LPSToRAS(column);
    for (py::ssize_t r = 0; r < 3; ++r)
    {
      cells(r, c) = ras[r];
    }
  }
  const auto origin = LPSToRAS(image->GetOrigin());
  for (py::ssize_t r = 0; r < 3; ++r)
  {
    cells(r, 3) = origin[r];
    cells(3, r) = 0.0;
  }
  cells(3, 3) = 1.0;
  return affine;
}

py::object
ArrayOfPoints(const itk::Image<itk::Vector<float, 3>, 2> * image)
{
  if (image == nullptr)
  {
    return py::none();
  }
  const auto         size = image->GetBufferedRegion().GetSize();
  py::array_t<float> array({ static_cast<py::ssize_t>(size[1]), static_cast<py::ssize_t>(size[0]), py::ssize_t{ 3 } });
  float *            target = array.mutable_data();
  const auto *       source = image->GetBufferPointer();
  for (std::size_t n = 0; n < size[0] * size[1]; ++n)
  {
    for (unsigned int c = 0; c < 3; ++c)
    {
      target[3 * n + c] = source[n][c];
    }
  }
  return std::move(array);
}
} // namespace vr::python
