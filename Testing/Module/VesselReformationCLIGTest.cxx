// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The command-line modules as 3D Slicer and a shell use them: the built executables and shared libraries are run
// (their paths come from CMake), their XML is parsed, their outputs read back, and every bad input of issue 3 is
// tried.

#include "vrCLIProgress.h"
#include "vrCenterlineIO.h"
#include "vrFilterSettingsText.h"
#include "vrImageIO.h"
#include "vrModuleDescription.h"
#include "vrReformationParameters.h"
#include "PlainBilateralDepthRelax.h"
#include "vrModuleRuns.h"
#include "vrTestFiles.h"
#include "vrTestImages.h"
#include "vrVolumeIO.h"

#include "itkGDCMImageIO.h"
#include "itkImageFileWriter.h"
#include "itkImageSeriesWriter.h"

#include "itkMetaDataObject.h"

#include <gtest/gtest.h>

#include <vtkNew.h>
#include <vtkXMLDataElement.h>
#include <vtkXMLDataParser.h>

#include <dlfcn.h>
#include <fcntl.h>
#include <csignal>
#include <sys/mount.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <thread>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

extern char ** environ;

namespace
{
using vr::test::Contains;
namespace fs = std::filesystem;

const std::string ReformationExecutable = VR_REFORMATION_EXE;
const std::string ReformationLibrary = VR_REFORMATION_LIB;
const std::string RelaxExecutable = VR_RELAX_EXE;
const std::string RelaxLibrary = VR_RELAX_LIB;
const fs::path    DataFolder = fs::path(VR_SHARED_DATA_DIR) / "vmtk-aorta-mra";

/** The SlicerExecutionModel ModuleProcessInformation layout, written here from Slicer's header independently of
 * the module's own copy, so that a layout mismatch fails. */
struct SlicerProcessInformation
{
  unsigned char Abort;
  float         Progress;
  float         StageProgress;
  char          ProgressMessage[1024];
  void (*ProgressCallbackFunction)(void *);
  void * ProgressCallbackClientData;
  double ElapsedTime;
};

using vr::test::RunLimits;
using vr::test::RunProgram;
using RunResult = vr::test::ModuleRun;

std::string
ReadText(const fs::path & path)
{
  std::ifstream      file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

void
WriteText(const fs::path & path, const std::string & text)
{
  std::ofstream file(path, std::ios::binary);
  file << text;
}

/** A fresh folder for one test, under the build tree. File systems an interrupted earlier run left mounted inside
 * it (the full-disk and read-only tests mount small ones) are unmounted first. */
fs::path
TestFolder()
{
  const auto *   info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path folder = fs::path(VR_TEST_OUTPUT_DIR) / (std::string(info->test_suite_name()) + "." + info->name());
  std::ifstream  mounts("/proc/mounts");
  std::string    device;
  std::string    mountPoint;
  std::string    rest;
  while (mounts >> device >> mountPoint && std::getline(mounts, rest))
  {
    if (mountPoint.rfind(folder.string() + "/", 0) == 0)
    {
      ::umount2(mountPoint.c_str(), MNT_DETACH);
    }
  }
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

template<typename TSymbol>
TSymbol
LoadSymbol(const std::string & library, const char * name)
{
  void * handle = dlopen(library.c_str(), RTLD_NOW | RTLD_LOCAL);
  EXPECT_NE(handle, nullptr) << dlerror();
  if (handle == nullptr)
  {
    return nullptr;
  }
  return reinterpret_cast<TSymbol>(dlsym(handle, name));
}

using EntryPoint = int (*)(int, char **);

/** Calls a shared library's ModuleEntryPoint in this process, as 3D Slicer does, capturing stdout and stderr. */
RunResult
RunInProcess(const std::string & library, const std::vector<std::string> & arguments)
{
  RunResult  result;
  EntryPoint entry = LoadSymbol<EntryPoint>(library, "ModuleEntryPoint");
  if (entry == nullptr)
  {
    ADD_FAILURE() << library << " has no ModuleEntryPoint";
    return result;
  }
  const fs::path capture = fs::path(VR_TEST_OUTPUT_DIR) / ".capture";
  fs::create_directories(capture);
  const fs::path           out = capture / ("in-process-out-" + std::to_string(::getpid()) + ".txt");
  const fs::path           err = capture / ("in-process-err-" + std::to_string(::getpid()) + ".txt");
  std::vector<std::string> copies = arguments;
  std::vector<char *>      argv;
  for (auto & argument : copies)
  {
    argv.push_back(argument.data());
  }
  argv.push_back(nullptr);

  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  const int savedOut = dup(STDOUT_FILENO);
  const int savedErr = dup(STDERR_FILENO);
  const int outFile = open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  const int errFile = open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  dup2(outFile, STDOUT_FILENO);
  dup2(errFile, STDERR_FILENO);
  result.ExitCode = entry(static_cast<int>(copies.size()), argv.data());
  std::cout.flush();
  std::cerr.flush();
  std::fflush(nullptr);
  dup2(savedOut, STDOUT_FILENO);
  dup2(savedErr, STDERR_FILENO);
  close(outFile);
  close(errFile);
  close(savedOut);
  close(savedErr);
  result.Out = ReadText(out);
  result.Err = ReadText(err);
  return result;
}

/** The files of a folder, by name. */
std::set<std::string>
FilesIn(const fs::path & folder)
{
  std::set<std::string> names;
  for (const auto & entry : fs::directory_iterator(folder))
  {
    names.insert(entry.path().filename().string());
  }
  return names;
}

// ---------------------------------------------------------------------------------------------------------------
// The XML description.

struct ParsedXML
{
  vtkNew<vtkXMLDataParser> Parser;
  vtkXMLDataElement *      Root{ nullptr };
};

/** Parses with VTK's expat-based parser, which rejects XML that is not well-formed. */
std::unique_ptr<ParsedXML>
ParseXML(const std::string & xml)
{
  auto               parsed = std::make_unique<ParsedXML>();
  std::istringstream stream(xml);
  parsed->Parser->SetStream(&stream);
  parsed->Parser->SetIgnoreCharacterData(0);
  if (!parsed->Parser->Parse())
  {
    return nullptr;
  }
  parsed->Root = parsed->Parser->GetRootElement();
  return parsed;
}

std::string
Text(vtkXMLDataElement * element)
{
  const char * data = element ? element->GetCharacterData() : nullptr;
  std::string  text = data ? data : "";
  const auto   first = text.find_first_not_of(" \t\r\n");
  return first == std::string::npos ? std::string() : text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

struct XMLParameter
{
  std::string              Tag;
  std::string              Name;
  std::string              LongFlag;
  std::string              Index;
  std::string              Default;
  bool                     HasDefault{ false };
  std::string              Channel;
  std::vector<std::string> Elements;
  std::vector<std::string> ChildOrder;
};

std::vector<XMLParameter>
ParametersOf(vtkXMLDataElement * root)
{
  std::vector<XMLParameter> parameters;
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
      for (int c = 0; c < element->GetNumberOfNestedElements(); ++c)
      {
        vtkXMLDataElement * child = element->GetNestedElement(c);
        const std::string   name = child->GetName();
        parameter.ChildOrder.push_back(name);
        if (name == "name")
        {
          parameter.Name = Text(child);
        }
        else if (name == "longflag")
        {
          parameter.LongFlag = Text(child);
        }
        else if (name == "index")
        {
          parameter.Index = Text(child);
        }
        else if (name == "default")
        {
          parameter.Default = Text(child);
          parameter.HasDefault = true;
        }
        else if (name == "channel")
        {
          parameter.Channel = Text(child);
        }
        else if (name == "element")
        {
          parameter.Elements.push_back(Text(child));
        }
      }
      parameters.push_back(parameter);
    }
  }
  return parameters;
}

std::string
XMLOf(const std::string & executable)
{
  const RunResult result = RunProgram({ executable, "--xml" });
  EXPECT_EQ(result.ExitCode, 0) << result.Err;
  return result.Out;
}

class ModuleXMLTest : public ::testing::TestWithParam<std::string>
{
};

TEST_P(ModuleXMLTest, IsWellFormedAndFollowsTheElementOrder)
{
  const std::string xml = XMLOf(GetParam());
  ASSERT_EQ(xml.compare(0, 5, "<?xml"), 0) << "3D Slicer only accepts a description that starts with <?xml";
  const auto parsed = ParseXML(xml);
  ASSERT_NE(parsed, nullptr) << "not well-formed:\n" << xml;
  vtkXMLDataElement * root = parsed->Root;
  EXPECT_STREQ(root->GetName(), "executable");

  const std::vector<std::string> header = { "category",          "title",   "description", "version",
                                            "documentation-url", "license", "contributor", "acknowledgements" };
  ASSERT_GT(root->GetNumberOfNestedElements(), static_cast<int>(header.size()));
  for (std::size_t k = 0; k < header.size(); ++k)
  {
    EXPECT_EQ(root->GetNestedElement(static_cast<int>(k))->GetName(), header[k]) << "element " << k;
  }
  for (int k = static_cast<int>(header.size()); k < root->GetNumberOfNestedElements(); ++k)
  {
    EXPECT_STREQ(root->GetNestedElement(k)->GetName(), "parameters") << "element " << k;
  }
  EXPECT_EQ(Text(root->FindNestedElementWithName("category")), "Vascular");
  const std::string acknowledgements = Text(root->FindNestedElementWithName("acknowledgements"));
  for (const char * part : { "Kretschmer",
                             "Preim",
                             "Stamminger",
                             "Bilateral Depth Filtering for Enhanced Vessel Reformation",
                             "EuroVis",
                             "2014",
                             "short paper" })
  {
    EXPECT_TRUE(Contains(acknowledgements, part)) << acknowledgements << " lacks " << part;
  }
  EXPECT_FALSE(Text(root->FindNestedElementWithName("description")).empty());
  // One source: the description platforms include says the same.
  EXPECT_EQ(Text(root->FindNestedElementWithName("category")), vr::ModuleDescription::Category);
  EXPECT_EQ(Text(root->FindNestedElementWithName("version")), vr::ModuleDescription::Version);
  EXPECT_EQ(Text(root->FindNestedElementWithName("contributor")), vr::ModuleDescription::Contributors);
  EXPECT_EQ(acknowledgements, vr::ModuleDescription::Acknowledgements);
  EXPECT_FALSE(std::string(vr::ModuleDescription::Contributors).empty());

  // Inside a parameter, CTK's schema (paramType and its extensions) fixes the order: name, longflag or index,
  // description, label, default, channel, then the type's own elements or constraints. docs/design.md 3.8 had label
  // before description; the schema wins (issue 12). ModuleXMLValidatesAgainstCTKSchema checks the whole schema with
  // xmllint.
  const std::map<std::string, int> rank = { { "name", 0 },        { "longflag", 1 }, { "index", 1 },
                                            { "description", 2 }, { "label", 3 },    { "default", 4 },
                                            { "channel", 5 },     { "element", 6 },  { "constraints", 6 } };
  std::set<std::string>            names;
  for (const auto & parameter : ParametersOf(root))
  {
    EXPECT_TRUE(names.insert(parameter.Name).second) << "two parameters named " << parameter.Name;
    EXPECT_NE(parameter.LongFlag.empty(), parameter.Index.empty()) << parameter.Name << ": longflag or index";
    int previous = -1;
    for (const auto & child : parameter.ChildOrder)
    {
      ASSERT_TRUE(rank.count(child)) << parameter.Name << " has an unexpected <" << child << ">";
      EXPECT_GE(rank.at(child), previous) << parameter.Name << ": <" << child << "> out of order";
      previous = rank.at(child);
    }
    const bool isFile = parameter.Tag == "image" || parameter.Tag == "file" || parameter.Tag == "geometry" ||
                        parameter.Tag == "directory";
    // A value the module returns: an output with CTK's index 1000 (the flavour --xml prints).
    const bool isReturned = parameter.Index == "1000";
    EXPECT_EQ(isFile || isReturned, !parameter.Channel.empty())
      << parameter.Name << ": files and returned values, and nothing else, have a channel";
    if (isReturned)
    {
      EXPECT_EQ(parameter.Channel, "output") << parameter.Name;
      EXPECT_FALSE(parameter.Default.empty()) << parameter.Name << ": a host passes the value of index 1000";
    }
    if (parameter.Tag == "string-enumeration")
    {
      EXPECT_FALSE(parameter.Elements.empty()) << parameter.Name;
      EXPECT_NE(std::find(parameter.Elements.begin(), parameter.Elements.end(), parameter.Default),
                parameter.Elements.end())
        << parameter.Name << ": the default is not one of the elements";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(BothModules,
                         ModuleXMLTest,
                         ::testing::Values(ReformationExecutable, RelaxExecutable),
                         [](const ::testing::TestParamInfo<std::string> & info)
                         { return fs::path(info.param).filename().string(); });

/** The long flags of an XML description. */
std::set<std::string>
FlagsOfXML(const std::string & xml)
{
  const auto            parsed = ParseXML(xml);
  std::set<std::string> flags;
  for (const auto & parameter : ParametersOf(parsed->Root))
  {
    if (!parameter.LongFlag.empty())
    {
      flags.insert(parameter.LongFlag);
    }
  }
  return flags;
}

/** A value of the right kind for a flag of this tag. */
std::string
SampleValue(const XMLParameter & parameter)
{
  if (!parameter.Elements.empty())
  {
    return parameter.Elements.back();
  }
  if (parameter.Tag == "integer" || parameter.Tag == "float")
  {
    return "1";
  }
  if (parameter.Tag == "integer-vector" || parameter.Tag == "float-vector")
  {
    return "8,8";
  }
  return "some-file.nrrd";
}

void
ExpectFlagsAreExactlyTheXMLs(const std::string & executable, const std::set<std::string> & expectedFlags)
{
  const std::string xml = XMLOf(executable);
  const auto        xmlFlags = FlagsOfXML(xml);
  EXPECT_EQ(xmlFlags, expectedFlags);

  // The usage lists exactly the XML's flags and the four every Slicer module takes.
  const RunResult help = RunProgram({ executable, "--help" });
  ASSERT_EQ(help.ExitCode, 0) << help.Err;
  std::set<std::string> helpFlags;
  const std::regex      flagAtLineStart("(^|\\n)  --([A-Za-z]+)");
  for (auto it = std::sregex_iterator(help.Out.begin(), help.Out.end(), flagAtLineStart); it != std::sregex_iterator();
       ++it)
  {
    helpFlags.insert((*it)[2]);
  }
  std::set<std::string> withReserved = xmlFlags;
  withReserved.insert({ "xml", "help", "processinformationaddress", "returnparameterfile" });
  EXPECT_EQ(helpFlags, withReserved) << help.Out;

  // The parser accepts each XML flag (it then misses the positional arguments), and nothing else.
  const auto parsed = ParseXML(xml);
  for (const auto & parameter : ParametersOf(parsed->Root))
  {
    if (parameter.LongFlag.empty())
    {
      continue;
    }
    const RunResult result = RunProgram({ executable, "--" + parameter.LongFlag, SampleValue(parameter) });
    EXPECT_NE(result.ExitCode, 0);
    EXPECT_FALSE(Contains(result.Err, "unknown flag")) << parameter.LongFlag << ": " << result.Err;
    EXPECT_TRUE(Contains(result.Err, "missing the first argument")) << parameter.LongFlag << ": " << result.Err;
  }
  for (const std::string flag : { "--bogus", "--Angle", "--output", "--fixlumen", "--outputcpr", "--mask2" })
  {
    if (xmlFlags.count(flag.substr(2)))
    {
      continue;
    }
    const RunResult result = RunProgram({ executable, flag, "1" });
    EXPECT_EQ(result.ExitCode, 1) << flag;
    EXPECT_TRUE(Contains(result.Err, "unknown flag " + flag)) << flag << ": " << result.Err;
  }
}

TEST(ModuleFlags, VesselReformationAcceptsExactlyItsXMLFlags)
{
  ExpectFlagsAreExactlyTheXMLs(ReformationExecutable,
                               { "angle",
                                 "up",
                                 "mode",
                                 "size",
                                 "spacing",
                                 "relaxation",
                                 "anisotropy",
                                 "jumpThreshold",
                                 "solver",
                                 "iterations",
                                 "fixLumen",
                                 "backend",
                                 "openclDevice",
                                 "interpolation",
                                 "slabThickness",
                                 "slabMode",
                                 "centerlineSpace",
                                 "segmentation",
                                 "outputDepth",
                                 "outputRelaxedDepth",
                                 "outputMask",
                                 "outputLabels",
                                 "outputUnfilteredCPR",
                                 "outputSurface",
                                 "outputPNG",
                                 "window",
                                 "level",
                                 "rotationSeries",
                                 "rotationAngles" });
}

TEST(ModuleFlags, BilateralDepthRelaxAcceptsExactlyItsXMLFlags)
{
  ExpectFlagsAreExactlyTheXMLs(
    RelaxExecutable,
    { "mask", "relaxation", "jumpThreshold", "anisotropy", "iterations", "solver", "backend", "openclDevice" });
}

TEST(ModuleDescription, TitlesAreTheModulesAndHelpIsTheDescriptions)
{
  const auto reformation = ParseXML(XMLOf(ReformationExecutable));
  const auto relax = ParseXML(XMLOf(RelaxExecutable));
  EXPECT_EQ(Text(reformation->Root->FindNestedElementWithName("title")), "Vessel Reformation");
  EXPECT_EQ(Text(reformation->Root->FindNestedElementWithName("title")), vr::ModuleDescription::Title);
  EXPECT_EQ(Text(reformation->Root->FindNestedElementWithName("description")), vr::ModuleDescription::Help);
  EXPECT_EQ(std::string(vr::ModuleDescription::Category), "Vascular");
  // 3D Slicer keys modules by title: the relax module needs its own.
  EXPECT_NE(Text(relax->Root->FindNestedElementWithName("title")), vr::ModuleDescription::Title);
}

TEST(ModuleFlags, PositionalArgumentsAndDefaultsAreDESIGNs)
{
  const auto                          parsed = ParseXML(XMLOf(ReformationExecutable));
  std::map<std::string, XMLParameter> byName;
  for (const auto & parameter : ParametersOf(parsed->Root))
  {
    byName[parameter.Name] = parameter;
  }
  EXPECT_EQ(byName["inputVolume"].Index, "0");
  EXPECT_EQ(byName["inputCenterlines"].Index, "1");
  EXPECT_EQ(byName["outputCPR"].Index, "2");
  EXPECT_EQ(byName["outputCPR"].Channel, "output");
  // docs/design.md: w = 1, 500 Jacobi iterations, scanline, linear; issue 13: the range kernel unset in the XML
  // (neither
  // --jumpThreshold nor --anisotropy is passed unless the user gives it) and J = 3 mm in the parameter object.
  const vr::ReformationParameters defaults;
  EXPECT_EQ(std::stod(byName["relaxation"].Default), 1.0);
  EXPECT_EQ(byName["anisotropy"].Default, "");
  EXPECT_EQ(byName["jumpThreshold"].Default, "");
  EXPECT_EQ(byName["solver"].Default, "jacobi");
  EXPECT_EQ(byName["iterations"].Default, "500");
  EXPECT_EQ(byName["mode"].Default, "scanline");
  EXPECT_EQ(byName["interpolation"].Default, "linear");
  EXPECT_EQ(byName["fixLumen"].Default, "on");
  EXPECT_EQ(byName["up"].Default, "S");
  EXPECT_EQ(defaults.Relaxation, 1.0);
  EXPECT_FALSE(defaults.Anisotropy.has_value());
  EXPECT_FALSE(defaults.JumpThreshold.has_value());
  EXPECT_EQ(defaults.EffectiveAnisotropy(), 1.0 / 9.0);
  EXPECT_EQ(defaults.Solver, itk::BilateralDepthRelaxSolver::Jacobi);
  EXPECT_EQ(defaults.Iterations, 500);
  EXPECT_EQ(defaults.Mode, itk::CPRDepthMode::Scanline);
  EXPECT_EQ(defaults.Interpolation, itk::CPRInterpolationMode::Linear);
  EXPECT_TRUE(defaults.FixLumen);
}

// ---------------------------------------------------------------------------------------------------------------
// The shared libraries.

/** A small depth map with a CPR-like step and a fixed mask, written through the module's own writer. */
void
WriteSmallDepthAndMask(const fs::path & depthPath, const fs::path & maskPath)
{
  auto                                 depth = vr::DepthImageType::New();
  auto                                 mask = vr::MaskImageType::New();
  const vr::DepthImageType::RegionType region({ { 0, 0 } }, { { 24, 16 } });
  depth->SetRegions(region);
  depth->Allocate();
  mask->SetRegions(region);
  mask->Allocate();
  for (unsigned int k = 0; k < 24 * 16; ++k)
  {
    const unsigned int column = k % 24;
    const unsigned int row = k / 24;
    depth->GetBufferPointer()[k] = column < 12 ? 2.0f : 5.0f + 0.1f * static_cast<float>(row);
    mask->GetBufferPointer()[k] = column == 3 || column == 20 ? 1 : 0;
  }
  vr::WriteImage2D(depth.GetPointer(), depthPath.string());
  vr::WriteImage2D(mask.GetPointer(), maskPath.string());
}

TEST(SharedLibraries, ExposeBothSymbolsAndTheExecutablesXML)
{
  for (const auto & [library, executable] :
       { std::make_pair(ReformationLibrary, ReformationExecutable), std::make_pair(RelaxLibrary, RelaxExecutable) })
  {
    const char * xml = LoadSymbol<const char *>(library, "XMLModuleDescription");
    ASSERT_NE(xml, nullptr) << library;
    EXPECT_NE(LoadSymbol<EntryPoint>(library, "ModuleEntryPoint"), nullptr) << library;
    EXPECT_EQ(std::string(xml), XMLOf(executable)) << library;
  }
}

TEST(SharedLibraries, RelaxEntryPointWritesWhatTheExecutableWrites)
{
  const fs::path folder = TestFolder();
  WriteSmallDepthAndMask(folder / "depth.nrrd", folder / "mask.nrrd");
  const std::vector<std::string> flags = {
    "--mask", (folder / "mask.nrrd").string(), "--iterations", "40", "--anisotropy", "0.25", "--backend", "cpu"
  };
  std::vector<std::string> byExecutable = { RelaxExecutable };
  byExecutable.insert(byExecutable.end(), flags.begin(), flags.end());
  byExecutable.push_back((folder / "depth.nrrd").string());
  byExecutable.push_back((folder / "by-executable.nrrd").string());
  std::vector<std::string> byLibrary = { "BilateralDepthRelax" };
  byLibrary.insert(byLibrary.end(), flags.begin(), flags.end());
  byLibrary.push_back((folder / "depth.nrrd").string());
  byLibrary.push_back((folder / "by-library.nrrd").string());

  const RunResult executable = RunProgram(byExecutable);
  const RunResult library = RunInProcess(RelaxLibrary, byLibrary);
  ASSERT_EQ(executable.ExitCode, 0) << executable.Err;
  ASSERT_EQ(library.ExitCode, 0) << library.Err;
  EXPECT_EQ(ReadText(folder / "by-executable.nrrd"), ReadText(folder / "by-library.nrrd"));
  EXPECT_TRUE(Contains(library.Out, "<filter-end>")) << library.Out;
}

TEST(SharedLibraries, ReformationEntryPointWritesWhatTheExecutableWrites)
{
  const fs::path folder = TestFolder();
  const auto     arguments = [&](const std::string & program, const std::string & prefix)
  {
    return std::vector<std::string>{ program,
                                     "--up",
                                     "auto",
                                     "--iterations",
                                     "50",
                                     "--backend",
                                     "cpu",
                                     "--outputRelaxedDepth",
                                     (folder / (prefix + "-relaxed.nrrd")).string(),
                                     "--outputSurface",
                                     (folder / (prefix + "-surface.vtp")).string(),
                                     (DataFolder / "aorta.mha").string(),
                                     (DataFolder / "aorta-centerline.vtp").string(),
                                     (folder / (prefix + "-cpr.nrrd")).string() };
  };
  const RunResult executable = RunProgram(arguments(ReformationExecutable, "exe"));
  const RunResult library = RunInProcess(ReformationLibrary, arguments("VesselReformation", "lib"));
  ASSERT_EQ(executable.ExitCode, 0) << executable.Err;
  ASSERT_EQ(library.ExitCode, 0) << library.Err;
  for (const char * suffix : { "-cpr.nrrd", "-relaxed.nrrd", "-surface.vtp" })
  {
    const std::string fromExecutable = ReadText(folder / (std::string("exe") + suffix));
    EXPECT_FALSE(fromExecutable.empty()) << suffix;
    EXPECT_EQ(fromExecutable, ReadText(folder / (std::string("lib") + suffix))) << suffix;
  }
}

TEST(SharedLibraries, ReportProgressThroughSlicersStructure)
{
  const fs::path folder = TestFolder();
  WriteSmallDepthAndMask(folder / "depth.nrrd", folder / "mask.nrrd");

  SlicerProcessInformation information{};
  int                      calls = 0;
  information.ProgressCallbackClientData = &calls;
  information.ProgressCallbackFunction = [](void * data) { ++*static_cast<int *>(data); };
  char address[64];
  std::snprintf(address, sizeof(address), "%p", static_cast<void *>(&information));

  const RunResult run = RunInProcess(RelaxLibrary,
                                     { "BilateralDepthRelax",
                                       "--processinformationaddress",
                                       address,
                                       "--iterations",
                                       "100",
                                       "--backend",
                                       "cpu",
                                       (folder / "depth.nrrd").string(),
                                       (folder / "out.nrrd").string() });
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  EXPECT_EQ(information.Progress, 1.0f);
  EXPECT_GT(calls, 10);
  EXPECT_GE(information.ElapsedTime, 0.0);
  EXPECT_FALSE(Contains(run.Out, "<filter-progress>")) << "in-process progress goes to the structure, not stdout";
  EXPECT_TRUE(fs::exists(folder / "out.nrrd"));
}

// ---------------------------------------------------------------------------------------------------------------
// Cancelling through Slicer's structure (issue 12): 3D Slicer sets Abort while the module runs in its processing
// thread; the run must stop within the iteration it is in, write nothing, and return what Slicer's CLI logic reads
// as "Cancelled": 0 (a non-zero value turns the status into "Completed with errors").

/** What Slicer's progress callback sees during a run that it cancels as soon as the relaxation reports. */
struct CancelProbe
{
  SlicerProcessInformation * Information{ nullptr };
  bool                       AbortSet{ false };
  float                      ProgressAtAbort{ 0.0f };
  int                        CallsBeforeAbort{ 0 };
  int                        CallsAfterAbort{ 0 };
};

void
CancelWhenTheRelaxationReports(void * data)
{
  auto * probe = static_cast<CancelProbe *>(data);
  if (probe->AbortSet)
  {
    ++probe->CallsAfterAbort;
    return;
  }
  ++probe->CallsBeforeAbort;
  if (std::strcmp(probe->Information->ProgressMessage, "relax") == 0)
  {
    probe->Information->Abort = 1;
    probe->AbortSet = true;
    probe->ProgressAtAbort = probe->Information->Progress;
  }
}

/** Runs \a library in this process with \a arguments after Slicer's first three (target, the structure's flag and
 * address), cancelling at the first progress report of the relaxation. */
RunResult
RunCancelledInProcess(const std::string &      library,
                      const std::string &      target,
                      std::vector<std::string> arguments,
                      CancelProbe &            probe)
{
  static SlicerProcessInformation information;
  information = SlicerProcessInformation{};
  probe = CancelProbe{};
  probe.Information = &information;
  information.ProgressCallbackFunction = CancelWhenTheRelaxationReports;
  information.ProgressCallbackClientData = &probe;
  char address[64];
  std::snprintf(address, sizeof(address), "%p", static_cast<void *>(&information));
  arguments.insert(arguments.begin(), { target, "--processinformationaddress", address });
  return RunInProcess(library, arguments);
}

/** The iterations the relax filter did before it stopped, from its "aborted after N of M iterations". */
long
IterationsDoneBeforeTheAbort(const std::string & message, long & of)
{
  std::smatch      match;
  const std::regex pattern("aborted after ([0-9]+) of ([0-9]+) iterations");
  if (!std::regex_search(message, match, pattern))
  {
    return -1;
  }
  of = std::stol(match[2]);
  return std::stol(match[1]);
}

TEST(SlicerCancel, ReformationStopsMidRelaxationReturnsZeroAndWritesNothing)
{
  const fs::path folder = TestFolder();
  WriteText(folder / "cpr.nrrd", "an earlier result that must survive");
  const auto  before = FilesIn(folder);
  CancelProbe probe;
  // 200 000 iterations of 256 x 256 pixels: seconds of relaxation that a run ignoring Abort would go through,
  // reporting progress at every percent.
  const RunResult run = RunCancelledInProcess(ReformationLibrary,
                                              "VesselReformation",
                                              { "--up",
                                                "auto",
                                                "--size",
                                                "256,256",
                                                "--iterations",
                                                "200000",
                                                "--backend",
                                                "cpu",
                                                "--outputDepth",
                                                (folder / "depth.nrrd").string(),
                                                "--outputSurface",
                                                (folder / "surface.vtp").string(),
                                                "--returnparameterfile",
                                                (folder / "returned.params").string(),
                                                (DataFolder / "aorta.mha").string(),
                                                (DataFolder / "aorta-centerline.vtp").string(),
                                                (folder / "cpr.nrrd").string() },
                                              probe);
  ASSERT_TRUE(probe.AbortSet) << "the relaxation never reported: " << run.Err;
  EXPECT_EQ(run.ExitCode, 0) << "3D Slicer reads a non-zero value as 'Completed with errors'\n" << run.Err;
  EXPECT_TRUE(Contains(run.Err, "VesselReformation: relaxation: cancelled")) << run.Err;
  EXPECT_FALSE(Contains(run.Err, "error")) << run.Err;
  // Quickly: no progress report after the abort (a run that went on would report every percent), and the filter
  // stopped within an iteration of the one it was in when Slicer asked.
  EXPECT_EQ(probe.CallsAfterAbort, 0);
  long       of = 0;
  const long done = IterationsDoneBeforeTheAbort(run.Err, of);
  EXPECT_EQ(of, 200000) << run.Err;
  EXPECT_GT(done, 0) << run.Err;
  EXPECT_LT(done, 200000 / 20) << "the relaxation went on after Abort: " << run.Err;
  // Nothing written: no output, no return-parameter file, no stray file, the earlier result intact.
  EXPECT_EQ(FilesIn(folder), before);
  EXPECT_EQ(ReadText(folder / "cpr.nrrd"), "an earlier result that must survive");
  std::cout << "cancelled at overall progress " << probe.ProgressAtAbort << " after " << probe.CallsBeforeAbort
            << " progress reports; the relax filter stopped after " << done << " of " << of << " iterations"
            << std::endl;
}

TEST(SlicerCancel, RelaxModuleStopsMidRelaxationReturnsZeroAndWritesNothing)
{
  const fs::path folder = TestFolder();
  // A 512 x 512 depth map with a step: 100 000 iterations that a run ignoring Abort would go through.
  auto                                 depth = vr::DepthImageType::New();
  const vr::DepthImageType::RegionType region({ { 0, 0 } }, { { 512, 512 } });
  depth->SetRegions(region);
  depth->Allocate();
  for (unsigned int k = 0; k < 512 * 512; ++k)
  {
    depth->GetBufferPointer()[k] = (k % 512) < 256 ? 2.0f : 9.0f;
  }
  vr::WriteImage2D(depth.GetPointer(), (folder / "depth.nrrd").string());
  const auto      before = FilesIn(folder);
  CancelProbe     probe;
  const RunResult run = RunCancelledInProcess(RelaxLibrary,
                                              "BilateralDepthRelax",
                                              { "--iterations",
                                                "100000",
                                                "--backend",
                                                "cpu",
                                                "--returnparameterfile",
                                                (folder / "returned.params").string(),
                                                (folder / "depth.nrrd").string(),
                                                (folder / "relaxed.nrrd").string() },
                                              probe);
  ASSERT_TRUE(probe.AbortSet) << run.Err;
  EXPECT_EQ(run.ExitCode, 0) << run.Err;
  EXPECT_TRUE(Contains(run.Err, "BilateralDepthRelax: relaxation: cancelled")) << run.Err;
  EXPECT_FALSE(Contains(run.Err, "error")) << run.Err;
  EXPECT_EQ(probe.CallsAfterAbort, 0);
  // The module stopped at its next progress report: the relaxation's progress is its fraction of iterations done.
  EXPECT_LT(probe.ProgressAtAbort, 0.05f);
  EXPECT_EQ(FilesIn(folder), before);
}

// ---------------------------------------------------------------------------------------------------------------
// What the modules compute.

TEST(BilateralDepthRelaxModule, RelaxesByEquationOneAndHoldsTheMask)
{
  const fs::path folder = TestFolder();
  // [0, 10, 0] with w = 1, a = 0, one iteration: each pixel becomes the mean of its neighbours, [10, 0, 10].
  auto depth = vr::DepthImageType::New();
  depth->SetRegions(vr::DepthImageType::RegionType({ { 0, 0 } }, { { 3, 1 } }));
  depth->Allocate();
  depth->GetBufferPointer()[0] = 0.0f;
  depth->GetBufferPointer()[1] = 10.0f;
  depth->GetBufferPointer()[2] = 0.0f;
  itk::EncapsulateMetaData<std::string>(depth->GetMetaDataDictionary(), "CPR_Note", "kept");
  vr::WriteImage2D(depth.GetPointer(), (folder / "depth.nrrd").string());
  const RunResult free = RunProgram({ RelaxExecutable,
                                      "--relaxation",
                                      "1",
                                      "--anisotropy",
                                      "0",
                                      "--iterations",
                                      "1",
                                      "--backend",
                                      "cpu",
                                      (folder / "depth.nrrd").string(),
                                      (folder / "free.nrrd").string() });
  ASSERT_EQ(free.ExitCode, 0) << free.Err;
  auto relaxed = vr::ReadDepthImage((folder / "free.nrrd").string());
  EXPECT_FLOAT_EQ(relaxed->GetBufferPointer()[0], 10.0f);
  EXPECT_FLOAT_EQ(relaxed->GetBufferPointer()[1], 0.0f);
  EXPECT_FLOAT_EQ(relaxed->GetBufferPointer()[2], 10.0f);
  std::string note;
  EXPECT_TRUE(itk::ExposeMetaData<std::string>(relaxed->GetMetaDataDictionary(), "CPR_Note", note));
  EXPECT_EQ(note, "kept");

  // With the ends fixed: [0, 0, 0].
  auto mask = vr::MaskImageType::New();
  mask->SetRegions(depth->GetLargestPossibleRegion());
  mask->Allocate();
  mask->GetBufferPointer()[0] = 1;
  mask->GetBufferPointer()[1] = 0;
  mask->GetBufferPointer()[2] = 1;
  vr::WriteImage2D(mask.GetPointer(), (folder / "mask.nrrd").string());
  const RunResult held = RunProgram({ RelaxExecutable,
                                      "--mask",
                                      (folder / "mask.nrrd").string(),
                                      "--anisotropy",
                                      "0",
                                      "--iterations",
                                      "1",
                                      "--backend",
                                      "cpu",
                                      (folder / "depth.nrrd").string(),
                                      (folder / "held.nrrd").string() });
  ASSERT_EQ(held.ExitCode, 0) << held.Err;
  relaxed = vr::ReadDepthImage((folder / "held.nrrd").string());
  EXPECT_FLOAT_EQ(relaxed->GetBufferPointer()[0], 0.0f);
  EXPECT_FLOAT_EQ(relaxed->GetBufferPointer()[1], 0.0f);
  EXPECT_FLOAT_EQ(relaxed->GetBufferPointer()[2], 0.0f);
}

// Issue 13: --jumpThreshold J is the range kernel's scale, R(d) = exp(-(d/J)^2), 3 mm when neither it nor
// --anisotropy is given; --solver steady gives the fixed point. The hand-worked case of depths [0, 1, 3] with the ends
// fixed, w = 1: one Jacobi pass moves the middle to f(1), the steady solver to the fixed point x = f(x) that the
// passes approach from 1 (vr::test::ThreePixelMiddleAfterOnePass, ThreePixelMiddleFixedPoint).
TEST(BilateralDepthRelaxModule, JumpThresholdScalesTheRangeKernelAndSteadyFindsTheFixedPoint)
{
  const fs::path folder = TestFolder();
  vr::WriteImage2D(vr::test::MakeDepthImage(3, 1, { 0.0f, 1.0f, 3.0f }).GetPointer(), (folder / "depth.nrrd").string());
  vr::WriteImage2D(vr::test::MakeMaskImage(3, 1, { 1, 0, 1 }).GetPointer(), (folder / "mask.nrrd").string());
  auto middle = [&](std::vector<std::string> flags, const std::string & name)
  {
    std::vector<std::string> command = {
      RelaxExecutable, "--mask", (folder / "mask.nrrd").string(), "--backend", "cpu"
    };
    command.insert(command.end(), flags.begin(), flags.end());
    command.push_back((folder / "depth.nrrd").string());
    command.push_back((folder / name).string());
    const RunResult run = RunProgram(command);
    EXPECT_EQ(run.ExitCode, 0) << run.Err;
    return static_cast<double>(vr::ReadDepthImage((folder / name).string())->GetBufferPointer()[1]);
  };
  auto expected = [](double J) { return vr::test::ThreePixelMiddleAfterOnePass(1.0, J); };
  EXPECT_NEAR(middle({ "--iterations", "1", "--jumpThreshold", "2" }, "j2.nrrd"), expected(2.0), 1e-6);
  EXPECT_NEAR(middle({ "--iterations", "1", "--anisotropy", "0.25" }, "a025.nrrd"), expected(2.0), 1e-6);
  EXPECT_NEAR(middle({ "--iterations", "1" }, "default.nrrd"), expected(3.0), 1e-6);
  EXPECT_NEAR(middle({ "--iterations", "1", "--jumpThreshold", "0.5" }, "j05.nrrd"), expected(0.5), 1e-6);
  const double fixedPoint = vr::test::ThreePixelMiddleFixedPoint(2.0);
  ASSERT_GT(std::abs(expected(2.0) - fixedPoint), 0.1) << "one Jacobi pass is not the fixed point here";
  EXPECT_NEAR(middle({ "--solver", "steady", "--jumpThreshold", "2" }, "steady.nrrd"), fixedPoint, 1e-3);
}

/** Numbers in a "CPR_*" metadata entry. */
std::vector<double>
MetadataNumbers(const vr::DepthImageType * image, const std::string & key)
{
  std::string text;
  itk::ExposeMetaData<std::string>(image->GetMetaDataDictionary(), key, text);
  std::istringstream  stream(text);
  std::vector<double> values;
  double              value = 0.0;
  while (stream >> value)
  {
    values.push_back(value);
  }
  return values;
}

TEST(VesselReformationModule, RealAortaCenterlinePixelsShowLumenAndFixedPixelsIgnoreRelaxation)
{
  const fs::path    folder = TestFolder();
  const std::string volume = (DataFolder / "aorta.mha").string();
  const std::string centerlines = (DataFolder / "aorta-centerline.vtp").string();
  constexpr float   lumen = 1850.0f;
  constexpr float   background = 230.0f;

  // Centerline pixels alone are fixed with --fixLumen off: each must show lumen.
  const RunResult centerlineRun = RunProgram({ ReformationExecutable,
                                               "--up",
                                               "auto",
                                               "--fixLumen",
                                               "off",
                                               "--backend",
                                               "cpu",
                                               "--outputMask",
                                               (folder / "centerline-mask.nrrd").string(),
                                               volume,
                                               centerlines,
                                               (folder / "centerline-cpr.nrrd").string() });
  ASSERT_EQ(centerlineRun.ExitCode, 0) << centerlineRun.Err;
  EXPECT_FALSE(Contains(centerlineRun.Err, "outside the volume")) << centerlineRun.Err;
  auto        cpr = vr::ReadDepthImage((folder / "centerline-cpr.nrrd").string());
  auto        mask = vr::ReadMaskImage((folder / "centerline-mask.nrrd").string());
  const auto  count = cpr->GetLargestPossibleRegion().GetNumberOfPixels();
  std::size_t centerlinePixels = 0;
  float       darkest = lumen;
  for (std::size_t k = 0; k < count; ++k)
  {
    if (mask->GetBufferPointer()[k])
    {
      ++centerlinePixels;
      darkest = std::min(darkest, cpr->GetBufferPointer()[k]);
    }
  }
  EXPECT_GT(centerlinePixels, 100u);
  EXPECT_GT(darkest, 0.5f * (lumen + background)) << "a centerline pixel shows background";

  // --up auto found the scan's y axis, along which the vessels run.
  const auto up = MetadataNumbers(cpr, "CPR_Up");
  ASSERT_EQ(up.size(), 3u);
  EXPECT_GT(std::abs(up[1]), 0.999) << up[0] << " " << up[1] << " " << up[2];

  // With lumen fixing (the default) and without relaxation, the fixed pixels are the same.
  const RunResult relaxedRun = RunProgram({ ReformationExecutable,
                                            "--up",
                                            "auto",
                                            "--backend",
                                            "cpu",
                                            "--outputMask",
                                            (folder / "mask.nrrd").string(),
                                            volume,
                                            centerlines,
                                            (folder / "relaxed-cpr.nrrd").string() });
  const RunResult unrelaxedRun = RunProgram({ ReformationExecutable,
                                              "--up",
                                              "auto",
                                              "--backend",
                                              "cpu",
                                              "--relaxation",
                                              "0",
                                              volume,
                                              centerlines,
                                              (folder / "unrelaxed-cpr.nrrd").string() });
  ASSERT_EQ(relaxedRun.ExitCode, 0) << relaxedRun.Err;
  ASSERT_EQ(unrelaxedRun.ExitCode, 0) << unrelaxedRun.Err;
  auto        relaxed = vr::ReadDepthImage((folder / "relaxed-cpr.nrrd").string());
  auto        unrelaxed = vr::ReadDepthImage((folder / "unrelaxed-cpr.nrrd").string());
  auto        fixedMask = vr::ReadMaskImage((folder / "mask.nrrd").string());
  std::size_t fixed = 0;
  std::size_t changed = 0;
  for (std::size_t k = 0; k < count; ++k)
  {
    if (fixedMask->GetBufferPointer()[k])
    {
      ++fixed;
      EXPECT_EQ(relaxed->GetBufferPointer()[k], unrelaxed->GetBufferPointer()[k]) << "fixed pixel " << k;
    }
    else if (relaxed->GetBufferPointer()[k] != unrelaxed->GetBufferPointer()[k])
    {
      ++changed;
    }
  }
  std::cout << "aorta: " << cpr->GetLargestPossibleRegion().GetSize() << " pixels, " << centerlinePixels
            << " centerline pixels, darkest " << darkest << "; " << fixed << " fixed pixels with lumen fixing, "
            << changed << " others changed by relaxation" << std::endl;
  EXPECT_GT(fixed, centerlinePixels) << "lumen fixing should fix more than the centerline";
  EXPECT_GT(changed, 0u) << "the relaxation changed no pixel";
}

TEST(VesselReformationModule, ReportsProgressInSlicersFormat)
{
  const fs::path  folder = TestFolder();
  const RunResult run = RunProgram({ ReformationExecutable,
                                     "--up",
                                     "auto",
                                     "--iterations",
                                     "20",
                                     "--backend",
                                     "cpu",
                                     (DataFolder / "aorta.mha").string(),
                                     (DataFolder / "aorta-centerline.vtp").string(),
                                     (folder / "cpr.nrrd").string() });
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  const auto start = run.Out.find("<filter-start>");
  const auto end = run.Out.find("<filter-end>");
  ASSERT_NE(start, std::string::npos) << run.Out;
  ASSERT_NE(end, std::string::npos) << run.Out;
  EXPECT_TRUE(Contains(run.Out, "<filter-name>VesselReformation</filter-name>"));
  std::vector<double> fractions;
  const std::regex    line("<filter-progress>([0-9.eE+-]+)</filter-progress>");
  for (auto it = std::sregex_iterator(run.Out.begin(), run.Out.end(), line); it != std::sregex_iterator(); ++it)
  {
    EXPECT_GT(static_cast<std::size_t>(it->position()), start);
    EXPECT_LT(static_cast<std::size_t>(it->position()), end);
    fractions.push_back(std::stod((*it)[1]));
  }
  ASSERT_GE(fractions.size(), 3u);
  EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
  EXPECT_EQ(fractions.back(), 1.0);
}

// The summary states the relaxation's settings in the one wording every caption uses (vr::DescribeFilterSettings),
// worked out here by hand from the flags: the kernel as given, then w and N, or the steady solver.
TEST(VesselReformationModule, SummaryStatesTheFilterSettingsAsEveryCaptionDoes)
{
  const fs::path  folder = TestFolder();
  const RunResult jacobi = RunProgram({ ReformationExecutable,
                                        "--up",
                                        "auto",
                                        "--jumpThreshold",
                                        "2",
                                        "--relaxation",
                                        "0.5",
                                        "--iterations",
                                        "20",
                                        "--backend",
                                        "cpu",
                                        (DataFolder / "aorta.mha").string(),
                                        (DataFolder / "aorta-centerline.vtp").string(),
                                        (folder / "jacobi.nrrd").string() });
  ASSERT_EQ(jacobi.ExitCode, 0) << jacobi.Err;
  EXPECT_TRUE(Contains(jacobi.Out, "(cpu, J = 2 mm, w = 0.5, 20 iterations)")) << jacobi.Out;
  vr::ReformationParameters parameters;
  parameters.JumpThreshold = 2.0;
  parameters.Relaxation = 0.5;
  parameters.Iterations = 20;
  EXPECT_TRUE(Contains(jacobi.Out, "(cpu, " + vr::DescribeFilterSettings(parameters) + ")")) << jacobi.Out;

  const RunResult steady = RunProgram({ ReformationExecutable,
                                        "--up",
                                        "auto",
                                        "--anisotropy",
                                        "0.25",
                                        "--solver",
                                        "steady",
                                        "--backend",
                                        "cpu",
                                        (DataFolder / "aorta.mha").string(),
                                        (DataFolder / "aorta-centerline.vtp").string(),
                                        (folder / "steady.nrrd").string() });
  ASSERT_EQ(steady.ExitCode, 0) << steady.Err;
  EXPECT_TRUE(Contains(steady.Out, "(cpu, a = 0.25 mm^-2, steady solver)")) << steady.Out;
}

TEST(CLIProgress, DrawsABarOnATerminal)
{
  std::ostringstream out;
  vr::CLIProgress    progress("VesselReformation", "comment", nullptr, out, /*terminal=*/true);
  progress.Start();
  progress.Update(0.42, "relax");
  std::ostringstream warnings;
  progress.Print(warnings, "warning: something");
  progress.Update(0.5, "relax");
  progress.End();
  EXPECT_EQ(warnings.str(), "warning: something\n");
  // The bar was ended before the warning went out, and redrawn after it.
  EXPECT_TRUE(Contains(out.str(), "relax     \n\r")) << out.str();
  EXPECT_FALSE(Contains(out.str(), "<filter")) << out.str();
  EXPECT_TRUE(Contains(out.str(), " 42% relax")) << out.str();
  EXPECT_TRUE(Contains(out.str(), "100%")) << out.str();
  EXPECT_EQ(out.str().back(), '\n');
}

// ---------------------------------------------------------------------------------------------------------------
// Bad input: a message naming the file, field or flag, exit 1, no crash, no output, an existing output intact.

class BadInputTest : public ::testing::Test
{
protected:
  void
  SetUp() override
  {
    m_Folder = TestFolder();
    WriteText(m_Folder / "cpr.nrrd", "an earlier result that must survive");
  }

  /** Runs VesselReformation with \a arguments then <outputCPR> (and a depth output), and checks the failure. */
  RunResult
  ExpectRejected(std::vector<std::string> arguments, const std::vector<std::string> & mentions)
  {
    arguments.insert(arguments.begin(), ReformationExecutable);
    arguments.insert(arguments.end() - 2, { "--outputDepth", (m_Folder / "depth.nrrd").string() });
    arguments.push_back((m_Folder / "cpr.nrrd").string());
    const auto      before = FilesIn(m_Folder);
    const RunResult result = RunProgram(arguments);
    EXPECT_FALSE(result.Crashed);
    EXPECT_EQ(result.ExitCode, 1) << result.Err;
    for (const auto & mention : mentions)
    {
      EXPECT_TRUE(Contains(result.Err, mention)) << "the message lacks \"" << mention << "\":\n" << result.Err;
    }
    EXPECT_TRUE(Contains(result.Err, "VesselReformation: error: ")) << result.Err;
    EXPECT_EQ(FilesIn(m_Folder), before) << "a file appeared or vanished";
    EXPECT_EQ(ReadText(m_Folder / "cpr.nrrd"), "an earlier result that must survive");
    return result;
  }

  std::string
  Volume() const
  {
    return (DataFolder / "aorta.mha").string();
  }
  std::string
  Centerlines() const
  {
    return (DataFolder / "aorta-centerline.vtp").string();
  }
  std::string
  Write(const std::string & name, const std::string & text) const
  {
    WriteText(m_Folder / name, text);
    return (m_Folder / name).string();
  }

  fs::path m_Folder;
};

TEST_F(BadInputTest, MissingVolumeFile)
{
  const std::string missing = (m_Folder / "no-such-volume.mha").string();
  ExpectRejected({ missing, Centerlines() }, { missing });
}

TEST_F(BadInputTest, MissingCenterlineFile)
{
  const std::string missing = (m_Folder / "no-such-centerlines.vtp").string();
  ExpectRejected({ Volume(), missing }, { missing });
}

TEST_F(BadInputTest, NRRDWithACorruptHeader)
{
  const std::string nrrd =
    Write("corrupt.nrrd", "NRRD0004\ntype: flaot\ndimension: 3\nsizes: 2 2 2\nencoding: raw\n\n01234567");
  ExpectRejected({ nrrd, Centerlines() }, { "corrupt.nrrd", "header" });
}

TEST_F(BadInputTest, TruncatedVTP)
{
  const std::string whole = ReadText(DataFolder / "aorta-centerline.vtp");
  const std::string vtp = Write("truncated.vtp", whole.substr(0, whole.size() / 3));
  ExpectRejected({ Volume(), vtp }, { "truncated.vtp" });
}

TEST_F(BadInputTest, MarkupsThatAreNotJSON)
{
  ExpectRejected({ Volume(), Write("broken.mrk.json", "{ \"markups\": [ { \"type\": \"Curve\", ") },
                 { "broken.mrk.json", "JSON" });
}

TEST_F(BadInputTest, MarkupsWithoutACurve)
{
  const std::string json = R"({"markups":[{"type":"Fiducial","coordinateSystem":"LPS",
    "controlPoints":[{"position":[1.0,2.0,3.0]}]}]})";
  ExpectRejected({ Volume(), Write("points.mrk.json", json) }, { "points.mrk.json", "Curve" });
}

TEST_F(BadInputTest, MarkupsPositionThatIsNotThreeNumbers)
{
  const std::string json = R"({"markups":[{"type":"Curve","coordinateSystem":"LPS",
    "controlPoints":[{"position":[1.0,2.0,3.0]},{"position":[1.0,2.0]}]}]})";
  ExpectRejected({ Volume(), Write("short.mrk.json", json) }, { "short.mrk.json", "position" });
}

