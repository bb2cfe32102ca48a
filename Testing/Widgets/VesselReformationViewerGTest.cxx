// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The VesselReformationViewer as built, in scripted mode (--screenshot): on the built-in phantom, on the VMTK aorta,
// and on bad input (exit 1 with a message, no PNG).
#include "vrInputError.h"
#include "vrTestFiles.h"
#include "vrTestProcess.h"
#include "vrVolumeIO.h"

#include <QColor>
#include <QImage>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <set>

namespace
{
namespace fs = std::filesystem;
using vr::test::ProcessResult;

/** A fresh folder for one test, under the build tree. */
fs::path
TestFolder()
{
  const auto *   info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path folder = fs::path(VR_TEST_OUTPUT_DIR) / (std::string(info->test_suite_name()) + "." + info->name());
  fs::remove_all(folder);
  fs::create_directories(folder);
  return folder;
}

ProcessResult
RunViewer(std::vector<std::string> arguments)
{
  arguments.insert(arguments.begin(), VR_VIEWER_EXE);
  ProcessResult result = vr::test::RunProcess(arguments, (fs::path(VR_TEST_OUTPUT_DIR) / ".capture").string());
  std::cout << "exit " << result.ExitCode << "\nstdout: " << result.Out << "stderr: " << result.Err << std::endl;
  return result;
}

/** What a screenshot shows, measured: its size, how many distinct colours, the spread of its grey values, and the
 * share of bright pixels (vessels, bone: grey > 200) among the grey pixels of the CPR view's half. */
struct PictureFacts
{
  int         Width{ 0 };
  int         Height{ 0 };
  std::size_t Colours{ 0 };
  double      GreyDeviation{ 0.0 };
  double      BrightShare{ 0.0 };
};

PictureFacts
Measure(const fs::path & png)
{
  PictureFacts facts;
  const QImage image(QString::fromStdString(png.string()));
  if (image.isNull())
  {
    return facts;
  }
  facts.Width = image.width();
  facts.Height = image.height();
  std::set<QRgb> colours;
  double         sum = 0.0;
  double         squares = 0.0;
  std::size_t    count = 0;
  std::size_t    greys = 0;
  std::size_t    bright = 0;
  for (int y = 0; y < image.height(); ++y)
  {
    for (int x = 0; x < image.width(); ++x)
    {
      const QRgb rgb = image.pixel(x, y);
      colours.insert(rgb);
      const double grey = qGray(rgb);
      sum += grey;
      squares += grey * grey;
      ++count;
      if (x > image.width() / 4 && x < 3 * image.width() / 5 && qRed(rgb) == qGreen(rgb) && qGreen(rgb) == qBlue(rgb) &&
          qRed(rgb) > 30)
      {
        ++greys;
        bright += qRed(rgb) > 200 ? 1 : 0;
      }
    }
  }
  facts.Colours = colours.size();
  const double mean = sum / static_cast<double>(count);
  facts.GreyDeviation = std::sqrt(std::max(0.0, squares / static_cast<double>(count) - mean * mean));
  facts.BrightShare = greys > 0 ? static_cast<double>(bright) / static_cast<double>(greys) : 0.0;
  return facts;
}

/** Runs the viewer with \a arguments and --screenshot \a png, expects a clean exit and a window-sized picture (1600
 * pixels wide) of more than 1500 colours (a flat or empty window has tens; without multisampling, which the views
 * leave off on Xvfb's software renderer, the smallest picture here, the VMTK aorta's, has about 1900) and a grey
 * deviation above 20, prints what it measured and leaves it in
 * \a facts. Call it through ASSERT_NO_FATAL_FAILURE: a crash or a failed run ends the test. */
void
TakeScreenshot(std::vector<std::string> arguments, const fs::path & png, PictureFacts & facts)
{
  arguments.push_back("--screenshot");
  arguments.push_back(png.string());
  const ProcessResult result = RunViewer(arguments);
  ASSERT_FALSE(result.Crashed);
  ASSERT_EQ(result.ExitCode, 0) << result.Err;
  ASSERT_TRUE(fs::exists(png));
  facts = Measure(png);
  EXPECT_EQ(facts.Width, 1600);
  EXPECT_GT(facts.Colours, 1500u) << "a CPR, overlays, a shaded 3D view and text";
  EXPECT_GT(facts.GreyDeviation, 20.0);
  std::cout << "colours " << facts.Colours << ", grey deviation " << facts.GreyDeviation << ", bright share "
            << facts.BrightShare << std::endl;
}

TEST(ViewerScreenshot, OnThePhantom)
{
  const fs::path folder = TestFolder();
  const fs::path png = folder / "phantom.png";
  PictureFacts   facts;
  ASSERT_NO_FATAL_FAILURE(TakeScreenshot({ "--phantomSpacing",
                                           "3",
                                           "--size",
                                           "256,512",
                                           "--iterations",
                                           "200",
                                           "--angle",
                                           "30",
                                           "--overlays",
                                           "centerlines,labels" },
                                         png,
                                         facts));
  EXPECT_EQ(facts.Height, 1000);
  EXPECT_GT(facts.BrightShare, 0.002) << "contrast-filled lumen and bone appear bright through the CTA window";
  EXPECT_EQ(fs::directory_iterator(folder) != fs::directory_iterator(), true);
  std::size_t files = 0;
  for ([[maybe_unused]] const auto & entry : fs::directory_iterator(folder))
  {
    ++files;
  }
  EXPECT_EQ(files, 1u) << "the PNG and no temporary file";
}

TEST(ViewerScreenshot, OnTheThoracicPhantomWithTheJumpThresholdAndTheSteadySolver)
{
  const fs::path folder = TestFolder();
  const fs::path png = folder / "thorax.png";
  PictureFacts   facts;
  ASSERT_NO_FATAL_FAILURE(TakeScreenshot({ "--phantom",
                                           "thorax",
                                           "--phantomSpacing",
                                           "3",
                                           "--size",
                                           "256,512",
                                           "--jumpThreshold",
                                           "3",
                                           "--solver",
                                           "steady",
                                           "--angle",
                                           "30",
                                           "--overlays",
                                           "centerlines" },
                                         png,
                                         facts));
  EXPECT_GT(facts.BrightShare, 0.002) << "the contrast-filled aorta and the spine through the CTA window";
}

TEST(ViewerScreenshot, OnTheVMTKAorta)
{
  const std::string data = vr::test::AortaDataFolder();
  if (data.empty())
  {
    GTEST_FAIL() << "VMTK's aorta (vmtk-aorta-mra) is missing from VR_SHARED_DATA_DIR (Testing/Data by default)";
  }
  const fs::path folder = TestFolder();
  const fs::path png = folder / "aorta.mha.png";
  PictureFacts   facts;
  ASSERT_NO_FATAL_FAILURE(TakeScreenshot({ (fs::path(data) / "aorta.mha").string(),
                                           (fs::path(data) / "aorta-centerline.vtp").string(),
                                           "--up",
                                           "auto",
                                           "--angle",
                                           "20" },
                                         png,
                                         facts));
  EXPECT_GT(facts.BrightShare, 0.02) << "the contrast-filled aorta and iliacs through the full-range window";
}

TEST(ViewerScreenshot, OnTheVMTKAortaWithItsLevelSetInsteadOfCenterlines)
{
  const std::string data = vr::test::AortaDataFolder();
  if (data.empty())
  {
    GTEST_FAIL() << "VMTK's aorta (vmtk-aorta-mra) is missing from VR_SHARED_DATA_DIR (Testing/Data by default)";
  }
  const fs::path folder = TestFolder();
  const fs::path png = folder / "aorta-levelset.png";
  PictureFacts   facts;
  ASSERT_NO_FATAL_FAILURE(TakeScreenshot({ (fs::path(data) / "aorta.mha").string(),
                                           "--segmentation",
                                           (fs::path(data) / "aorta-final-levelset.mha").string(),
                                           "--up",
                                           "auto",
                                           "--angle",
                                           "20" },
                                         png,
                                         facts));
  EXPECT_GT(facts.BrightShare, 0.02) << "the contrast-filled aorta and iliacs through the full-range window";

  // A segmentation file that does not read: the reader's message, exit 1, no picture.
  const std::string corrupt = (folder / "corrupt-mask.nii").string();
  vr::test::WriteTextFile(corrupt, "not a NIfTI header at all");
  const fs::path      never = folder / "never.png";
  const ProcessResult bad =
    RunViewer({ (fs::path(data) / "aorta.mha").string(), "--segmentation", corrupt, "--screenshot", never.string() });
  EXPECT_FALSE(bad.Crashed);
  EXPECT_EQ(bad.ExitCode, 1);
  EXPECT_NE(bad.Err.find("corrupt-mask.nii"), std::string::npos) << bad.Err;
  EXPECT_FALSE(fs::exists(never));
}

TEST(ViewerScreenshot, BadInputExitsWithOneAndAMessageAndWritesNoPicture)
{
  const fs::path    folder = TestFolder();
  const std::string png = (folder / "never.png").string();
  const std::string corrupt = (folder / "corrupt.nrrd").string();
  vr::test::WriteTextFile(corrupt, "NRRD0004\ntype: float\ndimension: 3\nsizes: 10 10\nencoding: raw\n\n");
  const std::string corruptMessage = vr::test::InputErrorOf([&] { vr::ReadVolume(corrupt); });
  ASSERT_FALSE(corruptMessage.empty());
  const std::string centerlines = (folder / "centerlines.csv").string();
  vr::test::WriteTextFile(centerlines, "branch,x,y,z\n1,0,0,0\n1,0,0,10\n");

  struct Case
  {
    std::vector<std::string> Arguments;
    std::string              Says;
  };
  const std::vector<Case> cases = {
    { { (folder / "missing.mha").string(), centerlines, "--screenshot", png }, "missing.mha" },
    { { corrupt, centerlines, "--screenshot", png }, corruptMessage },
    { { corrupt, "--screenshot", png }, "give both a volume and centerlines" },
    { { "--segmentation", corrupt, "--screenshot", png }, "--segmentation needs the volume" },
    { { corrupt, centerlines, "--segmentation", corrupt, "--screenshot", png }, "give one of them" },
    { { corrupt, "--segmentation", ",", "--screenshot", png }, "--segmentation" },
    { { "--relaxation", "2", "--screenshot", png }, "--relaxation" },
    { { "--angle", "abc", "--screenshot", png }, "--angle" },
    { { "--jumpThreshold", "2", "--anisotropy", "0.5", "--screenshot", png }, "both --jumpThreshold and --anisotropy" },
    { { "--anisotropy", "0.5", "--jumpThreshold", "2", "--screenshot", png }, "give one of them" },
    { { "--jumpThreshold", "0", "--screenshot", png }, "--jumpThreshold" },
    { { "--jumpThreshold", "2mm", "--screenshot", png }, "--jumpThreshold" },
    { { "--solver", "multigrid", "--screenshot", png }, "--solver" },
    { { "--size", "300,0", "--screenshot", png }, "--size" },
    { { "--phantom", "heart", "--screenshot", png }, "--phantom" },
    { { "--overlays", "vessels", "--screenshot", png }, "--overlays" },
    { { "--screenshot", (folder / "picture.jpg").string() }, ".png" },
    { { "--window", "400", "--screenshot", png }, "--level" },
    { { "--bogus", "--screenshot", png }, "--bogus" },
    { { "--screenshot",
        (folder / "no-such-folder" / "x.png").string(),
        "--phantomSpacing",
        "4",
        "--size",
        "64,128",
        "--iterations",
        "10" },
      "no-such-folder" },
  };
  for (const Case & test : cases)
  {
    const ProcessResult result = RunViewer(test.Arguments);
    EXPECT_FALSE(result.Crashed) << test.Arguments.front();
    EXPECT_EQ(result.ExitCode, 1) << test.Arguments.front();
    EXPECT_NE(result.Err.find("VesselReformationViewer: error: "), std::string::npos) << result.Err;
    EXPECT_NE(result.Err.find(test.Says), std::string::npos) << "expected \"" << test.Says << "\" in: " << result.Err;
    EXPECT_FALSE(fs::exists(png));
  }
}

TEST(ViewerScreenshot, HelpExitsWithZero)
{
  const ProcessResult result = RunViewer({ "--help" });
  EXPECT_EQ(result.ExitCode, 0);
  EXPECT_NE(result.Out.find("--screenshot"), std::string::npos);
}
} // namespace
