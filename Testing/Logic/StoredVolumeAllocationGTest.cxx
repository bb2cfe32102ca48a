// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// One allocation of the voxel bytes from the file to the resampler (issue 40, docs/design.md "Volumes in their stored
// type"): a 16-bit CT read from NRRD, NIfTI or MetaImage (plain, detached and compressed) or a DICOM folder, made a
// node as the viewer and the modules make it, converted by the logic and sampled by both resamplers, and read by the
// one-vessel logic too, allocates its voxel bytes once, and the resamplers read the node's buffer. Counted by
// vrAllocationCounter, which replaces malloc (so this executable is not built under the sanitizers), and for a DICOM
// folder by the mappings of the reader process's memfd in /proc/self/maps: the child decodes the slices into the
// memfd and this process maps the same pages, so the mapping is the one allocation, and no malloc'd block of half the
// voxel bytes may appear.
#include "vrAllocationCounter.h"
#include "vrCenterlineIO.h"
#include "vrDICOMTestSeries.h"
#include "vrNodeConversion.h"
#include "vrReformationInputs.h"
#include "vrTestFiles.h"
#include "vrTestProcess.h"
#include "vrText.h"
#include "vrVesselPathLogic.h"
#include "vrVesselReformationLogic.h"
#include "vrVolumeIO.h"

#include "itkImageFileWriter.h"

#include <gtest/gtest.h>

#include <vtkImageData.h>

#include <filesystem>

namespace
{
using ShortVolume = itk::Image<short, 3>;

/** A 160 x 128 x 96 CT-like int16 volume (3.9 MB): a bright tube along z in soft tissue with noise of 64 levels, so
 * that it compresses as a CT does (to about half) and a compressed file's bytes, held whole, would show in the peak. */
ShortVolume::Pointer
MakeVolume()
{
  auto                    volume = ShortVolume::New();
  ShortVolume::RegionType region;
  region.SetSize({ { 160, 128, 96 } });
  volume->SetRegions(region);
  ShortVolume::SpacingType spacing;
  spacing[0] = 0.7;
  spacing[1] = 0.7;
  spacing[2] = 1.0;
  volume->SetSpacing(spacing);
  volume->Allocate();
  short *       voxel = volume->GetBufferPointer();
  std::uint32_t noise = 1;
  for (int k = 0; k < 96; ++k)
  {
    for (int j = 0; j < 128; ++j)
    {
      for (int i = 0; i < 160; ++i)
      {
        const double distance = std::hypot(i - 80.0, j - 64.0);
        noise = noise * 1103515245u + 12345u;
        *voxel++ = static_cast<short>((distance < 6.0 ? 350 : 40) + static_cast<int>((noise >> 16) % 64));
      }
    }
  }
  return volume;
}

/** A centerline along the tube, in LPS. */
itk::CenterlineTree
TubeCenterline()
{
  itk::CenterlineBranch branch;
  branch.Id = 1;
  for (int k = 4; k <= 92; k += 4)
  {
    itk::Point<double, 3> point;
    point[0] = 80 * 0.7;
    point[1] = 64 * 0.7;
    point[2] = k;
    branch.Points.push_back(point);
    branch.Radii.push_back(4.0);
  }
  itk::CenterlineTree tree;
  tree.AddBranch(branch);
  return tree;
}

struct Written
{
  std::string Path;
  bool        Compress;
};

void
PrintTo(const Written & written, std::ostream * os)
{
  *os << written.Path << (written.Compress ? " (compressed)" : "");
}

class StoredVolumeAllocation : public ::testing::TestWithParam<Written>
{
};
} // namespace

