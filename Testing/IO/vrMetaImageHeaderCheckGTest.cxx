// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The MetaImage header check (issue 25): headers ITK writes and VMTK's files pass, and ITK reads the accepted variants
// (blank lines, CRLF, "==", fields MetaIO does not know) as they were written; each way a header can make MetaIO hang,
// overflow or read the next line's values is refused naming the line and the field, the fuzzer's hang among them.
#include "vrInputError.h"
#include "vrMetaImageHeaderCheck.h"
#include "vrTestFiles.h"

#include "itkImage.h"
#include "itkImageFileWriter.h"
#include "itkMetaImageIO.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace
{
namespace fs = std::filesystem;

/** CheckMetaImageHeaderBytes()'s message for \a header, empty when it passes. */
std::string
CheckMessage(const std::string & header)
{
  try
  {
    vr::detail::CheckMetaImageHeaderBytes(header.data(), header.size(), "volume x.mha");
  }
  catch (const vr::InputError & error)
  {
    return error.what();
  }
  return std::string();
}

std::string
ReadBytes(const fs::path & path)
{
  std::ifstream input(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(input)), std::istreambuf_iterator<char>());
}

/** A valid 3D header with \a extra lines before DimSize, voxels of 2 x 3 x 4 shorts following. */
std::string
Header(const std::string & extra = std::string())
{
  return "ObjectType = Image\nNDims = 3\nBinaryData = True\nBinaryDataByteOrderMSB = False\n"
         "TransformMatrix = 1 0 0 0 1 0 0 0 1\nOffset = -1.5 2 3e1\nElementSpacing = 0.5 0.75 1.25\n" +
         extra + "DimSize = 2 3 4\nElementType = MET_SHORT\nElementDataFile = LOCAL\n" + std::string(48, '\0');
}

/** Header() with the line starting with \a field replaced by \a line. */
std::string
WithLine(const std::string & field, const std::string & line)
{
  std::string header = Header();
  const auto  at = header.find(field + " =");
  EXPECT_NE(at, std::string::npos) << field;
  return header.replace(at, header.find('\n', at) - at, line);
}

void
ExpectRefused(const std::string & header, const std::string & mention)
{
  const std::string message = CheckMessage(header);
  EXPECT_NE(message.find("volume x.mha: MetaImage header "), std::string::npos) << message;
  EXPECT_NE(message.find(mention), std::string::npos) << "wanted \"" << mention << "\" in: " << message;
}

TEST(MetaImageHeaderCheck, PassesWhatITKWritesAndVMTKsFiles)
{
  const vr::test::ScopedTemporaryFolder temporary;
  const fs::path &                      folder = temporary.Path();
  using ImageType = itk::Image<short, 3>;
  auto image = ImageType::New();
  image->SetRegions(ImageType::SizeType{ { 5, 6, 7 } });
  image->Allocate(true);
  const double             spacing[3] = { 0.6, 0.8, 1.1 };
  ImageType::DirectionType direction;
  direction.SetIdentity();
  direction[0][0] = -1.0;
  direction[1][1] = -1.0;
  image->SetSpacing(spacing);
  image->SetDirection(direction);
  for (const char * name : { "written.mha", "written.mhd" })
  {
    const fs::path path = folder / name;
    itk::WriteImage(image, path.string(), true);
    EXPECT_NO_THROW(vr::detail::CheckMetaImageHeader(path.string(), name)) << name;
  }
  EXPECT_EQ(CheckMessage(Header()), "");
  const std::string shared = vr::test::AortaDataFolder();
  if (shared.empty())
  {
    GTEST_FAIL() << "VMTK's aorta (vmtk-aorta-mra) is missing from VR_SHARED_DATA_DIR (Testing/Data by default)";
  }
  for (const char * name : { "aorta.mha", "aorta-final-levelset.mha" })
  {
    EXPECT_NO_THROW(vr::detail::CheckMetaImageHeader((fs::path(shared) / name).string(), name)) << name;
  }
}

