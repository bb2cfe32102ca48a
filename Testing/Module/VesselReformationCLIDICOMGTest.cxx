// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// A DICOM series read by the VesselReformation module as it was acquired, or refused by name (issue 37,
// docs/dicom-series.md). The series are written byte by byte (vrDICOMTestSeries.h, no GDCM) from the thoracic phantom
// rounded to whole HU; its NRRD and NIfTI copies give the reference CPR. A sound series, head or feet first, with one
// rescale for all files or one for each, gives their CPR; each fault gives its documented result, naming the files:
// read with a warning (a missing slice, interpolated; a duplicate, left out), read the same (Slice Thickness changed,
// stray files skipped with a note), or refused with nothing written (a second series, one file of another size or
// pixel format, short pixel data, a false transfer syntax, a non-finite rescale, a tilted gantry).
#include "itkCPRViewGeometry.h"
#include "itkCTAPhantom.h"
#include "vrCenterlineIO.h"
#include "vrDICOMCampaign.h"
#include "vrDICOMTestSeries.h"
#include "vrImageIO.h"
#include "vrModuleRuns.h"
#include "vrTestFiles.h"
#include "vrVolumeIO.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <set>
#include <sstream>

namespace
{
namespace fs = std::filesystem;
using namespace vr::test;

constexpr const char * Earlier = "an earlier result that must survive";

/** The phantom, its centerlines and the reference CPR, made once for the suite. */
struct Scene
{
  vr::VolumeImageType::Pointer Volume;
  fs::path                     Folder;
  std::string                  Centerlines;
  std::vector<std::string>     ViewArguments{ "--size", "96,192", "--iterations", "30", "--angle", "30" };
};

const Scene &
TheScene()
{
  static const Scene scene = []
  {
    Scene made;
    // A folder for this process: CTest runs each test in one, several at a time.
    const auto * test = ::testing::UnitTest::GetInstance()->current_test_info();
    made.Folder = fs::path(VR_TEST_OUTPUT_DIR) / test->name();
    fs::remove_all(made.Folder);
    fs::create_directories(made.Folder);
    auto phantom = itk::MakeCTAPhantom(itk::CTAPhantomKind::Thorax, 3.0);
    phantom.Source->Update();
    made.Volume = QuantizedCT(phantom.Source->GetOutput());
    made.Centerlines = (made.Folder / "centerlines.vtp").string();
    vr::WriteCenterlines(phantom.Tree, made.Centerlines);
    return made;
  }();
  return scene;
}

struct ModuleResult
{
  ModuleRun                          Module;
  std::map<std::string, std::string> Returned;
  fs::path                           Output;
};

/** Runs VesselReformation on \a volume into a fresh folder holding an earlier cpr.nrrd, returning its values. */
ModuleResult
RunModule(const std::string & volume, const std::string & name, const std::vector<std::string> & extra = {})
{
  const Scene &  scene = TheScene();
  const fs::path folder = scene.Folder / ("out-" + name);
  fs::remove_all(folder);
  fs::create_directories(folder);
  {
    std::ofstream(folder / "cpr.nrrd") << Earlier;
  }
  std::vector<std::string> arguments{ VR_REFORMATION_EXE,      volume,
                                      scene.Centerlines,       (folder / "cpr.nrrd").string(),
                                      "--returnparameterfile", (folder / "returned.txt").string() };
  arguments.insert(arguments.end(), scene.ViewArguments.begin(), scene.ViewArguments.end());
  arguments.insert(arguments.end(), extra.begin(), extra.end());
  ModuleResult run;
  run.Module = RunProgram(arguments, 300.0);
  run.Output = folder / "cpr.nrrd";
  std::ifstream returned(folder / "returned.txt");
  for (std::string line; std::getline(returned, line);)
  {
    const auto equals = line.find(" = ");
    if (equals != std::string::npos)
    {
      run.Returned[line.substr(0, equals)] = line.substr(equals + 3);
    }
  }
  std::cout << "exit " << run.Module.ExitCode << ", stderr:\n" << run.Module.Err << std::endl;
  return run;
}

/** The CPR of the phantom written as \a extension (.nrrd, .nii): the reference. */
const vr::DepthImageType::Pointer &
ReferenceCPR(const std::string & extension = ".nrrd")
{
  static std::map<std::string, vr::DepthImageType::Pointer> references;
  auto &                                                    reference = references[extension];
  if (!reference)
  {
    const std::string volume = (TheScene().Folder / ("phantom" + extension)).string();
    vr::WriteVolume(TheScene().Volume, volume);
    const ModuleResult run = RunModule(volume, "reference" + extension);
    EXPECT_EQ(run.Module.ExitCode, 0) << run.Module.Err;
    reference = vr::ReadDepthImage(run.Output.string());
  }
  return reference;
}

/** The largest difference between two CPRs of one size (infinite for two sizes). */
double
LargestDifference(const vr::DepthImageType * a, const vr::DepthImageType * b)
{
  if (a->GetLargestPossibleRegion() != b->GetLargestPossibleRegion())
  {
    return INFINITY;
  }
  double largest = 0.0;
  for (std::size_t k = 0; k < a->GetLargestPossibleRegion().GetNumberOfPixels(); ++k)
  {
    largest = std::max(largest, std::abs(static_cast<double>(a->GetBufferPointer()[k]) - b->GetBufferPointer()[k]));
  }
  return largest;
}

/** The sound series as MakeCTSeries writes it, changed by \a change, in a folder of its own. */
std::string
WriteSeries(const std::string &                                       name,
            const std::function<void(std::vector<DICOMTestFile> &)> & change = {},
            const CTSeriesOptions &                                   options = CTSeriesOptions())
{
  std::vector<DICOMTestFile> files = MakeCTSeries(TheScene().Volume, options);
  if (change)
  {
    change(files);
  }
  const fs::path folder = TheScene().Folder / name;
  fs::remove_all(folder);
  WriteDICOMTestFolder(folder.string(), files);
  return folder.string();
}

/** The file named \a name of \a files. */
DICOMTestFile &
Named(std::vector<DICOMTestFile> & files, const std::string & name)
{
  for (auto & file : files)
  {
    if (file.Name == name)
    {
      return file;
    }
  }
  throw std::logic_error("no file " + name);
}

/** Expects a refusal: exit 1, every one of \a mentions in the message, the earlier output kept and nothing beside. */
void
ExpectRefused(const ModuleResult & run, const std::vector<std::string> & mentions)
{
  EXPECT_FALSE(run.Module.Crashed);
  EXPECT_EQ(run.Module.ExitCode, 1) << run.Module.Err;
  for (const std::string & mention : mentions)
  {
    EXPECT_TRUE(Contains(run.Module.Err, mention)) << "the message lacks \"" << mention << "\":\n" << run.Module.Err;
  }
  EXPECT_TRUE(Contains(run.Module.Err, "VesselReformation: error: volume folder ") ||
              Contains(run.Module.Err, "VesselReformation: error: --series: volume folder "))
    << run.Module.Err;
  EXPECT_EQ(ReadTextFile(run.Output.string()), Earlier);
  std::set<std::string> beside;
  for (const auto & entry : fs::directory_iterator(run.Output.parent_path()))
  {
    beside.insert(entry.path().filename().string());
  }
  EXPECT_EQ(beside, std::set<std::string>{ "cpr.nrrd" }) << "a file appeared beside the earlier output";
}

/** Expects a read: exit 0, and the CPR of the reference within 1e-3 HU unless \a sameImage is false. */
void
ExpectRead(const ModuleResult & run, bool sameImage = true)
{
  ASSERT_FALSE(run.Module.Crashed);
  ASSERT_EQ(run.Module.ExitCode, 0) << run.Module.Err;
  if (sameImage)
  {
    EXPECT_LE(LargestDifference(vr::ReadDepthImage(run.Output.string()), ReferenceCPR()), 1e-3);
  }
}

std::string
InFolder(const std::string & folder, const std::string & name)
{
  return (fs::path(folder) / name).string();
}
} // namespace

