// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The command-line modules in the platforms' own machinery (issue 12): the module folder a platform scans, the two
// flavours of the description (CTK's schema for --xml, 3D Slicer's beside the module), the values the modules return
// (Slicer's --returnparameterfile, CTK's filter-result lines), a shared-library run on Slicer's in-memory image names,
// and the cut surface and centerline models in Slicer's model layout.

#include "vrCLIModuleDescription.h"
#include "vrCenterlineIO.h"
#include "vrImageIO.h"
#include "vrModuleRuns.h"
#include "vrSlicerMemoryImageIO.h"
#include "vrSurfaceIO.h"
#include "vrText.h"
#include "vrTestFiles.h"
#include "vrVolumeIO.h"

#include "itkImageRegionIteratorWithIndex.h"
#include "itkMetaDataObject.h"

#include <gtest/gtest.h>

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataReader.h>
#include <vtkPolyDataWriter.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLPolyDataWriter.h>

#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using vr::test::Contains;
namespace fs = std::filesystem;
using vr::test::ModuleRun;

const fs::path ModuleFolder = VR_CLI_MODULES_DIR;

/** The modules the build registers (vr_add_cli_module), from CMake's list (comma-separated). */
std::vector<std::string>
ModuleNames()
{
  std::vector<std::string> names;
  std::istringstream       list(VR_CLI_MODULE_NAMES);
  std::string              name;
  while (std::getline(list, name, ','))
  {
    if (!name.empty())
    {
      names.push_back(name);
    }
  }
  return names;
}

std::string
Executable(const std::string & module)
{
  return (ModuleFolder / module).string();
}

std::string
Library(const std::string & module)
{
  return (ModuleFolder / ("lib" + module + "Lib.so")).string();
}

bool
IsExecutableFile(const fs::path & path)
{
  struct stat status
  {
  };
  return ::stat(path.c_str(), &status) == 0 && (status.st_mode & (S_IXUSR | S_IXGRP | S_IXOTH)) != 0;
}

std::string
XMLOf(const std::string & module)
{
  const ModuleRun run = vr::test::RunProgram({ Executable(module), "--xml" }, 5.0);
  EXPECT_EQ(run.ExitCode, 0) << run.Err;
  return run.Out;
}

/** What 3D Slicer's ModuleDescription::ReadParameterFile reads from a return-parameter file: for each line, the key
 * before the first '=' and the value after it, both trimmed of blanks (SlicerExecutionModel, ModuleDescription.cxx). */
std::vector<std::pair<std::string, std::string>>
ReadSlicerParameterFile(const std::string & path)
{
  std::vector<std::pair<std::string, std::string>> entries;
  std::ifstream                                    file(path);
  std::string                                      line;
  const auto                                       trim = [](std::string text)
  {
    const auto first = text.find_first_not_of(" \t\r\n");
    if (first == std::string::npos)
    {
      return std::string();
    }
    return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
  };
  while (std::getline(file, line))
  {
    const auto start = line.find_first_not_of(" \t");
    if (start == std::string::npos)
    {
      continue;
    }
    const auto stop = line.find_first_of('=', start);
    if (stop == std::string::npos)
    {
      ADD_FAILURE() << "a line without '=' in " << path << ": " << line;
      continue;
    }
    entries.emplace_back(trim(line.substr(start, stop - start)), trim(line.substr(stop + 1)));
  }
  return entries;
}

/** The names of the parameters 3D Slicer returns, by its rule (ModuleParameter::IsReturnParameter): channel output,
 * no flag, no long flag, no index. */
std::vector<std::string>
SlicerReturnParameters(const vr::CLIModuleDescription & description)
{
  std::vector<std::string> names;
  for (const auto & parameter : description.Parameters)
  {
    if (parameter.Channel == "output" && parameter.LongFlag.empty() && parameter.Index < 0)
    {
      names.push_back(parameter.Name);
    }
  }
  return names;
}

/** The names of the parameters CTK returns, by its rule (ctkCmdLineModuleParameter::isReturnParameter): channel
 * output and index 1000. */
std::vector<std::string>
CTKReturnParameters(const vr::CLIModuleDescription & description)
{
  std::vector<std::string> names;
  for (const auto & parameter : description.Parameters)
  {
    if (parameter.Channel == "output" && parameter.Index == 1000)
    {
      names.push_back(parameter.Name);
    }
  }
  return names;
}

// ---------------------------------------------------------------------------------------------------------------
// The module folder.