TEST_P(StoredVolumeAllocation, TheVoxelBytesAreAllocatedOnceFromTheFileToTheResampler)
{
  const vr::test::ScopedTemporaryFolder folder;
  const std::string                     path = folder.File(GetParam().Path);
  const bool                            dicom = GetParam().Path == "dicom";
  std::size_t                           voxelBytes = 0;
  {
    const auto volume = MakeVolume();
    voxelBytes = volume->GetLargestPossibleRegion().GetNumberOfPixels() * sizeof(short);
    if (dicom)
    {
      // Signed 16-bit files with the identity rescale, written byte by byte (vrDICOMTestSeries).
      auto intensities = vr::VolumeImageType::New();
      intensities->CopyInformation(volume);
      intensities->SetRegions(volume->GetLargestPossibleRegion());
      intensities->Allocate();
      std::copy(volume->GetBufferPointer(),
                volume->GetBufferPointer() + volume->GetLargestPossibleRegion().GetNumberOfPixels(),
                intensities->GetBufferPointer());
      vr::test::CTSeriesOptions options;
      options.Signed = true;
      vr::test::WriteDICOMTestFolder(path, vr::test::MakeCTSeries(intensities, options));
    }
    else
    {
      auto writer = itk::ImageFileWriter<ShortVolume>::New();
      writer->SetInput(volume);
      writer->SetFileName(path);
      writer->SetUseCompression(GetParam().Compress);
      writer->Update();
    }
  }
  std::uintmax_t fileBytes = 0;
  for (const auto & entry : std::filesystem::recursive_directory_iterator(folder.Path()))
  {
    fileBytes += entry.is_regular_file() ? entry.file_size() : 0;
  }
  const auto                centerlines = vr::ConvertTreeToCenterlineNode(TubeCenterline(), "tube");
  vr::ReformationParameters parameters;
  parameters.ImageSize[0] = 48;
  parameters.ImageSize[1] = 64;
  parameters.Iterations = 20;
  parameters.Backend = vr::RelaxBackend::CPU;
  vr::VesselReformationLogic logic;
  vr::VesselPathLogic        pathLogic;

  // From here on: no block of half the voxel bytes or more but the voxels'.
  const long long before = vr::test::AllocatedBytes();
  vr::test::ResetAllocationPeak();
  vr::test::CountAllocationsOfAtLeast(static_cast<long long>(voxelBytes / 2));

  auto node = vr::ReadVolumeNode(path); // the viewer's way; the modules' is the same two calls
  logic.SetVolumeNode(node);
  logic.SetCenterlineNode(centerlines);
  logic.SetParameters(parameters);
  logic.Update();
  pathLogic.SetVolumeNode(node); // the one-vessel logic takes the same node
  pathLogic.SetCenterlineNode(vr::ConvertTreeToCenterlineNode(TubeCenterline(), "tube"));
  pathLogic.SetCrossSectionsEnabled(true);
  pathLogic.Update();

  // A DICOM folder's voxels: the reader process's memfd, mapped here (its header page and the voxels).
  long long mapped = 0;
  long long mappings = 0;
  for (const vr::test::ProcessMapping & mapping : vr::test::MappingsNamed("memfd:vrReadDICOMSeries volume"))
  {
    mapped += static_cast<long long>(mapping.Bytes());
    ++mappings;
  }
  const long long large = vr::test::LargeAllocations() + mappings;
  const long long largeBytes = vr::test::LargeAllocationBytes() + mapped;
  const long long peak = vr::test::AllocationPeak() - before + mapped;
  vr::test::CountAllocationsOfAtLeast(0);
  std::cout << GetParam().Path << (GetParam().Compress ? " (compressed)" : "") << ": " << large
            << " blocks of at least half the voxel bytes (" << largeBytes << " bytes, of which " << mappings
            << " mappings of " << mapped << " bytes; voxels " << voxelBytes << "), peak " << peak
            << " bytes above the start, files " << fileBytes << " bytes\n";
  EXPECT_EQ(large, 1);
  EXPECT_EQ(mappings, dicom ? 1 : 0);
  EXPECT_LT(largeBytes, static_cast<long long>(voxelBytes + (dicom ? 8192 : 4096)));
  const void * voxels = node->GetImageData()->GetScalarPointer();
  EXPECT_EQ(node->GetImageData()->GetScalarType(), VTK_SHORT);
  EXPECT_EQ(static_cast<const void *>(
              dynamic_cast<const ShortVolume *>(logic.GetResampleFilter()->GetVolume())->GetBufferPointer()),
            voxels);
  // The one-vessel logic samples the same voxels, through its own conversion of the same node.
  EXPECT_EQ(static_cast<const void *>(
              dynamic_cast<const ShortVolume &>(*pathLogic.GetInputCache()->GetVolume(node)->Image).GetBufferPointer()),
            voxels);
  // The peak: the voxels, the vessel's cross-sections (a float image of its own) and what a 48 x 64 view and the rest
  // of a short vessel path take (under 1 MiB); no compressed file held whole (about half the voxel bytes here).
  const auto sectionBytes = static_cast<long long>(
    pathLogic.GetOutputs().CrossSections->GetLargestPossibleRegion().GetNumberOfPixels() * sizeof(float));
  std::cout << "cross-sections " << sectionBytes << " bytes; the rest "
            << peak - static_cast<long long>(voxelBytes) - sectionBytes << " bytes\n";
  EXPECT_LT(peak, static_cast<long long>(voxelBytes + (1u << 20)) + sectionBytes);
}

INSTANTIATE_TEST_SUITE_P(Formats,
                         StoredVolumeAllocation,
                         ::testing::Values(Written{ "ct.nrrd", false },
                                           Written{ "ct.nrrd", true },
                                           Written{ "ct.nhdr", false },
                                           Written{ "ct.nii", false },
                                           Written{ "ct.nii.gz", false },
                                           Written{ "ct.mha", false },
                                           Written{ "ct.mha", true },
                                           Written{ "ct.mhd", false },
                                           Written{ "dicom", false }),
                         [](const ::testing::TestParamInfo<Written> & info)
                         {
                           std::string name = info.param.Path + (info.param.Compress ? "_gz" : "");
                           for (char & c : name)
                           {
                             c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           }
                           return name;
                         });