TEST(DICOMSeriesModule, ASoundSeriesGivesTheCPROfTheSameVolumeAsNRRDAndNIfTI)
{
  // The two formats agree with each other first.
  ASSERT_LE(LargestDifference(ReferenceCPR(".nrrd"), ReferenceCPR(".nii")), 1e-3);
  struct Variant
  {
    std::string     Name;
    CTSeriesOptions Options;
  };
  // The series of one rescale are read in their stored type (uint16 with intercept -1024, int16, int16 with slope
  // 0.5) and sampled with the rescale applied per sample in double; those of a rescale per file as float intensities.
  // Against the float NRRD's CPR: 1e-3 HU, as everywhere in this suite: the phantom's values are whole HU (and their
  // doubles exact), so the two differ only by the order of rescale and interpolation in double (about 1e-12 HU) and
  // the CPR written as float (2^-24 of 3071 HU, 2e-4 HU); the volume read is equal to the phantom at every voxel.
  std::vector<Variant> variants(7);
  variants[0].Name = "head-first";
  variants[1].Name = "feet-first";
  variants[1].Options.FeetFirst = true;
  variants[2].Name = "rescale-per-file";
  variants[2].Options.Rescale = [](unsigned int slice) -> std::pair<double, double> {
    return { slice % 3 == 0 ? 1.0 : slice % 3 == 1 ? 0.5 : 0.25, -1024.0 - static_cast<double>(slice % 7) };
  };
  variants[3].Name = "signed-feet-first-rescale-per-file";
  variants[3].Options.Signed = true;
  variants[3].Options.FeetFirst = true;
  variants[3].Options.Rescale = [](unsigned int slice) -> std::pair<double, double> {
    return { slice % 2 == 0 ? 0.25 : 1.0, static_cast<double>(slice % 5) - 2.0 };
  };
  variants[4].Name = "implicit-vr";
  variants[4].Options.Encoding.ExplicitVR = false;
  variants[5].Name = "big-endian";
  variants[5].Options.Encoding.BigEndian = true;
  variants[6].Name = "signed-one-rescale-slope-0.5";
  variants[6].Options.Signed = true;
  variants[6].Options.Rescale = [](unsigned int) { return std::pair<double, double>(0.5, -3.0); };
  for (const Variant & variant : variants)
  {
    SCOPED_TRACE(variant.Name);
    const std::string  folder = WriteSeries(variant.Name, {}, variant.Options);
    const ModuleResult run = RunModule(folder, variant.Name);
    ASSERT_EQ(run.Module.ExitCode, 0) << run.Module.Err;
    EXPECT_FALSE(Contains(run.Module.Err, "warning")) << run.Module.Err;
    EXPECT_EQ(run.Returned.at("inputWarnings"), "none");
    const auto   cpr = vr::ReadDepthImage(run.Output.string());
    const double fromNRRD = LargestDifference(cpr, ReferenceCPR(".nrrd"));
    const double fromNIfTI = LargestDifference(cpr, ReferenceCPR(".nii"));
    EXPECT_LE(fromNRRD, 1e-3);
    EXPECT_LE(fromNIfTI, 1e-3);
    std::cout << variant.Name << ": largest CPR difference " << fromNRRD << " HU from the NRRD's, " << fromNIfTI
              << " HU from the NIfTI's" << std::endl;
    // The volume itself, voxel by voxel at the same points (feet first: another index order, the same space).
    EXPECT_EQ(SlicesThatDiffer(vr::ReadVolume(folder), TheScene().Volume, 0.0), std::vector<unsigned int>());
  }
}