TEST(MetaImageHeaderCheck, AcceptedVariantsAreReadByITKAsWritten)
{
  // What the walk accepts beyond ITK's own writing, each read by ITK to the same size and spacing: a check that
  // accepted a header ITK reads otherwise would be one that drifts from the library.
  const vr::test::ScopedTemporaryFolder temporary;
  const fs::path &                      folder = temporary.Path();
  std::string                           crlf = Header();
  for (std::size_t at = crlf.find('\n'); at < crlf.find("ElementDataFile"); at = crlf.find('\n', at + 2))
  {
    crlf.insert(at, "\r");
  }
  const std::string variants[] = {
    Header("\n\nComment = made by hand: a value with = and : in it\n"),
    Header("SomeToolsOwnField = 1 2 3\n"),
    Header("ElementNumberOfChannels = 1\nHeaderSize = -1\nElementMin = -1024\nColor = 1 0 0 1\n"),
    WithLine("ElementSpacing", "ElementSpacing == 0.5\t0.75  1.25"),
    crlf,
  };
  int index = 0;
  for (const std::string & header : variants)
  {
    SCOPED_TRACE(header.substr(0, header.find("ElementDataFile")));
    EXPECT_EQ(CheckMessage(header), "");
    const fs::path path = folder / ("variant-" + std::to_string(index++) + ".mha");
    std::ofstream(path, std::ios::binary) << header;
    auto io = itk::MetaImageIO::New();
    io->SetFileName(path.string());
    ASSERT_NO_THROW(io->ReadImageInformation());
    ASSERT_EQ(io->GetNumberOfDimensions(), 3u);
    EXPECT_EQ(io->GetDimensions(0), 2u);
    EXPECT_EQ(io->GetDimensions(1), 3u);
    EXPECT_EQ(io->GetDimensions(2), 4u);
    EXPECT_DOUBLE_EQ(io->GetSpacing(0), 0.5);
    EXPECT_DOUBLE_EQ(io->GetSpacing(2), 1.25);
    EXPECT_DOUBLE_EQ(io->GetOrigin(2), 30.0);
  }
}

TEST(MetaImageHeaderCheck, RefusesDimensionsMetaIOCannotHold)
{
  // -3 made MetaIO read 2^64 numbers for DimSize (the fuzzer's hang); 11 overflows its arrays of 10.
  ExpectRefused(WithLine("NDims", "NDims =-3"), "line 2: NDims = -3: must be 1 whole number from 1 to 4");
  ExpectRefused(WithLine("NDims", "NDims = 11"), "NDims = 11: must be");
  ExpectRefused(WithLine("NDims", "NDims = 2.5"), "NDims = 2.5");
  ExpectRefused(WithLine("NDims", "NDims = 1e10"), "NDims = 1e10");
  ExpectRefused(WithLine("NDims", "NDims = "), "NDims = : must be");
  ExpectRefused(WithLine("NDims", "NDims = 3 3"), "NDims = 3 3");
  // Before NDims, MetaIO refuses an array; the walk does not guess its length.
  ExpectRefused("ObjectType = Image\nDimSize = 2 3 4\nNDims = 3\n", "DimSize comes before NDims");
  ExpectRefused(Header("NDims = 4\n"), "NDims appears a second time");
}