TEST(ModuleFolder, HoldsOnlyTheModulesAndEachAnswersXMLWithinFiveSeconds)
{
  ASSERT_FALSE(ModuleNames().empty());
  std::set<std::string> expected;
  for (const auto & module : ModuleNames())
  {
    expected.insert({ module, "lib" + module + "Lib.so", module + ".xml" });
  }
  std::set<std::string> found;
  for (const auto & entry : fs::directory_iterator(ModuleFolder))
  {
    found.insert(entry.path().filename().string());
  }
  EXPECT_EQ(found, expected) << "the module folder must hold the modules and nothing else";

  for (const auto & module : ModuleNames())
  {
    // The executable: what 3D Slicer (files without a dot), MITK (every executable file) and a shell run. Slicer
    // gives --xml 5 s and reads any output on stderr as an error.
    EXPECT_TRUE(IsExecutableFile(Executable(module))) << module;
    const ModuleRun xml = vr::test::RunProgram({ Executable(module), "--xml" }, 5.0, ModuleFolder.string());
    EXPECT_FALSE(xml.TimedOut) << module << " --xml took more than 5 s";
    EXPECT_EQ(xml.ExitCode, 0) << module;
    EXPECT_EQ(xml.Err, "") << module;
    EXPECT_EQ(xml.Out.compare(0, 6, "<?xml "), 0) << module << ": Slicer's parser needs <?xml first";

    // The shared library: 3D Slicer loads it (lib<name>Lib.so) and reads XMLModuleDescription; its ModuleEntryPoint
    // answers --xml with the same text. Not executable, so that MITK's folder scan does not run it.
    EXPECT_FALSE(IsExecutableFile(Library(module))) << Library(module) << " is executable: MITK would run it";
    const auto * symbol = static_cast<const char *>(vr::test::LibrarySymbol(Library(module), "XMLModuleDescription"));
    ASSERT_NE(symbol, nullptr) << Library(module);
    const ModuleRun inProcess = vr::test::RunEntryPointInProcess(Library(module), { module, "--xml" }, 5.0);
    EXPECT_FALSE(inProcess.TimedOut) << module << " ModuleEntryPoint --xml took more than 5 s";
    EXPECT_EQ(inProcess.ExitCode, 0) << module;
    EXPECT_EQ(inProcess.Out, xml.Out) << module;
    EXPECT_EQ(std::string(symbol), xml.Out) << module;

    // The description beside them, under the names 3D Slicer looks for: <file's base name>.xml for the executable
    // (qSlicerCLIExecutableModuleFactoryItem), the library's name without "lib" and "Lib" (qSlicerUtils::
    // extractModuleNameFromLibraryName) for the library. Not executable either.
    const std::string libraryBase = fs::path(Library(module)).stem().string();
    const std::string libraryModule = libraryBase.substr(3, libraryBase.size() - 6);
    EXPECT_EQ(libraryModule, module);
    const fs::path sidecar = ModuleFolder / (module + ".xml");
    EXPECT_TRUE(fs::exists(sidecar));
    EXPECT_FALSE(IsExecutableFile(sidecar));
  }
}

TEST(ModuleFolder, SlicersDescriptionIsTheCTKOneWithReturnValuesDeclaredSlicersWay)
{
  for (const auto & module : ModuleNames())
  {
    const std::string ctk = XMLOf(module);
    const std::string slicer = vr::test::ReadTextFile((ModuleFolder / (module + ".xml")).string());
    // The same text but for the index lines of the returned values.
    std::string withoutReturnIndex = std::regex_replace(ctk, std::regex("\n *<index>1000</index>"), "");
    EXPECT_EQ(withoutReturnIndex, slicer) << module;
    EXPECT_NE(ctk, slicer) << module << " returns no value";

    // Each host finds the same returned values by its own rule, and the module's parser agrees with both.
    const auto ctkDescription = vr::CLIModuleDescription::FromXML(ctk.c_str());
    const auto slicerDescription = vr::CLIModuleDescription::FromXML(slicer.c_str());
    const auto byCTK = CTKReturnParameters(ctkDescription);
    EXPECT_FALSE(byCTK.empty()) << module;
    EXPECT_EQ(SlicerReturnParameters(slicerDescription), byCTK) << module;
    EXPECT_TRUE(SlicerReturnParameters(ctkDescription).empty()) << module << ": --xml must satisfy CTK's schema";
    std::vector<std::string> byParser;
    for (const auto * parameter : ctkDescription.ReturnValues())
    {
      byParser.push_back(parameter->Name);
    }
    EXPECT_EQ(byParser, byCTK) << module;
    // Nothing else differs: the positional parameters and the flags are the same in both.
    ASSERT_EQ(ctkDescription.Parameters.size(), slicerDescription.Parameters.size());
    for (std::size_t k = 0; k < ctkDescription.Parameters.size(); ++k)
    {
      const auto & a = ctkDescription.Parameters[k];
      const auto & b = slicerDescription.Parameters[k];
      EXPECT_EQ(a.Name, b.Name);
      EXPECT_EQ(a.LongFlag, b.LongFlag);
      EXPECT_EQ(a.IsReturnValue() ? -1 : a.Index, b.Index) << a.Name;
    }
  }
}

