// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The input cache of the module logic: each node converted once until it changes, the values shared by every user
// of the cache (two logics on one volume hold one image), a failed conversion retried.
#include "vrLogicTestFixture.h"

#include "vrInputError.h"
#include "vrReformationInputCache.h"
#include "vrTestFiles.h"

#include <vtkImageData.h>

namespace
{
using namespace vr::test::logic;
using vr::ReformationInputCache;

TEST(ReformationInputCache, ConvertsTheVolumeOnceUntilTheNodeChangesAndGivesItsSmallestVoxel)
{
  const auto            vessels = TwoVessels();
  const auto            node = MakeVolumeNode(vessels);
  ReformationInputCache cache;
  const auto            first = cache.GetVolume(node);
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(cache.GetVolume(node), first) << "an unchanged node is converted again";
  // MakeVolumeNode's voxels are Lumen or Background; the smallest is Background.
  EXPECT_EQ(first->Minimum, Background);

  // One voxel set below every other by hand: a modified node is converted again, with the new minimum.
  node->GetImageData()->SetScalarComponentFromFloat(3, 4, 5, 0, -7.0);
  node->Modified();
  const auto second = cache.GetVolume(node);
  EXPECT_NE(second, first);
  EXPECT_EQ(second->Minimum, -7.0f);
  EXPECT_EQ(first->Minimum, Background) << "a value handed out earlier must not change";

  // Another node with the same voxels is another input.
  const auto other = MakeVolumeNode(vessels);
  EXPECT_NE(cache.GetVolume(other), second);
}

TEST(ReformationInputCache, ConvertsTheCenterlinesOnceUntilTheNodeChanges)
{
  const auto            vessels = TwoVessels();
  const auto            node = MakeCenterlineNode(vessels);
  ReformationInputCache cache;
  const auto            first = cache.GetCenterlines(node);
  ASSERT_NE(first, nullptr);
  // The branch leaves the trunk at its point z = 25: the tree holds the trunk's two parts and the branch.
  EXPECT_EQ(first->GetBranches().size(), 3u);
  EXPECT_EQ(cache.GetCenterlines(node), first);
  node->Modified();
  EXPECT_NE(cache.GetCenterlines(node), first);
}

// The vessel labels are part of what the mask is made of: new labels make it again; labels no voxel has throw,
// naming the node, and leave nothing cached, so that the next call with good labels converts.
TEST(ReformationInputCache, MakesTheSegmentationAgainForNewLabelsAndRetriesAfterAFailure)
{
  const auto vessels = TwoVessels();
  const auto node = MakeVolumeNode(vessels);
  node->SetName("vessels");
  ReformationInputCache cache;
  const auto            lumen = cache.GetSegmentation(node, { Lumen });
  ASSERT_NE(lumen, nullptr);
  EXPECT_EQ(cache.GetSegmentation(node, { Lumen }), lumen);
  EXPECT_EQ(lumen->Values, nullptr) << "the node names no region";

  const std::string message = vr::test::InputErrorOf([&] { cache.GetSegmentation(node, { 5.0 }); });
  EXPECT_TRUE(vr::test::Contains(message, "segmentation \"vessels\": no voxel with label 5")) << message;

  const auto again = cache.GetSegmentation(node, { Lumen });
  EXPECT_NE(again, lumen) << "the failed call must leave no entry behind";
  EXPECT_NE(cache.GetSegmentation(node, { Background }), again);
}

// Two logics on the same nodes through one cache: one conversion, one image that both pipelines hold, and the same
// CPR as a logic with a cache of its own.
TEST(ReformationInputCache, TwoLogicsSharingOneCacheHoldOneVolume)
{
  const auto                 vessels = TwoVessels();
  const auto                 volume = MakeVolumeNode(vessels);
  const auto                 centerlines = MakeCenterlineNode(vessels);
  auto                       cache = std::make_shared<ReformationInputCache>();
  vr::VesselReformationLogic first;
  vr::VesselReformationLogic second;
  vr::VesselReformationLogic alone;
  for (vr::VesselReformationLogic * logic : { &first, &second, &alone })
  {
    logic->SetVolumeNode(volume);
    logic->SetCenterlineNode(centerlines);
    logic->SetParameters(QuickParameters());
    logic->SetSurfaceEnabled(false);
  }
  first.SetInputCache(cache);
  second.SetInputCache(cache);
  EXPECT_EQ(first.GetInputCache(), cache);
  EXPECT_NE(alone.GetInputCache(), cache);

  first.Update();
  const auto converted = cache->GetVolume(volume);
  second.Update();
  alone.Update();
  EXPECT_EQ(cache->GetVolume(volume), converted) << "the second logic converted the volume again";
  EXPECT_EQ(first.GetResampleFilter()->GetVolume(), converted->Image.GetPointer());
  EXPECT_EQ(second.GetResampleFilter()->GetVolume(), converted->Image.GetPointer());
  EXPECT_NE(alone.GetResampleFilter()->GetVolume(), converted->Image.GetPointer());

  const vr::DepthImageType * shared = second.GetResampleFilter()->GetOutput();
  const vr::DepthImageType * own = alone.GetResampleFilter()->GetOutput();
  ASSERT_EQ(shared->GetBufferedRegion(), own->GetBufferedRegion());
  const std::size_t count = shared->GetBufferedRegion().GetNumberOfPixels();
  EXPECT_TRUE(std::equal(shared->GetBufferPointer(), shared->GetBufferPointer() + count, own->GetBufferPointer()));

  // A logic given back a cache of its own converts again on its next update.
  const unsigned int conversions = second.GetStageCounts().Conversion;
  second.SetInputCache(nullptr);
  EXPECT_NE(second.GetInputCache(), cache);
  second.Update();
  EXPECT_EQ(second.GetStageCounts().Conversion, conversions + 1);
  EXPECT_NE(second.GetResampleFilter()->GetVolume(), converted->Image.GetPointer());
}
} // namespace
