// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrSurfacePreview.h"

#include "vrCutSurface.h"
#include "vrInputError.h"

#include <vtkImageData.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>

namespace vr
{
namespace
{
/** The pixels (s i, s j) of a one-slice float node, as a 2D image on \a view. */
DepthImageType::Pointer
PickPixels(VolumeNode * node, unsigned int stride, const itk::CPRViewGeometry & view, const char * what)
{
  vtkImageData * data = node != nullptr ? node->GetImageData() : nullptr;
  if (data == nullptr || data->GetScalarType() != VTK_FLOAT || data->GetNumberOfScalarComponents() != 1)
  {
    throw InputError(std::string("surface preview: the ") + what + " is missing or not a float image");
  }
  int dimensions[3];
  data->GetDimensions(dimensions);
  const auto fullWidth = static_cast<std::size_t>(dimensions[0]);
  const auto size = view.GetSize();
  auto       image = DepthImageType::New();
  view.ConfigureImage(image.GetPointer());
  image->Allocate();
  const auto * source = static_cast<const float *>(data->GetScalarPointer());
  float *      target = image->GetBufferPointer();
  for (std::size_t j = 0; j < size[1]; ++j)
  {
    for (std::size_t i = 0; i < size[0]; ++i)
    {
      target[j * size[0] + i] = source[(stride * j) * fullWidth + stride * i];
    }
  }
  return image;
}
} // namespace

unsigned int
PreviewSurfaceStride(unsigned int width, unsigned int height)
{
  const double pixels = static_cast<double>(width) * static_cast<double>(height);
  auto stride = static_cast<unsigned int>(std::max(1.0, std::floor(std::sqrt(pixels / PreviewSurfacePointBudget))));
  while (static_cast<double>((width + stride - 1) / stride) * ((height + stride - 1) / stride) >
         PreviewSurfacePointBudget)
  {
    ++stride;
  }
  return stride;
}

vtkSmartPointer<vtkPolyData>
BuildPreviewSurface(const ReformationOutputs & outputs, unsigned int stride)
{
  if (!outputs.CPR || !outputs.RelaxedDepth)
  {
    return nullptr;
  }
  stride = std::max(1u, stride);
  const itk::CPRViewGeometry &   full = outputs.View;
  itk::CPRViewGeometry::SizeType size;
  size[0] = (full.GetSize()[0] - 1) / stride + 1;
  size[1] = (full.GetSize()[1] - 1) / stride + 1;
  itk::CPRViewGeometry::SpacingType spacing;
  spacing[0] = full.GetSpacing()[0] * stride;
  spacing[1] = full.GetSpacing()[1] * stride;
  // The coarse view's pixel (i, j) is the full view's (s i, s j): its centre is the full view's plane point at the
  // coarse grid's middle.
  const auto                 center = full.PlanePoint(0.5 * stride * (static_cast<double>(size[0]) - 1.0),
                                      0.5 * stride * (static_cast<double>(size[1]) - 1.0));
  const itk::CPRViewGeometry coarse(full.GetUp(), full.GetAngleInDegrees(), center, size, spacing);
  const auto                 depth = PickPixels(outputs.RelaxedDepth, stride, coarse, "relaxed depth");
  const auto                 cpr = PickPixels(outputs.CPR, stride, coarse, "CPR");
  return BuildCutSurface(depth, cpr, coarse, DefaultMaximumBridgedDepthJump(coarse));
}
} // namespace vr
