// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The demo as built, small: it writes through the one output writer (the cut surface in LPS with Slicer's marker, as
// the module and the viewer do) and states the filter settings in the one wording of every caption.

#include "itkCTAPhantom.h"
#include "vrNodeConversion.h"
#include "vrVesselReformationLogic.h"

#include "vrModuleRuns.h"
#include "vrTestFiles.h"

#include <gtest/gtest.h>

#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>

#include <algorithm>
#include <string>
#include <vector>

namespace
{
bool
Contains(const std::string & text, const std::string & part)
{
  return text.find(part) != std::string::npos;
}
} // namespace

TEST(VesselReformationDemo, WritesThroughTheOneWriterAndCaptionsInTheOneWording)
{
  vr::test::ScopedTemporaryFolder folder;
  const vr::test::ModuleRun       run = vr::test::RunProgram({ VR_DEMO_EXE,
                                                               "--phantom",
                                                               "runoff",
                                                               "--phantomSpacing",
                                                               "3",
                                                               "--size",
                                                               "48,96",
                                                               "--iterations",
                                                               "20",
                                                               "--backend",
                                                               "cpu",
                                                               "--output",
                                                               folder.Path().string() },
                                                       600.0);
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  // The run-off phantom's middle column is plain smoothing (a = 0), the right one the default J = 3 mm.
  EXPECT_TRUE(Contains(run.Out, "isotropic relaxation (a = 0 mm^-2, w = 1, 20 iterations, cpu):")) << run.Out;
  EXPECT_TRUE(Contains(run.Out, "bilateral relaxation (J = 3 mm, w = 1, 20 iterations, cpu):")) << run.Out;
  const std::vector<std::string> expected = {
    "cpr-filtered.png",   "cpr-unfiltered.nrrd", "cpr-unfiltered.png",   "cpr.nrrd",   "cut-surface.vtp",
    "depth-filtered.png", "depth-relaxed.nrrd",  "depth-unfiltered.png", "depth.nrrd", "figure2-comparison.png"
  };
  EXPECT_EQ(folder.Entries(), expected);

  // The cut surface: LPS with "SPACE" = "LPS", read with VTK's own reader. The reference is the logic's RAS surface
  // of the same phantom and settings, computed here, with x and y negated.
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(folder.File("cut-surface.vtp").c_str());
  reader->Update();
  vtkPolyData * file = reader->GetOutput();
  auto *        space = vtkStringArray::SafeDownCast(file->GetFieldData()->GetAbstractArray("SPACE"));
  ASSERT_NE(space, nullptr) << "no SPACE marker in cut-surface.vtp";
  EXPECT_EQ(space->GetValue(0), "LPS");

  auto phantom = itk::MakeCTAPhantom(itk::CTAPhantomKind::Runoff, 3.0);
  phantom.Source->Update();
  vr::VesselReformationLogic logic;
  logic.SetVolumeNode(vr::ConvertItkImageToVolumeNode(phantom.Source->GetOutput(), "RunoffPhantom"));
  logic.SetCenterlineNode(vr::ConvertTreeToCenterlineNode(phantom.Tree, "RunoffCenterlines"));
  vr::ReformationParameters parameters;
  parameters.AngleInDegrees = phantom.DesignAngleInDegrees;
  parameters.ImageSize[0] = 48;
  parameters.ImageSize[1] = 96;
  parameters.Iterations = 20;
  parameters.Relaxation = 1.0;
  parameters.Backend = vr::RelaxBackend::CPU;
  logic.SetParameters(parameters);
  vtkPolyData * surface = logic.Update().Surface;
  ASSERT_NE(surface, nullptr);
  ASSERT_EQ(file->GetNumberOfPoints(), surface->GetNumberOfPoints());
  for (vtkIdType k : { vtkIdType{ 0 }, surface->GetNumberOfPoints() / 2, surface->GetNumberOfPoints() - 1 })
  {
    double ras[3];
    double lps[3];
    surface->GetPoint(k, ras);
    file->GetPoint(k, lps);
    EXPECT_NEAR(lps[0], -ras[0], 1e-4) << "point " << k;
    EXPECT_NEAR(lps[1], -ras[1], 1e-4) << "point " << k;
    EXPECT_NEAR(lps[2], ras[2], 1e-4) << "point " << k;
  }
}

TEST(VesselReformationDemo, VisibilityModeComparesTheModesAtTheAngleThatHidesTheMost)
{
  vr::test::ScopedTemporaryFolder folder;
  const vr::test::ModuleRun       run = vr::test::RunProgram({ VR_DEMO_EXE,
                                                               "--phantom",
                                                               "runoff",
                                                               "--phantomSpacing",
                                                               "3",
                                                               "--size",
                                                               "64,128",
                                                               "--iterations",
                                                               "20",
                                                               "--backend",
                                                               "cpu",
                                                               "--mode",
                                                               "visibility",
                                                               "--output",
                                                               folder.Path().string() },
                                                       600.0);
  ASSERT_EQ(run.ExitCode, 0) << run.Err;
  // The run-off phantom's legs overlap the most near 120 degrees (docs/visibility.md): the demo goes there itself.
  EXPECT_TRUE(Contains(run.Out, "view at the angle that hides the most (below)")) << run.Out;
  EXPECT_TRUE(Contains(run.Out, "where vessels hide each other the most")) << run.Out;
  EXPECT_TRUE(Contains(run.Out, "hidden in all: ")) << run.Out;
  for (const char * name :
       { "visibility-comparison.png", "hidden-labels.nrrd", "hidden-lengths.csv", "occlusion-profile.csv" })
  {
    const auto entries = folder.Entries();
    EXPECT_NE(std::find(entries.begin(), entries.end(), name), entries.end()) << name;
  }
  EXPECT_TRUE(Contains(vr::test::ReadTextFile(folder.File("hidden-lengths.csv")), ",whole tree,")) << run.Out;
}