// ---------------------------------------------------------------------------------------------------------------
// A small scene made in code: a volume whose intensity is linear in LPS, so that every CPR pixel and every surface
// point has a value known in closed form, and straight centerlines.

/** The intensity of the test volume at the LPS point (x, y, z): the same at every y, so the depth does not matter. */
double
LinearIntensity(double x, double y, double z)
{
  (void)y;
  return 2.0 * x + 3.0 * z + 100.0;
}

/** 40 x 40 x 60 voxels of 1 mm, stored as 3D Slicer often gets them: the first two axes pointing to the patient's
 * right and anterior (direction diag(-1, -1, 1)), origin (19, 19, -30) LPS, so x and y run from 19 down to -20. */
itk::Image<short, 3>::Pointer
MakeLinearVolume()
{
  using Volume = itk::Image<short, 3>;
  auto volume = Volume::New();
  volume->SetRegions(Volume::SizeType{ { 40, 40, 60 } });
  Volume::DirectionType direction;
  direction.SetIdentity();
  direction[0][0] = -1.0;
  direction[1][1] = -1.0;
  volume->SetDirection(direction);
  const double origin[3] = { 19.0, 19.0, -30.0 };
  volume->SetOrigin(origin);
  volume->Allocate();
  itk::ImageRegionIteratorWithIndex<Volume> it(volume, volume->GetLargestPossibleRegion());
  for (; !it.IsAtEnd(); ++it)
  {
    Volume::PointType point;
    volume->TransformIndexToPhysicalPoint(it.GetIndex(), point);
    it.Set(static_cast<short>(LinearIntensity(point[0], point[1], point[2])));
  }
  return volume;
}

/** Straight vertical centerlines at x = \a xs (LPS), y = 0, z from -20 to 20 mm, with a lumen radius of 2 mm. */
vtkSmartPointer<vtkPolyData>
MakeVerticalCenterlinesLPS(const std::vector<double> & xs)
{
  auto points = vtkSmartPointer<vtkPoints>::New();
  auto lines = vtkSmartPointer<vtkCellArray>::New();
  auto radius = vtkSmartPointer<vtkDoubleArray>::New();
  radius->SetName("Radius");
  for (const double x : xs)
  {
    lines->InsertNextCell(41);
    for (int z = -20; z <= 20; ++z)
    {
      lines->InsertCellPoint(points->InsertNextPoint(x, 0.0, z));
      radius->InsertNextValue(2.0);
    }
  }
  auto polyData = vtkSmartPointer<vtkPolyData>::New();
  polyData->SetPoints(points);
  polyData->SetLines(lines);
  polyData->GetPointData()->AddArray(radius);
  return polyData;
}

/** Writes \a polyDataLPS as 3D Slicer's model storage writes a model node (vtkMRMLModelStorageNode, compression on):
 * .vtp appended and zlib-compressed with a "SPACE" field-data string array "LPS"; .vtk version 4.2, binary, with
 * the header "3D Slicer output. SPACE=LPS". The points are LPS already. */
void
WriteAsSlicerModel(vtkPolyData * polyDataLPS, const std::string & path)
{
  if (path.size() > 4 && path.compare(path.size() - 4, 4, ".vtp") == 0)
  {
    auto copy = vtkSmartPointer<vtkPolyData>::New();
    copy->ShallowCopy(polyDataLPS);
    auto space = vtkSmartPointer<vtkStringArray>::New();
    space->SetName("SPACE");
    space->InsertNextValue("LPS");
    copy->GetFieldData()->AddArray(space);
    auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
    writer->SetInputData(copy);
    writer->SetFileName(path.c_str());
    writer->SetCompressorType(vtkXMLWriter::ZLIB);
    writer->SetDataMode(vtkXMLWriter::Appended);
    ASSERT_EQ(writer->Write(), 1) << path;
    return;
  }
  auto writer = vtkSmartPointer<vtkPolyDataWriter>::New();
  writer->SetInputData(polyDataLPS);
  writer->SetFileName(path.c_str());
  writer->SetFileVersion(42);
  writer->SetFileType(VTK_BINARY);
  writer->SetHeader("3D Slicer output. SPACE=LPS");
  ASSERT_EQ(writer->Write(), 1) << path;
}

