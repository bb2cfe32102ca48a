// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// A volume beyond 2^31 bytes (issue 40): 512 x 512 x 4200 int16, 2,202,009,600 bytes, as a run-off CTA of 4 200
// slices. Each format's file is sparse (its zeros are holes that take no disk) but for four slices at each end, where
// the voxels hold 1000 + 3 i (i the column index; a linear function, so that linear interpolation reproduces it
// exactly). The volume is read (NRRD, MetaImage, NIfTI), its first and last voxels checked in the buffer, and it is
// reformed along a vertical centerline and read along it as one vessel: the rows of both images that sample the end
// slices must give 1000 + 3 i at the point they sample. Every byte offset into the voxels past slice 4096 exceeds
// 2^31, so a 32-bit index anywhere on the way (reader, node, conversion, sampler) reads the wrong voxel or crashes.
#include "vrCenterlineIO.h"
#include "vrInputError.h"
#include "vrNodeConversion.h"
#include "vrReformationInputs.h"
#include "vrTestFiles.h"
#include "vrTestNifti.h"
#include "vrVesselPathLogic.h"
#include "vrVesselReformationLogic.h"
#include "vrVolumeIO.h"

#include <gtest/gtest.h>

#include <vtkImageData.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fcntl.h>
#include <unistd.h>
#include <vector>

namespace
{
constexpr long long Columns = 512;
constexpr long long Rows = 512;
constexpr long long Slices = 4200;
constexpr long long SliceVoxels = Columns * Rows;
constexpr long long VoxelBytes = SliceVoxels * Slices * 2;
constexpr double    PixelSpacing = 0.8;
constexpr double    SliceSpacing = 0.5;
constexpr int       PatternSlices = 4;

static_assert(VoxelBytes > (1LL << 31), "the volume must be larger than 2^31 bytes");

short
Pattern(long long column)
{
  return static_cast<short>(1000 + 3 * column);
}

/** Writes \a count slices of the pattern at slice \a first of the voxels that start at byte \a offset of \a file. */
void
WritePatternSlices(int file, long long offset, long long first, long long count)
{
  std::vector<short> slice(static_cast<std::size_t>(SliceVoxels));
  for (long long j = 0; j < Rows; ++j)
  {
    for (long long i = 0; i < Columns; ++i)
    {
      slice[static_cast<std::size_t>(j * Columns + i)] = Pattern(i);
    }
  }
  for (long long k = first; k < first + count; ++k)
  {
    const auto bytes = static_cast<std::size_t>(SliceVoxels * 2);
    ASSERT_EQ(pwrite(file, slice.data(), bytes, static_cast<off_t>(offset + k * SliceVoxels * 2)),
              static_cast<ssize_t>(bytes));
  }
}

/** A sparse file of \a header followed by the voxels: holes but for the pattern slices at both ends. */
void
WriteSparseVolume(const std::string & path, const std::vector<unsigned char> & header)
{
  const int file = open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  ASSERT_GE(file, 0) << path;
  if (!header.empty())
  {
    ASSERT_EQ(write(file, header.data(), header.size()), static_cast<ssize_t>(header.size()));
  }
  const auto offset = static_cast<long long>(header.size());
  ASSERT_EQ(ftruncate(file, static_cast<off_t>(offset + VoxelBytes)), 0);
  WritePatternSlices(file, offset, 0, PatternSlices);
  WritePatternSlices(file, offset, Slices - PatternSlices, PatternSlices);
  close(file);
}

std::string
WriteVolumeFiles(const vr::test::ScopedTemporaryFolder & folder, const std::string & format)
{
  if (format == "nrrd")
  {
    WriteSparseVolume(folder.File("large.raw"), {});
    vr::test::WriteTextFile(folder.File("large.nhdr"),
                            "NRRD0004\ntype: int16\ndimension: 3\nspace: left-posterior-superior\nsizes: 512 512 4200\n"
                            "space directions: (0.8,0,0) (0,0.8,0) (0,0,0.5)\nspace origin: (0,0,0)\nendian: little\n"
                            "encoding: raw\ndata file: large.raw\n\n");
    return folder.File("large.nhdr");
  }
  if (format == "mhd")
  {
    WriteSparseVolume(folder.File("large.raw"), {});
    vr::test::WriteTextFile(folder.File("large.mhd"),
                            "ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n"
                            "CompressedData = False\nTransformMatrix = 1 0 0 0 1 0 0 0 1\nOffset = 0 0 0\n"
                            "ElementSpacing = 0.8 0.8 0.5\nDimSize = 512 512 4200\nElementType = MET_SHORT\n"
                            "ElementDataFile = large.raw\n");
    return folder.File("large.mhd");
  }
  // NIfTI-1: a qform offset of (-10, 20, 30) mm LPS... in RAS; the checks below read the geometry from the image.
  const double spacing[3] = { PixelSpacing, PixelSpacing, SliceSpacing };
  WriteSparseVolume(folder.File("large.nii"),
                    vr::test::Nifti1Header({ { 512, 512, 4200 } }, 4, 16, spacing, 1.0f, 0.0f, false));
  return folder.File("large.nii");
}

/** The pattern's value at physical point \a point of \a volume when it lies where the pattern holds exactly (inside
 * the pattern slices at either end, interpolation included, and inside the columns); NaN elsewhere. */
double
ExpectedAt(const itk::ImageBase<3> * volume, const itk::Point<double, 3> & point)
{
  itk::ContinuousIndex<double, 3> index;
  volume->TransformPhysicalPointToContinuousIndex(point, index);
  const bool nearStart = index[2] >= 0.0 && index[2] <= PatternSlices - 1.0;
  const bool nearEnd = index[2] >= Slices - PatternSlices && index[2] <= Slices - 1.0;
  if (!(nearStart || nearEnd) || index[0] < 0.0 || index[0] > Columns - 1.0 || index[1] < 0.0 || index[1] > Rows - 1.0)
  {
    return std::nan("");
  }
  return 1000.0 + 3.0 * index[0];
}

class LargeVolume : public ::testing::TestWithParam<std::string>
{
};
} // namespace

