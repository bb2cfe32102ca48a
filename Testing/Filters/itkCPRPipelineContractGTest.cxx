// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The ITK pipeline contract of the three filters, connected as a user composes them (depth -> relax -> resample):
// - setting a parameter to the value it already has reruns nothing, while a new value reruns its filter and what
//   follows (so the counters below can tell);
// - the resample filter computes only a requested sub-region;
// - a new volume of the same geometry reruns resampling only; one of another geometry reruns the depth map too.
// Executions are counted with ITK's StartEvent on each filter.
#include "vrTestImages.h"

#include "itkBilateralDepthRelaxFilter.h"
#include "itkCPRDepthImageFilter.h"
#include "itkCPRResampleImageFilter.h"
#include "itkImageRegionIteratorWithIndex.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <functional>

namespace
{
using vr::test::DepthImage;
using vr::test::P;
using vr::test::VolumeImage;
using DepthFilter = itk::CPRDepthImageFilter<DepthImage>;
using RelaxFilter = itk::BilateralDepthRelaxFilter<DepthImage>;
using ResampleFilter = itk::CPRResampleImageFilter<VolumeImage, DepthImage>;

/** A 40 x 40 x 60 volume of 1 mm voxels whose value is a + x + 2 y + 3 z (LPS mm): linear, so resampling is exact. */
VolumeImage::Pointer
MakeVolume(double offset, double spacing = 1.0)
{
  auto                     volume = VolumeImage::New();
  VolumeImage::RegionType  region;
  VolumeImage::SizeType    size{ { 40, 40, 60 } };
  VolumeImage::SpacingType spacings;
  spacings.Fill(spacing);
  region.SetSize(size);
  volume->SetRegions(region);
  volume->SetSpacing(spacings);
  volume->Allocate();
  for (itk::ImageRegionIteratorWithIndex<VolumeImage> it(volume, region); !it.IsAtEnd(); ++it)
  {
    VolumeImage::PointType x;
    volume->TransformIndexToPhysicalPoint(it.GetIndex(), x);
    it.Set(static_cast<float>(offset + x[0] + 2.0 * x[1] + 3.0 * x[2]));
  }
  return volume;
}

/** Two vessels inside the volume, with radii, crossing depths so that the relaxation has seams to work on. */
itk::CenterlineTree
MakeTree()
{
  itk::CenterlineTree   tree;
  itk::CenterlineBranch left;
  left.Id = 1;
  left.Points = { P(10, 15, 5), P(12, 18, 30), P(11, 22, 54) };
  left.Radii = { 2.0, 2.0, 1.5 };
  itk::CenterlineBranch right;
  right.Id = 2;
  right.Points = { P(28, 25, 8), P(27, 20, 30), P(29, 14, 50) };
  right.Radii = { 1.5, 1.5, 1.0 };
  tree.AddBranch(left);
  tree.AddBranch(right);
  return tree;
}

struct Pipeline
{
  DepthFilter::Pointer    Depth = DepthFilter::New();
  RelaxFilter::Pointer    Relax = RelaxFilter::New();
  ResampleFilter::Pointer Resample = ResampleFilter::New();
  unsigned int            DepthRuns{ 0 };
  unsigned int            RelaxRuns{ 0 };
  unsigned int            ResampleRuns{ 0 };

  explicit Pipeline(VolumeImage * volume)
  {
    itk::CPRViewSpecification view;
    view.AngleInDegrees = 20.0;
    Depth->SetCenterlineTree(MakeTree());
    Depth->SetViewSpecification(view);
    Depth->SetReferenceVolume(volume);
    Relax->SetInput(Depth->GetDepthOutput());
    Relax->SetFixedMask(Depth->GetFixedMaskOutput());
    Relax->SetNumberOfIterations(20);
    Resample->SetVolume(volume);
    Resample->SetDepth(Relax->GetOutput());
    Depth->AddObserver(itk::StartEvent(), [this](const itk::EventObject &) { ++DepthRuns; });
    Relax->AddObserver(itk::StartEvent(), [this](const itk::EventObject &) { ++RelaxRuns; });
    Resample->AddObserver(itk::StartEvent(), [this](const itk::EventObject &) { ++ResampleRuns; });
  }

  void
  Update()
  {
    Resample->UpdateLargestPossibleRegion();
  }

