// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// CPRDepthImageFilter keeps its work buffers between updates so that a new angle allocates nothing. A filter
// that has already served other angles and sizes must give exactly the maps a fresh filter gives.
#include "vrTestImages.h"

#include "itkCPRDepthImageFilter.h"
#include "itkRunoffPhantomImageSource.h"

#include <gtest/gtest.h>

namespace
{
using DepthFilter = itk::CPRDepthImageFilter<vr::test::DepthImage>;

struct Maps
{
  std::vector<float>         Depth;
  std::vector<unsigned char> Fixed;
  std::vector<uint32_t>      Owner;
};

itk::CPRViewSpecification
ViewAt(double angle, unsigned int width, unsigned int height)
{
  itk::CPRViewSpecification specification;
  specification.AngleInDegrees = angle;
  specification.ImageSize[0] = width;
  specification.ImageSize[1] = height;
  return specification;
}

Maps
Update(DepthFilter * filter, const itk::CPRViewSpecification & specification, itk::CPRDepthMode mode)
{
  filter->SetViewSpecification(specification);
  filter->SetMode(mode);
  filter->Update();
  return { vr::test::PixelsOf(filter->GetDepthOutput()),
           vr::test::PixelsOf(filter->GetFixedMaskOutput()),
           vr::test::PixelsOf(filter->GetOwnerLabelOutput()) };
}

Maps
Fresh(const itk::CenterlineTree & tree, const itk::CPRViewSpecification & specification, itk::CPRDepthMode mode)
{
  auto filter = DepthFilter::New();
  filter->SetCenterlineTree(tree);
  return Update(filter, specification, mode);
}
} // namespace

TEST(CPRDepthImageFilterReuse, RotatedAndResizedFilterGivesTheMapsOfAFreshOne)
{
  const itk::CenterlineTree tree = itk::RunoffPhantomImageSource::New()->GetCenterlineTree();
  auto                      kept = DepthFilter::New();
  kept->SetCenterlineTree(tree);
  // Larger, then smaller, then larger again: the buffers shrink and grow in between.
  const itk::CPRViewSpecification views[] = {
    ViewAt(30.0, 256, 768), ViewAt(75.0, 128, 200), ViewAt(-40.0, 300, 900), ViewAt(30.0, 256, 768)
  };
  for (const auto mode : { itk::CPRDepthMode::Scanline, itk::CPRDepthMode::Nearest })
  {
    for (const auto & view : views)
    {
      SCOPED_TRACE(std::to_string(view.AngleInDegrees) + " degrees");
      const Maps reused = Update(kept, view, mode);
      const Maps fresh = Fresh(tree, view, mode);
      EXPECT_TRUE(reused.Depth == fresh.Depth);
      EXPECT_TRUE(reused.Fixed == fresh.Fixed);
      EXPECT_TRUE(reused.Owner == fresh.Owner);
      // Non-trivial maps: vessels own pixels and fix some.
      EXPECT_GT(std::count(fresh.Fixed.begin(), fresh.Fixed.end(), 1), 100);
    }
  }
}