/** The argument list of a VesselReformation run on the linear scene: a 21 x 31 view of 1 mm pixels centred on the
 * centerlines, looking from anterior (up S, angle 0: screen-right is LPS +x, screen-down -z). */
std::vector<std::string>
LinearSceneView()
{
  return { "--size", "21,31", "--spacing", "1", "--backend", "cpu", "--iterations", "50" };
}

/** The CPR value of pixel (i, j) of that view: centre (x0, 0, 0), pixel (i, j) at x = x0 + i - 10, z = 15 - j. */
double
ExpectedCPR(unsigned int i, unsigned int j, double x0)
{
  return LinearIntensity(x0 + static_cast<double>(i) - 10.0, 0.0, 15.0 - static_cast<double>(j));
}

// ---------------------------------------------------------------------------------------------------------------
// In-process, on 3D Slicer's in-memory image names.

TEST(SlicerInMemory, TheSharedLibraryReadsAndWritesSlicerNamesAndNothingTouchesTheDisk)
{
  vr::test::SlicerMemoryImageIOFactory::RegisterOneFactory();
  vr::test::ScopedTemporaryFolder inputs;
  vr::test::ScopedTemporaryFolder workingFolder;
  // The centerlines: a model node, which Slicer always hands over as a file in its model layout.
  const std::string centerlines = inputs.File("BDAA_vtkMRMLModelNodeB.vtp");
  WriteAsSlicerModel(MakeVerticalCenterlinesLPS({ 0.0 }), centerlines);
  const auto inputFiles = inputs.Entries();

  vr::test::MemoryScene scene;
  scene.SetImage("vtkMRMLScalarVolumeNode1", MakeLinearVolume().GetPointer());
  // As Slicer runs a shared-library module (vtkSlicerCLIModuleLogic): its target ("slicer:" and the entry point's
  // address), the progress structure, the flags, then the positional arguments.
  vr::test::SlicerModuleProcessInformation information;
  std::vector<std::string>                 arguments = { "slicer:" + vr::test::AddressText(vr::test::LibrarySymbol(
                                                       Library("VesselReformation"), "ModuleEntryPoint")),
                                                         "--processinformationaddress",
                                                         vr::test::AddressText(&information) };
  for (const auto & argument : LinearSceneView())
  {
    arguments.push_back(argument);
  }
  arguments.insert(arguments.end(),
                   { "--outputDepth",
                     scene.NameOf("vtkMRMLScalarVolumeNode3"),
                     scene.NameOf("vtkMRMLScalarVolumeNode1"),
                     centerlines,
                     scene.NameOf("vtkMRMLScalarVolumeNode2") });
  const ModuleRun run =
    vr::test::RunEntryPointInProcess(Library("VesselReformation"), arguments, 0.0, workingFolder.Path().string());
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  EXPECT_EQ(information.Progress, 1.0f);

  // Nothing on disk: not in the working folder (where a name taken for a relative path would land), not beside the
  // centerlines, and the in-memory names were read and written through the scene's ImageIO.
  EXPECT_EQ(workingFolder.Entries(), std::vector<std::string>{});
  EXPECT_EQ(inputs.Entries(), inputFiles);
  ASSERT_NE(scene.FindNode("vtkMRMLScalarVolumeNode1"), nullptr);
  EXPECT_GE(scene.FindNode("vtkMRMLScalarVolumeNode1")->Reads, 1u);
  EXPECT_EQ(
    scene.NodeIds(),
    (std::vector<std::string>{ "vtkMRMLScalarVolumeNode1", "vtkMRMLScalarVolumeNode2", "vtkMRMLScalarVolumeNode3" }));

  // The CPR, in memory: every pixel the closed-form value of the volume on the plane through the centerline.
  const auto cpr = scene.GetImage<itk::Image<float, 2>>("vtkMRMLScalarVolumeNode2");
  ASSERT_NE(cpr, nullptr) << "the CPR node holds no 2D float image";
  EXPECT_EQ(scene.FindNode("vtkMRMLScalarVolumeNode2")->Writes, 1u);
  const auto size = cpr->GetLargestPossibleRegion().GetSize();
  ASSERT_EQ(size[0], 21u);
  ASSERT_EQ(size[1], 31u);
  double largestError = 0.0;
  for (unsigned int j = 0; j < size[1]; ++j)
  {
    for (unsigned int i = 0; i < size[0]; ++i)
    {
      const double value =
        cpr->GetPixel({ { static_cast<itk::IndexValueType>(i), static_cast<itk::IndexValueType>(j) } });
      largestError = std::max(largestError, std::abs(value - ExpectedCPR(i, j, 0.0)));
    }
  }
  EXPECT_LT(largestError, 1e-3) << "the CPR is not the volume sampled on the view plane";
  std::string up;
  EXPECT_TRUE(itk::ExposeMetaData<std::string>(cpr->GetMetaDataDictionary(), "CPR_Up", up));
  std::cout << "in-memory CPR " << size[0] << " x " << size[1] << ", largest deviation from the closed form "
            << largestError << "; view up " << up << std::endl;
  const auto depth = scene.GetImage<itk::Image<float, 2>>("vtkMRMLScalarVolumeNode3");
  ASSERT_NE(depth, nullptr);
  EXPECT_EQ(depth->GetLargestPossibleRegion().GetSize(), size);
}