TEST(DICOMSeriesModule, AMissingSliceIsInterpolatedWithAWarningNamingTheGapTheFilesAndThePosition)
{
  // Head first, IMnnnn.dcm holds the volume's slice (slices - n): IM0020.dcm is slice 19, between IM0021 and IM0019.
  const Scene &      scene = TheScene();
  const unsigned int slices = static_cast<unsigned int>(scene.Volume->GetLargestPossibleRegion().GetSize()[2]);
  const unsigned int gap = slices - 20;
  const std::string  folder =
    WriteSeries("missing-slice",
                [](std::vector<DICOMTestFile> & files)
                {
                  files.erase(std::find_if(
                    files.begin(), files.end(), [](const auto & file) { return file.Name == "IM0020.dcm"; }));
                });
  const ModuleResult run = RunModule(folder, "missing-slice");
  ExpectRead(run, false);
  const double       z = scene.Volume->GetOrigin()[2] + gap * scene.Volume->GetSpacing()[2];
  std::ostringstream position;
  position << "the missing slice at (" << scene.Volume->GetOrigin()[0] << ", " << scene.Volume->GetOrigin()[1] << ", "
           << z << ") mm is interpolated linearly";
  for (const std::string & mention : { "warning: volume folder " + folder,
                                       "has a gap of 6 mm between the files " + InFolder(folder, "IM0021.dcm") +
                                         " and " + InFolder(folder, "IM0019.dcm"),
                                       position.str() })
  {
    EXPECT_TRUE(Contains(run.Module.Err, mention)) << mention;
    const std::string returned = mention.rfind("warning: ", 0) == 0 ? mention.substr(9) : mention;
    EXPECT_TRUE(Contains(run.Returned.at("inputWarnings"), returned)) << returned;
  }

  // The volume: every slice at its file's position with its pixels, the missing one halfway between its neighbours.
  vr::VolumeReadReport report;
  const auto           read = vr::ReadVolume(folder, vr::VolumeReadOptions(), &report);
  ASSERT_EQ(report.Warnings.size(), 1u);
  ASSERT_EQ(read->GetLargestPossibleRegion().GetSize(), scene.Volume->GetLargestPossibleRegion().GetSize());
  EXPECT_EQ(SlicesThatDiffer(read, scene.Volume, 0.0), std::vector<unsigned int>{ gap });
  for (unsigned int k = 0; k < slices; ++k)
  {
    vr::VolumeImageType::PointType point;
    read->TransformIndexToPhysicalPoint({ { 0, 0, k } }, point);
    EXPECT_NEAR(point[2], scene.Volume->GetOrigin()[2] + k * scene.Volume->GetSpacing()[2], 1e-9) << "slice " << k;
  }
  const auto size = read->GetLargestPossibleRegion().GetSize();
  for (unsigned int y = 0; y < size[1]; y += 7)
  {
    for (unsigned int x = 0; x < size[0]; x += 7)
    {
      const double below = scene.Volume->GetPixel({ { x, y, gap - 1 } });
      const double above = scene.Volume->GetPixel({ { x, y, gap + 1 } });
      EXPECT_FLOAT_EQ(read->GetPixel({ { x, y, gap } }), static_cast<float>(0.5 * (below + above)));
    }
  }

  // The CPR: the sound series' in every row farther than one slice from the gap (a row of an up = S view lies at one
  // height), another in some rows near it.
  const auto   cpr = vr::ReadDepthImage(run.Output.string());
  const auto & reference = ReferenceCPR();
  const auto   view = itk::CPRViewGeometry::ReadFromDictionary(cpr->GetMetaDataDictionary());
  const auto   width = cpr->GetLargestPossibleRegion().GetSize()[0];
  const auto   height = cpr->GetLargestPossibleRegion().GetSize()[1];
  std::size_t  nearRowsThatDiffer = 0;
  for (unsigned int row = 0; row < height; ++row)
  {
    const bool near = std::abs(view.PlanePoint(0.0, row)[2] - z) < scene.Volume->GetSpacing()[2];
    double     largest = 0.0;
    for (unsigned int column = 0; column < width; ++column)
    {
      largest = std::max(
        largest,
        std::abs(static_cast<double>(cpr->GetPixel({ { column, row } })) - reference->GetPixel({ { column, row } })));
    }
    if (near)
    {
      nearRowsThatDiffer += largest > 1e-3 ? 1 : 0;
    }
    else
    {
      EXPECT_LE(largest, 1e-3) << "row " << row << ", " << view.PlanePoint(0.0, row)[2] << " mm";
    }
  }
  EXPECT_GT(nearRowsThatDiffer, 0u) << "the gap's rows show the interpolation";
  std::cout << nearRowsThatDiffer << " rows within a slice of the gap differ from the sound series' CPR" << std::endl;
}

