// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "itkCenterlineExtractionFilter.h"

#include "itkCenterlineBranchGeometry.h"
#include "itkCenterlineSkeleton.h"

#include <algorithm>
#include <sstream>
#include <limits>

namespace itk
{
namespace detail
{
namespace
{
using MaskImageType = CenterlineForeground::MaskImageType;

/** Throws the message as it is; the filter adds its name. */
[[noreturn]] void
Fail(const std::string & message)
{
  throw ExceptionObject(__FILE__, __LINE__, message, "ExtractCenterlinesFromPaddedMask");
}

/** The foreground voxel nearest to \a point (LPS mm), and its distance. */
std::pair<uint32_t, double>
NearestForegroundVoxel(const CenterlineForeground & foreground,
                       const MaskImageType *        mask,
                       const Point<double, 3> &     point)
{
  uint32_t nearest = 0;
  double   nearestDistance = std::numeric_limits<double>::infinity();
  for (uint32_t voxel = 0; voxel < foreground.Size(); ++voxel)
  {
    Point<double, 3> position;
    mask->TransformIndexToPhysicalPoint(foreground.IndexOf(voxel), position);
    const double distance = position.EuclideanDistanceTo(point);
    if (distance < nearestDistance)
    {
      nearestDistance = distance;
      nearest = voxel;
    }
  }
  return { nearest, nearestDistance };
}
} // namespace
} // namespace detail

CenterlineExtractionOutcome
ExtractCenterlinesFromPaddedMask(const Image<unsigned char, 3> *      paddedMask,
                                 const CenterlineExtractionSettings & settings,
                                 const std::function<void(double)> &  progress)
{
  using namespace detail; // the foreground, skeleton and branch geometry behind it
  const auto &                             spacing = paddedMask->GetSpacing();
  const double                             smallestSpacing = std::min({ spacing[0], spacing[1], spacing[2] });
  const double                             largestSpacing = std::max({ spacing[0], spacing[1], spacing[2] });
  const CenterlineForeground               foreground = MakeCenterlineForeground(paddedMask);
  const std::vector<std::vector<uint32_t>> components = FindForegroundComponents(foreground);
  progress(0.4);

  // Root voxels, by component.
  std::vector<uint32_t> componentOf(foreground.Size(), 0);
  for (std::size_t c = 0; c < components.size(); ++c)
  {
    for (const uint32_t voxel : components[c])
    {
      componentOf[voxel] = static_cast<uint32_t>(c);
    }
  }
  std::vector<int64_t> rootVoxel(components.size(), -1);
  for (std::size_t k = 0; k < settings.RootPoints.size(); ++k)
  {
    const auto [voxel, gap] = NearestForegroundVoxel(foreground, paddedMask, settings.RootPoints[k]);
    if (gap > settings.RootPointTolerance)
    {
      std::ostringstream message;
      message << "root point " << k + 1 << " " << settings.RootPoints[k] << " (LPS, mm) lies " << gap
              << " mm from the nearest foreground voxel, more than the tolerance of " << settings.RootPointTolerance
              << " mm; is it in the wrong coordinate system?";
      Fail(message.str());
    }
    int64_t & assigned = rootVoxel[componentOf[voxel]];
    if (assigned >= 0)
    {
      std::ostringstream message;
      message << "root point " << k + 1 << " " << settings.RootPoints[k]
              << " (LPS, mm) lies in the same connected component as an earlier root point; give at most one per "
                 "component";
      Fail(message.str());
    }
    assigned = voxel;
  }

  SkeletonParameters skeletonParameters;
  skeletonParameters.InvalidationScale = settings.InvalidationScale;
  skeletonParameters.InvalidationMargin = largestSpacing;
  skeletonParameters.SpurRadiusRatio = settings.SpurRadiusRatio;
  skeletonParameters.MinimumBranchLength = settings.MinimumBranchLength;
  BranchGeometryParameters geometryParameters;
  geometryParameters.PointSpacing = settings.PointSpacing > 0.0 ? settings.PointSpacing : 0.5 * smallestSpacing;

  CenterlineExtractionOutcome outcome;
  outcome.NumberOfComponents = components.size();
  outcome.NumberOfForegroundVoxels = foreground.Size();
  SkeletonTracer tracer(foreground);
  std::size_t    traced = 0;
  for (std::size_t c = 0; c < components.size(); ++c)
  {
    const SkeletonTree skeleton = tracer.Trace(components[c], skeletonParameters, rootVoxel[c]);
    if (skeleton.Branches.empty())
    {
      ++outcome.NumberOfComponentsWithoutCenterline;
    }
    const int firstId = static_cast<int>(outcome.Tree.GetNumberOfBranches()) + 1;
    for (auto & branch : MakeCenterlineBranches(skeleton, foreground, paddedMask, geometryParameters, firstId))
    {
      outcome.Tree.AddBranch(std::move(branch));
    }
    for (const auto & branch : skeleton.Branches)
    {
      outcome.ParentBranchIds.push_back(branch.Parent < 0 ? 0 : firstId + branch.Parent);
    }
    traced += components[c].size();
    progress(0.4 + 0.6 * static_cast<double>(traced) / static_cast<double>(foreground.Size()));
  }
  if (outcome.Tree.GetNumberOfBranches() == 0)
  {
    Fail("no centerline: none of the segmentation's " + std::to_string(components.size()) +
         " connected components (the largest " + std::to_string(components.front().size()) +
         " voxels) is elongated enough to have one; a vessel must be longer than it is wide");
  }
  outcome.Tree.Validate();
  return outcome;
}

template class CenterlineExtractionFilter<Image<unsigned char, 3>>;
template class CenterlineExtractionFilter<Image<short, 3>>;
template class CenterlineExtractionFilter<Image<unsigned short, 3>>;
template class CenterlineExtractionFilter<Image<int, 3>>;
template class CenterlineExtractionFilter<Image<float, 3>>;
} // namespace itk