// ---------------------------------------------------------------------------------------------------------------
// Return values.

/** The linear volume as NRRD and two vertical centerlines 10 mm apart as CSV (LPS), in a fresh folder. */
class LinearScene : public ::testing::Test
{
protected:
  void
  SetUp() override
  {
    vr::test::WriteTextFile(m_Folder.File("centerlines.csv"),
                            []
                            {
                              std::string text = "branch,x,y,z,radius\n";
                              for (const int x : { -5, 5 })
                              {
                                for (int z = -20; z <= 20; ++z)
                                {
                                  text += std::to_string(x == -5 ? 1 : 2) + "," + std::to_string(x) + ",0," +
                                          std::to_string(z) + ",1.5\n";
                                }
                              }
                              return text;
                            }());
    auto volume = MakeLinearVolume();
    auto floatVolume = vr::VolumeImageType::New();
    floatVolume->SetRegions(volume->GetLargestPossibleRegion());
    floatVolume->CopyInformation(volume);
    floatVolume->Allocate();
    for (std::size_t k = 0; k < volume->GetLargestPossibleRegion().GetNumberOfPixels(); ++k)
    {
      floatVolume->GetBufferPointer()[k] = volume->GetBufferPointer()[k];
    }
    vr::WriteVolume(floatVolume, m_Folder.File("volume.nrrd"));
  }

  /** \return \a program, the view's flags, \a flags, the volume and the centerlines, then \a tail (the output). */
  std::vector<std::string>
  Arguments(const std::string &              program,
            const std::vector<std::string> & flags,
            const std::vector<std::string> & tail) const
  {
    std::vector<std::string> arguments = { program };
    for (const auto & argument : LinearSceneView())
    {
      arguments.push_back(argument);
    }
    arguments.insert(arguments.end(), flags.begin(), flags.end());
    arguments.insert(arguments.end(), { m_Folder.File("volume.nrrd"), m_Folder.File("centerlines.csv") });
    arguments.insert(arguments.end(), tail.begin(), tail.end());
    return arguments;
  }

  std::map<std::string, std::string>
  CheckedParameterFile(const std::string & path, const std::string & module) const
  {
    const std::string text = vr::test::ReadTextFile(path);
    // One "name = value" line per returned value, nothing else.
    const std::regex   line("^[A-Za-z_][A-Za-z0-9_]* = [^ \n][^\n]*$");
    std::istringstream lines(text);
    std::string        each;
    while (std::getline(lines, each))
    {
      EXPECT_TRUE(std::regex_match(each, line)) << "\"" << each << "\"";
    }
    const auto                         entries = ReadSlicerParameterFile(path);
    std::vector<std::string>           keys;
    std::map<std::string, std::string> values;
    for (const auto & [key, value] : entries)
    {
      keys.push_back(key);
      values[key] = value;
    }
    const auto slicer =
      vr::CLIModuleDescription::FromXML(vr::test::ReadTextFile((ModuleFolder / (module + ".xml")).string()).c_str());
    EXPECT_EQ(keys, SlicerReturnParameters(slicer)) << text;
    return values;
  }

  vr::test::ScopedTemporaryFolder m_Folder;
};

