// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The command-line modules given bad input (issue 3): a message naming the file, field or flag, exit 1, no crash, no
// output, an existing output intact (BadInputTest, vrCLITestSupport.h).
#include "vrCLITestSupport.h"

namespace
{
using namespace vr::test::cli;

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

} // namespace
