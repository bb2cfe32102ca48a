// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// A kept set of the DICOM campaign's cases (issue 37; Testing/Tools/DICOMFaultCampaign runs thousands), replayed on
// the thoracic phantom at 3 mm: every kind of fault alone, and copies 1-12 of seed 37 (one to three faults each, on
// series written explicit or implicit VR or big-endian, head or feet first, signed or not, rescaled per file or not).
// Each copy is generated here, the same on every machine (vrDICOMFaults.h), the module run on it and the run put in a
// class; each must be in the class docs/dicom-series.md documents for its faults, naming them.
#include "itkCTAPhantom.h"
#include "vrCenterlineIO.h"
#include "vrDICOMCampaign.h"

#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <memory>

namespace
{
namespace fs = std::filesystem;
using namespace vr::test;

vr::test::DICOMCampaign &
Campaign()
{
  static std::unique_ptr<DICOMCampaign> campaign = []
  {
    // A folder for this process: CTest runs each test in one, several at a time.
    const auto *   test = ::testing::UnitTest::GetInstance()->current_test_info();
    const fs::path folder = fs::path(VR_TEST_OUTPUT_DIR) / (std::string(test->test_suite_name()) + "." + test->name());
    fs::create_directories(folder);
    auto phantom = itk::MakeCTAPhantom(itk::CTAPhantomKind::Thorax, 3.0);
    phantom.Source->Update();
    DICOMCampaignSetup setup;
    setup.Module = VR_REFORMATION_EXE;
    setup.WorkFolder = (folder / "run").string();
    setup.Volume = QuantizedCT(phantom.Source->GetOutput());
    setup.Centerlines = (folder / "centerlines.vtp").string();
    vr::WriteCenterlines(phantom.Tree, setup.Centerlines);
    setup.ModuleArguments = { "--size", "96,192", "--iterations", "30", "--angle", "30" };
    return std::make_unique<DICOMCampaign>(setup);
  }();
  return *campaign;
}

std::string
Described(const DICOMCampaignRun & run)
{
  std::string text = "[" + run.Variant + "] expected " + ToString(run.Expected) + ", got " + run.Observed + " " +
                     run.Finding + "; faults:";
  for (const DICOMFault & fault : run.Faults)
  {
    text += " " + fault.Kind + " (" + fault.Detail + ");";
  }
  return text + "\n" + run.Message;
}

class EachFault : public ::testing::TestWithParam<std::size_t>
{
};

TEST_P(EachFault, AloneGivesItsDocumentedResult)
{
  const DICOMFaultKind & kind = DICOMFaultKinds()[GetParam()];
  SCOPED_TRACE(kind.Name);
  auto phantom = itk::MakeCTAPhantom(itk::CTAPhantomKind::Thorax, 3.0);
  phantom.Source->Update();
  std::vector<DICOMTestFile> files = MakeCTSeries(QuantizedCT(phantom.Source->GetOutput()));
  CampaignRandom             random(3700 + GetParam());
  std::set<std::string>      touched;
  const DICOMFault           fault = ApplyDICOMFault(kind.Name, files, random, touched);
  ASSERT_EQ(fault.Kind, kind.Name) << "the fault could be made";
  const fs::path folder = fs::path(VR_TEST_OUTPUT_DIR) / ("fault-" + std::to_string(GetParam()));
  fs::remove_all(folder);
  WriteDICOMTestFolder(folder.string(), files);
  const DICOMCampaignRun run = Campaign().Classify(folder.string(), { fault }, "explicit VR, head first");
  EXPECT_TRUE(run.Correct) << Described(run);
  EXPECT_EQ(run.Observed, ToString(kind.Expected)) << Described(run);
  std::cout << kind.Name << ": " << fault.Detail << " -> " << run.Observed << "\n" << run.Message << std::endl;
}

INSTANTIATE_TEST_SUITE_P(DICOMCampaign,
                         EachFault,
                         ::testing::Range(std::size_t{ 0 }, DICOMFaultKinds().size()),
                         [](const ::testing::TestParamInfo<std::size_t> & info)
                         {
                           std::string name;
                           for (const char c : DICOMFaultKinds()[info.param].Name)
                           {
                             name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           }
                           return name;
                         });

class KeptCopy : public ::testing::TestWithParam<unsigned int>
{
};

TEST_P(KeptCopy, IsInItsDocumentedClass)
{
  const DICOMCampaignRun run = Campaign().Run(37, GetParam());
  EXPECT_TRUE(run.Correct) << Described(run);
  std::cout << Described(run) << std::endl;
}

INSTANTIATE_TEST_SUITE_P(DICOMCampaignSeed37, KeptCopy, ::testing::Range(1u, 13u));
} // namespace
