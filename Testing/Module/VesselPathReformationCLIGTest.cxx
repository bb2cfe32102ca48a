// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The VesselPathReformation command-line module (issue 21) as a shell and 3D Slicer run it: an oblique tube with a
// known 50 % stenosis in a rotated, anisotropic volume, measured from its segmentation and from its radii; the
// outputs it writes; and every bad input the issue names: exit 1, a message naming the flag or file, nothing written.

#include "vrCenterlineIO.h"
#include "vrImageIO.h"
#include "vrModuleRuns.h"
#include "vrTestFiles.h"
#include "vrTestImages.h"
#include "vrTestSegmentations.h"
#include "vrVolumeIO.h"

#include "itkImageFileReader.h"
#include "itkImageFileWriter.h"
#include "itkImageRegionIterator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace
{
namespace fs = std::filesystem;
using vr::test::Contains;
using vr::test::ModuleRun;
using vr::test::P;
using PointType = itk::Point<double, 3>;

const std::string Executable = VR_PATH_EXE;
const std::string Library = VR_PATH_LIB;

// The tube: from Start() along the unit Axis(), 60 mm long; radius 4 mm, a 10 mm long stenosis centred at s = 30 mm:
// down to 2 mm over 4 mm, 2 mm for 2 mm, up again over 4 mm (50 % diameter stenosis, 75 % area stenosis).
constexpr double TubeLength = 60.0;
constexpr double HealthyRadius = 4.0;
constexpr double NarrowRadius = 2.0;

double
TrueRadius(double s)
{
  const double distance = std::abs(s - 30.0);
  if (distance >= 5.0)
  {
    return HealthyRadius;
  }
  return distance <= 1.0 ? NarrowRadius : NarrowRadius + (HealthyRadius - NarrowRadius) * (distance - 1.0) / 4.0;
}

itk::Vector<double, 3>
Axis()
{
  itk::Vector<double, 3> axis;
  axis[0] = 1.0;
  axis[1] = 2.0;
  axis[2] = 3.0;
  axis.Normalize();
  return axis;
}

PointType
Start()
{
  return P(-12.0, -20.0, -30.0);
}

itk::CenterlineTree
TubeTree()
{
  itk::CenterlineBranch branch;
  branch.Id = 1;
  for (double s = 0.0; s <= TubeLength + 1e-9; s += 0.5)
  {
    branch.Points.push_back(Start() + Axis() * s);
    branch.Radii.push_back(TrueRadius(s));
  }
  itk::CenterlineTree tree;
  tree.AddBranch(branch);
  return tree;
}

struct TubeFiles
{
  fs::path Folder;
  fs::path Volume;
  fs::path Centerlines;
  fs::path Mask;
};

template<typename TImage>
void
Write(const TImage * image, const fs::path & path)
{
  auto writer = itk::ImageFileWriter<TImage>::New();
  writer->SetInput(image);
  writer->SetFileName(path.string());
  writer->Update();
}

/** A rotated, anisotropic grid holding the tube: mask 1 inside, volume 400 inside and 0 outside. */
TubeFiles
MakeTubeFiles(const std::string & name)
{
  TubeFiles files;
  files.Folder = vr::test::FreshFolderForThisTest(VR_TEST_OUTPUT_DIR, "VesselPathReformation." + name + ".");
  itk::Vector<double, 3> spacing;
  spacing[0] = 0.6;
  spacing[1] = 0.8;
  spacing[2] = 0.7;
  itk::Size<3> size{ { 110, 100, 110 } };
  const auto   mask =
    vr::test::MakeLabelMap(size, spacing, P(-40.0, -45.0, -40.0), vr::test::RotationMatrix(1, 1, 0, 20));
  vr::test::DrawTubes(mask, TubeTree());
  auto volume = vr::VolumeImageType::New();
  volume->CopyInformation(mask);
  volume->SetRegions(mask->GetLargestPossibleRegion());
  volume->Allocate();
  itk::ImageRegionIterator<vr::VolumeImageType>     out(volume, volume->GetLargestPossibleRegion());
  itk::ImageRegionConstIterator<vr::test::LabelMap> in(mask, mask->GetLargestPossibleRegion());
  for (; !out.IsAtEnd(); ++out, ++in)
  {
    out.Set(in.Get() ? 400.0f : 0.0f);
  }
  files.Volume = files.Folder / "tube.nrrd";
  files.Mask = files.Folder / "tube-mask.nrrd";
  files.Centerlines = files.Folder / "tube.csv";
  Write(volume.GetPointer(), files.Volume);
  Write(mask.GetPointer(), files.Mask);
  vr::WriteCenterlines(TubeTree(), files.Centerlines.string(), vr::CoordinateSpace::LPS);
  return files;
}

ModuleRun
RunModule(std::vector<std::string> arguments)
{
  arguments.insert(arguments.begin(), Executable);
  return vr::test::RunProgram(arguments);
}

std::map<std::string, std::string>
ReturnedValues(const fs::path & file)
{
  std::map<std::string, std::string> values;
  std::istringstream                 lines(vr::test::ReadTextFile(file.string()));
  for (std::string line; std::getline(lines, line);)
  {
    const auto equals = line.find(" = ");
    if (equals != std::string::npos)
    {
      values[line.substr(0, equals)] = line.substr(equals + 3);
    }
  }
  return values;
}

/** The CAD-RADS class of a % diameter stenosis, written here from the classes' definition. */
int
ExpectedCADRADS(double percent)
{
  const double rounded = std::floor(percent + 0.5);
  return rounded <= 0 ? 0 : rounded < 25 ? 1 : rounded < 50 ? 2 : rounded < 70 ? 3 : 4;
}

TEST(VesselPathReformationModule, MeasuresAKnownStenosisFromTheSegmentation)
{
  const TubeFiles files = MakeTubeFiles("segmentation");
  const fs::path  cpr = files.Folder / "cpr.nrrd";
  const fs::path  table = files.Folder / "lumen.csv";
  const fs::path  stack = files.Folder / "sections.nrrd";
  const fs::path  points = files.Folder / "points.nrrd";
  const fs::path  folds = files.Folder / "folds.nrrd";
  const fs::path  returned = files.Folder / "returned.txt";
  const ModuleRun run = RunModule({ files.Volume.string(),
                                    files.Centerlines.string(),
                                    cpr.string(),
                                    "--segmentation",
                                    files.Mask.string(),
                                    "--spacing",
                                    "0.5",
                                    "--width",
                                    "30",
                                    "--outputLumenTable",
                                    table.string(),
                                    "--outputCrossSections",
                                    stack.string(),
                                    "--outputPoints",
                                    points.string(),
                                    "--outputFoldMask",
                                    folds.string(),
                                    "--gradingScale",
                                    "cad-rads",
                                    "--returnparameterfile",
                                    returned.string() });
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  auto values = ReturnedValues(returned);
  EXPECT_NEAR(std::stod(values.at("pathLength")), TubeLength, 0.01);
  // CAD-RADS because the user said so (the tube has no name).
  EXPECT_EQ(values.at("gradingScale"), "CAD-RADS");
  EXPECT_EQ(values.at("lumenSource"), "segmentation");
  EXPECT_NEAR(std::stod(values.at("minimalLumenDiameter")), 2.0 * NarrowRadius, 0.2);
  EXPECT_NEAR(std::stod(values.at("minimalLumenDiameterArcLength")), 30.0, 1.0);
  EXPECT_NEAR(std::stod(values.at("diameterStenosis")), 50.0, 3.0);
  EXPECT_NEAR(std::stod(values.at("areaStenosis")), 75.0, 4.0);
  EXPECT_EQ(std::stoi(values.at("cadRads")), ExpectedCADRADS(std::stod(values.at("diameterStenosis"))));
  EXPECT_EQ(values.at("foldedPixels"), "0");

  // The CPR: 61 columns of 0.5 mm, the tube (400) in the middle column along the whole path.
  const vr::DepthImageType::Pointer image = vr::ReadDepthImage(cpr.string());
  const auto                        cprSize = image->GetLargestPossibleRegion().GetSize();
  EXPECT_EQ(cprSize[0], 61u);
  EXPECT_NEAR(static_cast<double>(cprSize[1]), TubeLength / 0.5, 1.5);
  for (itk::IndexValueType row = 4; row + 4 < static_cast<itk::IndexValueType>(cprSize[1]); ++row)
  {
    EXPECT_GT(image->GetPixel({ { 30, row } }), 200.0f) << "row " << row;
    EXPECT_LT(image->GetPixel({ { 0, row } }), 200.0f) << "row " << row;
  }
  // The table: comment lines stating the grading, a header starting with the columns, one row per section,
  // RAS centres on the axis.
  std::ifstream tableStream(table);
  std::string   header;
  std::string   comments;
  while (std::getline(tableStream, header) && header.rfind("# ", 0) == 0)
  {
    comments += header + "\n";
  }
  EXPECT_TRUE(Contains(comments, "reference: interpolated within each segment")) << comments;
  EXPECT_TRUE(Contains(comments, "scale CAD-RADS (chosen by the user)")) << comments;
  EXPECT_EQ(header.rfind("arc_length_mm,ras_r_mm,ras_a_mm,ras_s_mm,area_mm2,equivalent_diameter_mm,min_diameter_mm,"
                         "max_diameter_mm,reference_diameter_mm",
                         0),
            0u)
    << header;
  std::size_t rows = 0;
  for (std::string line; std::getline(tableStream, line); ++rows)
  {
    std::istringstream fields(line);
    std::string        field;
    double             s = 0, r = 0, a = 0, z = 0;
    std::getline(fields, field, ',');
    s = std::stod(field);
    std::getline(fields, field, ',');
    r = std::stod(field);
    std::getline(fields, field, ',');
    a = std::stod(field);
    std::getline(fields, field, ',');
    z = std::stod(field);
    const PointType onAxis = Start() + Axis() * s;
    EXPECT_NEAR(r, -onAxis[0], 1e-3);
    EXPECT_NEAR(a, -onAxis[1], 1e-3);
    EXPECT_NEAR(z, onAxis[2], 1e-3);
  }
  EXPECT_NEAR(static_cast<double>(rows), TubeLength / 0.5, 1.5);
  for (const fs::path & path : { stack, points, folds })
  {
    EXPECT_TRUE(fs::exists(path)) << path;
  }
  EXPECT_TRUE(Contains(run.Out, "headline: ")) << run.Out;
  EXPECT_TRUE(Contains(run.Out, "CAD-RADS")) << run.Out;
}

TEST(VesselPathReformationModule, MeasuresTheSameStenosisFromTheRadiiAlone)
{
  const TubeFiles files = MakeTubeFiles("radii");
  const fs::path  returned = files.Folder / "returned.txt";
  const ModuleRun run = RunModule({ files.Volume.string(),
                                    files.Centerlines.string(),
                                    (files.Folder / "cpr.nrrd").string(),
                                    "--returnparameterfile",
                                    returned.string() });
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  auto values = ReturnedValues(returned);
  EXPECT_EQ(values.at("lumenSource"), "centerline radius");
  EXPECT_NEAR(std::stod(values.at("minimalLumenDiameter")), 2.0 * NarrowRadius, 0.2);
  EXPECT_NEAR(std::stod(values.at("minimalLumenDiameterArcLength")), 30.0, 1.0);
  EXPECT_NEAR(std::stod(values.at("diameterStenosis")), 50.0, 3.0);
  // Without a name and without --gradingScale: a peripheral artery's category, no CAD-RADS class.
  EXPECT_EQ(values.at("cadRads"), "");
  EXPECT_EQ(values.at("gradingScale"), "peripheral");
  EXPECT_TRUE(values.at("grade") == "50–99 % (peripheral)" || values.at("grade") == "20–49 % (peripheral)")
    << values.at("grade");
  EXPECT_TRUE(Contains(values.at("segments"), "segment 1")) << values.at("segments");
  EXPECT_EQ(values.at("referenceScope"), "each segment");
  EXPECT_NE(values.at("excludedSections"), "0");
}

TEST(VesselPathReformationModule, WithoutCenterlinesThePathComesFromTheSegmentation)
{
  // The centerlines extracted from the mask (as Extract Centerlines makes them) give the path: about the tube's
  // length (the extraction stops short of the tube's rounded ends), and the same stenosis measured on the mask.
  const TubeFiles files = MakeTubeFiles("extracted");
  const fs::path  returned = files.Folder / "returned.txt";
  const ModuleRun run = RunModule({ files.Volume.string(),
                                    (files.Folder / "cpr.nrrd").string(),
                                    "--segmentation",
                                    files.Mask.string(),
                                    "--returnparameterfile",
                                    returned.string() });
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  EXPECT_TRUE(Contains(run.Out, "extracted from")) << run.Out;
  auto values = ReturnedValues(returned);
  EXPECT_EQ(values.at("lumenSource"), "segmentation");
  EXPECT_GT(std::stod(values.at("pathLength")), TubeLength - 10.0);
  EXPECT_LT(std::stod(values.at("pathLength")), TubeLength + 1.0);
  EXPECT_NEAR(std::stod(values.at("minimalLumenDiameter")), 2.0 * NarrowRadius, 0.2);
  EXPECT_NEAR(std::stod(values.at("diameterStenosis")), 50.0, 3.0);
}

TEST(VesselPathReformationModule, TheRobustReferenceFindsTheSameStenosis)
{
  // The second reference method: a robust line through the profile, the stenotic dip weighted out; on a tube of one
  // healthy radius it is the healthy diameter, so the stenosis is the same 50 %.
  const TubeFiles files = MakeTubeFiles("robust");
  const fs::path  returned = files.Folder / "returned.txt";
  const ModuleRun run = RunModule({ files.Volume.string(),
                                    files.Centerlines.string(),
                                    (files.Folder / "cpr.nrrd").string(),
                                    "--segmentation",
                                    files.Mask.string(),
                                    "--referenceMethod",
                                    "robust",
                                    "--returnparameterfile",
                                    returned.string() });
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  auto values = ReturnedValues(returned);
  EXPECT_EQ(values.at("referenceMethod"), "robust fit");
  EXPECT_NEAR(std::stod(values.at("referenceDiameter")), 2.0 * HealthyRadius, 0.25);
  EXPECT_NEAR(std::stod(values.at("diameterStenosis")), 50.0, 3.0);
}

/** A run that must fail: exit 1, the message naming \a named, no output written and an existing one kept. */
void
ExpectRefused(const TubeFiles & files, const std::vector<std::string> & extra, const std::string & named)
{
  const fs::path cpr = files.Folder / "cpr.nrrd";
  const fs::path table = files.Folder / "lumen.csv";
  vr::test::WriteTextFile(table.string(), "kept");
  std::vector<std::string> arguments{
    files.Volume.string(), files.Centerlines.string(), cpr.string(), "--outputLumenTable", table.string()
  };
  arguments.insert(arguments.end(), extra.begin(), extra.end());
  const ModuleRun run = RunModule(arguments);
  EXPECT_EQ(run.ExitCode, 1) << run.Err;
  EXPECT_FALSE(run.Crashed);
  EXPECT_TRUE(Contains(run.Err, "error")) << run.Err;
  EXPECT_TRUE(Contains(run.Err, named)) << "expected the message to name " << named << ":\n" << run.Err;
  EXPECT_FALSE(fs::exists(cpr)) << "an output was written";
  EXPECT_EQ(vr::test::ReadTextFile(table.string()), "kept") << "an existing output was changed";
}

TEST(VesselPathReformationModule, RefusesBadInputNamingTheFlagOrFile)
{
  const TubeFiles files = MakeTubeFiles("bad");
  ExpectRefused(files, { "--branch", "7" }, "--branch");
  ExpectRefused(files, { "--pathRange", "10,10.2", "--sectionSpacing", "1" }, "--sectionSpacing");
  ExpectRefused(files, { "--pathRange", "10,500" }, "--pathRange");
  ExpectRefused(files, { "--width", "0" }, "--width");
  ExpectRefused(files, { "--width", "nan" }, "--width");
  ExpectRefused(files, { "--spacing", "-1" }, "--spacing");
  ExpectRefused(files, { "--spacing", "nan" }, "--spacing");
  ExpectRefused(files, { "--referencePoints", "5,400" }, "--referencePoints");
  ExpectRefused(files, { "--gradingScale", "coronary" }, "--gradingScale");

  // A segmentation that misses the path: a mask of a blob far from the tube.
  const auto mask = vr::test::MakeLabelMap(itk::Size<3>{ { 20, 20, 20 } },
                                           itk::Vector<double, 3>(1.0),
                                           P(200, 200, 200),
                                           vr::test::RotationMatrix(0, 0, 1, 0));
  mask->FillBuffer(1);
  const fs::path elsewhere = files.Folder / "elsewhere.nrrd";
  Write(mask.GetPointer(), elsewhere);
  ExpectRefused(files, { "--segmentation", elsewhere.string() }, "elsewhere.nrrd");
}

TEST(VesselPathReformationModule, RunsInProcessAsSlicerLoadsIt)
{
  const TubeFiles files = MakeTubeFiles("inprocess");
  const fs::path  cpr = files.Folder / "cpr.nrrd";
  const ModuleRun run = vr::test::RunEntryPointInProcess(
    Library, { "VesselPathReformation", files.Volume.string(), files.Centerlines.string(), cpr.string() });
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  EXPECT_TRUE(fs::exists(cpr));
}

/** Slicer's progress callback in the cancel test: sets Abort when the module reports its reformation stage. */
void
AbortAtTheReformation(void * data)
{
  auto * information = static_cast<vr::test::SlicerModuleProcessInformation *>(data);
  if (std::string(information->ProgressMessage) == "reformation")
  {
    information->Abort = 1;
  }
}

TEST(VesselPathReformationModule, ACancelledRunWritesNothingAndReportsCancelledAsSlicerReadsIt)
{
  const TubeFiles                                 files = MakeTubeFiles("cancel");
  const fs::path                                  cpr = files.Folder / "cpr.nrrd";
  const fs::path                                  table = files.Folder / "lumen.csv";
  static vr::test::SlicerModuleProcessInformation information;
  information = vr::test::SlicerModuleProcessInformation{};
  information.ProgressCallbackFunction = AbortAtTheReformation;
  information.ProgressCallbackClientData = &information;
  const ModuleRun run = vr::test::RunEntryPointInProcess(Library,
                                                         { "VesselPathReformation",
                                                           "--processinformationaddress",
                                                           vr::test::AddressText(&information),
                                                           files.Volume.string(),
                                                           files.Centerlines.string(),
                                                           cpr.string(),
                                                           "--outputLumenTable",
                                                           table.string() });
  EXPECT_EQ(run.ExitCode, 0) << "Slicer reads a cancelled run's 0 as Cancelled: " << run.Err;
  EXPECT_EQ(information.Abort, 1);
  EXPECT_TRUE(Contains(run.Err + run.Out, "cancelled")) << run.Err;
  EXPECT_FALSE(fs::exists(cpr));
  EXPECT_FALSE(fs::exists(table));
}
} // namespace