class ReturnValues : public LinearScene
{
};
class SlicerModels : public LinearScene
{
};

/** \return \a text as a number, NaN when all of it is not one. */
double
Number(const std::string & text)
{
  double value = 0.0;
  return vr::ParseWholeDouble(text, value) ? value : std::nan("");
}

TEST_F(ReturnValues, ReformationWritesOneLinePerDeclaredOutputParameterAsSlicerReadsThem)
{
  const std::string file = m_Folder.File("returned.params");
  const ModuleRun   run =
    vr::test::RunProgram(Arguments(Executable("VesselReformation"),
                                   { "--returnparameterfile", file, "--outputSurface", m_Folder.File("surface.vtp") },
                                   { m_Folder.File("cpr.nrrd") }));
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  auto values = CheckedParameterFile(file, "VesselReformation");
  EXPECT_EQ(values["backendUsed"], "cpu");
  EXPECT_EQ(values["imageSize"], "21,31");
  EXPECT_EQ(values["numberOfBranches"], "2");
  for (const char * time : { "conversionTime", "depthTime", "relaxTime", "resampleTime", "surfaceTime" })
  {
    const double milliseconds = Number(values[time]);
    EXPECT_TRUE(std::isfinite(milliseconds)) << time << " = " << values[time];
    EXPECT_GE(milliseconds, 0.0) << time;
  }
  EXPECT_GT(Number(values["relaxTime"]), 0.0);
  EXPECT_GT(Number(values["surfaceTime"]), 0.0) << "a surface was built";
  std::cout << vr::test::ReadTextFile(file);

  // Without a surface its time is 0.
  const ModuleRun noSurface = vr::test::RunProgram(
    Arguments(Executable("VesselReformation"), { "--returnparameterfile", file }, { m_Folder.File("cpr.nrrd") }));
  ASSERT_EQ(noSurface.ExitCode, 0) << noSurface.Err;
  values = CheckedParameterFile(file, "VesselReformation");
  EXPECT_EQ(Number(values["surfaceTime"]), 0.0);
}

TEST_F(ReturnValues, InProcessWithSlicersArgumentsTheFileIsWrittenToo)
{
  // Slicer's order: target, --processinformationaddress, --returnparameterfile, flags, positional arguments.
  const std::string                        file = m_Folder.File("in-process.params");
  vr::test::SlicerModuleProcessInformation information;
  std::vector<std::string>                 arguments = {
                    "slicer:0x1", "--processinformationaddress", vr::test::AddressText(&information), "--returnparameterfile", file
  };
  const auto rest = Arguments("", {}, { m_Folder.File("cpr.nrrd") });
  arguments.insert(arguments.end(), rest.begin() + 1, rest.end());
  const ModuleRun run = vr::test::RunEntryPointInProcess(Library("VesselReformation"), arguments);
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  auto values = CheckedParameterFile(file, "VesselReformation");
  EXPECT_EQ(values["imageSize"], "21,31");
  EXPECT_EQ(values["numberOfBranches"], "2");
}

TEST_F(ReturnValues, CTKHostsGetFilterResultLinesAndTheirTrailingValueIsAccepted)
{
  // CTK's local-process backend passes the value of an index-1000 parameter after the positional arguments; the
  // module takes it as long as it is a value one of them can hold, and reports every value as a filter-result.
  const ModuleRun run =
    vr::test::RunProgram(Arguments(Executable("VesselReformation"), {}, { m_Folder.File("cpr.nrrd"), "none" }));
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  std::map<std::string, std::string> results;
  const std::regex                   result("<filter-result name=\"([A-Za-z_0-9]+)\">([^<]*)</filter-result>");
  for (auto it = std::sregex_iterator(run.Out.begin(), run.Out.end(), result); it != std::sregex_iterator(); ++it)
  {
    EXPECT_LT(static_cast<std::size_t>(it->position()), run.Out.find("<filter-end>"));
    results[(*it)[1]] = (*it)[2];
  }
  const auto               ctk = vr::CLIModuleDescription::FromXML(XMLOf("VesselReformation").c_str());
  std::vector<std::string> names;
  for (const auto & entry : results)
  {
    names.push_back(entry.first);
  }
  auto declared = CTKReturnParameters(ctk);
  std::sort(declared.begin(), declared.end());
  EXPECT_EQ(names, declared) << run.Out;
  EXPECT_EQ(results["numberOfBranches"], "2");
  EXPECT_EQ(results["imageSize"], "21,31");

  // More after the positional arguments than the one returned value a host appends is still refused. (One token alone
  // is taken for it: inputWarnings is text, which any token is, and a host passes back what it showed last.)
  const ModuleRun extra = vr::test::RunProgram(
    Arguments(Executable("VesselReformation"), {}, { m_Folder.File("cpr.nrrd"), "none", "extra.nrrd" }));
  EXPECT_EQ(extra.ExitCode, 1);
  EXPECT_TRUE(Contains(extra.Err, "unexpected argument")) << extra.Err;
  EXPECT_FALSE(fs::exists(m_Folder.File("extra.nrrd")));
}

