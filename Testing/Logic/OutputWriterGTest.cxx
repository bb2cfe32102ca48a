// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The one writer of a reformation's outputs (vrOutputWriter.h), the single-vessel reading's writer on the same shape
// (vrVesselPathOutputWriter.h), and the one description of the filter settings (vrFilterSettingsText.h): the files
// and their contents, the cut surface in LPS with its marker, all or nothing.

#include "itkCTAPhantom.h"
#include "vrFilterSettingsText.h"
#include "vrImageIO.h"
#include "vrInputError.h"
#include "vrNodeConversion.h"
#include "vrOutputWriter.h"
#include "vrVesselPathOutputWriter.h"
#include "vrVesselReformationLogic.h"
#include "vrVolumeIO.h"

#include "vrTestFiles.h"

#include <gtest/gtest.h>

#include <vtkFieldData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace
{
using vr::test::ScopedTemporaryFolder;

/** The run-off phantom at 3 mm, a small view, 20 Jacobi iterations: outputs with a cut surface, quickly. */
const vr::ReformationOutputs &
PhantomOutputs()
{
  static vr::VesselReformationLogic logic;
  static bool                       updated = false;
  if (!updated)
  {
    auto phantom = itk::MakeCTAPhantom(itk::CTAPhantomKind::Runoff, 3.0);
    phantom.Source->Update();
    logic.SetVolumeNode(vr::ConvertItkImageToVolumeNode(phantom.Source->GetOutput(), "Runoff"));
    logic.SetCenterlineNode(vr::ConvertTreeToCenterlineNode(phantom.Tree, "RunoffCenterlines"));
    vr::ReformationParameters parameters;
    parameters.AngleInDegrees = phantom.DesignAngleInDegrees;
    parameters.ImageSize[0] = 48;
    parameters.ImageSize[1] = 96;
    parameters.Iterations = 20;
    parameters.Backend = vr::RelaxBackend::CPU;
    logic.SetParameters(parameters);
    logic.Update();
    updated = true;
  }
  return logic.GetOutputs();
}

/** The surface file as VTK reads it, with no conversion of ours: its points as stored and its "SPACE" marker. */
vtkSmartPointer<vtkPolyData>
ReadRaw(const std::string & path)
{
  vtkNew<vtkXMLPolyDataReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

std::string
SpaceMarker(vtkPolyData * surface)
{
  auto * space = vtkStringArray::SafeDownCast(surface->GetFieldData()->GetAbstractArray("SPACE"));
  return space && space->GetNumberOfValues() == 1 ? space->GetValue(0) : std::string("(no SPACE array)");
}

/** An image of \a size whose pixel k (in buffer order) holds \a value(k): contents a test can name by hand. */
template<typename TImage, typename TValue>
typename TImage::Pointer
NumberedImage(const typename TImage::SizeType & size, TValue value)
{
  auto image = TImage::New();
  image->SetRegions(typename TImage::RegionType(size));
  image->Allocate();
  const auto count = image->GetLargestPossibleRegion().GetNumberOfPixels();
  for (std::size_t k = 0; k < count; ++k)
  {
    image->GetBufferPointer()[k] = value(k);
  }
  return image;
}

/** A single-vessel reading's results made by hand: a 3 x 4 CPR holding 0.5 k, a fold mask of alternate pixels, a
 * 2 x 2 x 3 cross-section stack holding k; no point image, no lumen. */
vr::VesselPathOutputs
HandMadeVesselPathResults()
{
  vr::VesselPathOutputs results;
  results.CPR = NumberedImage<vr::DepthImageType>({ { 3, 4 } }, [](std::size_t k) { return 0.5f * k; });
  results.FoldMask = NumberedImage<vr::MaskImageType>({ { 3, 4 } }, [](std::size_t k) { return k % 2; });
  results.CrossSections =
    NumberedImage<vr::VolumeImageType>({ { 2, 2, 3 } }, [](std::size_t k) { return static_cast<float>(k); });
  return results;
}

/** Whether \a written holds \a expected's pixels, in order. */
template<typename TImage, typename TExpected>
bool
SamePixels(const TImage * written, const TExpected * expected)
{
  const auto count = expected->GetLargestPossibleRegion().GetNumberOfPixels();
  return written->GetLargestPossibleRegion().GetSize() == expected->GetLargestPossibleRegion().GetSize() &&
         std::equal(expected->GetBufferPointer(), expected->GetBufferPointer() + count, written->GetBufferPointer());
}

std::size_t
Occurrences(const std::string & text, const std::string & word)
{
  std::size_t count = 0;
  for (auto at = text.find(word); at != std::string::npos; at = text.find(word, at + word.size()))
  {
    ++count;
  }
  return count;
}
} // namespace

// The wording worked out from the parameters by hand: the kernel as given, then w and N, or the steady solver.
TEST(FilterSettingsText, StatesTheKernelAsGivenAndTheSolver)
{
  vr::ReformationParameters parameters; // J = 3 mm by default, w = 1, 500 Jacobi iterations
  EXPECT_EQ(vr::DescribeFilterSettings(parameters), "J = 3 mm, w = 1, 500 iterations");
  EXPECT_EQ(vr::DescribeFilterSettings(parameters, "\n"), "J = 3 mm, w = 1\n500 iterations");
  parameters.JumpThreshold = 2.5;
  parameters.Relaxation = 0.75;
  parameters.Iterations = 20;
  EXPECT_EQ(vr::DescribeFilterSettings(parameters), "J = 2.5 mm, w = 0.75, 20 iterations");
  parameters.JumpThreshold.reset();
  parameters.Anisotropy = 0.5;
  EXPECT_EQ(vr::DescribeFilterSettings(parameters), "a = 0.5 mm^-2, w = 0.75, 20 iterations");
  parameters.Solver = itk::BilateralDepthRelaxSolver::Steady; // neither w nor N applies to the fixed point
  EXPECT_EQ(vr::DescribeFilterSettings(parameters), "a = 0.5 mm^-2, steady solver");
  EXPECT_EQ(vr::DescribeFilterSettings(parameters, "\n"), "a = 0.5 mm^-2\nsteady solver");
  EXPECT_STREQ(vr::UnfilteredSettingsText, "unfiltered (w = 0)");
}

TEST(OutputWriter, WritesEveryOutputOfAFolderUnderItsName)
{
  const vr::ReformationOutputs & outputs = PhantomOutputs();
  ScopedTemporaryFolder          folder;
  const auto paths = vr::WriteOutputs(outputs, vr::OutputSelection{}, folder.Path().string(), 900.0, 200.0);
  EXPECT_EQ(paths.size(), 8u);
  const std::vector<std::string> expected = { "cpr-unfiltered.nrrd", "cpr.nrrd",   "cpr.png",     "cut-surface.vtp",
                                              "depth-relaxed.nrrd",  "depth.nrrd", "labels.nrrd", "mask.nrrd" };
  EXPECT_EQ(folder.Entries(), expected) << "no staging folder left behind either";
  // Each image is the logic's node it names.
  const auto same = [](const vr::DepthImageType * written, const vr::DepthImageType * node)
  {
    const auto count = node->GetLargestPossibleRegion().GetNumberOfPixels();
    return written->GetLargestPossibleRegion().GetNumberOfPixels() == count &&
           std::equal(node->GetBufferPointer(),
                      node->GetBufferPointer() + count,
                      written->GetBufferPointer(),
                      [](float a, float b) { return a == b || (a != a && b != b); });
  };
  EXPECT_TRUE(same(vr::ReadDepthImage(folder.File("cpr.nrrd")), vr::ConvertVolumeNodeToDepthImage(outputs.CPR)));
  EXPECT_TRUE(same(vr::ReadDepthImage(folder.File("cpr-unfiltered.nrrd")),
                   vr::ConvertVolumeNodeToDepthImage(outputs.UnfilteredCPR)));
  EXPECT_TRUE(same(vr::ReadDepthImage(folder.File("depth.nrrd")), vr::ConvertVolumeNodeToDepthImage(outputs.Depth)));
  EXPECT_TRUE(same(vr::ReadDepthImage(folder.File("depth-relaxed.nrrd")),
                   vr::ConvertVolumeNodeToDepthImage(outputs.RelaxedDepth)));
}

// As 3D Slicer writes models: LPS, and "SPACE" = "LPS" in the file. The logic's surface is RAS, so each point of the
// file is the logic's point with x and y negated.
TEST(OutputWriter, WritesTheCutSurfaceInLPSWithSlicersMarker)
{
  const vr::ReformationOutputs & outputs = PhantomOutputs();
  ASSERT_TRUE(outputs.Surface);
  ASSERT_GT(outputs.Surface->GetNumberOfPoints(), 100);
  ScopedTemporaryFolder folder;
  vr::OutputSelection   surfaceOnly{ false, false, false, false, false, false, true };
  vr::WriteOutputs(outputs, surfaceOnly, folder.Path().string(), 900.0, 200.0);
  const auto file = ReadRaw(folder.File("cut-surface.vtp"));
  EXPECT_EQ(SpaceMarker(file), "LPS");
  ASSERT_EQ(file->GetNumberOfPoints(), outputs.Surface->GetNumberOfPoints());
  for (vtkIdType k :
       { vtkIdType{ 0 }, outputs.Surface->GetNumberOfPoints() / 2, outputs.Surface->GetNumberOfPoints() - 1 })
  {
    double ras[3];
    double lps[3];
    outputs.Surface->GetPoint(k, ras);
    file->GetPoint(k, lps);
    EXPECT_FLOAT_EQ(lps[0], -ras[0]) << "point " << k;
    EXPECT_FLOAT_EQ(lps[1], -ras[1]) << "point " << k;
    EXPECT_FLOAT_EQ(lps[2], ras[2]) << "point " << k;
  }
}

// Nothing half-written: an output that cannot be written (no cut surface) leaves the folder as it was, an older
// file of the same name included.
TEST(OutputWriter, WritesNothingWhenAnOutputIsMissing)
{
  vr::ReformationOutputs outputs = PhantomOutputs();
  outputs.Surface = nullptr;
  ScopedTemporaryFolder folder;
  {
    std::ofstream old(folder.File("cpr.nrrd"));
    old << "an older file";
  }
  {
    vr::OutputWriter writer;
    writer.Add(vr::ReformationOutput::CPR, folder.File("cpr.nrrd"), "--outputCPR");
    writer.Add(vr::ReformationOutput::CutSurface, folder.File("surface.vtp"), "--outputSurface");
    EXPECT_TRUE(writer.Has(vr::ReformationOutput::CutSurface));
    EXPECT_FALSE(writer.Has(vr::ReformationOutput::Depth));
    try
    {
      writer.Write(outputs, 900.0, 200.0);
      ADD_FAILURE() << "a missing cut surface must be refused";
    }
    catch (const vr::InputError & error)
    {
      EXPECT_NE(std::string(error.what()).find("--outputSurface"), std::string::npos) << error.what();
      EXPECT_NE(std::string(error.what()).find("no cut surface"), std::string::npos) << error.what();
    }
    EXPECT_THROW(writer.Add(vr::ReformationOutput::CPR, folder.File("again.nrrd"), "--outputCPR"), vr::InputError);
  } // the failed run ends: its staging folder goes
  EXPECT_EQ(folder.Entries(), std::vector<std::string>{ "cpr.nrrd" });
  std::ifstream old(folder.File("cpr.nrrd"));
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(old), {}), "an older file");
}

