// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The ExtractCenterlines command-line module as 3D Slicer and a shell use it (issue 15): its XML against CTK's
// schema, its flags against its parser, runs on the VMTK aorta and on label maps made in code, the shared library,
// and every bad input of the issue: a clear message, exit 1, no output and an existing one kept.

#include "vrCenterlineIO.h"
#include "vrModuleRuns.h"
#include "vrTestFiles.h"
#include "vrTestImages.h"
#include "vrTestSegmentations.h"

#include "itkImageFileWriter.h"

#include <gtest/gtest.h>

#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>
#include <vtkXMLPolyDataReader.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>

namespace
{
namespace fs = std::filesystem;
using vr::test::Contains;
using vr::test::LabelMap;
using vr::test::ModuleRun;
using vr::test::P;

const std::string Executable = VR_EXTRACT_EXE;
const std::string Library = VR_EXTRACT_LIB;
const fs::path    DataFolder = fs::path(VR_SHARED_DATA_DIR) / "vmtk-aorta-mra";

fs::path
TestFolder()
{
  return vr::test::FreshFolderForThisTest(VR_TEST_OUTPUT_DIR, "ExtractCenterlines.");
}

ModuleRun
RunModule(std::vector<std::string> arguments)
{
  arguments.insert(arguments.begin(), Executable);
  return vr::test::RunProgram(arguments);
}

itk::Vector<double, 3>
V(double x, double y, double z)
{
  itk::Vector<double, 3> v;
  v[0] = x;
  v[1] = y;
  v[2] = z;
  return v;
}

itk::Matrix<double, 3, 3>
Identity()
{
  itk::Matrix<double, 3, 3> identity;
  identity.SetIdentity();
  return identity;
}

template<typename TImage>
void
WriteTestImage(const TImage * image, const fs::path & path)
{
  auto writer = itk::ImageFileWriter<TImage>::New();
  writer->SetInput(image);
  writer->SetFileName(path.string());
  writer->Update();
}

/** A label map of two tubes: label 2 (radius 3, along z at x = 12) and label 7 (a Y, trunk radius 4 at x = 40). */
LabelMap::Pointer
TwoVessels()
{
  auto                image = vr::test::MakeLabelMap({ { 60, 50, 70 } }, V(0.8, 0.8, 1.0), P(-10, 5, -20), Identity());
  itk::CenterlineTree tube;
  tube.AddBranch(vr::test::TubeBranch(1, vr::test::SegmentPoints(P(0, 25, -14), P(1, 26, 40), 0.5), 3.0));
  vr::test::DrawTubes(image, tube, 2);
  itk::CenterlineTree y;
  y.AddBranch(vr::test::TubeBranch(1, vr::test::SegmentPoints(P(22, 25, -15), P(22, 25, 10), 0.5), 4.0));
  y.AddBranch(vr::test::TubeBranch(2, vr::test::SegmentPoints(P(22, 25, 10), P(14, 30, 44), 0.5), 2.8));
  y.AddBranch(vr::test::TubeBranch(3, vr::test::SegmentPoints(P(22, 25, 10), P(32, 20, 44), 0.5), 2.8));
  vr::test::DrawTubes(image, y, 7);
  return image;
}

// ---------------------------------------------------------------------------------------------------------------
// The description.

struct XMLParameter
{
  std::string                        Tag;
  std::string                        Name;
  std::string                        LongFlag;
  std::string                        Index;
  std::vector<std::string>           ChildOrder;
  std::map<std::string, std::string> Attributes;
};

std::string
XMLOf()
{
  const ModuleRun run = RunModule({ "--xml" });
  EXPECT_EQ(run.ExitCode, 0) << run.Err;
  return run.Out;
}

std::vector<XMLParameter>
ParametersOf(const std::string & xml, std::string * category = nullptr)
{
  vtkNew<vtkXMLDataParser> parser;
  std::istringstream       stream(xml);
  parser->SetStream(&stream);
  parser->SetIgnoreCharacterData(0);
  EXPECT_TRUE(parser->Parse()) << "not well-formed:\n" << xml;
  std::vector<XMLParameter> parameters;
  vtkXMLDataElement *       root = parser->GetRootElement();
  if (root == nullptr)
  {
    return parameters;
  }
  if (category != nullptr && root->FindNestedElementWithName("category") != nullptr)
  {
    *category = root->FindNestedElementWithName("category")->GetCharacterData();
  }
  for (int g = 0; g < root->GetNumberOfNestedElements(); ++g)
  {
    vtkXMLDataElement * group = root->GetNestedElement(g);
    if (std::string(group->GetName()) != "parameters")
    {
      continue;
    }
    for (int p = 0; p < group->GetNumberOfNestedElements(); ++p)
    {
      vtkXMLDataElement * element = group->GetNestedElement(p);
      const std::string   tag = element->GetName();
      if (tag == "label" || tag == "description")
      {
        continue;
      }
      XMLParameter parameter;
      parameter.Tag = tag;
      for (int a = 0; a < element->GetNumberOfAttributes(); ++a)
      {
        parameter.Attributes[element->GetAttributeName(a)] = element->GetAttributeValue(a);
      }
      for (int c = 0; c < element->GetNumberOfNestedElements(); ++c)
      {
        vtkXMLDataElement * child = element->GetNestedElement(c);
        const std::string   name = child->GetName();
        const char *        data = child->GetCharacterData();
        std::string         text = data ? data : "";
        text.erase(0, text.find_first_not_of(" \t\r\n"));
        text.erase(text.find_last_not_of(" \t\r\n") + 1);
        parameter.ChildOrder.push_back(name);
        if (name == "name")
        {
          parameter.Name = text;
        }
        else if (name == "longflag")
        {
          parameter.LongFlag = text;
        }
        else if (name == "index")
        {
          parameter.Index = text;
        }
      }
      parameters.push_back(parameter);
    }
  }
  return parameters;
}

TEST(ExtractCenterlinesXML, IsWellFormedInCTKOrderAndValidatesAgainstCTKsSchema)
{
  const std::string xml = XMLOf();
  ASSERT_EQ(xml.compare(0, 5, "<?xml"), 0) << "3D Slicer only accepts a description that starts with <?xml";
  std::string category;
  const auto  parameters = ParametersOf(xml, &category);
  EXPECT_NE(category.find("Vascular"), std::string::npos);
  // CTK's order inside each parameter.
  const std::map<std::string, int> rank = { { "name", 0 },        { "longflag", 1 }, { "index", 1 },
                                            { "description", 2 }, { "label", 3 },    { "default", 4 },
                                            { "channel", 5 },     { "element", 6 },  { "constraints", 6 } };
  for (const auto & parameter : parameters)
  {
    int previous = -1;
    for (const auto & child : parameter.ChildOrder)
    {
      ASSERT_TRUE(rank.count(child)) << parameter.Name << " has an unexpected <" << child << ">";
      EXPECT_GE(rank.at(child), previous) << parameter.Name << ": <" << child << "> out of CTK's order";
      previous = rank.at(child);
    }
  }
  // The root point says its frame.
  const auto root = std::find_if(parameters.begin(), parameters.end(), [](const auto & p) { return p.Name == "root"; });
  ASSERT_NE(root, parameters.end());
  EXPECT_EQ(root->Tag, "point");
  EXPECT_EQ(root->Attributes.at("coordinateSystem"), "ras");

  // Validation against CTK's schema is the ctest ModuleXMLValidatesAgainstCTKSchema.ExtractCenterlines.
}

TEST(ExtractCenterlinesXML, FlagsAreExactlyTheParsers)
{
  const auto            parameters = ParametersOf(XMLOf());
  std::set<std::string> flags;
  for (const auto & parameter : parameters)
  {
    if (!parameter.LongFlag.empty())
    {
      flags.insert(parameter.LongFlag);
    }
  }
  EXPECT_EQ(flags, (std::set<std::string>{ "labels", "root", "minimumBranchLength" }));
  std::map<std::string, std::string> indices;
  for (const auto & parameter : parameters)
  {
    indices[parameter.Name] = parameter.Index;
  }
  EXPECT_EQ(indices["segmentation"], "0");
  EXPECT_EQ(indices["outputCenterlines"], "1");

  // The usage lists them and the three every Slicer module takes.
  const ModuleRun help = RunModule({ "--help" });
  ASSERT_EQ(help.ExitCode, 0) << help.Err;
  std::set<std::string> helpFlags;
  const std::regex      flagAtLineStart("(^|\\n)  --([A-Za-z]+)");
  for (auto it = std::sregex_iterator(help.Out.begin(), help.Out.end(), flagAtLineStart); it != std::sregex_iterator();
       ++it)
  {
    helpFlags.insert((*it)[2]);
  }
  std::set<std::string> expected = flags;
  expected.insert({ "xml", "help", "processinformationaddress", "returnparameterfile" });
  EXPECT_EQ(helpFlags, expected) << help.Out;
  // Each flag is accepted with a good value (the run then misses its arguments); unknown ones are not.
  for (const auto & [flag, value] : std::map<std::string, std::string>{
         { "labels", "1,2" }, { "root", "1.5,-2,3e1" }, { "minimumBranchLength", "4" } })
  {
    const ModuleRun run = RunModule({ "--" + flag, value });
    EXPECT_EQ(run.ExitCode, 1);
    EXPECT_TRUE(Contains(run.Err, "missing the first argument")) << flag << ": " << run.Err;
  }
  for (const std::string flag : { "--label", "--Root", "--output", "--bogus" })
  {
    const ModuleRun run = RunModule({ flag, "1" });
    EXPECT_EQ(run.ExitCode, 1) << flag;
    EXPECT_TRUE(Contains(run.Err, "unknown flag " + flag)) << flag << ": " << run.Err;
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Runs.

TEST(ExtractCenterlinesModule, AortaLevelSetInEveryFormatReadsBackAsVMTKsTree)
{
  const fs::path            folder = TestFolder();
  const itk::CenterlineTree vmtk = vr::ReadCenterlines((DataFolder / "aorta-centerline.vtp").string());
  for (const std::string extension : { ".vtp", ".vtk", ".mrk.json", ".tre", ".csv" })
  {
    const fs::path  output = folder / ("aorta" + extension);
    const ModuleRun run = RunModule({ (DataFolder / "aorta-final-levelset.mha").string(), output.string() });
    ASSERT_EQ(run.ExitCode, 0) << run.Err;
    EXPECT_TRUE(Contains(run.Out, "ExtractCenterlines: 3 branches in 1 tree")) << run.Out;
    EXPECT_TRUE(Contains(run.Out, "level set (inside where < 0)")) << run.Out;
    const itk::CenterlineTree tree = vr::ReadCenterlines(output.string());
    ASSERT_EQ(tree.GetNumberOfBranches(), 3u) << extension;
    ASSERT_TRUE(tree.HasRadii()) << extension;
    std::vector<double> distances;
    std::vector<double> radiusDifferences;
    for (const auto & branch : tree.GetBranches())
    {
      for (std::size_t k = 0; k < branch.Points.size(); ++k)
      {
        const auto nearest = vr::test::NearestPointOnTree(branch.Points[k], vmtk);
        distances.push_back(nearest.Nearest.Distance);
        radiusDifferences.push_back(std::abs(branch.Radii[k] - nearest.Nearest.Radius));
      }
    }
    std::cout << extension << ": " << tree.GetNumberOfPoints() << " points, median distance to VMTK's "
              << vr::test::Quantile(distances, 0.5) << " mm, median radius difference "
              << vr::test::Quantile(radiusDifferences, 0.5) << " mm" << std::endl;
    // Markups curves are control points read back through Slicer's spline: a little looser.
    EXPECT_LT(vr::test::Quantile(distances, 0.5), 1.5) << extension;
    EXPECT_LT(vr::test::Quantile(radiusDifferences, 0.5), 1.0) << extension;
  }
  // VMTK's radius array name in the .vtp.
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName((folder / "aorta.vtp").c_str());
  reader->Update();
  EXPECT_NE(reader->GetOutput()->GetPointData()->GetArray("MaximumInscribedSphereRadius"), nullptr);
  EXPECT_EQ(vr::test::FolderEntries(folder).size(), 5u) << "a temporary file was left";
}

TEST(ExtractCenterlinesModule, ReturnsWhatItExtracted)
{
  // 3D Slicer's returned values: the counts of the tree written, its length summed from the file read back.
  const fs::path  folder = TestFolder();
  const fs::path  output = folder / "aorta.vtp";
  const fs::path  returned = folder / "returned.txt";
  const ModuleRun run = RunModule({ (DataFolder / "aorta-final-levelset.mha").string(),
                                    output.string(),
                                    "--returnparameterfile",
                                    returned.string() });
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  const itk::CenterlineTree tree = vr::ReadCenterlines(output.string());
  double                    length = 0.0;
  for (const auto & branch : tree.GetBranches())
  {
    for (std::size_t k = 1; k < branch.Points.size(); ++k)
    {
      length += branch.Points[k - 1].EuclideanDistanceTo(branch.Points[k]);
    }
  }
  std::map<std::string, std::string> values;
  std::istringstream                 lines(vr::test::ReadTextFile(returned.string()));
  for (std::string line; std::getline(lines, line);)
  {
    const auto equals = line.find(" = ");
    ASSERT_NE(equals, std::string::npos) << line;
    values[line.substr(0, equals)] = line.substr(equals + 3);
  }
  EXPECT_EQ(values["numberOfBranches"], std::to_string(tree.GetNumberOfBranches()));
  EXPECT_EQ(values["numberOfTrees"], "1");
  EXPECT_NEAR(std::stod(values.at("centerlineLength")), length, 0.1);
  EXPECT_GT(std::stod(values.at("extractionTime")), 0.0);
}

TEST(ExtractCenterlinesModule, LabelsChooseVesselsAndMasksCombine)
{
  const fs::path folder = TestFolder();
  const auto     image = TwoVessels();
  WriteTestImage(image.GetPointer(), folder / "labels.nii.gz");

  // Every non-zero voxel: two trees (1 + 3 branches).
  ModuleRun run = RunModule({ (folder / "labels.nii.gz").string(), (folder / "all.csv").string() });
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  EXPECT_TRUE(Contains(run.Out, "4 branches in 2 trees")) << run.Out;
  // Label 7: the Y.
  run = RunModule({ "--labels", "7", (folder / "labels.nii.gz").string(), (folder / "y.csv").string() });
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  EXPECT_TRUE(Contains(run.Out, "3 branches in 1 tree")) << run.Out;
  // Label 2: the tube, running along z at x = 0..1 (LPS).
  run = RunModule({ "--labels", "2", (folder / "labels.nii.gz").string(), (folder / "tube.csv").string() });
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  const itk::CenterlineTree tube = vr::ReadCenterlines((folder / "tube.csv").string());
  ASSERT_EQ(tube.GetNumberOfBranches(), 1u);
  EXPECT_LT(std::abs(tube.GetBranches()[0].Points.front()[0] - 0.5), 1.5);

  // The two vessels as two files, TotalSegmentator's way; the second on another grid: resampled, with a warning.
  auto tubeOnly = vr::test::MakeLabelMap({ { 60, 50, 70 } }, V(0.8, 0.8, 1.0), P(-10, 5, -20), Identity());
  auto yOnly = vr::test::MakeLabelMap({ { 45, 38, 60 } }, V(1.0, 1.0, 1.2), P(-8, 6, -19), Identity());
  for (itk::SizeValueType k = 0; k < image->GetBufferedRegion().GetNumberOfPixels(); ++k)
  {
    tubeOnly->GetBufferPointer()[k] = image->GetBufferPointer()[k] == 2 ? 1 : 0;
  }
  itk::CenterlineTree y;
  y.AddBranch(vr::test::TubeBranch(1, vr::test::SegmentPoints(P(22, 25, -15), P(22, 25, 10), 0.5), 4.0));
  y.AddBranch(vr::test::TubeBranch(2, vr::test::SegmentPoints(P(22, 25, 10), P(14, 30, 44), 0.5), 2.8));
  y.AddBranch(vr::test::TubeBranch(3, vr::test::SegmentPoints(P(22, 25, 10), P(32, 20, 44), 0.5), 2.8));
  vr::test::DrawTubes(yOnly, y, 1);
  WriteTestImage(tubeOnly.GetPointer(), folder / "tube.nii.gz");
  WriteTestImage(yOnly.GetPointer(), folder / "y.nrrd");
  run = RunModule(
    { (folder / "tube.nii.gz").string() + "," + (folder / "y.nrrd").string(), (folder / "both.tre").string() });
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  EXPECT_TRUE(Contains(run.Out, "4 branches in 2 trees")) << run.Out;
  EXPECT_TRUE(Contains(run.Out, "2 files")) << run.Out;
  EXPECT_TRUE(Contains(run.Err, "warning: segmentation " + (folder / "y.nrrd").string() + " is on another grid"))
    << run.Err;
  EXPECT_TRUE(Contains(run.Err, "resampled onto the latter's (nearest neighbour)")) << run.Err;
}

TEST(ExtractCenterlinesModule, RootPointInRASTurnsTheTree)
{
  const fs::path        folder = TestFolder();
  auto                  image = vr::test::MakeLabelMap({ { 30, 30, 60 } }, V(1, 1, 1), P(0, 0, 0), Identity());
  itk::CenterlineBranch tube = vr::test::TubeBranch(1, vr::test::SegmentPoints(P(15, 15, 4), P(15, 16, 55), 0.5), 3.0);
  for (std::size_t k = 0; k < tube.Radii.size(); ++k)
  {
    tube.Radii[k] = 2.5 + 2.0 * static_cast<double>(k) / static_cast<double>(tube.Radii.size() - 1); // wide at the top
  }
  itk::CenterlineTree tree;
  tree.AddBranch(tube);
  vr::test::DrawTubes(image, tree);
  WriteTestImage(image.GetPointer(), folder / "tube.nrrd");
  ModuleRun run = RunModule({ (folder / "tube.nrrd").string(), (folder / "default.csv").string() });
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  EXPECT_GT(vr::ReadCenterlines((folder / "default.csv").string()).GetBranches()[0].Points.front()[2], 45.0);
  // The narrow end, LPS (15, 15, 4), is RAS (-15, -15, 4).
  run = RunModule({ "--root", "-15,-15,4", (folder / "tube.nrrd").string(), (folder / "rooted.csv").string() });
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  EXPECT_LT(vr::ReadCenterlines((folder / "rooted.csv").string()).GetBranches()[0].Points.front()[2], 10.0);
  // The same numbers taken as LPS would lie 30 mm away: an error that asks about the frame.
  run = RunModule({ "--root", "15,15,4", (folder / "tube.nrrd").string(), (folder / "wrong.csv").string() });
  EXPECT_EQ(run.ExitCode, 1);
  EXPECT_TRUE(Contains(run.Err, "error: --root: root point 1 (15, 15, 4) RAS lies")) << run.Err;
  EXPECT_TRUE(Contains(run.Err, "is it in LPS")) << run.Err;
  EXPECT_FALSE(fs::exists(folder / "wrong.csv"));
}

TEST(ExtractCenterlinesModule, ReportsProgressAndTheLibraryWritesWhatTheExecutableWrites)
{
  const fs::path    folder = TestFolder();
  const std::string segmentation = (DataFolder / "aorta-final-levelset.mha").string();
  const ModuleRun   executable = RunModule({ segmentation, (folder / "exe.vtp").string() });
  ASSERT_EQ(executable.ExitCode, 0) << executable.Err;
  EXPECT_TRUE(Contains(executable.Out, "<filter-name>ExtractCenterlines</filter-name>"));
  std::vector<double> fractions;
  const std::regex    line("<filter-progress>([0-9.eE+-]+)</filter-progress>");
  for (auto it = std::sregex_iterator(executable.Out.begin(), executable.Out.end(), line); it != std::sregex_iterator();
       ++it)
  {
    fractions.push_back(std::stod((*it)[1]));
  }
  ASSERT_GE(fractions.size(), 3u);
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_EQ(fractions.back(), 1.0);
  EXPECT_LT(executable.Out.find("<filter-start>"), executable.Out.find("<filter-progress>"));
  EXPECT_GT(executable.Out.find("<filter-end>"), executable.Out.rfind("<filter-progress>"));

  const ModuleRun library =
    vr::test::RunEntryPointInProcess(Library, { "ExtractCenterlines", segmentation, (folder / "lib.vtp").string() });
  ASSERT_EQ(library.ExitCode, 0) << library.Err;
  EXPECT_EQ(vr::test::ReadTextFile((folder / "exe.vtp").string()),
            vr::test::ReadTextFile((folder / "lib.vtp").string()));
  const char * xml = static_cast<const char *>(vr::test::LibrarySymbol(Library, "XMLModuleDescription"));
  ASSERT_NE(xml, nullptr);
  EXPECT_EQ(std::string(xml), XMLOf());
}

// ---------------------------------------------------------------------------------------------------------------
// Bad input: a message naming the file, field or flag; exit 1; no crash; no output; an existing output kept.

class ExtractCenterlinesBadInput : public ::testing::Test
{
protected:
  void
  SetUp() override
  {
    m_Folder = TestFolder();
    std::ofstream(m_Folder / "out.vtp") << "an earlier result that must survive";
  }

  /** Runs with \a arguments then the output, expects the failure, the mentions, no new file and the old output. */
  void
  ExpectRejected(std::vector<std::string> arguments, const std::vector<std::string> & mentions)
  {
    arguments.push_back((m_Folder / "out.vtp").string());
    const auto      before = vr::test::FolderEntries(m_Folder);
    const ModuleRun run = RunModule(arguments);
    EXPECT_FALSE(run.Crashed);
    EXPECT_EQ(run.ExitCode, 1) << run.Err;
    EXPECT_TRUE(Contains(run.Err, "ExtractCenterlines: error: ")) << run.Err;
    for (const auto & mention : mentions)
    {
      EXPECT_TRUE(Contains(run.Err, mention)) << "the message lacks \"" << mention << "\":\n" << run.Err;
    }
    std::cout << "  " << run.Err;
    EXPECT_EQ(vr::test::FolderEntries(m_Folder), before) << "a file appeared or vanished";
    EXPECT_EQ(vr::test::ReadTextFile((m_Folder / "out.vtp").string()), "an earlier result that must survive");
  }

  fs::path m_Folder;
};

TEST_F(ExtractCenterlinesBadInput, FuzzFindingsAreRefusedByName)
{
  // NIfTI headers whose NaN srow made ITK 5.2's reader abort in vnl's SVD (issue 25): sizeof_hdr is garbage, which
  // the NIfTI library ignores when dim[0] is valid.
  for (const char * name : { "nifti-nan-srow-abort.nii", "nifti-nan-srow-abort-2.nii" })
  {
    ExpectRejected({ std::string(VR_FINDINGS_DIR) + "/" + name }, { name, "NIfTI header field sizeof_hdr" });
  }
  // A corrupt DICOM file that makes GDCM abort, named like a segmentation: GDCM is not asked whether it reads it.
  const fs::path dicom = m_Folder / "mask.nrrd";
  fs::copy_file(fs::path(VR_FINDINGS_DIR) / "dicom-meta-explicit-assert" / "IM0018.dcm", dicom);
  ExpectRejected({ dicom.string() }, { "mask.nrrd" });
  // A MetaImage header with NDims = -3, on which MetaIO read 2^64 numbers (the fifth fuzzing round's hang).
  const fs::path mha = m_Folder / "mask.mha";
  vr::test::WriteTextFile(mha.string(),
                          "ObjectType = Image\nNDims =-3\nDimSize = 2 2 2\nElementType = MET_UCHAR\n"
                          "ElementDataFile = LOCAL\n" +
                            std::string(8, '\1'));
  ExpectRejected({ mha.string() }, { "mask.mha: MetaImage header line 2: NDims = -3" });
  fs::remove(mha);
}

TEST_F(ExtractCenterlinesBadInput, EmptyMask)
{
  auto empty = vr::test::MakeLabelMap({ { 20, 20, 20 } }, V(1, 1, 1), P(0, 0, 0), Identity());
  WriteTestImage(empty.GetPointer(), m_Folder / "empty.nii.gz");
  ExpectRejected({ (m_Folder / "empty.nii.gz").string() }, { "empty.nii.gz", "no vessel voxel: every voxel is 0" });
}

TEST_F(ExtractCenterlinesBadInput, NoForegroundInTheChosenLabels)
{
  WriteTestImage(TwoVessels().GetPointer(), m_Folder / "labels.nrrd");
  ExpectRejected({ "--labels", "3,9", (m_Folder / "labels.nrrd").string() },
                 { "--labels: ", "labels.nrrd", "no voxel with label 3, 9", "the values present are 0 2 7" });
  ExpectRejected({ "--labels", "-2", (m_Folder / "labels.nrrd").string() },
                 { "--labels: vessel labels: -2 is not a label" });
}

TEST_F(ExtractCenterlinesBadInput, TwoDimensionalImage)
{
  auto image = itk::Image<unsigned char, 2>::New();
  image->SetRegions(itk::Image<unsigned char, 2>::RegionType({ { 0, 0 } }, { { 32, 24 } }));
  image->Allocate(true);
  image->SetPixel({ { 5, 5 } }, 1);
  WriteTestImage(image.GetPointer(), m_Folder / "slice.nii.gz");
  ExpectRejected({ (m_Folder / "slice.nii.gz").string() },
                 { "slice.nii.gz", "a 2D image (32 x 24 pixels)", "must be 3D" });
}

TEST_F(ExtractCenterlinesBadInput, MissingUnreadableAndLevelSetWithLabels)
{
  ExpectRejected({ (m_Folder / "missing.nii.gz").string() }, { "missing.nii.gz", "no such file" });
  std::ofstream(m_Folder / "garbage.nrrd") << "NRRD0004\nthis is not a header\n";
  ExpectRejected({ (m_Folder / "garbage.nrrd").string() }, { "garbage.nrrd" });
  fs::remove(m_Folder / "garbage.nrrd");
  ExpectRejected({ "--labels", "1", (DataFolder / "aorta-final-levelset.mha").string() },
                 { "aorta-final-levelset.mha", "level set", "labels cannot be chosen" });
}

TEST_F(ExtractCenterlinesBadInput, NothingElongatedAndBadFlags)
{
  auto                image = vr::test::MakeLabelMap({ { 30, 30, 30 } }, V(1, 1, 1), P(0, 0, 0), Identity());
  itk::CenterlineTree ball;
  ball.AddBranch(vr::test::TubeBranch(1, { P(15, 15, 15), P(15, 15, 15) }, 7.0));
  vr::test::DrawTubes(image, ball);
  WriteTestImage(image.GetPointer(), m_Folder / "ball.nrrd");
  ExpectRejected({ (m_Folder / "ball.nrrd").string() }, { "ball.nrrd", "no centerline", "longer than it is wide" });
  ExpectRejected({ "--root", "1,2", (m_Folder / "ball.nrrd").string() }, { "--root", "three comma-separated numbers" });
  ExpectRejected({ "--minimumBranchLength", "-1", (m_Folder / "ball.nrrd").string() },
                 { "--minimumBranchLength", "must be >= 0" });
}

TEST_F(ExtractCenterlinesBadInput, OutputsAreCheckedBeforeTheWork)
{
  const std::string segmentation = (DataFolder / "aorta-final-levelset.mha").string();
  const auto        before = vr::test::FolderEntries(m_Folder);
  ModuleRun         run = RunModule({ segmentation, (m_Folder / "tree.stl").string() });
  EXPECT_EQ(run.ExitCode, 1);
  EXPECT_TRUE(Contains(run.Err, "tree.stl")) << run.Err;
  run = RunModule({ segmentation, (m_Folder / "no-such-folder" / "tree.vtp").string() });
  EXPECT_EQ(run.ExitCode, 1);
  EXPECT_TRUE(Contains(run.Err, "no-such-folder")) << run.Err;
  EXPECT_EQ(vr::test::FolderEntries(m_Folder), before);
}
} // namespace