TEST(DICOMSeriesModule, ADuplicateFileIsLeftOutWithAWarningAndTheImageIsTheSame)
{
  const std::string  folder = WriteSeries("duplicate",
                                         [](std::vector<DICOMTestFile> & files)
                                         {
                                           DICOMTestFile copy = Named(files, "IM0030.dcm");
                                           copy.Name = "IM0030 (2).dcm";
                                           files.push_back(copy);
                                         });
  const ModuleResult run = RunModule(folder, "duplicate");
  ExpectRead(run);
  // The first by name is kept ("IM0030 (2).dcm" sorts before "IM0030.dcm"); either is the same image.
  const std::string said = "the DICOM file " + InFolder(folder, "IM0030.dcm") + " is a copy of " +
                           InFolder(folder, "IM0030 (2).dcm") + " (the same SOP Instance UID";
  EXPECT_TRUE(Contains(run.Module.Err, "warning: volume folder " + folder + ": " + said)) << run.Module.Err;
  EXPECT_TRUE(Contains(run.Returned.at("inputWarnings"), said));
}

TEST(DICOMSeriesModule, ASecondSeriesIsListedAndNothingIsReadUntilOneIsChosen)
{
  const std::string scoutUID = "1.2.826.0.1.3680043.9.7731.37.8";
  const std::string folder =
    WriteSeries("two-series",
                [&scoutUID](std::vector<DICOMTestFile> & files)
                {
                  for (int k = 1; k <= 2; ++k)
                  {
                    DICOMTestFile scout = files.front();
                    scout.Name = "scout" + std::to_string(k) + ".dcm";
                    scout.Values.assign(32 * 32, -1000.0);
                    scout.Data.SetUS(0x0028, 0x0010, 32);
                    scout.Data.SetUS(0x0028, 0x0011, 32);
                    scout.Data.SetText(0x0020, 0x000E, "UI", scoutUID);
                    scout.Data.SetText(0x0008, 0x0018, "UI", scoutUID + "." + std::to_string(k));
                    scout.Data.SetText(0x0008, 0x103E, "LO", "Topogram");
                    scout.Data.SetText(0x0020, 0x0011, "IS", "1");
                    files.push_back(scout);
                  }
                });
  const auto & size = TheScene().Volume->GetLargestPossibleRegion().GetSize();
  ExpectRefused(RunModule(folder, "two-series"),
                { "VesselReformation: error: --series: volume folder " + folder + ": holds 2 DICOM series; choose one",
                  "1: series 1 \"Topogram\" (CT), 2 files of 32 x 32 pixels, Series Instance UID " + scoutUID,
                  "files " + InFolder(folder, "scout1.dcm") + ", " + InFolder(folder, "scout2.dcm"),
                  "2: series 3 \"CTA 1.5 mm\" (CT), " + std::to_string(size[2]) + " files of " +
                    std::to_string(size[0]) + " x " + std::to_string(size[1]) + " pixels, Series Instance UID " +
                    CTSeriesOptions().SeriesInstanceUID });
  // Chosen by its number or by its UID: the CT alone, as the sound series.
  ExpectRead(RunModule(folder, "two-series-2", { "--series", "2" }));
  ExpectRead(RunModule(folder, "two-series-uid", { "--series", CTSeriesOptions().SeriesInstanceUID }));
  // A choice that names none is said, with the list.
  ExpectRefused(RunModule(folder, "two-series-3", { "--series", "3" }),
                { "--series: volume folder " + folder + ": the DICOM series chosen, 3, is no series of the folder",
                  "1: series 1 \"Topogram\"" });
  // One file of the CT's UID given another UID is a series of its own, named.
  const std::string strayed =
    WriteSeries("one-file-other-uid",
                [](std::vector<DICOMTestFile> & files)
                { Named(files, "IM0011.dcm").Data.SetText(0x0020, 0x000E, "UI", "1.2.826.0.1.3680043.9.7731.37.9"); });
  ExpectRefused(RunModule(strayed, "one-file-other-uid"),
                { "holds 2 DICOM series", "1 file of", "file " + InFolder(strayed, "IM0011.dcm") });
}

