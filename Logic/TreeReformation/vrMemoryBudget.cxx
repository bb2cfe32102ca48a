// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrMemoryBudget.h"

#include "itkCPRViewGeometry.h"
#include "vrInputError.h"
#include "vrParameterName.h"

#include <climits>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <unistd.h>

namespace vr
{
namespace
{
std::string
Gibibytes(double bytes)
{
  std::ostringstream text;
  text << std::setprecision(3) << bytes / (1024.0 * 1024.0 * 1024.0) << " GiB";
  return text.str();
}
// Visibility mode's own bytes per pixel besides every update's (measured as those: 55.9-56.0 on both phantoms and the
// aorta, 256 x 512 to 1024 x 2048): its footprint buffers (eleven of 4 bytes), the nearest fill's column winners, the
// hidden labels of the assignment and their output node (4 each).
constexpr double VisibilityBytesPerPixel = 56.0;
} // namespace

double
EstimateReformationBytes(const itk::Size<2> & size,
                         std::size_t          relaxWorkspaceBytes,
                         bool                 surface,
                         itk::CPRDepthMode    mode)
{
  // Bytes per view pixel at the peak of an update besides the relaxation's workspace, counted as allocated bytes
  // (Testing/Tools/MeasureReformationMemory; 74.7-75.0 and 83.8-83.9 at 256 x 512, 512 x 1024 and 1024 x 2048):
  // - every update: the centerline raster, the depth assignment, the depth filter's outputs (the hidden labels among
  //   them, 0 outside Visibility mode), the relaxed depth, both CPR images and the output nodes of all of them: 75;
  // - the cut surface: points, scalars and two triangles a pixel: 84.
  // The relax filter keeps its workspace through the stages after it, so it adds to the peak whole.
  double perPixel = 75.0;
  if (surface)
  {
    perPixel += 84.0;
  }
  if (mode == itk::CPRDepthMode::Visibility)
  {
    perPixel += VisibilityBytesPerPixel;
  }
  return perPixel * static_cast<double>(size[0]) * static_cast<double>(size[1]) +
         static_cast<double>(relaxWorkspaceBytes);
}

double
AvailableMemoryInBytes()
{
  std::ifstream meminfo("/proc/meminfo");
  std::string   key;
  double        kibibytes = 0.0;
  std::string   unit;
  while (meminfo >> key >> kibibytes >> unit)
  {
    if (key == "MemAvailable:")
    {
      return kibibytes * 1024.0;
    }
  }
  const long pages = ::sysconf(_SC_AVPHYS_PAGES);
  const long pageSize = ::sysconf(_SC_PAGESIZE);
  return pages > 0 && pageSize > 0 ? static_cast<double>(pages) * pageSize : 1e18;
}

void
CheckViewFitsInMemory(const itk::CPRViewGeometry &                           view,
                      bool                                                   sizeGiven,
                      itk::BilateralDepthRelaxFilter<itk::Image<float, 2>> & relax,
                      bool                                                   surface,
                      itk::CPRDepthMode                                      mode)
{
  const auto &       size = view.GetSize();
  std::ostringstream origin;
  if (sizeGiven)
  {
    origin << "view size = " << size[0] << "," << size[1];
  }
  else
  {
    origin << "the view of " << size[0] << " x " << size[1] << " pixels (pixel spacing " << view.GetSpacing()[0] << ","
           << view.GetSpacing()[1] << " mm)";
  }
  const char * parameter = sizeGiven ? ParameterName::ViewSize : ParameterName::PixelSpacing;
  if (size[0] > static_cast<itk::SizeValueType>(INT_MAX) || size[1] > static_cast<itk::SizeValueType>(INT_MAX))
  {
    throw InputError(origin.str() + ": at most " + std::to_string(INT_MAX) + " pixels per side are supported",
                     parameter);
  }
  const double needed = EstimateReformationBytes(size, relax.GetWorkspaceBytes(size), surface, mode);
  const double available = AvailableMemoryInBytes();
  if (needed > available)
  {
    throw InputError(origin.str() + ": the images would need about " + Gibibytes(needed) + ", more than the " +
                       Gibibytes(available) +
                       " of memory available; choose a smaller view size or a larger pixel spacing",
                     parameter);
  }
}
} // namespace vr