TEST_P(LargeVolume, IsReadReformedAndReadAsOneVesselAtBothEnds)
{
  const vr::test::ScopedTemporaryFolder folder;
  const std::string                     path = WriteVolumeFiles(folder, GetParam());

  auto node = vr::ReadVolumeNode(path);
  {
    // The buffer: int16, every voxel, the pattern at both ends, zeros between.
    ASSERT_EQ(node->GetImageData()->GetScalarType(), VTK_SHORT);
    ASSERT_EQ(node->GetImageData()->GetNumberOfPoints(), SliceVoxels * Slices);
    const auto * voxels = static_cast<const short *>(node->GetImageData()->GetScalarPointer());
    for (const long long i : { 0LL, 1LL, 255LL, 511LL })
    {
      EXPECT_EQ(voxels[i], Pattern(i)) << "first slice, column " << i;
      EXPECT_EQ(voxels[(Slices - 1) * SliceVoxels + (Rows - 1) * Columns + i], Pattern(i))
        << "last slice, column " << i;
      EXPECT_EQ(voxels[(Slices - PatternSlices) * SliceVoxels + 17 * Columns + i], Pattern(i));
      EXPECT_EQ(voxels[(Slices / 2) * SliceVoxels + 99 * Columns + i], 0) << "the middle is a hole";
    }
    EXPECT_EQ(voxels[SliceVoxels * Slices - 1], Pattern(Columns - 1)) << "the last voxel, byte 2^31 + 54,525,950";
  }

  // A vertical centerline at the volume's middle column and row, from the first slice to the last.
  const vr::StoredVolume    stored = vr::ConvertVolumeNodeToStoredVolume(node);
  const itk::ImageBase<3> * volume = stored.Image;
  itk::CenterlineBranch     branch;
  branch.Id = 1;
  for (long long k = 0; k <= 20; ++k)
  {
    itk::ContinuousIndex<double, 3> index;
    index[0] = 255.5;
    index[1] = 255.5;
    index[2] = 0.5 + (Slices - 2.0) * static_cast<double>(k) / 20.0;
    itk::Point<double, 3> point;
    volume->TransformContinuousIndexToPhysicalPoint(index, point);
    branch.Points.push_back(point);
  }
  itk::CenterlineTree tree;
  tree.AddBranch(branch);

  // The whole-tree reformation: a 64-pixel wide CPR, one row per slice's spacing, the whole length.
  vr::VesselReformationLogic logic;
  logic.SetVolumeNode(node);
  logic.SetCenterlineNode(vr::ConvertTreeToCenterlineNode(tree, "vertical"));
  vr::ReformationParameters parameters;
  parameters.Backend = vr::RelaxBackend::CPU;
  parameters.Iterations = 5;
  parameters.PixelSpacing[0] = 1.0;
  parameters.PixelSpacing[1] = SliceSpacing;
  parameters.ImageSize[0] = 64;
  parameters.ImageSize[1] = 4300;
  logic.SetParameters(parameters);
  const vr::ReformationOutputs outputs = logic.Update();
  const auto                   cpr = vr::ConvertVolumeNodeToDepthImage(outputs.CPR);
  const auto                   depth = vr::ConvertVolumeNodeToDepthImage(outputs.RelaxedDepth);
  int                          checked[2] = { 0, 0 };
  for (unsigned int j = 0; j < 4300; ++j)
  {
    for (unsigned int i = 0; i < 64; ++i)
    {
      const itk::Index<2>         pixel = { { i, j } };
      const itk::Point<double, 3> point =
        outputs.View.PlanePoint(i, j) + outputs.View.GetV() * static_cast<double>(depth->GetPixel(pixel));
      const double expected = ExpectedAt(volume, point);
      if (std::isnan(expected))
      {
        continue;
      }
      ASSERT_NEAR(cpr->GetPixel(pixel), expected, 2e-3) << "pixel " << i << ", " << j;
      ++checked[point[2] > 500.0 ? 1 : 0];
    }
  }
  std::cout << "CPR: " << checked[0] << " pixels checked at the first slices, " << checked[1] << " at the last\n";
  EXPECT_GE(checked[0], 64 * 3);
  EXPECT_GE(checked[1], 64 * 3);

  // The same vessel straightened: its first and last rows sample the end slices.
  vr::VesselPathLogic pathLogic;
  pathLogic.SetVolumeNode(node);
  const auto pathCenterlines = vr::ConvertTreeToCenterlineNode(tree, "centerlines");
  pathLogic.GetInputCache()->SetCenterlines(pathCenterlines, tree);
  pathLogic.SetCenterlineNode(pathCenterlines);
  pathLogic.SetPointImageEnabled(true);
  vr::VesselPathParameters pathParameters;
  pathParameters.Width = 40.0;
  pathParameters.PixelSpacing = SliceSpacing;
  pathLogic.SetParameters(pathParameters);
  const vr::VesselPathOutputs & results = pathLogic.Update();
  const auto                    size = results.CPR->GetLargestPossibleRegion().GetSize();
  int                           sampled[2] = { 0, 0 };
  for (itk::SizeValueType j = 0; j < size[1]; ++j)
  {
    for (itk::SizeValueType i = 0; i < size[0]; ++i)
    {
      const itk::Index<2> pixel = { { static_cast<itk::IndexValueType>(i), static_cast<itk::IndexValueType>(j) } };
      const itk::Vector<float, 3> & at = results.Points->GetPixel(pixel);
      itk::Point<double, 3>         point;
      for (unsigned int axis = 0; axis < 3; ++axis)
      {
        point[axis] = at[axis];
      }
      const double expected = ExpectedAt(volume, point);
      if (std::isnan(expected))
      {
        continue;
      }
      // The points are stored as float: 1e-4 mm of position is 4e-4 of a value that rises 3.75 a millimetre.
      ASSERT_NEAR(results.CPR->GetPixel(pixel), expected, 2e-2) << "pixel " << i << ", " << j;
      ++sampled[point[2] > 500.0 ? 1 : 0];
    }
  }
  std::cout << "straightened CPR: " << sampled[0] << " pixels checked at the first slices, " << sampled[1]
            << " at the last\n";
  EXPECT_GT(sampled[0], 40);
  EXPECT_GT(sampled[1], 40);
}

INSTANTIATE_TEST_SUITE_P(Formats, LargeVolume, ::testing::Values("nrrd", "mhd", "nii"));