TEST(DICOMSeriesModule, OneFileOfAnotherSizeOrPixelFormatIsNamedWithTheAttributeAndBothValues)
{
  struct Case
  {
    std::string   Name;
    std::uint16_t Element;
    std::string   Value;
    std::string   Said;
  };
  const auto &            size = TheScene().Volume->GetLargestPossibleRegion().GetSize();
  const std::vector<Case> cases = {
    { "rows", 0x0010, "64", "Rows (0028,0010) 64, not " + std::to_string(size[1]) },
    { "columns", 0x0011, "64", "Columns (0028,0011) 64, not " + std::to_string(size[0]) },
    { "bits-allocated", 0x0100, "8", "Bits Allocated (0028,0100) 8, not 16" },
    { "bits-stored", 0x0101, "16", "Bits Stored (0028,0101) 16, not 12" },
    { "representation", 0x0103, "1", "Pixel Representation (0028,0103) 1, not 0" },
    { "photometric", 0x0004, "MONOCHROME1", "Photometric Interpretation (0028,0004) MONOCHROME1, not MONOCHROME2" },
  };
  for (const Case & c : cases)
  {
    SCOPED_TRACE(c.Name);
    const std::string folder =
      WriteSeries(c.Name,
                  [&c](std::vector<DICOMTestFile> & files)
                  {
                    auto & file = Named(files, "IM0012.dcm");
                    if (c.Element == 0x0004)
                    {
                      file.Data.SetText(0x0028, c.Element, "CS", c.Value);
                    }
                    else
                    {
                      file.Data.SetUS(0x0028, c.Element, static_cast<std::uint16_t>(std::stoi(c.Value)));
                    }
                  });
    ExpectRefused(RunModule(folder, c.Name),
                  { c.Said,
                    "(the other " + std::to_string(size[2] - 1) + " files of this Series Instance UID)",
                    "file " + InFolder(folder, "IM0012.dcm") });
  }
}