TEST_F(BadInputTest, CSVWithAMissingColumn)
{
  ExpectRejected({ Volume(), Write("two-columns.csv", "branch,x,y\n1,0,0\n1,0,1\n") }, { "two-columns.csv", "z" });
}

TEST_F(BadInputTest, CSVWithANonNumericValue)
{
  ExpectRejected({ Volume(), Write("letters.csv", "branch,x,y,z\n1,0,0,0\n1,0,abc,1\n") }, { "letters.csv", "abc" });
}

TEST_F(BadInputTest, EmptyCenterlineFiles)
{
  ExpectRejected({ Volume(), Write("empty.csv", "") }, { "empty.csv" });
  ExpectRejected({ Volume(), Write("empty.vtp", "") }, { "empty.vtp" });
  ExpectRejected({ Volume(), Write("header-only.csv", "branch,x,y,z\n") }, { "header-only.csv" });
}

TEST_F(BadInputTest, UnknownFlag)
{
  ExpectRejected({ "--bogus", "3", Volume(), Centerlines() }, { "unknown flag --bogus" });
}

TEST_F(BadInputTest, RelaxationOutsideItsRange)
{
  ExpectRejected({ "--relaxation", "2", Volume(), Centerlines() }, { "--relaxation", "2" });
}

TEST_F(BadInputTest, BothJumpThresholdAndAnisotropy)
{
  ExpectRejected({ "--jumpThreshold", "3", "--anisotropy", "0.5", Volume(), Centerlines() },
                 { "--jumpThreshold", "--anisotropy", "give one" });
}