  /** How many of (depth, relax, resample) ran during \a change followed by an update. */
  std::array<unsigned int, 3>
  RunsAfter(const std::function<void()> & change)
  {
    const std::array<unsigned int, 3> before{ DepthRuns, RelaxRuns, ResampleRuns };
    change();
    Update();
    return { DepthRuns - before[0], RelaxRuns - before[1], ResampleRuns - before[2] };
  }
};

using Runs = std::array<unsigned int, 3>;
constexpr Runs None{ 0, 0, 0 };
constexpr Runs All{ 1, 1, 1 };
constexpr Runs RelaxAndResample{ 0, 1, 1 };
constexpr Runs ResampleOnly{ 0, 0, 1 };
} // namespace

TEST(CPRPipelineContract, AnUnchangedPipelineRerunsNothing)
{
  auto     volume = MakeVolume(0.0);
  Pipeline pipeline(volume);
  pipeline.Update();
  EXPECT_EQ(pipeline.DepthRuns, 1u);
  EXPECT_EQ(pipeline.RelaxRuns, 1u);
  EXPECT_EQ(pipeline.ResampleRuns, 1u);
  EXPECT_EQ(pipeline.RunsAfter([] {}), None);
}

TEST(CPRPipelineContract, EqualValueSettersOfTheDepthFilterRerunNothing)
{
  auto     volume = MakeVolume(0.0);
  Pipeline pipeline(volume);
  pipeline.Update();
  DepthFilter * depth = pipeline.Depth;
  // A copy of the same tree and of the same specification, not the same objects.
  const itk::CenterlineTree       tree = MakeTree();
  const itk::CPRViewSpecification view = depth->GetViewSpecification();
  EXPECT_EQ(pipeline.RunsAfter([&] { depth->SetCenterlineTree(tree); }), None);
  EXPECT_EQ(pipeline.RunsAfter([&] { depth->SetViewSpecification(view); }), None);
  EXPECT_EQ(pipeline.RunsAfter([&] { depth->SetMode(depth->GetMode()); }), None);
  EXPECT_EQ(pipeline.RunsAfter([&] { depth->SetFixLumen(depth->GetFixLumen()); }), None);
  EXPECT_EQ(pipeline.RunsAfter([&] { depth->SetReferenceVolume(volume); }), None);

  // New values do rerun: the counters would see a rerun.
  itk::CPRViewSpecification turned = view;
  turned.AngleInDegrees += 5.0;
  EXPECT_EQ(pipeline.RunsAfter([&] { depth->SetViewSpecification(turned); }), All);
  itk::CenterlineTree moved = tree;
  moved.GetBranches()[0].Points[1][0] += 1.0;
  EXPECT_EQ(pipeline.RunsAfter([&] { depth->SetCenterlineTree(moved); }), All);
  EXPECT_EQ(pipeline.RunsAfter([&] { depth->SetMode(itk::CPRDepthMode::Nearest); }), All);
  EXPECT_EQ(pipeline.RunsAfter([&] { depth->SetFixLumen(false); }), All);
}

TEST(CPRPipelineContract, EqualValueSettersOfTheRelaxFilterRerunNothing)
{
  auto     volume = MakeVolume(0.0);
  Pipeline pipeline(volume);
  pipeline.Update();
  RelaxFilter * relax = pipeline.Relax;
  EXPECT_EQ(pipeline.RunsAfter([&] { relax->SetRelaxation(relax->GetRelaxation()); }), None);
  EXPECT_EQ(pipeline.RunsAfter([&] { relax->SetAnisotropy(relax->GetAnisotropy()); }), None);
  EXPECT_EQ(pipeline.RunsAfter([&] { relax->SetNumberOfIterations(relax->GetNumberOfIterations()); }), None);
  EXPECT_EQ(pipeline.RunsAfter([&] { relax->SetFixedMask(pipeline.Depth->GetFixedMaskOutput()); }), None);

  EXPECT_EQ(pipeline.RunsAfter([&] { relax->SetRelaxation(0.5); }), RelaxAndResample);
  EXPECT_EQ(pipeline.RunsAfter([&] { relax->SetAnisotropy(0.1); }), RelaxAndResample);
  EXPECT_EQ(pipeline.RunsAfter([&] { relax->SetNumberOfIterations(21); }), RelaxAndResample);
}