TEST_F(ReturnValues, RelaxModuleReturnsItsBackendSizeAndTime)
{
  auto depth = vr::DepthImageType::New();
  depth->SetRegions(vr::DepthImageType::RegionType({ { 0, 0 } }, { { 24, 16 } }));
  depth->Allocate(true);
  vr::WriteImage2D(depth.GetPointer(), m_Folder.File("depth.nrrd"));
  const std::string file = m_Folder.File("relax.params");
  const ModuleRun   run = vr::test::RunProgram({ Executable("BilateralDepthRelax"),
                                                 "--backend",
                                                 "cpu",
                                                 "--returnparameterfile",
                                                 file,
                                                 m_Folder.File("depth.nrrd"),
                                                 m_Folder.File("relaxed.nrrd") });
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  auto values = CheckedParameterFile(file, "BilateralDepthRelax");
  EXPECT_EQ(values["backendUsed"], "cpu");
  EXPECT_EQ(values["imageSize"], "24,16");
  EXPECT_GE(Number(values["relaxTime"]), 0.0);
  // The backend's reason, in the log.
  EXPECT_TRUE(Contains(run.Out, "24 x 16 pixels")) << run.Out;
  EXPECT_TRUE(Contains(run.Out, "on cpu; relax backend: cpu requested\n")) << run.Out;

  // The steady solver asked for on OpenCL relaxes on the CPU, and the log says why.
  const ModuleRun steady = vr::test::RunProgram({ Executable("BilateralDepthRelax"),
                                                  "--backend",
                                                  "opencl",
                                                  "--solver",
                                                  "steady",
                                                  m_Folder.File("depth.nrrd"),
                                                  m_Folder.File("relaxed-steady.nrrd") });
  ASSERT_EQ(steady.ExitCode, 0) << steady.Err;
  EXPECT_TRUE(
    Contains(steady.Out, "on cpu; relax backend: opencl: the steady solver has no OpenCL kernel, so the CPU\n"))
    << steady.Out;
}

TEST_F(ReturnValues, AReturnParameterFileInAMissingFolderFailsBeforeTheWork)
{
  const std::string nowhere = m_Folder.File("no-such-folder/returned.params");
  const ModuleRun   run = vr::test::RunProgram(
    Arguments(Executable("VesselReformation"), { "--returnparameterfile", nowhere }, { m_Folder.File("cpr.nrrd") }));
  EXPECT_EQ(run.ExitCode, 1);
  EXPECT_TRUE(Contains(run.Err, "--returnparameterfile")) << run.Err;
  EXPECT_TRUE(Contains(run.Err, "no-such-folder")) << run.Err;
  EXPECT_FALSE(fs::exists(m_Folder.File("cpr.nrrd"))) << "the run went on";
}

// ---------------------------------------------------------------------------------------------------------------
// Models: the cut surface as Slicer writes models, centerlines in Slicer's model layout.