TEST(OutputWriter, WritesNothingOnAnAbandonedRunAndRefusesAnEmptySelection)
{
  ScopedTemporaryFolder folder;
  {
    std::ofstream old(folder.File("cpr.nrrd"));
    old << "an older file";
  }
  {
    vr::OutputWriter writer;
    writer.Add(vr::ReformationOutput::CPR, folder.File("cpr.nrrd"), "--outputCPR");
    writer.Write(PhantomOutputs(), 900.0, 200.0);
    // Never committed: the run ended before its other work was done.
  }
  EXPECT_EQ(folder.Entries(), std::vector<std::string>{ "cpr.nrrd" });
  std::ifstream old(folder.File("cpr.nrrd"));
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(old), {}), "an older file");
  EXPECT_THROW(vr::WriteOutputs(PhantomOutputs(),
                                vr::OutputSelection{ false, false, false, false, false, false, false },
                                folder.Path().string(),
                                900.0,
                                200.0),
               vr::InputError);
}

// The single-vessel writer: each reserved output, nothing else, with the hand-made results' pixels.
TEST(VesselPathOutputWriter, WritesEachReservedOutputAndNothingElse)
{
  const vr::VesselPathOutputs results = HandMadeVesselPathResults();
  ScopedTemporaryFolder       folder;
  vr::VesselPathOutputWriter  writer;
  writer.Add(vr::VesselPathOutput::CPR, folder.File("cpr.nrrd"), "--outputCPR");
  writer.Add(vr::VesselPathOutput::FoldMask, folder.File("folds.nrrd"), "--outputFoldMask");
  writer.Add(vr::VesselPathOutput::CrossSections, folder.File("sections.nrrd"), "--outputCrossSections");
  EXPECT_TRUE(writer.Has(vr::VesselPathOutput::FoldMask));
  EXPECT_FALSE(writer.Has(vr::VesselPathOutput::Points));
  EXPECT_FALSE(writer.Has(vr::VesselPathOutput::LumenTable));
  writer.Write(results);
  // Staged, not published: the folder holds the run's staging folder alone until CommitAll.
  const std::vector<std::string> staged = folder.Entries();
  ASSERT_EQ(staged.size(), 1u);
  EXPECT_EQ(staged[0].rfind(".vr-staging-", 0), 0u) << staged[0];
  writer.CommitAll();
  const std::vector<std::string> expected = { "cpr.nrrd", "folds.nrrd", "sections.nrrd" };
  EXPECT_EQ(folder.Entries(), expected) << "no staging folder left behind either";
  EXPECT_TRUE(SamePixels(vr::ReadDepthImage(folder.File("cpr.nrrd")).GetPointer(), results.CPR.GetPointer()));
  EXPECT_TRUE(SamePixels(vr::ReadMaskImage(folder.File("folds.nrrd")).GetPointer(), results.FoldMask.GetPointer()));
  EXPECT_TRUE(
    SamePixels(vr::ReadVolume(folder.File("sections.nrrd")).GetPointer(), results.CrossSections.GetPointer()));
}