TEST(CPRPipelineContract, EqualValueSettersOfTheResampleFilterRerunNothing)
{
  auto     volume = MakeVolume(0.0);
  Pipeline pipeline(volume);
  pipeline.Update();
  ResampleFilter * resample = pipeline.Resample;
  resample->SetView(pipeline.Depth->GetView());
  resample->SetDefaultValue(-1000.0f);
  pipeline.Update();
  EXPECT_EQ(pipeline.RunsAfter([&] { resample->SetView(pipeline.Depth->GetView()); }), None);
  EXPECT_EQ(pipeline.RunsAfter([&] { resample->SetDefaultValue(-1000.0f); }), None);
  EXPECT_EQ(pipeline.RunsAfter([&] { resample->SetInterpolation(resample->GetInterpolation()); }), None);
  EXPECT_EQ(pipeline.RunsAfter([&] { resample->SetSlabThickness(resample->GetSlabThickness()); }), None);
  EXPECT_EQ(pipeline.RunsAfter([&] { resample->SetSlabMode(resample->GetSlabMode()); }), None);
  EXPECT_EQ(pipeline.RunsAfter([&] { resample->SetVolume(volume); }), None);

  EXPECT_EQ(pipeline.RunsAfter([&] { resample->SetDefaultValue(-999.0f); }), ResampleOnly);
  EXPECT_EQ(pipeline.RunsAfter([&] { resample->SetInterpolation(itk::CPRInterpolationMode::Nearest); }), ResampleOnly);
  EXPECT_EQ(pipeline.RunsAfter([&] { resample->SetSlabThickness(2.0); }), ResampleOnly);
  EXPECT_EQ(pipeline.RunsAfter([&] { resample->ClearView(); }), ResampleOnly);
  EXPECT_EQ(pipeline.RunsAfter([&] { resample->ClearView(); }), None);
}

TEST(CPRPipelineContract, TheResampleFilterComputesOnlyARequestedSubRegion)
{
  auto     volume = MakeVolume(0.0);
  Pipeline pipeline(volume);
  pipeline.Update();
  const DepthImage::Pointer full = pipeline.Resample->GetOutput();
  const auto                fullPixels = vr::test::PixelsOf(full.GetPointer());
  const auto                fullRegion = full->GetLargestPossibleRegion();
  const auto                width = fullRegion.GetSize()[0];
  ASSERT_GT(width, 20u);
  ASSERT_GT(fullRegion.GetSize()[1], 30u);

  DepthImage::RegionType sub;
  sub.SetIndex({ { 5, 7 } });
  sub.SetSize({ { 11, 13 } });
  pipeline.Resample->Modified(); // compute again, now for the sub-region alone
  pipeline.Resample->GetOutput()->SetRequestedRegion(sub);
  pipeline.Resample->Update();
  const DepthImage * output = pipeline.Resample->GetOutput();
  EXPECT_EQ(output->GetBufferedRegion(), sub);
  EXPECT_EQ(output->GetLargestPossibleRegion(), fullRegion);
  EXPECT_EQ(output->GetRequestedRegion(), sub);
  for (itk::ImageRegionConstIteratorWithIndex<DepthImage> it(output, sub); !it.IsAtEnd(); ++it)
  {
    const auto index = it.GetIndex();
    EXPECT_EQ(it.Get(), fullPixels[index[1] * width + index[0]]) << "pixel " << index;
  }
  EXPECT_EQ(pipeline.DepthRuns, 1u);
  EXPECT_EQ(pipeline.RelaxRuns, 1u);
}

TEST(CPRPipelineContract, ANewVolumeOfTheSameGeometryRerunsResamplingOnly)
{
  auto     volume = MakeVolume(0.0);
  Pipeline pipeline(volume);
  pipeline.Update();
  const auto before = vr::test::PixelsOf(pipeline.Resample->GetOutput());

  // Another phase of the same scan: the same grid, other voxels.
  auto brighter = MakeVolume(100.0);
  EXPECT_EQ(pipeline.RunsAfter(
              [&]
              {
                pipeline.Depth->SetReferenceVolume(brighter);
                pipeline.Resample->SetVolume(brighter);
              }),
            ResampleOnly);
  const auto after = vr::test::PixelsOf(pipeline.Resample->GetOutput());
  ASSERT_EQ(after.size(), before.size());
  // Inside the volume the linear ramp moved by exactly 100.
  std::size_t shifted = 0;
  for (std::size_t k = 0; k < after.size(); ++k)
  {
    shifted += std::abs(after[k] - before[k] - 100.0f) < 1e-3f ? 1 : 0;
  }
  EXPECT_GT(shifted, after.size() / 2);

  // A volume of another spacing changes the view's default pixel spacing: everything reruns.
  auto finer = MakeVolume(0.0, 0.5);
  EXPECT_EQ(pipeline.RunsAfter(
              [&]
              {
                pipeline.Depth->SetReferenceVolume(finer);
                pipeline.Resample->SetVolume(finer);
              }),
            All);
  EXPECT_DOUBLE_EQ(pipeline.Depth->GetView().GetSpacing()[0], 0.5);
}
