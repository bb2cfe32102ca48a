// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// VesselReformation --segmentation (issue 15, items 4 and 6): the VMTK aorta reformed along the centerlines of its
// own level set in one run, and the bad input of a segmentation: a clear message, exit 1, nothing written.

#include "vrImageIO.h"
#include "vrModuleRuns.h"
#include "vrTestFiles.h"
#include "vrVolumeIO.h"

#include "itkImageFileWriter.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace
{
namespace fs = std::filesystem;
using vr::test::Contains;
using vr::test::ModuleRun;

const std::string Executable = VR_REFORMATION_EXE;
const fs::path    DataFolder = fs::path(VR_SHARED_DATA_DIR) / "vmtk-aorta-mra";

fs::path
TestFolder()
{
  return vr::test::FreshFolderForThisTest(VR_TEST_OUTPUT_DIR, "VesselReformationSegmentation.");
}

ModuleRun
RunModule(std::vector<std::string> arguments)
{
  arguments.insert(arguments.begin(), Executable);
  return vr::test::RunProgram(arguments);
}

std::string
Volume()
{
  return (DataFolder / "aorta.mha").string();
}

std::string
LevelSet()
{
  return (DataFolder / "aorta-final-levelset.mha").string();
}

double
Median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  return values.empty() ? 0.0 : values[values.size() / 2];
}

TEST(VesselReformationSegmentation, AortaReformedAlongItsOwnLevelSetsCenterlinesShowsLumen)
{
  const fs::path  folder = TestFolder();
  const ModuleRun run = RunModule({ "--up",
                                    "auto",
                                    "--backend",
                                    "cpu",
                                    "--segmentation",
                                    LevelSet(),
                                    "--outputMask",
                                    (folder / "mask.nrrd").string(),
                                    "--outputPNG",
                                    (folder / "cpr.png").string(),
                                    Volume(),
                                    (folder / "cpr.nrrd").string() });
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  EXPECT_TRUE(Contains(run.Out, "VesselReformation: 3 branches (extracted from aorta-final-levelset.mha: level set"))
    << run.Out;
  EXPECT_TRUE(Contains(run.Out, "centerline extraction")) << run.Out;
  EXPECT_FALSE(Contains(run.Err, "warning")) << run.Err;
  const auto          cpr = vr::ReadDepthImage((folder / "cpr.nrrd").string());
  const auto          mask = vr::ReadMaskImage((folder / "mask.nrrd").string());
  std::vector<double> fixed;
  std::vector<double> free;
  for (std::size_t k = 0; k < cpr->GetBufferedRegion().GetNumberOfPixels(); ++k)
  {
    (mask->GetBufferPointer()[k] ? fixed : free).push_back(cpr->GetBufferPointer()[k]);
  }
  std::cout << "aorta CPR along the extracted centerlines: " << cpr->GetLargestPossibleRegion().GetSize() << " pixels, "
            << fixed.size() << " fixed, their median " << Median(fixed) << " (lumen about 1850, background 230); the "
            << free.size() << " others' median " << Median(free) << std::endl;
  ASSERT_GT(fixed.size(), 200u);
  EXPECT_GT(Median(fixed), 1500.0);
}

TEST(VesselReformationSegmentation, SegmentationOnAnotherGridWarnsAndStillShowsLumen)
{
  // The level set resampled to coarser voxels shifted by a third of a voxel: same vessels, another grid.
  const fs::path folder = TestFolder();
  const auto     levelSet = vr::ReadVolume(LevelSet());
  auto           coarse = vr::VolumeImageType::New();
  auto           spacing = levelSet->GetSpacing();
  auto           size = levelSet->GetLargestPossibleRegion().GetSize();
  for (unsigned int axis = 0; axis < 3; ++axis)
  {
    spacing[axis] *= 1.25;
    size[axis] = static_cast<itk::SizeValueType>(size[axis] / 1.25);
  }
  auto origin = levelSet->GetOrigin();
  origin[0] += 0.3;
  coarse->SetRegions(vr::VolumeImageType::RegionType(size));
  coarse->SetSpacing(spacing);
  coarse->SetOrigin(origin);
  coarse->SetDirection(levelSet->GetDirection());
  coarse->Allocate();
  for (itk::SizeValueType k = 0; k < coarse->GetBufferedRegion().GetNumberOfPixels(); ++k)
  {
    vr::VolumeImageType::IndexType index;
    index[0] = static_cast<long>(k % size[0]);
    index[1] = static_cast<long>((k / size[0]) % size[1]);
    index[2] = static_cast<long>(k / (size[0] * size[1]));
    itk::Point<double, 3> point;
    coarse->TransformIndexToPhysicalPoint(index, point);
    vr::VolumeImageType::IndexType nearest;
    const bool                     inside = levelSet->TransformPhysicalPointToIndex(point, nearest);
    coarse->GetBufferPointer()[k] = inside ? levelSet->GetPixel(nearest) : 1.0f;
  }
  vr::WriteVolume(coarse, (folder / "coarse-levelset.nrrd").string());
  const ModuleRun run = RunModule({ "--up",
                                    "auto",
                                    "--backend",
                                    "cpu",
                                    "--segmentation",
                                    (folder / "coarse-levelset.nrrd").string(),
                                    "--outputMask",
                                    (folder / "mask.nrrd").string(),
                                    Volume(),
                                    (folder / "cpr.nrrd").string() });
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  EXPECT_TRUE(Contains(run.Err, "warning: segmentation \"coarse-levelset.nrrd\" lies on another grid")) << run.Err;
  const auto          cpr = vr::ReadDepthImage((folder / "cpr.nrrd").string());
  const auto          mask = vr::ReadMaskImage((folder / "mask.nrrd").string());
  std::vector<double> fixed;
  for (std::size_t k = 0; k < cpr->GetBufferedRegion().GetNumberOfPixels(); ++k)
  {
    if (mask->GetBufferPointer()[k])
    {
      fixed.push_back(cpr->GetBufferPointer()[k]);
    }
  }
  std::cout << "on a coarser grid: fixed pixels' median " << Median(fixed) << std::endl;
  EXPECT_GT(Median(fixed), 1500.0);
}