TEST(DICOMSeriesModule, ShortPixelDataAndACutFileAreNamed)
{
  const auto &      size = TheScene().Volume->GetLargestPossibleRegion().GetSize();
  const std::size_t bytes = 2 * size[0] * size[1];
  std::string       folder = WriteSeries(
    "short-pixel-data", [](std::vector<DICOMTestFile> & files) { Named(files, "IM0007.dcm").PixelDataChange = -100; });
  ExpectRefused(RunModule(folder, "short-pixel-data"),
                { "the DICOM file " + InFolder(folder, "IM0007.dcm") + ": its Pixel Data (7FE0,0010) hold " +
                    std::to_string(bytes - 100) + " bytes, where Rows x Columns x Bits Allocated",
                  "ask for " + std::to_string(bytes) });
  folder = WriteSeries("cut-file",
                       [](std::vector<DICOMTestFile> & files)
                       {
                         auto & file = Named(files, "IM0007.dcm");
                         file.TruncateTo = EncodeDICOMFile(file).size() - 1000;
                       });
  ExpectRefused(RunModule(folder, "cut-file"),
                { "the DICOM file " + InFolder(folder, "IM0007.dcm") + " ends inside its Pixel Data" });
}

TEST(DICOMSeriesModule, AFalseTransferSyntaxIsNamed)
{
  for (const auto & [name, uid] :
       std::vector<std::pair<std::string, std::string>>{ { "claims-big-endian", "1.2.840.10008.1.2.2" },
                                                         { "claims-implicit", "1.2.840.10008.1.2" },
                                                         { "claims-jpeg", "1.2.840.10008.1.2.4.50" },
                                                         { "claims-rle", "1.2.840.10008.1.2.5" } })
  {
    SCOPED_TRACE(name);
    const std::string claimed = uid; // a structured binding cannot be captured before C++20
    const std::string folder = WriteSeries(name,
                                           [&claimed](std::vector<DICOMTestFile> & files)
                                           { Named(files, "IM0009.dcm").Encoding.ClaimedTransferSyntax = claimed; });
    ExpectRefused(RunModule(folder, name), { InFolder(folder, "IM0009.dcm") });
  }
}

