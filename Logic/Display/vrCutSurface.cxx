// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCutSurface.h"

#include "vrCoordinateFrames.h"
#include "vrInputError.h"

#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace vr
{
double
DefaultMaximumBridgedDepthJump(const itk::CPRViewGeometry & view)
{
  return 4.0 * std::max(view.GetSpacing()[0], view.GetSpacing()[1]);
}

vtkSmartPointer<vtkPolyData>
BuildCutSurface(const DepthImageType *       depth,
                const DepthImageType *       intensity,
                const itk::CPRViewGeometry & view,
                double                       maximumBridgedJump)
{
  if (depth == nullptr || intensity == nullptr)
  {
    throw InputError("cut surface: the depth map and the CPR image are both needed");
  }
  const auto size = view.GetSize();
  if (depth->GetBufferedRegion().GetSize() != size || intensity->GetBufferedRegion().GetSize() != size)
  {
    std::ostringstream message;
    message << "cut surface: the depth map (" << depth->GetBufferedRegion().GetSize() << ") and the CPR image ("
            << intensity->GetBufferedRegion().GetSize() << ") must both have the view's size " << size;
    throw InputError(message.str());
  }
  if (!(std::isfinite(maximumBridgedJump) && maximumBridgedJump >= 0.0))
  {
    throw InputError("cut surface: maximum bridged depth jump = " + std::to_string(maximumBridgedJump) +
                     " mm must be finite and >= 0");
  }

  const std::size_t width = size[0];
  const std::size_t height = size[1];
  const auto        pixelCount = static_cast<vtkIdType>(width) * static_cast<vtkIdType>(height);
  const float *     d = depth->GetBufferPointer();
  const float *     values = intensity->GetBufferPointer();

  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(pixelCount);
  auto intensities = vtkSmartPointer<vtkFloatArray>::New();
  intensities->SetName(CutSurfaceIntensityArrayName);
  intensities->SetNumberOfValues(pixelCount);
  auto depths = vtkSmartPointer<vtkFloatArray>::New();
  depths->SetName(CutSurfaceDepthArrayName);
  depths->SetNumberOfValues(pixelCount);
  for (std::size_t j = 0; j < height; ++j)
  {
    for (std::size_t i = 0; i < width; ++i)
    {
      const std::size_t k = j * width + i;
      const auto        ras = LPSToRAS(view.SurfacePoint(static_cast<double>(i), static_cast<double>(j), d[k]));
      points->SetPoint(static_cast<vtkIdType>(k), ras[0], ras[1], ras[2]);
      intensities->SetValue(static_cast<vtkIdType>(k), values[k]);
      depths->SetValue(static_cast<vtkIdType>(k), d[k]);
    }
  }

  // Connectivity in VTK 9's offsets + connectivity layout, filled directly: a million triangles through
  // InsertNextCell would be several times slower.
  auto              offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  auto              connectivity = vtkSmartPointer<vtkIdTypeArray>::New();
  const std::size_t quads = width > 1 && height > 1 ? (width - 1) * (height - 1) : 0;
  offsets->Allocate(2 * static_cast<vtkIdType>(quads) + 1);
  connectivity->Allocate(6 * static_cast<vtkIdType>(quads));
  offsets->InsertNextValue(0);
  const auto bridged = [&](std::size_t a, std::size_t b, std::size_t c)
  {
    const float low = std::min({ d[a], d[b], d[c] });
    const float high = std::max({ d[a], d[b], d[c] });
    return static_cast<double>(high) - static_cast<double>(low) <= maximumBridgedJump;
  };
  const auto addTriangle = [&](std::size_t a, std::size_t b, std::size_t c)
  {
    connectivity->InsertNextValue(static_cast<vtkIdType>(a));
    connectivity->InsertNextValue(static_cast<vtkIdType>(b));
    connectivity->InsertNextValue(static_cast<vtkIdType>(c));
    offsets->InsertNextValue(connectivity->GetNumberOfValues());
  };
  for (std::size_t j = 0; j + 1 < height; ++j)
  {
    for (std::size_t i = 0; i + 1 < width; ++i)
    {
      const std::size_t p00 = j * width + i;
      const std::size_t p10 = p00 + 1;
      const std::size_t p01 = p00 + width;
      const std::size_t p11 = p01 + 1;
      if (bridged(p00, p10, p11))
      {
        addTriangle(p00, p10, p11);
      }
      if (bridged(p00, p11, p01))
      {
        addTriangle(p00, p11, p01);
      }
    }
  }
  auto triangles = vtkSmartPointer<vtkCellArray>::New();
  triangles->SetData(offsets, connectivity);

  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->SetPoints(points);
  surface->SetPolys(triangles);
  surface->GetPointData()->SetScalars(intensities);
  surface->GetPointData()->AddArray(depths);
  return surface;
}
} // namespace vr
