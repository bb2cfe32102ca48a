// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#ifndef vrCLITestSupport_h
#define vrCLITestSupport_h

// What the tests of the VesselReformation and BilateralDepthRelax modules share: the modules' paths (from CMake),
// a fresh folder per test, running a shared library's entry point in this process, small inputs, and the bad-input
// fixture that checks a run is refused with nothing written.

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

namespace vr::test::cli
{
using vr::test::Contains;
namespace fs = std::filesystem;

const std::string ReformationExecutable = VR_REFORMATION_EXE;
const std::string ReformationLibrary = VR_REFORMATION_LIB;
const std::string RelaxExecutable = VR_RELAX_EXE;
const std::string RelaxLibrary = VR_RELAX_LIB;
const fs::path    DataFolder = fs::path(VR_SHARED_DATA_DIR) / "vmtk-aorta-mra";

/** The SlicerExecutionModel ModuleProcessInformation layout, written in the test support from Slicer's header
 * independently of the module's own copy, so that a layout mismatch fails. */
using SlicerProcessInformation = vr::test::SlicerModuleProcessInformation;

using vr::test::RunLimits;
using vr::test::RunProgram;
using RunResult = vr::test::ModuleRun;

inline std::string
ReadText(const fs::path & path)
{
  std::ifstream      file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

inline void
WriteText(const fs::path & path, const std::string & text)
{
  std::ofstream file(path, std::ios::binary);
  file << text;
}

/** A fresh folder for one test, under the build tree (vr::test::FreshFolderForThisTest). */
inline fs::path
TestFolder()
{
  return vr::test::FreshFolderForThisTest(VR_TEST_OUTPUT_DIR, "");
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
inline RunResult
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
inline std::set<std::string>
FilesIn(const fs::path & folder)
{
  std::set<std::string> names;
  for (const auto & entry : fs::directory_iterator(folder))
  {
    names.insert(entry.path().filename().string());
  }
  return names;
}

/** A small depth map with a CPR-like step and a fixed mask, written through the module's own writer. */
inline void
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

/** A small NRRD volume of \a size voxels, 1 mm, value 100, with \a change applied to its voxels. */
inline std::string
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

} // namespace vr::test::cli

#endif