TEST_F(BadInputTest, NegativeIterations)
{
  ExpectRejected({ "--iterations", "-5", Volume(), Centerlines() }, { "--iterations", "-5" });
}

TEST_F(BadInputTest, ZeroWidth)
{
  ExpectRejected({ "--size", "0,10", Volume(), Centerlines() }, { "--size", "0,10" });
}

TEST_F(BadInputTest, SizeThatDoesNotFitInMemory)
{
  ExpectRejected({ "--size", "100000000,100000000", Volume(), Centerlines() },
                 { "--size", "100000000,100000000", "memory" });
}

TEST_F(BadInputTest, OutputFolderThatDoesNotExist)
{
  const std::string nowhere = (m_Folder / "no-such-folder" / "x.nrrd").string();
  ExpectRejected({ "--outputMask", nowhere, Volume(), Centerlines() }, { "--outputMask", "no-such-folder" });
}

TEST_F(BadInputTest, AWriteThatFailsAfterTheOthersLeavesNoOutputAtAll)
{
  // The CPR and the mask are written first; the surface writer then refuses the extension. Nothing may land.
  ExpectRejected({ "--iterations",
                   "10",
                   "--outputMask",
                   (m_Folder / "mask.nrrd").string(),
                   "--outputSurface",
                   (m_Folder / "surface.xyz").string(),
                   Volume(),
                   Centerlines() },
                 { "surface.xyz" });
}

