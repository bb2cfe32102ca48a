// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The .vtp centerline reader's checks of what VTK's XML parser read (issue 25): the cell arrays before VTK builds
// cells, the array lengths against the piece's counts, and VTK's messages (output window and vtkLogger) kept off
// the terminal.
#include "vrCenterlineIO.h"
#include "vrInputError.h"
#include "vrTestFiles.h"
#include "vrVTKErrorCapture.h"

#include <gtest/gtest.h>
#include <vtkDoubleArray.h>
#include <vtkSetGet.h>
#include <vtkSmartPointer.h>

#include <functional>
#include <string>

namespace
{
#define EXPECT_MESSAGE_HAS(message, part)                                                                              \
  EXPECT_NE((message).find(part), std::string::npos) << "message: " << (message) << "\nmissing: " << (part)

using vr::test::InputErrorAndPrintedTextOf;

/** One piece of three points and one polyline, every array ASCII. */
std::string
Vtp(const std::string & lines,
    const std::string & points,
    const std::string & radius,
    const std::string & connectivity,
    const std::string & offsets)
{
  return "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
         "<PolyData>\n"
         "<Piece NumberOfPoints=\"3\" NumberOfVerts=\"0\" NumberOfLines=\"" +
         lines +
         "\" NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n"
         "<PointData><DataArray type=\"Float64\" Name=\"Radius\" format=\"ascii\">" +
         radius +
         "</DataArray></PointData>\n"
         "<Points><DataArray type=\"Float32\" NumberOfComponents=\"3\" format=\"ascii\">" +
         points +
         "</DataArray></Points>\n"
         "<Lines>\n"
         "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">" +
         connectivity +
         "</DataArray>\n"
         "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">" +
         offsets +
         "</DataArray>\n"
         "</Lines>\n"
         "</Piece>\n"
         "</PolyData>\n"
         "</VTKFile>\n";
}

const std::string Points = "0 0 0 0 0 10 0 0 20";

TEST(CheckedVTPReader, AValidFileReads)
{
  vr::test::ScopedTemporaryFolder folder;
  vr::test::WriteTextFile(folder.File("valid.vtp"), Vtp("1", Points, "1 2 3", "0 1 2", "3"));
  const itk::CenterlineTree tree = vr::ReadCenterlines(folder.File("valid.vtp"));
  ASSERT_EQ(tree.GetNumberOfBranches(), 1U);
  EXPECT_EQ(tree.GetBranches()[0].Points.size(), 3U);
  EXPECT_EQ(tree.GetBranches()[0].Radii[2], 3.0);
}

TEST(CheckedVTPReader, FuzzFindingIsRefusedNamingTheArrayAndPrintsNothing)
{
  const std::string path = std::string(VR_FUZZ_CORPUS_DIR) + "/vtp/crash-ascii-offsets-huge.vtp";
  std::string       printed;
  const std::string message = InputErrorAndPrintedTextOf([&] { vr::ReadCenterlines(path); }, printed);
  EXPECT_MESSAGE_HAS(message, "centerline file " + path + ": the offsets array of Lines: the last offset is ");
  EXPECT_MESSAGE_HAS(message, "but the connectivity array holds 3 ids");
  EXPECT_EQ(printed, "") << "VTK's own text leaked to the terminal";
}

TEST(CheckedVTPReader, CellArraysAndArrayLengthsAreCheckedNamingTheArray)
{
  vr::test::ScopedTemporaryFolder folder;
  const struct
  {
    std::string Text;
    std::string Expected;
  } cases[] = {
    { Vtp("1", Points, "1 2 3", "0 1 5", "3"), "the connectivity array of Lines: id 2 is point 5 of the piece's 3" },
    { Vtp("1", Points, "1 2 3", "0 1 -1", "3"), "the connectivity array of Lines: id 2 is point -1 of the piece's 3" },
    { Vtp("1", Points, "1 2 3", "0 1 2", "2"),
      "the offsets array of Lines: the last offset is 2, but the connectivity "
      "array holds 3 ids" },
    { Vtp("2", Points, "1 2 3", "0 1 2", "2 1"), "the offsets array of Lines: offset 1 (1) is below the one before" },
    { Vtp("1", Points, "1 2", "0 1 2", "3"),
      "the PointData array \"Radius\" holds 2 values; the piece's counts need 3" },
    { Vtp("1", "0 0 0 0 0 10 0 0", "1 2 3", "0 1 2", "3"),
      "the Points array \"\" holds 8 values; the piece's counts "
      "need 9" },
    { Vtp("1", Points, "1 2 3", "0 1 2", "3 3"),
      "the Lines array \"offsets\" holds 2 values; the piece's counts need 1" },
  };
  int index = 0;
  for (const auto & c : cases)
  {
    const std::string path = folder.File("case" + std::to_string(index++) + ".vtp");
    vr::test::WriteTextFile(path, c.Text);
    std::string       printed;
    const std::string message = InputErrorAndPrintedTextOf([&] { vr::ReadCenterlines(path); }, printed);
    EXPECT_MESSAGE_HAS(message, "centerline file " + path + ": ");
    EXPECT_MESSAGE_HAS(message, c.Expected);
    EXPECT_EQ(printed, "") << "VTK's own text leaked to the terminal";
  }
}

/** VTK 9.1 hands an error on an object without an ErrorEvent observer to vtkLogger as well as to the output
 * window; vtkLogger prints it to stderr itself unless the capture silences it. */
TEST(VTKErrorCapture, LoggerOutputIsRecordedNotPrinted)
{
  auto array = vtkSmartPointer<vtkDoubleArray>::New();
  testing::internal::CaptureStderr();
  testing::internal::CaptureStdout();
  bool        recorded = false;
  std::string first;
  {
    vr::detail::VTKErrorCapture capture;
    vtkErrorWithObjectMacro(array, << "a test error from an unobserved object");
    recorded = capture.HasErrors();
    first = capture.FirstError();
  }
  std::string printed = testing::internal::GetCapturedStdout();
  printed += testing::internal::GetCapturedStderr();
  EXPECT_TRUE(recorded);
  EXPECT_EQ(first, "a test error from an unobserved object");
  EXPECT_EQ(printed, "");
}
} // namespace