// An output asked for but not computed is refused naming its flag (once) and what is missing; nothing is published,
// an older file of the same name is kept.
TEST(VesselPathOutputWriter, WritesNothingWhenAnOutputWasNotComputed)
{
  struct Case
  {
    vr::VesselPathOutput Output;
    const char *         Name;
    const char *         Flag;
    const char *         Missing;
  };
  const Case cases[] = {
    { vr::VesselPathOutput::LumenTable, "lumen.csv", "--outputLumenTable", "no lumen to tabulate" },
    { vr::VesselPathOutput::Points, "points.nrrd", "--outputPoints", "the point image" },
  };
  for (const Case & missing : cases)
  {
    SCOPED_TRACE(missing.Flag);
    vr::VesselPathOutputs results = HandMadeVesselPathResults();
    ScopedTemporaryFolder folder;
    vr::test::WriteTextFile(folder.File(missing.Name), "an older file");
    {
      vr::VesselPathOutputWriter writer;
      writer.Add(vr::VesselPathOutput::CPR, folder.File("cpr.nrrd"), "--outputCPR");
      writer.Add(missing.Output, folder.File(missing.Name), missing.Flag);
      try
      {
        writer.Write(results);
        ADD_FAILURE() << "an output that was not computed must be refused";
      }
      catch (const vr::InputError & error)
      {
        EXPECT_EQ(Occurrences(error.what(), missing.Flag), 1u) << error.what();
        EXPECT_NE(std::string(error.what()).find(missing.Missing), std::string::npos) << error.what();
      }
    } // the failed run ends: its staging folder goes
    EXPECT_EQ(folder.Entries(), std::vector<std::string>{ missing.Name });
    EXPECT_EQ(vr::test::ReadTextFile(folder.File(missing.Name)), "an older file");
  }
}