TEST_F(BadInputTest, CenterlinesWithNoPointInTheVolumeAreRefusedNamingBothFiles)
{
  // The .vtp is RAS; read as LPS, every point lands outside the volume (checked here from the volume's own bounds),
  // so a reformation would be empty: refused, naming both files and the coordinate system as the likely cause.
  const auto  volume = vr::ReadVolume(Volume());
  const auto  tree = vr::ReadCenterlines(Centerlines(), vr::CoordinateSpace::LPS);
  std::size_t inside = 0;
  for (const auto & branch : tree.GetBranches())
  {
    for (const auto & point : branch.Points)
    {
      itk::ContinuousIndex<double, 3> index;
      volume->TransformPhysicalPointToContinuousIndex(point, index);
      inside += volume->GetLargestPossibleRegion().IsInside(index) ? 1 : 0;
    }
  }
  ASSERT_EQ(inside, 0u) << "the case needs centerlines wholly outside the volume";
  ExpectRejected(
    { "--centerlineSpace", "LPS", "--iterations", "10", "--backend", "cpu", Volume(), Centerlines() },
    { "aorta-centerline.vtp", "aorta.mha", "none of the", "other coordinate system", "--centerlineSpace" });
}

TEST_F(BadInputTest, CenterlinesMostlyOutsideTheVolumeWarnInFullAndTheRunContinues)
{
  // The aorta's centerlines moved up along the volume's z axis until between 60 and 90 % of their points (counted
  // here) leave it.
  const auto volume = vr::ReadVolume(Volume());
  auto       tree = vr::ReadCenterlines(Centerlines());
  double     outside = 0.0;
  for (double shift = 0.0; shift < 1000.0 && !(outside > 0.6 && outside < 0.9); shift += 1.0)
  {
    std::size_t out = 0;
    std::size_t all = 0;
    for (const auto & branch : tree.GetBranches())
    {
      for (auto point : branch.Points)
      {
        point[2] += shift;
        itk::ContinuousIndex<double, 3> index;
        volume->TransformPhysicalPointToContinuousIndex(point, index);
        out += volume->GetLargestPossibleRegion().IsInside(index) ? 0 : 1;
        ++all;
      }
    }
    outside = static_cast<double>(out) / static_cast<double>(all);
    if (outside > 0.6 && outside < 0.9)
    {
      for (auto & branch : tree.GetBranches())
      {
        for (auto & point : branch.Points)
        {
          point[2] += shift;
        }
      }
    }
  }
  ASSERT_GT(outside, 0.6);
  ASSERT_LT(outside, 0.9);
  const std::string moved = (m_Folder / "moved-centerlines.vtp").string();
  vr::WriteCenterlines(tree, moved);
  const RunResult result = RunProgram({ ReformationExecutable,
                                        "--iterations",
                                        "10",
                                        "--backend",
                                        "cpu",
                                        Volume(),
                                        moved,
                                        (m_Folder / "cpr.nrrd").string() });
  EXPECT_EQ(result.ExitCode, 0) << result.Err;
  // The whole warning, not a line cut short.
  for (const char * part : { "warning: ",
                             "moved-centerlines.vtp",
                             "points lie outside the volume",
                             "aorta.mha",
                             "RAS or LPS",
                             "The reformation continues." })
  {
    EXPECT_TRUE(Contains(result.Err, part)) << "lacks \"" << part << "\":\n" << result.Err;
  }
  EXPECT_NE(ReadText(m_Folder / "cpr.nrrd"), "an earlier result that must survive") << "the run did not write";
}