// The one false claim GDCM reads through: a data set written with implicit VR under the Transfer Syntax UID of explicit
// VR little-endian (GDCM parses it again with implicit VR). The file passes every check, so the series is read, the
// same volume, with a warning naming the file (found by the DICOM fault campaign, seed 4, copy 750 of the run-off
// phantom's series, which the reader had read without a word).
TEST(DICOMSeriesModule, ExplicitVRClaimedOverImplicitVRDataIsReadWithAWarningNamingTheFile)
{
  CTSeriesOptions options;
  options.Encoding.ExplicitVR = false;
  const std::string folder = WriteSeries(
    "implicit-claims-explicit",
    [](std::vector<DICOMTestFile> & files)
    { Named(files, "IM0009.dcm").Encoding.ClaimedTransferSyntax = "1.2.840.10008.1.2.1"; },
    options);
  const ModuleResult run = RunModule(folder, "implicit-claims-explicit");
  ExpectRead(run);
  EXPECT_TRUE(Contains(run.Module.Err,
                       "warning: volume folder " + folder + ": the DICOM file " + InFolder(folder, "IM0009.dcm") +
                         " declares explicit VR (Transfer Syntax UID \"1.2.840.10008.1.2.1\") but its data set is "
                         "written with implicit VR"))
    << run.Module.Err;
  EXPECT_TRUE(Contains(run.Returned.at("inputWarnings"), InFolder(folder, "IM0009.dcm")));
  EXPECT_EQ(SlicesThatDiffer(vr::ReadVolume(folder), TheScene().Volume, 0.0), std::vector<unsigned int>());
}

// Two such files: the warning names the first and counts the other, in the singular.
TEST(DICOMSeriesModule, TwoFilesClaimingExplicitVROverImplicitVRDataAreNamedAndCounted)
{
  CTSeriesOptions options;
  options.Encoding.ExplicitVR = false;
  const std::string folder = WriteSeries(
    "implicit-claims-explicit-twice",
    [](std::vector<DICOMTestFile> & files)
    {
      Named(files, "IM0009.dcm").Encoding.ClaimedTransferSyntax = "1.2.840.10008.1.2.1";
      Named(files, "IM0012.dcm").Encoding.ClaimedTransferSyntax = "1.2.840.10008.1.2.1";
    },
    options);
  const ModuleResult run = RunModule(folder, "implicit-claims-explicit-twice");
  ExpectRead(run);
  EXPECT_TRUE(Contains(run.Module.Err,
                       "the DICOM file " + InFolder(folder, "IM0009.dcm") +
                         " and 1 other file of the series declare explicit VR"))
    << run.Module.Err;
  EXPECT_EQ(SlicesThatDiffer(vr::ReadVolume(folder), TheScene().Volume, 0.0), std::vector<unsigned int>());
}

TEST(DICOMSeriesModule, SliceThicknessIsNoReasonToMoveOrDropASlice)
{
  for (const std::string & value : { "0", "-1", "NaN", "removed", "25" })
  {
    SCOPED_TRACE(value);
    const std::string  folder = WriteSeries("thickness-" + value,
                                           [&value](std::vector<DICOMTestFile> & files)
                                           {
                                             auto & file = Named(files, "IM0015.dcm");
                                             if (value == "removed")
                                             {
                                               file.Data.Remove(0x0018, 0x0050);
                                             }
                                             else
                                             {
                                               file.Data.SetText(0x0018, 0x0050, "DS", value);
                                             }
                                           });
    const ModuleResult run = RunModule(folder, "thickness-" + value);
    ExpectRead(run);
    EXPECT_FALSE(Contains(run.Module.Err, "warning")) << run.Module.Err;
  }
}

TEST(DICOMSeriesModule, ANonFiniteOrAbsurdRescaleIsRefusedNamingTheFileAndTheAttribute)
{
  for (const auto & [element, value, said] : std::vector<std::tuple<std::uint16_t, std::string, std::string>>{
         { 0x1053, "inf", "its Rescale Slope (0028,1053) is \"inf\", not a finite decimal number" },
         { 0x1053, "0", "its Rescale Slope (0028,1053) is \"0\": a slope of 0" },
         { 0x1052, "1e308", "its Rescale Intercept (0028,1052) is \"1e308\": an intercept larger than 1e9" },
         { 0x1052, "-inf", "its Rescale Intercept (0028,1052) is \"-inf\", not a finite decimal number" },
         { 0x1053,
           "1e8",
           "its Rescale Slope (0028,1053) 1e+08 and Rescale Intercept (0028,1052) -1024 make its stored "
           "value" } })
  {
    SCOPED_TRACE(value);
    const std::string folder = WriteSeries("rescale",
                                           [element = element, value = value](std::vector<DICOMTestFile> & files)
                                           { Named(files, "IM0005.dcm").Data.SetText(0x0028, element, "DS", value); });
    ExpectRefused(RunModule(folder, "rescale"), { "the DICOM file " + InFolder(folder, "IM0005.dcm") + ": " + said });
  }
}