// A lumen table is CSV or TSV by its extension: any other is refused when it is reserved, before any work, and an
// output reserved twice is refused as the reformation's writer refuses it.
TEST(VesselPathOutputWriter, RefusesALumenTableOfAnotherExtensionAndAnOutputReservedTwiceAtOnce)
{
  ScopedTemporaryFolder folder;
  {
    vr::VesselPathOutputWriter writer;
    try
    {
      writer.Add(vr::VesselPathOutput::LumenTable, folder.File("lumen.txt"), "--outputLumenTable");
      ADD_FAILURE() << "a lumen table named .txt must be refused";
    }
    catch (const vr::InputError & error)
    {
      EXPECT_NE(std::string(error.what()).find("--outputLumenTable"), std::string::npos) << error.what();
      EXPECT_NE(std::string(error.what()).find("lumen.txt"), std::string::npos) << error.what();
    }
    EXPECT_FALSE(writer.Has(vr::VesselPathOutput::LumenTable));
    writer.Add(vr::VesselPathOutput::CPR, folder.File("cpr.nrrd"), "--outputCPR");
    EXPECT_THROW(writer.Add(vr::VesselPathOutput::CPR, folder.File("again.nrrd"), "--outputCPR"), vr::InputError);
  }
  EXPECT_EQ(folder.Entries(), std::vector<std::string>{});
}
