// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The command-line modules given hostile input (issue 14), checked as bad input is (BadInputTest,
// vrCLITestSupport.h).
#include "vrCLITestSupport.h"

#include <cctype>
#include <functional>
#include <sstream>

namespace
{
using namespace vr::test::cli;

// ---------------------------------------------------------------------------------------------------------------
// Hostile input (issue 14): each class of file or flag that once crashed, hung, or was silently accepted. Every case
// exits 1 with a message naming the file, field or flag, writes nothing, leaves the earlier cpr.nrrd byte for byte,
// and leaves no stray file (ExpectRejected).

TEST_F(BadInputTest, TruncatedLegacyVTK)
{
  const fs::path vtk = m_Folder / "aorta.vtk";
  vr::WriteCenterlines(vr::ReadCenterlines(Centerlines()), vtk.string());
  const std::string whole = ReadText(vtk);
  for (const double fraction : { 0.2, 0.5, 0.9 })
  {
    const std::string truncated =
      Write("truncated.vtk", whole.substr(0, static_cast<std::size_t>(fraction * static_cast<double>(whole.size()))));
    ExpectRejected({ Volume(), truncated }, { "truncated.vtk" });
  }
  fs::remove(vtk);
  fs::remove(m_Folder / "truncated.vtk");
}

TEST_F(BadInputTest, LegacyVTKWithMiscountedPointsOrRadii)
{
  const std::string header = "# vtk DataFile Version 4.2\ncenterline\nASCII\nDATASET POLYDATA\n";
  // Ten points declared, three given.
  const std::string fewPoints =
    Write("few-points.vtk", header + "POINTS 10 float\n0 0 0 0 0 10 0 0 20\nLINES 1 4\n3 0 1 2\n");
  ExpectRejected({ Volume(), fewPoints }, { "few-points.vtk" });
  // Three radii declared, one given: VTK warns and leaves the others uninitialised.
  const std::string fewRadii = Write("few-radii.vtk",
                                     header + "POINTS 3 float\n0 0 0 0 0 10 0 0 20\nLINES 1 4\n3 0 1 2\n" +
                                       "POINT_DATA 3\nSCALARS Radius float 1\nLOOKUP_TABLE default\n2.0\n");
  ExpectRejected({ Volume(), fewRadii }, { "few-radii.vtk" });
  // A version no VTK writer writes: VTK 9.1's reader read past its stream on "51" (a fuzzer's find).
  const std::string laterVersion = Write("version-51.vtk",
                                         "# vtk DataFile Version 51\ncenterline\nASCII\nDATASET POLYDATA\n"
                                         "POINTS 3 float\n0 0 0 0 0 10 0 0 20\nLINES 1 4\n3 0 1 2\n");
  ExpectRejected({ Volume(), laterVersion }, { "version-51.vtk", "version" });
  // A line of 1000 points in a file of three.
  const std::string longLine =
    Write("long-line.vtk", header + "POINTS 3 float\n0 0 0 0 0 10 0 0 20\nLINES 1 4\n1000 0 1 2\n");
  ExpectRejected({ Volume(), longLine }, { "long-line.vtk" });
}

TEST_F(BadInputTest, VTPWithOffsetsOrConnectivityOutsideItsArrays)
{
  const auto vtp = [](const std::string & connectivity, const std::string & offsets)
  {
    return "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"1.0\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt64\">\n<PolyData>\n<Piece NumberOfPoints=\"3\" NumberOfVerts=\"0\" NumberOfLines=\"1\" "
           "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n<Points>\n<DataArray type=\"Float32\" NumberOfComponents=\"3\" "
           "format=\"ascii\">0 0 0 0 0 10 0 0 20</DataArray>\n</Points>\n<Lines>\n<DataArray type=\"Int64\" "
           "Name=\"connectivity\" format=\"ascii\">" +
           connectivity + "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">" + offsets +
           "</DataArray>\n</Lines>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  };
  ExpectRejected({ Volume(), Write("offsets.vtp", vtp("0 1 2", "1000000")) }, { "offsets.vtp" });
  ExpectRejected({ Volume(), Write("negative-offsets.vtp", vtp("0 1 2", "-5")) }, { "negative-offsets.vtp" });
  ExpectRejected({ Volume(), Write("connectivity.vtp", vtp("0 1 99", "3")) }, { "connectivity.vtp", "99" });
}

// Issue 25: the files fresh fuzzing found (kept in Testing/Fuzz/corpus, replayed there too), given as users would
// give them: two legacy .vtk files that crashed VTK 9.1's reader (two LINES sections around a METADATA block) and a
// .vtp whose offset of 8e18 ran VTK out of memory. Refused by name, with no VTK text of their own on stderr.
TEST_F(BadInputTest, CenterlineFilesFromFuzzing)
{
  const fs::path corpus(VR_FUZZ_CORPUS_DIR);
  const struct
  {
    fs::path    File;
    std::string Mention;
  } cases[] = {
    { corpus / "vtk" / "crash-two-lines-sections.vtk", "METADATA: \"LINES 1 4\" is neither" },
    { corpus / "vtk" / "crash-metadata-lines-segv-2.vtk", "METADATA: \"LINES 1 4\" is neither" },
    { corpus / "vtp" / "crash-ascii-offsets-huge.vtp", "the offsets array of Lines: the last offset is" },
  };
  for (const auto & c : cases)
  {
    ExpectRejected({ Volume(), c.File.string() }, { "centerline file " + c.File.string() + ": ", c.Mention });
    const RunResult result =
      RunProgram({ ReformationExecutable, Volume(), c.File.string(), (m_Folder / "cpr.nrrd").string() });
    for (const std::string raw : { "ERR|", "ERROR: In ", "Warning: In ", "out of memory" })
    {
      EXPECT_FALSE(Contains(result.Err, raw)) << result.Err;
    }
    // In the host's process, as 3D Slicer runs the module's library: an error, not the end of the host.
    const RunResult library = RunInProcess(
      ReformationLibrary, { "VesselReformation", Volume(), c.File.string(), (m_Folder / "cpr.nrrd").string() });
    EXPECT_EQ(library.ExitCode, 1) << library.Err;
    EXPECT_TRUE(Contains(library.Err, "centerline file " + c.File.string() + ": ")) << library.Err;
    EXPECT_EQ(ReadText(m_Folder / "cpr.nrrd"), "an earlier result that must survive");
  }
}

// Issue 25, fifth fuzzing round: a MetaImage header with NDims = -3 made MetaIO read 2^64 numbers for DimSize, and the
// module never returned. The fuzzer's file (its first byte picked the harness's extension), as a user's volume: refused
// by name and line, by the program and in the host's process.
TEST_F(BadInputTest, MetaImageVolumeWithNegativeDimensionsFromFuzzing)
{
  const std::string bytes =
    ReadText(fs::path(VR_FUZZ_CORPUS_DIR) / "volume" / "crash-metaimage-negative-ndims-hang").substr(1);
  const std::string mha = Write("hang.mha", bytes);
  ExpectRejected({ mha, Centerlines() }, { "volume " + mha + ": MetaImage header line 2: NDims = -3: must be" });
  const RunResult library =
    RunInProcess(ReformationLibrary, { "VesselReformation", mha, Centerlines(), (m_Folder / "cpr.nrrd").string() });
  EXPECT_EQ(library.ExitCode, 1) << library.Err;
  EXPECT_TRUE(Contains(library.Err, "NDims = -3")) << library.Err;
  EXPECT_EQ(ReadText(m_Folder / "cpr.nrrd"), "an earlier result that must survive");
  fs::remove(mha);
}

TEST_F(BadInputTest, VTPWhoseBinaryHeadersDeclareMoreThanTheFileHolds)
{
  // VTK 9.1 allocates what a binary array's size header declares before reading it (fuzzing found a compressed
  // header asking for 2.6 GB). Headers written by hand: base64 of little-endian UInt32 words.
  const auto vtp = [](const std::string & compressor, const std::string & radii)
  {
    return "<?xml version=\"1.0\"?>\n<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt32\"" +
           compressor +
           ">\n<PolyData>\n<Piece NumberOfPoints=\"3\" NumberOfVerts=\"0\" NumberOfLines=\"1\" "
           "NumberOfStrips=\"0\" NumberOfPolys=\"0\">\n<PointData>\n<DataArray type=\"Float64\" Name=\"Radius\" "
           "format=\"binary\">" +
           radii +
           "</DataArray>\n</PointData>\n<Points>\n<DataArray type=\"Float32\" NumberOfComponents=\"3\" "
           "format=\"ascii\">0 0 0 0 0 10 0 0 20</DataArray>\n</Points>\n<Lines>\n<DataArray type=\"Int64\" "
           "Name=\"connectivity\" format=\"ascii\">0 1 2</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" "
           "format=\"ascii\">3</DataArray>\n</Lines>\n</Piece>\n</PolyData>\n</VTKFile>\n";
  };
  // Uncompressed: one word, 0x10000000 bytes (256 MiB), then 4 bytes: "AAAAEAAAAAA=".
  ExpectRejected({ Volume(), Write("uncompressed.vtp", vtp("", "AAAAEAAAAAA=")) }, { "uncompressed.vtp", "declares" });
  // Compressed: 1 block of 0x9C000000 bytes (2.6 GB), last block 0, compressed size 16: "AQAAAAAAAJwAAAAAEAAAAA==".
  ExpectRejected(
    { Volume(), Write("compressed.vtp", vtp(" compressor=\"vtkZLibDataCompressor\"", "AQAAAAAAAJwAAAAAEAAAAA==")) },
    { "compressed.vtp", "declares" });
}

TEST_F(BadInputTest, TubeFileDeclaringTwoBillionPoints)
{
  const std::string tre = Write("huge.tre",
                                "ObjectType = Scene\nNDims = 3\nNObjects = 1\nObjectType = Tube\nNDims = 3\nID = 1\n"
                                "ParentID = -1\nPointDim = 4 x y z r\nNPoints = 2000000000\nPoints = \n0 0 0 1\n");
  ExpectRejected({ Volume(), tre }, { "huge.tre", "NPoints", "2000000000" });
  const std::string dims = Write("dims.tre",
                                 "ObjectType = Scene\nNDims = 3\nNObjects = 1\nObjectType = Tube\nNDims = 200\nID = 1\n"
                                 "ParentID = -1\nPointDim = 4 x y z r\nNPoints = 1\nPoints = \n0 0 0 1\n");
  ExpectRejected({ Volume(), dims }, { "dims.tre", "NDims" });
  // A field with nothing after its "=": MetaIO's scene reader throws a standard exception on it and leaks what it had
  // read (a fuzzer's find).
  const std::string bare = Write("bare.tre",
                                 "ObjectType = Scene\nNDims = 3\nNObjects = 1\nObjectType = Tube\nNDims =\nID = 1\n"
                                 "ParentID = -1\nPointDim = 4 x y z r\nNPoints = 1\nPoints = \n0 0 0 1\n");
  ExpectRejected({ Volume(), bare }, { "bare.tre", "no value" });
  // A PointDim longer than MetaIO's fixed field, which it then reads past (a fuzzer's find).
  const std::string wide = Write("wide.tre",
                                 "ObjectType = Scene\nNDims = 3\nNObjects = 1\nObjectType = Tube\nNDims = 3\nID = 1\n"
                                 "ParentID = -1\nPointDim = x y z r" +
                                   std::string(300, 'q') + "\nNPoints = 1\nPoints = \n0 0 0 1\n");
  ExpectRejected({ Volume(), wide }, { "wide.tre", "200 characters" });
  // A scene declaring more objects than it holds: MetaIO's scene reader fails part-way and leaks (a fuzzer's find).
  const std::string short_ = Write("short.tre",
                                   "ObjectType = Scene\nNDims = 3\nNObjects = 4\nObjectType = Tube\nNDims = 3\nID = 1\n"
                                   "ParentID = -1\nPointDim = x y z r\nNPoints = 1\nPoints = \n0.5 0.5 0.5 1.5\n");
  ExpectRejected({ Volume(), short_ }, { "short.tre", "NObjects = 4" });
  // A PointDim with a run of spaces: MetaIO counts it as more than one separator and then reads its array's unset last
  // entries (the sixth fuzzing round's find, a wild pointer in MetaTube::M_Read); and a field name longer than the 80
  // bytes MetaIO copies it into.
  const auto tube = [](const std::string & pointDim)
  {
    return "ObjectType = Scene\nNDims = 3\nNObjects = 1\nObjectType = Tube\nNDims = 3\nID = 1\nParentID = -1\n"
           "PointDim = " +
           pointDim + "\nNPoints = 1\nPoints = \n0.5 0.5 0.5 1.5\n";
  };
  ExpectRejected({ Volume(), Write("spaces.tre", tube("x y    z r")) },
                 { "spaces.tre", "PointDim = x y    z r: must be field names separated by single spaces" });
  ExpectRejected({ Volume(), Write("word.tre", tube("x y z " + std::string(80, 'r'))) },
                 { "word.tre", "each of at most 79 characters" });
  ExpectRejected({ Volume(), Write("tab.tre", tube("x y\tz r")) }, { "tab.tre", "PointDim" });
  const std::string found =
    Write("found.tre", ReadText(fs::path(VR_FUZZ_CORPUS_DIR) / "tre" / "crash-pointdim-space-run-wild-pointer"));
  ExpectRejected({ Volume(), found },
                 { "centerline file " + found + ": object 4 (Tube): PointDim = id x y z red green " });
}

TEST_F(BadInputTest, MarkupsNestedAHundredThousandDeep)
{
  const std::string json =
    Write("deep.mrk.json", "{\"markups\": " + std::string(100000, '[') + std::string(100000, ']') + "}");
  ExpectRejected({ Volume(), json }, { "deep.mrk.json", "nest" });
}

TEST_F(BadInputTest, TruncatedMetaImage)
{
  const std::string whole = ReadText(DataFolder / "aorta.mha");
  const std::string mha = Write("truncated.mha", whole.substr(0, whole.size() / 2));
  ExpectRejected({ mha, Centerlines() }, { "truncated.mha", "truncated" });
}

TEST_F(BadInputTest, VolumeWithANaNVoxel)
{
  const std::string volume = WriteSmallVolume(m_Folder / "nan.nrrd",
                                              [](vr::VolumeImageType * image) {
                                                image->SetPixel({ { 3, 4, 5 } }, std::nanf(""));
                                              });
  ExpectRejected({ volume, Centerlines() }, { "nan.nrrd", "(3, 4, 5)", "nan" });
}

TEST_F(BadInputTest, NIfTIWithANonFiniteOrientation)
{
  // ITK 5.2's NIfTI reader hands the sform to vnl's SVD, which aborts the process on NaN (a fuzzer's find). NIfTI-1:
  // srow_x[0] is the float at byte 280 of the 348-byte header.
  const fs::path nii = m_Folder / "orientation.nii";
  WriteSmallVolume(nii);
  std::string bytes = ReadText(nii);
  ASSERT_GT(bytes.size(), 348u);
  const float nan = std::nanf("");
  std::memcpy(&bytes[280], &nan, sizeof(nan));
  const std::string patched = Write("orientation.nii", bytes);
  ExpectRejected({ patched, Centerlines() }, { "orientation.nii", "srow_x" });
}

TEST_F(BadInputTest, FuzzFindingsInNIfTIHeaders)
{
  // sizeof_hdr is garbage (the NIfTI library ignores it when dim[0] is valid) and srow_x holds NaN, which made ITK
  // 5.2's reader abort in vnl's SVD (issue 25); the second has a NIfTI-2 magic in a NIfTI-1 layout.
  for (const char * name : { "nifti-nan-srow-abort.nii", "nifti-nan-srow-abort-2.nii" })
  {
    const RunResult run = ExpectRejected({ std::string(VR_FINDINGS_DIR) + "/" + name, Centerlines() },
                                         { name, "NIfTI header field sizeof_hdr" });
    EXPECT_EQ(std::count(run.Err.begin(), run.Err.end(), '\n'), 1) << "only the module's message:\n" << run.Err;
  }
}

/** Checks that \a err holds the module's error alone: its line, and the lines of a list of series after it. */
void
ExpectOnlyTheModulesMessage(const std::string & err)
{
  std::istringstream lines(err);
  std::string        line;
  ASSERT_TRUE(std::getline(lines, line));
  EXPECT_EQ(line.rfind("VesselReformation: error: ", 0), 0u) << err;
  while (std::getline(lines, line))
  {
    EXPECT_TRUE(line.size() > 3 && line.rfind("  ", 0) == 0 && std::isdigit(static_cast<unsigned char>(line[2])))
      << "only the module's message (and its list of series):\n"
      << err;
  }
}

/** Checks that a DICOM folder was read: no error of the reader's (a later error, the centerlines', may follow). */
void
ExpectTheSeriesRead(const std::string & err)
{
  EXPECT_FALSE(Contains(err, "DICOM file")) << err;
  EXPECT_FALSE(Contains(err, "DICOM series")) << err;
  EXPECT_FALSE(Contains(err, "error: volume folder")) << err;
}

/** Writes a 6 x 5 x \a slices series of short slices with ITK's GDCM IO into \a folder, as ITK's DICOM examples do,
 * slice z at (0, 0, 2z) mm, or at \a position(z) where that is not empty. */
void
WriteDICOMSeries(const fs::path &                                   folder,
                 unsigned int                                       slices = 4,
                 const std::function<std::string(unsigned int z)> & position = {})
{
  using Volume = itk::Image<short, 3>;
  using Slice = itk::Image<short, 2>;
  auto volume = Volume::New();
  volume->SetRegions(Volume::RegionType({ { 0, 0, 0 } }, { { 6, 5, slices } }));
  volume->SetSpacing(itk::Vector<double, 3>(2.0));
  volume->Allocate(true);
  fs::create_directories(folder);
  std::vector<std::unique_ptr<itk::MetaDataDictionary>> owned;
  std::vector<itk::MetaDataDictionary *>                dictionaries;
  std::vector<std::string>                              names;
  for (unsigned int z = 0; z < slices; ++z)
  {
    auto              dictionary = std::make_unique<itk::MetaDataDictionary>();
    const std::string at = position ? position(z) : std::string();
    itk::EncapsulateMetaData<std::string>(*dictionary, "0020|000e", "1.2.826.0.1.3680043.2.1125.9.1");
    itk::EncapsulateMetaData<std::string>(*dictionary, "0020|0013", std::to_string(z + 1));
    itk::EncapsulateMetaData<std::string>(*dictionary, "0020|0032", at.empty() ? "0\\0\\" + std::to_string(2 * z) : at);
    itk::EncapsulateMetaData<std::string>(*dictionary, "0020|0037", "1\\0\\0\\0\\1\\0");
    dictionaries.push_back(dictionary.get());
    owned.push_back(std::move(dictionary));
    names.push_back((folder / ("slice" + std::to_string(z + 1) + ".dcm")).string());
  }
  auto io = itk::GDCMImageIO::New();
  io->KeepOriginalUIDOn();
  auto writer = itk::ImageSeriesWriter<Volume, Slice>::New();
  writer->SetInput(volume);
  writer->SetImageIO(io);
  writer->SetFileNames(names);
  writer->SetMetaDataDictionaryArray(&dictionaries);
  writer->Update();
}

TEST_F(BadInputTest, FuzzFindingsInDICOMSeries)
{
  // Files of a DICOM series that made Debian's GDCM assert, i.e. abort the process (issue 25). Alone, dropped into a
  // good series, or named like a volume file: refused, naming the file, with no GDCM or ITK line on the terminal.
  const fs::path good = m_Folder / "series";
  WriteDICOMSeries(good);
  for (const char * finding : { "dicom-meta-explicit-assert/IM0018.dcm",
                                "dicom-meta-implicit-assert/IM0009.dcm",
                                "dicom-samples-per-pixel-assert/IM0017.dcm",
                                "dicom-truncated-assert/IM0011.dcm",
                                "dicom-bits-allocated-unhandled/IM0030.dcm",
                                "dicom-acr-nema-assert/IM0027.dcm",
                                // The mutation campaign's: a position GDCM reads leniently as another number, which
                                // displaced the volume with no file named (vrDICOMSliceGeometry.h).
                                "dicom-position-byte-9f/IM0019.dcm",
                                "dicom-position-byte-ff/IM0003.dcm",
                                "dicom-position-dot-became-backslash/IM0024.dcm",
                                // With it in its series, GDCM's sort fell back to instance numbers and crashed.
                                "dicom-position-sort-crash/IM0014.dcm" })
  {
    const fs::path    file = fs::path(VR_FINDINGS_DIR) / finding;
    const std::string name = file.filename().string();
    {
      const RunResult run =
        ExpectRejected({ file.parent_path().string(), Centerlines() }, { "the DICOM file " + file.string() });
      EXPECT_EQ(std::count(run.Err.begin(), run.Err.end(), '\n'), 1) << "only the module's message:\n" << run.Err;
    }

    // In a good series: nothing read, and the file named (refused, or GDCM died on it, or, as it belongs to another
    // series than the good one's, listed as a second series of one file).
    if (std::string(finding).find("assert") != std::string::npos)
    {
      const fs::path mixed = m_Folder / ("mixed-" + name);
      fs::create_directories(mixed);
      for (const auto & entry : fs::directory_iterator(good))
      {
        fs::copy_file(entry.path(), mixed / entry.path().filename());
      }
      fs::copy_file(file, mixed / name);
      const RunResult run = ExpectRejected({ mixed.string(), Centerlines() }, { (mixed / name).string() });
      EXPECT_TRUE(Contains(run.Err, "is not read") || Contains(run.Err, "(nothing was read)")) << run.Err;
      ExpectOnlyTheModulesMessage(run.Err);
    }

    const fs::path named = m_Folder / ("scan-" + name + ".nrrd");
    fs::copy_file(file, named);
    {
      const RunResult run = ExpectRejected({ named.string(), Centerlines() }, { named.string() });
      EXPECT_EQ(std::count(run.Err.begin(), run.Err.end(), '\n'), 1) << "only the module's message:\n" << run.Err;
    }
  }
  // The good series itself is read (and then fails for want of overlap with the aorta's centerlines, not for DICOM).
  const RunResult run =
    RunProgram({ ReformationExecutable, good.string(), Centerlines(), (m_Folder / "ok.nrrd").string() });
  EXPECT_FALSE(run.Crashed);
  ExpectTheSeriesRead(run.Err);
  EXPECT_FALSE(Contains(run.Err, "GDCM")) << run.Err;
}

// Issue 25, sixth fuzzing round: a one-file folder (the dicom harness's input: each file a 4-byte little-endian length
// and its bytes) on which GDCM asserted (gdcmAttribute.h:445) while it sorted the folder's files into series, and the
// message named the folder only. Since issue 37 the reader process reads the attributes itself and GDCM sorts nothing:
// the file is refused by its own fault (a Rescale Intercept without a Rescale Slope), named. Alone and in a good
// series, by the program and in the host's process.
TEST_F(BadInputTest, DICOMFileOnWhichGDCMsSeriesSortAsserts)
{
  const std::string packed = ReadText(fs::path(VR_FUZZ_CORPUS_DIR) / "dicom" / "crash-gdcm-sort-attribute-assert");
  ASSERT_GE(packed.size(), 4u);
  const std::size_t length = static_cast<unsigned char>(packed[0]) | (static_cast<unsigned char>(packed[1]) << 8) |
                             (static_cast<unsigned char>(packed[2]) << 16) |
                             (std::size_t{ static_cast<unsigned char>(packed[3]) } << 24);
  ASSERT_EQ(length + 4, packed.size()) << "one file in the finding";
  const fs::path alone = m_Folder / "sort-assert";
  fs::create_directories(alone);
  const std::string file = (alone / "IM0001.dcm").string();
  Write("sort-assert/IM0001.dcm", packed.substr(4));
  {
    const RunResult run = ExpectRejected({ alone.string(), Centerlines() }, { "the DICOM file " + file, "not read" });
    EXPECT_EQ(std::count(run.Err.begin(), run.Err.end(), '\n'), 1) << "only the module's message:\n" << run.Err;
  }
  const RunResult library = RunInProcess(
    ReformationLibrary, { "VesselReformation", alone.string(), Centerlines(), (m_Folder / "cpr.nrrd").string() });
  EXPECT_EQ(library.ExitCode, 1) << library.Err;
  EXPECT_TRUE(Contains(library.Err, "the DICOM file " + file)) << library.Err;
  EXPECT_EQ(ReadText(m_Folder / "cpr.nrrd"), "an earlier result that must survive");

  const fs::path mixed = m_Folder / "series-with-sort-assert";
  WriteDICOMSeries(mixed);
  fs::copy_file(file, mixed / "IM0001.dcm");
  ExpectRejected({ mixed.string(), Centerlines() }, { (mixed / "IM0001.dcm").string() });
}

// Issue 25, the DICOM mutation campaign: a file whose position GDCM read as another number moved the whole volume,
// and the module said only that the centerlines lie outside it. A file off the series' line of slices (5 mm aside in
// the plane, a valid number) is named; ITK takes the origin from the first file, so that one too.
TEST_F(BadInputTest, DICOMSeriesWithAFileOffItsLineOfSlices)
{
  for (const unsigned int off : { 3u, 0u })
  {
    const fs::path folder = m_Folder / ("off-line-" + std::to_string(off));
    WriteDICOMSeries(
      folder, 8, [off](unsigned int z) { return (z == off ? "5\\0\\" : "0\\0\\") + std::to_string(2 * z); });
    const std::string file = (folder / ("slice" + std::to_string(off + 1) + ".dcm")).string();
    const RunResult   run =
      ExpectRejected({ folder.string(), Centerlines() },
                     { "the DICOM file " + file + " lies off the series' line of slices", "the series is not read" });
    EXPECT_EQ(std::count(run.Err.begin(), run.Err.end(), '\n'), 1) << "only the module's message:\n" << run.Err;
  }
  // The same series in line is read (and then fails for want of overlap with the aorta's centerlines, not for DICOM).
  const fs::path good = m_Folder / "in-line";
  WriteDICOMSeries(good, 8);
  const RunResult run =
    RunProgram({ ReformationExecutable, good.string(), Centerlines(), (m_Folder / "ok.nrrd").string() });
  ExpectTheSeriesRead(run.Err);
}

TEST_F(BadInputTest, APNGNamedLikeAVolume)
{
  // ITK picks its reader by content: a PNG named .nrrd would reach libpng, whose default error handler (ITK 5.2's
  // PNG reader sets no other) aborts the process on a corrupt file (a fuzzer's find). Only NRRD, NIfTI, MetaImage
  // and DICOM are read as volumes.
  using Slice = itk::Image<unsigned char, 2>;
  auto slice = Slice::New();
  slice->SetRegions(Slice::RegionType({ { 0, 0 } }, { { 8, 8 } }));
  slice->Allocate(true);
  auto writer = itk::ImageFileWriter<Slice>::New();
  writer->SetInput(slice);
  writer->SetFileName((m_Folder / "slice.png").string());
  writer->Update();
  const std::string png = ReadText(m_Folder / "slice.png");
  fs::remove(m_Folder / "slice.png");
  const std::string named = Write("scan.nrrd", png.substr(0, png.size() / 2));
  ExpectRejected({ named, Centerlines() }, { "scan.nrrd", "PNG" });
}

TEST_F(BadInputTest, FourDimensionalVolume)
{
  using Image4D = itk::Image<float, 4>;
  auto image = Image4D::New();
  image->SetRegions(Image4D::RegionType({ { 0, 0, 0, 0 } }, { { 6, 5, 4, 3 } }));
  image->Allocate(true);
  auto writer = itk::ImageFileWriter<Image4D>::New();
  writer->SetInput(image);
  writer->SetFileName((m_Folder / "series.nrrd").string());
  writer->Update();
  ExpectRejected({ (m_Folder / "series.nrrd").string(), Centerlines() }, { "series.nrrd", "4D", "6 x 5 x 4 x 3" });
}

TEST_F(BadInputTest, NamedPipesFailWithinSecondsInsteadOfHanging)
{
  ASSERT_EQ(::mkfifo((m_Folder / "pipe.mha").c_str(), 0600), 0);
  ASSERT_EQ(::mkfifo((m_Folder / "pipe.vtp").c_str(), 0600), 0);
  const auto start = std::chrono::steady_clock::now();
  ExpectRejected({ (m_Folder / "pipe.mha").string(), Centerlines() }, { "pipe.mha", "named pipe" });
  ExpectRejected({ Volume(), (m_Folder / "pipe.vtp").string() }, { "pipe.vtp", "named pipe" });
  // A detached MetaImage header whose data file is the pipe.
  const std::string header = Write("detached.mhd",
                                   "ObjectType = Image\nNDims = 3\nDimSize = 2 2 2\nElementType = MET_FLOAT\n"
                                   "ElementDataFile = pipe.mha\n");
  ExpectRejected({ header, Centerlines() }, { "detached.mhd", "pipe.mha", "named pipe" });
  // A pipe nobody writes blocks a reader forever; three refusals take a second or two, and up to 20 s in a sanitizer
  // build on a loaded machine, so the bound tells a hang from a slow run with room to spare.
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 60.0);
}

TEST_F(BadInputTest, CenterlineCoordinatesOf1e30)
{
  const std::string csv = Write("far.csv", "branch,x,y,z\n1,0,0,0\n1,1e30,0,0\n");
  ExpectRejected({ Volume(), csv }, { "far.csv", "1e+30" });
}

TEST_F(BadInputTest, PixelSpacingOf1eMinus300)
{
  ExpectRejected({ "--spacing", "1e-300", Volume(), Centerlines() }, { "--spacing", "1e-300" });
}

TEST_F(BadInputTest, ProcessInformationAddressIsRefusedByTheExecutable)
{
  ExpectRejected({ "--processinformationaddress", "0x1234", Volume(), Centerlines() },
                 { "--processinformationaddress" });
  ExpectRejected({ "--processinformationaddress=0x1234", Volume(), Centerlines() }, { "--processinformationaddress" });
}

/** Mounts a tmpfs of \a bytes at \a folder (read-only when \a readOnly); false when this process may not mount. */
bool
MountSmallFileSystem(const fs::path & folder, std::size_t bytes, bool readOnly)
{
  fs::create_directories(folder);
  const std::string options = "size=" + std::to_string(bytes);
  if (::mount("tmpfs", folder.c_str(), "tmpfs", 0, options.c_str()) != 0)
  {
    return false;
  }
  if (readOnly && ::mount("tmpfs", folder.c_str(), "tmpfs", MS_REMOUNT | MS_RDONLY, options.c_str()) != 0)
  {
    ::umount(folder.c_str());
    return false;
  }
  return true;
}

TEST_F(BadInputTest, ReadOnlyOutputFolder)
{
  const fs::path readOnly = m_Folder / "read-only";
  fs::create_directories(readOnly);
  bool mounted = false;
  if (::geteuid() == 0)
  {
    // Permissions do not stop root: a read-only file system does.
    mounted = MountSmallFileSystem(readOnly, 1 << 20, true);
    if (!mounted)
    {
      GTEST_SKIP() << "running as root without the right to mount a read-only tmpfs: cannot make a folder root may "
                      "not write";
    }
  }
  else
  {
    fs::permissions(readOnly, fs::perms::owner_read | fs::perms::owner_exec);
  }
  const std::string mask = (readOnly / "mask.nrrd").string();
  ExpectRejected({ "--outputMask", mask, Volume(), Centerlines() },
                 { "--outputMask", "read-only", "cannot be written" });
  EXPECT_TRUE(fs::is_empty(readOnly));
  if (mounted)
  {
    ::umount(readOnly.c_str());
  }
  fs::permissions(readOnly, fs::perms::owner_all);
  fs::remove(readOnly);
}

TEST_F(BadInputTest, FullDisk)
{
  // The outputs go to a file system of 16 KiB, which holds the earlier results but not the new CPR, its depth map and
  // its PNG at 256 x 512 pixels. Without the right to mount one, an injected write failure stands in: RLIMIT_FSIZE
  // makes every write past 4 KiB fail.
  const fs::path full = m_Folder / "full";
  const bool     mounted = MountSmallFileSystem(full, 16 << 10, false);
  fs::create_directories(full);
  WriteText(full / "cpr.nrrd", "an earlier result that must survive");
  WriteText(full / "cpr.png", "an earlier picture that must survive");
  const auto before = FilesIn(full);
  const auto beforeHere = FilesIn(m_Folder);
  RunLimits  limits;
  if (!mounted)
  {
    limits.FileSizeLimit = 4096;
  }
  // First every output on the full disk; then only the PNG (libpng's writer once aborted the process there), the
  // CPR beside the earlier one on a roomy disk.
  for (const bool onlyPNG : { false, true })
  {
    const fs::path  cprFolder = onlyPNG ? m_Folder : full;
    const RunResult result = RunProgram({ ReformationExecutable,
                                          "--iterations",
                                          "10",
                                          "--size",
                                          "256,512",
                                          "--outputPNG",
                                          (full / "cpr.png").string(),
                                          "--outputDepth",
                                          (cprFolder / "depth.nrrd").string(),
                                          Volume(),
                                          Centerlines(),
                                          (cprFolder / "cpr.nrrd").string() },
                                        limits);
    EXPECT_FALSE(result.Crashed) << result.Err;
    EXPECT_EQ(result.ExitCode, 1) << result.Err;
    EXPECT_TRUE(Contains(result.Err, "VesselReformation: error: ")) << result.Err;
    EXPECT_TRUE(Contains(result.Err, (full / "").string())) << "the message names no output file:\n" << result.Err;
    EXPECT_TRUE(!onlyPNG || Contains(result.Err, "cpr.png")) << result.Err;
    EXPECT_EQ(FilesIn(full), before) << "a file appeared or vanished";
    EXPECT_EQ(FilesIn(m_Folder), beforeHere) << "a file appeared or vanished";
    EXPECT_EQ(ReadText(full / "cpr.nrrd"), "an earlier result that must survive");
    EXPECT_EQ(ReadText(full / "cpr.png"), "an earlier picture that must survive");
    EXPECT_EQ(ReadText(m_Folder / "cpr.nrrd"), "an earlier result that must survive");
    std::cout << (mounted ? "16 KiB tmpfs" : "RLIMIT_FSIZE 4 KiB") << ": " << result.Err;
    if (!mounted)
    {
      break; // RLIMIT_FSIZE limits every file of the run, wherever it is
    }
  }
  if (mounted)
  {
    ::umount(full.c_str());
  }
}
} // namespace
