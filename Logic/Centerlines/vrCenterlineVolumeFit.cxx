// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrCenterlineVolumeFit.h"

#include "vrCoordinateFrames.h"
#include "vrInputError.h"
#include "vrParameterName.h"

#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>

#include <cmath>
#include <sstream>

namespace vr
{
namespace
{
/** Whether continuous index \a index lies within half a voxel of the grid [low, low + size). */
bool
InsideGrid(const double index[3], const long low[3], const long size[3])
{
  for (int axis = 0; axis < 3; ++axis)
  {
    if (!(index[axis] >= low[axis] - 0.5 && index[axis] <= low[axis] + size[axis] - 0.5))
    {
      return false;
    }
  }
  return true;
}
} // namespace

CenterlineVolumeFit
MeasureCenterlineVolumeFit(const itk::CenterlineTree & tree, const itk::ImageBase<3> * volume)
{
  CenterlineVolumeFit fit;
  const auto &        region = volume->GetLargestPossibleRegion();
  const long          low[3] = { region.GetIndex(0), region.GetIndex(1), region.GetIndex(2) };
  const long          size[3] = { static_cast<long>(region.GetSize(0)),
                                  static_cast<long>(region.GetSize(1)),
                                  static_cast<long>(region.GetSize(2)) };
  for (const auto & branch : tree.GetBranches())
  {
    for (const auto & point : branch.Points)
    {
      itk::ContinuousIndex<double, 3> index;
      volume->TransformPhysicalPointToContinuousIndex(point, index);
      const double ijk[3] = { index[0], index[1], index[2] };
      fit.Outside += InsideGrid(ijk, low, size) ? 0 : 1;
      ++fit.Points;
    }
  }
  return fit;
}

CenterlineVolumeFit
MeasureCenterlineVolumeFit(const itk::CenterlineTree & tree, const VolumeNode * volume)
{
  CenterlineVolumeFit fit;
  vtkImageData *      image = volume->GetImageData();
  int                 extent[6] = { 0, -1, 0, -1, 0, -1 };
  if (image != nullptr)
  {
    image->GetExtent(extent);
  }
  const long           low[3] = { extent[0], extent[2], extent[4] };
  const long           size[3] = { extent[1] - extent[0] + 1L, extent[3] - extent[2] + 1L, extent[5] - extent[4] + 1L };
  vtkNew<vtkMatrix4x4> rasToIJK;
  vtkMatrix4x4::Invert(volume->GetIJKToRASMatrix(), rasToIJK);
  for (const auto & branch : tree.GetBranches())
  {
    for (const auto & point : branch.Points)
    {
      const auto   ras = LPSToRAS(point);
      const double in[4] = { ras[0], ras[1], ras[2], 1.0 };
      double       ijk[4];
      rasToIJK->MultiplyPoint(in, ijk);
      fit.Outside += InsideGrid(ijk, low, size) ? 0 : 1;
      ++fit.Points;
    }
  }
  return fit;
}

std::string
CheckCenterlineVolumeFit(const CenterlineVolumeFit & fit,
                         const std::string &         centerlines,
                         const std::string &         volume,
                         bool                        extracted)
{
  const double outside = fit.OutsideFraction();
  if (outside <= 0.5)
  {
    return std::string();
  }
  std::ostringstream message;
  message << centerlines << ": ";
  if (fit.Outside == fit.Points)
  {
    message << "none of the " << fit.Points << " points lies inside " << volume;
    if (extracted)
    {
      message << "; the segmentation does not cover the volume";
      throw InputError(message.str());
    }
    message << ". They are most likely in the other coordinate system (RAS against LPS: set the centerlines' "
               "coordinate system), or belong to another scan. Nothing was reformatted";
    throw InputError(message.str(), ParameterName::CenterlineSpace);
  }
  message << std::lround(100.0 * outside) << "% of the " << fit.Points << " points lie outside " << volume
          << (extracted ? "; the segmentation covers little of the volume. The reformation continues."
                        : "; they may be in the other coordinate system: check whether the centerlines are in RAS "
                          "or LPS. The reformation continues.");
  return message.str();
}
} // namespace vr