TEST(DICOMSeriesModule, ATiltedSeriesIsRefusedWithItsAngle)
{
  const double      z0 = TheScene().Volume->GetOrigin()[2];
  const std::string folder = WriteSeries("tilted",
                                         [z0](std::vector<DICOMTestFile> & files)
                                         {
                                           for (auto & file : files)
                                           {
                                             std::istringstream text(file.Data.Text(0x0020, 0x0032));
                                             double             x, y, z;
                                             char               separator;
                                             text >> x >> separator >> y >> separator >> z;
                                             std::ostringstream moved;
                                             moved.precision(12);
                                             moved << x << "\\" << y + std::tan(20.0 * M_PI / 180.0) * (z - z0) << "\\"
                                                   << z;
                                             file.Data.SetText(0x0020, 0x0032, "DS", moved.str());
                                             file.Data.SetText(0x0018, 0x1120, "DS", "20");
                                           }
                                         });
  ExpectRefused(RunModule(folder, "tilted"),
                { "the DICOM series is tilted (a gantry tilt)",
                  "at 20 degrees to their normal",
                  "Gantry/Detector Tilt (0018,1120): \"20\"" });
}

TEST(DICOMSeriesModule, StrayFilesAreSkippedWithANoteAndTheImageIsTheSame)
{
  const std::string  folder = WriteSeries("stray-files",
                                         [](std::vector<DICOMTestFile> & files)
                                         {
                                           DICOMTestFile note;
                                           note.Name = "notes.txt";
                                           note.Raw = "late arterial phase\n";
                                           DICOMTestFile empty;
                                           empty.Name = "empty.dcm";
                                           empty.Raw = "";
                                           DICOMTestFile folder;
                                           folder.Name = "thumbnails";
                                           folder.Folder = true;
                                           DICOMTestFile dicomdir;
                                           dicomdir.Name = "DICOMDIR";
                                           dicomdir.Data.SetText(0x0002, 0x0002, "UI", "1.2.840.10008.1.3.10");
                                           dicomdir.Data.SetText(0x0002, 0x0003, "UI", "1.2.3.4.5.6");
                                           dicomdir.Data.SetText(0x0004, 0x1130, "CS", "VR37");
                                           dicomdir.OmitPixelData = true;
                                           files.insert(files.end(), { note, empty, folder, dicomdir });
                                         });
  const ModuleResult run = RunModule(folder, "stray-files");
  ExpectRead(run);
  EXPECT_FALSE(Contains(run.Module.Err, "warning")) << run.Module.Err;
  EXPECT_TRUE(Contains(run.Module.Err,
                       "note: volume folder " + folder +
                         ": 4 entries of the folder were skipped, not read: 1 "
                         "sub-folder (thumbnails), 1 empty file (empty.dcm), 1 file that is not DICOM (notes.txt), 1 "
                         "DICOMDIR (DICOMDIR)"))
    << run.Module.Err;
}

TEST(DICOMSeriesModule, TheSingleVesselModuleChoosesASeriesToo)
{
  const std::string folder = WriteSeries("two-series-path",
                                         [](std::vector<DICOMTestFile> & files)
                                         {
                                           DICOMTestFile other = files.front();
                                           other.Name = "other.dcm";
                                           other.Data.SetText(0x0020, 0x000E, "UI", "1.2.826.0.1.3680043.9.7731.37.10");
                                           files.push_back(other);
                                         });
  const std::string output = (TheScene().Folder / "path-cpr.nrrd").string();
  ModuleRun         run = RunProgram({ VR_PATH_EXE, folder, TheScene().Centerlines, output }, 300.0);
  EXPECT_EQ(run.ExitCode, 1) << run.Err;
  EXPECT_TRUE(Contains(run.Err,
                       "VesselPathReformation: error: --series: volume folder " + folder +
                         ": holds 2 DICOM "
                         "series"))
    << run.Err;
  EXPECT_FALSE(fs::exists(output));
  run = RunProgram({ VR_PATH_EXE, folder, TheScene().Centerlines, output, "--series", "2" }, 300.0);
  EXPECT_EQ(run.ExitCode, 0) << run.Err;
  EXPECT_TRUE(fs::exists(output));
}