TEST_F(BadInputTest, RelaxModuleRejectsAMissingDepthAMaskOfAnotherSizeAndBadParameters)
{
  WriteSmallDepthAndMask(m_Folder / "depth.nrrd", m_Folder / "mask.nrrd");
  auto small = vr::MaskImageType::New();
  small->SetRegions(vr::MaskImageType::RegionType({ { 0, 0 } }, { { 5, 5 } }));
  small->Allocate(true);
  vr::WriteImage2D(small.GetPointer(), (m_Folder / "small-mask.nrrd").string());
  WriteText(m_Folder / "relaxed.nrrd", "an earlier result that must survive");
  const std::string output = (m_Folder / "relaxed.nrrd").string();
  const std::string depth = (m_Folder / "depth.nrrd").string();
  const auto        before = FilesIn(m_Folder);
  const std::vector<std::pair<std::vector<std::string>, std::vector<std::string>>> cases = {
    { { (m_Folder / "missing.nrrd").string(), output }, { "missing.nrrd" } },
    { { "--mask", (m_Folder / "small-mask.nrrd").string(), depth, output }, { "--mask", "small-mask.nrrd", "5 x 5" } },
    { { "--relaxation", "2", depth, output }, { "--relaxation", "2" } },
    { { "--iterations", "-5", depth, output }, { "--iterations", "-5" } },
    { { "--anisotropy", "nan", depth, output }, { "--anisotropy", "nan" } },
    { { "--jumpThreshold", "0", depth, output }, { "--jumpThreshold", "0" } },
    { { "--jumpThreshold", "3", "--anisotropy", "0.5", depth, output }, { "--jumpThreshold", "--anisotropy" } },
    { { "--solver", "multigrid", depth, output }, { "--solver", "multigrid" } },
    { { "--backend", "gpu", depth, output }, { "--backend", "gpu" } },
    { { "--bogus", depth, output }, { "unknown flag --bogus" } },
    { { depth }, { "missing the second argument <outputDepth>" } },
  };
  for (const auto & [arguments, mentions] : cases)
  {
    std::vector<std::string> command = { RelaxExecutable };
    command.insert(command.end(), arguments.begin(), arguments.end());
    const RunResult result = RunProgram(command);
    EXPECT_FALSE(result.Crashed);
    EXPECT_EQ(result.ExitCode, 1) << arguments.front();
    for (const auto & mention : mentions)
    {
      EXPECT_TRUE(Contains(result.Err, mention)) << "the message lacks \"" << mention << "\":\n" << result.Err;
    }
    EXPECT_EQ(FilesIn(m_Folder), before);
    EXPECT_EQ(ReadText(m_Folder / "relaxed.nrrd"), "an earlier result that must survive");
  }
}