// ---------------------------------------------------------------------------------------------------------------
// Bad input.

class VesselReformationSegmentationBadInput : public ::testing::Test
{
protected:
  void
  SetUp() override
  {
    m_Folder = TestFolder();
    std::ofstream(m_Folder / "cpr.nrrd") << "an earlier result that must survive";
  }

  void
  ExpectRejected(std::vector<std::string> arguments, const std::vector<std::string> & mentions)
  {
    arguments.insert(arguments.begin(), { "--backend", "cpu", "--outputDepth", (m_Folder / "depth.nrrd").string() });
    arguments.push_back((m_Folder / "cpr.nrrd").string());
    const auto      before = vr::test::FolderEntries(m_Folder);
    const ModuleRun run = RunModule(arguments);
    EXPECT_FALSE(run.Crashed);
    EXPECT_EQ(run.ExitCode, 1) << run.Err;
    EXPECT_TRUE(Contains(run.Err, "VesselReformation: error: ")) << run.Err;
    for (const auto & mention : mentions)
    {
      EXPECT_TRUE(Contains(run.Err, mention)) << "the message lacks \"" << mention << "\":\n" << run.Err;
    }
    std::cout << "  " << run.Err;
    EXPECT_EQ(vr::test::FolderEntries(m_Folder), before) << "a file appeared or vanished";
    EXPECT_EQ(vr::test::ReadTextFile((m_Folder / "cpr.nrrd").string()), "an earlier result that must survive");
  }

  template<typename TImage>
  std::string
  Write(const TImage * image, const std::string & name)
  {
    auto writer = itk::ImageFileWriter<TImage>::New();
    writer->SetInput(image);
    writer->SetFileName((m_Folder / name).string());
    writer->Update();
    return (m_Folder / name).string();
  }

  fs::path m_Folder;
};

TEST_F(VesselReformationSegmentationBadInput, NeitherOrBothCenterlineSources)
{
  ExpectRejected({ Volume() }, { "no centerlines", "<inputCenterlines>", "--segmentation" });
  ExpectRejected({ "--segmentation", LevelSet(), Volume(), (DataFolder / "aorta-centerline.vtp").string() },
                 { "both <inputCenterlines> and --segmentation give centerlines" });
}

TEST_F(VesselReformationSegmentationBadInput, EmptyMask)
{
  const auto levelSet = vr::ReadVolume(LevelSet());
  auto       empty = itk::Image<unsigned char, 3>::New();
  empty->CopyInformation(levelSet);
  empty->SetRegions(levelSet->GetLargestPossibleRegion());
  empty->Allocate(true);
  ExpectRejected({ "--segmentation", Write(empty.GetPointer(), "empty.nii.gz"), Volume() },
                 { "empty.nii.gz", "no vessel voxel: every voxel is 0" });
}

TEST_F(VesselReformationSegmentationBadInput, MaskOfAnotherPlace)
{
  // The level set moved 400 mm away: it does not overlap the volume.
  auto levelSet = vr::ReadVolume(LevelSet());
  auto origin = levelSet->GetOrigin();
  origin[2] += 400.0;
  levelSet->SetOrigin(origin);
  vr::WriteVolume(levelSet, (m_Folder / "elsewhere.nrrd").string());
  ExpectRejected({ "--segmentation", (m_Folder / "elsewhere.nrrd").string(), Volume() },
                 { "segmentation \"elsewhere.nrrd\"", "does not overlap the volume \"aorta.mha\"" });
}

TEST_F(VesselReformationSegmentationBadInput, TwoDimensionalAndMissingSegmentations)
{
  auto slice = itk::Image<unsigned char, 2>::New();
  slice->SetRegions(itk::Image<unsigned char, 2>::RegionType({ { 0, 0 } }, { { 40, 30 } }));
  slice->Allocate(true);
  ExpectRejected({ "--segmentation", Write(slice.GetPointer(), "slice.nrrd"), Volume() },
                 { "slice.nrrd", "a 2D image (40 x 30 pixels)" });
  ExpectRejected({ "--segmentation", (m_Folder / "missing.nii.gz").string(), Volume() },
                 { "missing.nii.gz", "no such file" });
}
} // namespace