TEST(MetaImageHeaderCheck, RefusesNumericFieldsMetaIOWouldReadOtherwise)
{
  // Fewer values than MetaIO wants: it would take the rest from the next line.
  ExpectRefused(WithLine("DimSize", "DimSize = 2 3"), "DimSize = 2 3: must be 3 whole numbers from 1 to");
  ExpectRefused(WithLine("DimSize", "DimSize = 2 3 4 5"), "DimSize = 2 3 4 5");
  ExpectRefused(WithLine("DimSize", "DimSize = 2 0 4"), "DimSize = 2 0 4");
  ExpectRefused(WithLine("DimSize", "DimSize = 2 3 3000000000"), "DimSize");
  ExpectRefused(WithLine("DimSize", "DimSize = 2 2 *2"), "DimSize = 2 2 *2");
  ExpectRefused(WithLine("TransformMatrix", "TransformMatrix = 1 0 0 0 1 0 0 0"), "(NDims = 3)");
  ExpectRefused(WithLine("ElementSpacing", "ElementSpacing = 0.5 nan 1"), "ElementSpacing = 0.5 nan 1");
  ExpectRefused(WithLine("ElementSpacing", "ElementSpacing = 0.5 inf 1"), "ElementSpacing");
  ExpectRefused(WithLine("ElementSpacing", "ElementSpacing = 0.5 1e999 1"), "ElementSpacing");
  // Hexadecimal: strtod reads 16, MetaIO's stream reads 0 and fails on the x.
  ExpectRefused(WithLine("Offset", "Offset = 0x10 0 0"), "Offset = 0x10 0 0");
  ExpectRefused(WithLine("Offset", "Offset = 1. .5 -"), "Offset");
  ExpectRefused(Header("HeaderSize = -2\n"), "HeaderSize = -2");
  ExpectRefused(Header("ElementNumberOfChannels = 0\n"), "ElementNumberOfChannels = 0");
  ExpectRefused(Header("CompressedDataSize = -1\n"), "CompressedDataSize = -1");
  ExpectRefused(Header("Color = 1 0 0\n"), "Color = 1 0 0: must be 4 finite numbers");
  ExpectRefused(WithLine("ElementType", "ElementType = MET_HALF"), "MET_HALF is not a MetaIO element type");
}

TEST(MetaImageHeaderCheck, RefusesLinesMetaIOWouldSplitOtherwise)
{
  // A line with no "=": MetaIO would look for the value on the next line.
  ExpectRefused(Header("just some words\n"), "\"just some words\" is not \"Name = value\"");
  // ":" before "=" ends MetaIO's name there.
  ExpectRefused(Header("Comment: x = y\n"), "is not \"Name = value\"");
  ExpectRefused(Header(" = 3\n"), "has no field name");
  ExpectRefused(Header("Comment = caf\xc3\xa9\n"), "not printable ASCII");
  ExpectRefused(Header("Comment = a\rb\n"), "not printable ASCII");
  ExpectRefused(Header("Comment = " + std::string(500, 'a') + "\n"), "over 400 characters");
  ExpectRefused(Header(std::string(70000, '\n')), "longer than 64 KiB");
  ExpectRefused("ObjectType = Image\nNDims = 3\nDimSize = 2 3 4\nElementType = MET_SHORT\n",
                "ends without ElementDataFile");
  ExpectRefused("ObjectType = Image\nNDims = 3\nElementType = MET_SHORT\nElementDataFile = LOCAL\n",
                "ElementDataFile comes before NDims, DimSize and ElementType");
  ExpectRefused(WithLine("ElementDataFile", "ElementDataFile = "), "names no data file");
  // A file list or pattern MetaIO splits into words, wrongly on a run of spaces (as it did a tube's PointDim).
  ExpectRefused(WithLine("ElementDataFile", "ElementDataFile = LIST  2D"), "a file list or pattern must be words");
  ExpectRefused(WithLine("ElementDataFile", "ElementDataFile = slice%03d.raw 1  4 1"), "separated by single spaces");
  EXPECT_EQ(CheckMessage(WithLine("ElementDataFile", "ElementDataFile = slice%03d.raw 1 4 1")), "");
  EXPECT_EQ(CheckMessage(WithLine("ElementDataFile", "ElementDataFile = my  voxels.raw")), "") << "one file name";
}

TEST(MetaImageHeaderCheck, RefusesTheFuzzersHang)
{
  // The harness's first byte picks the extension; the rest is the file.
  const std::string input =
    ReadBytes(fs::path(VR_FUZZ_CORPUS_DIR) / "volume" / "crash-metaimage-negative-ndims-hang").substr(1);
  ExpectRefused(input, "line 2: NDims = -3");
  // Its NDims line alone, in an otherwise valid header.
  ExpectRefused(WithLine("NDims", "NDims =-3"), "NDims = -3");
}
} // namespace