// ---------------------------------------------------------------------------------------------------------------
// Hostile input (issue 14): each class of file or flag that once crashed, hung, or was silently accepted. Every case
// exits 1 with a message naming the file, field or flag, writes nothing, leaves the earlier cpr.nrrd byte for byte,
// and leaves no stray file (ExpectRejected).

/** A small NRRD volume of \a size voxels, 1 mm, value 100, with \a change applied to its voxels. */
std::string
WriteSmallVolume(const fs::path & path, const std::function<void(vr::VolumeImageType *)> & change = {})
{
  auto volume = vr::VolumeImageType::New();
  volume->SetRegions(vr::VolumeImageType::RegionType({ { 0, 0, 0 } }, { { 8, 8, 8 } }));
  volume->Allocate();
  volume->FillBuffer(100.0f);
  if (change)
  {
    change(volume);
  }
  vr::WriteVolume(volume, path.string());
  return path.string();
}

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

/** Writes a 6 x 5 x 4 series of short slices with ITK's GDCM IO into \a folder, as ITK's DICOM examples do. */
void
WriteDicomSeries(const fs::path & folder)
{
  using Volume = itk::Image<short, 3>;
  using Slice = itk::Image<short, 2>;
  auto volume = Volume::New();
  volume->SetRegions(Volume::RegionType({ { 0, 0, 0 } }, { { 6, 5, 4 } }));
  volume->SetSpacing(itk::Vector<double, 3>(2.0));
  volume->Allocate(true);
  fs::create_directories(folder);
  std::vector<std::unique_ptr<itk::MetaDataDictionary>> owned;
  std::vector<itk::MetaDataDictionary *>                dictionaries;
  std::vector<std::string>                              names;
  for (unsigned int z = 0; z < 4; ++z)
  {
    auto dictionary = std::make_unique<itk::MetaDataDictionary>();
    itk::EncapsulateMetaData<std::string>(*dictionary, "0020|000e", "1.2.826.0.1.3680043.2.1125.9.1");
    itk::EncapsulateMetaData<std::string>(*dictionary, "0020|0013", std::to_string(z + 1));
    itk::EncapsulateMetaData<std::string>(*dictionary, "0020|0032", "0\\0\\" + std::to_string(2 * z));
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
  WriteDicomSeries(good);
  for (const char * finding : { "dicom-meta-explicit-assert/IM0018.dcm",
                                "dicom-meta-implicit-assert/IM0009.dcm",
                                "dicom-samples-per-pixel-assert/IM0017.dcm",
                                "dicom-truncated-assert/IM0011.dcm",
                                "dicom-bits-allocated-unhandled/IM0030.dcm",
                                "dicom-acr-nema-assert/IM0027.dcm" })
  {
    const fs::path    file = fs::path(VR_FINDINGS_DIR) / finding;
    const std::string name = file.filename().string();
    {
      const RunResult run =
        ExpectRejected({ file.parent_path().string(), Centerlines() }, { "the DICOM file " + file.string() });
      EXPECT_EQ(std::count(run.Err.begin(), run.Err.end(), '\n'), 1) << "only the module's message:\n" << run.Err;
    }

    // In a good series: refused, naming it, where GDCM dies on it (the file of 50448 bits fails in ITK's read, and
    // it belongs to another series than the good one, which is read without it).
    if (std::string(finding).find("assert") != std::string::npos)
    {
      const fs::path mixed = m_Folder / ("mixed-" + name);
      fs::create_directories(mixed);
      for (const auto & entry : fs::directory_iterator(good))
      {
        fs::copy_file(entry.path(), mixed / entry.path().filename());
      }
      fs::copy_file(file, mixed / name);
      const RunResult run =
        ExpectRejected({ mixed.string(), Centerlines() }, { (mixed / name).string(), "is not read" });
      EXPECT_EQ(std::count(run.Err.begin(), run.Err.end(), '\n'), 1) << "only the module's message:\n" << run.Err;
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
  EXPECT_FALSE(Contains(run.Err, "DICOM")) << run.Err;
  EXPECT_FALSE(Contains(run.Err, "GDCM")) << run.Err;
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
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
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