TEST_F(SlicerModels, TheCutSurfaceIsWrittenInLPSWithItsMarkerAndReadsBackHonouringIt)
{
  for (const std::string name : { "surface.vtp", "surface.vtk" })
  {
    const std::string path = m_Folder.File(name);
    const ModuleRun   run = vr::test::RunProgram(
      Arguments(Executable("VesselReformation"), { "--outputSurface", path }, { m_Folder.File("cpr.nrrd") }));
    ASSERT_EQ(run.ExitCode, 0) << run.Err;

    // The file as VTK reads it, with no help from us: the marker, and points in LPS (each point's intensity is the
    // linear volume's value there; in RAS, x would be negated and the 2x term would differ).
    vtkSmartPointer<vtkPolyData> raw;
    if (name == "surface.vtp")
    {
      auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
      reader->SetFileName(path.c_str());
      reader->Update();
      raw = reader->GetOutput();
      auto * space = vtkStringArray::SafeDownCast(raw->GetFieldData()->GetAbstractArray("SPACE"));
      ASSERT_NE(space, nullptr) << name;
      EXPECT_EQ(space->GetValue(0), "LPS");
    }
    else
    {
      auto reader = vtkSmartPointer<vtkPolyDataReader>::New();
      reader->SetFileName(path.c_str());
      reader->Update();
      raw = reader->GetOutput();
      EXPECT_TRUE(Contains(reader->GetHeader(), "SPACE=LPS")) << reader->GetHeader();
    }
    ASSERT_GT(raw->GetNumberOfPoints(), 0);
    vtkDataArray * intensity = raw->GetPointData()->GetArray("Intensity");
    ASSERT_NE(intensity, nullptr);
    double largestError = 0.0;
    for (vtkIdType k = 0; k < raw->GetNumberOfPoints(); ++k)
    {
      const double * p = raw->GetPoint(k);
      largestError = std::max(largestError, std::abs(intensity->GetTuple1(k) - LinearIntensity(p[0], p[1], p[2])));
    }
    EXPECT_LT(largestError, 1e-3) << name << ": the points are not where their intensity was sampled (LPS)";

    // Read back the way Slicer does: the marker decides.
    vr::CoordinateSpace stored = vr::CoordinateSpace::Auto;
    const auto          ras = vr::ReadSurface(path, vr::CoordinateSpace::RAS, &stored);
    EXPECT_EQ(stored, vr::CoordinateSpace::LPS) << name;
    ASSERT_EQ(ras->GetNumberOfPoints(), raw->GetNumberOfPoints());
    for (vtkIdType k = 0; k < raw->GetNumberOfPoints(); k += 37)
    {
      EXPECT_EQ(ras->GetPoint(k)[0], -raw->GetPoint(k)[0]);
      EXPECT_EQ(ras->GetPoint(k)[1], -raw->GetPoint(k)[1]);
      EXPECT_EQ(ras->GetPoint(k)[2], raw->GetPoint(k)[2]);
    }
    std::cout << name << ": " << raw->GetNumberOfPoints() << " points, SPACE=LPS, largest intensity deviation "
              << largestError << std::endl;
  }
}

TEST_F(SlicerModels, CenterlinesInSlicersModelLayoutGiveTheCPRTheirCSVGives)
{
  // The same two centerlines as the CSV, written as Slicer writes a model node (LPS, SPACE marker, Radius).
  auto model = MakeVerticalCenterlinesLPS({ -5.0, 5.0 });
  auto radius = vtkDoubleArray::SafeDownCast(model->GetPointData()->GetArray("Radius"));
  for (vtkIdType k = 0; k < radius->GetNumberOfTuples(); ++k)
  {
    radius->SetValue(k, 1.5);
  }
  WriteAsSlicerModel(model, m_Folder.File("model.vtp"));
  WriteAsSlicerModel(model, m_Folder.File("model.vtk"));
  const ModuleRun fromCSV =
    vr::test::RunProgram(Arguments(Executable("VesselReformation"), {}, { m_Folder.File("csv.nrrd") }));
  ASSERT_EQ(fromCSV.ExitCode, 0) << fromCSV.Err;
  const auto expected = vr::ReadDepthImage(m_Folder.File("csv.nrrd"));
  for (const std::string name : { "model.vtp", "model.vtk" })
  {
    std::vector<std::string> arguments = { Executable("VesselReformation") };
    for (const auto & argument : LinearSceneView())
    {
      arguments.push_back(argument);
    }
    arguments.insert(arguments.end(),
                     { m_Folder.File("volume.nrrd"), m_Folder.File(name), m_Folder.File(name + ".nrrd") });
    const ModuleRun run = vr::test::RunProgram(arguments);
    ASSERT_EQ(run.ExitCode, 0) << run.Err;
    EXPECT_FALSE(Contains(run.Err, "outside the volume")) << run.Err;
    EXPECT_TRUE(Contains(run.Out, "2 branches")) << run.Out;
    const auto cpr = vr::ReadDepthImage(m_Folder.File(name + ".nrrd"));
    ASSERT_EQ(cpr->GetLargestPossibleRegion(), expected->GetLargestPossibleRegion());
    for (std::size_t k = 0; k < cpr->GetLargestPossibleRegion().GetNumberOfPixels(); ++k)
    {
      ASSERT_EQ(cpr->GetBufferPointer()[k], expected->GetBufferPointer()[k]) << name << " pixel " << k;
    }
  }
}
} // namespace
