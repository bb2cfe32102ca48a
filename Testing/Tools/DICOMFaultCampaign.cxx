// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// DICOMFaultCampaign: the tag-aware DICOM campaign of issue 37. Writes a CT series with full geometry from a phantom
// (its values rounded to whole HU), makes copies with one to three semantic faults each (vrDICOMFaults.h: missing
// slices, duplicates, a second series, wrong attributes, false transfer syntaxes, rescales, stray files, gaps,
// tilts...), runs the VesselReformation module on every copy and puts each run in a class: read-identical,
// read-with-warning (the warning names the fault), refused-naming-the-file, or one of the wrong classes. Prints the
// table of classes, the outcome of each fault kind, one message of each kind and every copy in a wrong class (replay
// one with --seed S --first C --copies 1 --keep DIR).
//
//   DICOMFaultCampaign [--copies N=1000] [--seed S]... [--first C=1] [--phantom thorax|runoff] [--spacing MM=2]
//                      [--work DIR] [--keep DIR] [--module PATH]
// --module runs another VesselReformation than the build's (a copy, so that a rebuild during a long campaign cannot
// fail runs; VR_DICOM_SERIES_READER then names the reader process this tool's own reads use).
#include "itkCTAPhantom.h"
#include "vrCenterlineIO.h"
#include "vrDICOMCampaign.h"

#include <gdcmTrace.h>

#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <string>
#include <vector>

namespace
{
namespace fs = std::filesystem;
using namespace vr::test;

int
Usage()
{
  std::cerr << "usage: DICOMFaultCampaign [--copies N] [--seed S]... [--first C] [--phantom thorax|runoff] "
               "[--spacing MM] [--work DIR] [--keep DIR] [--module PATH]\n";
  return 2;
}
} // namespace

int
main(int argc, char * argv[])
{
  unsigned int               copies = 1000;
  unsigned int               first = 1;
  std::vector<std::uint64_t> seeds;
  std::string                phantom = "thorax";
  double                     spacing = 2.0;
  std::string                work = (fs::temp_directory_path() / "vr-dicom-fault-campaign").string();
  std::string                keep;
  std::string                module = VR_REFORMATION_EXE;
  for (int k = 1; k < argc; ++k)
  {
    const std::string flag = argv[k];
    if (k + 1 >= argc)
    {
      return Usage();
    }
    const std::string value = argv[++k];
    if (flag == "--copies")
    {
      copies = static_cast<unsigned int>(std::stoul(value));
    }
    else if (flag == "--first")
    {
      first = static_cast<unsigned int>(std::stoul(value));
    }
    else if (flag == "--seed")
    {
      seeds.push_back(std::stoull(value));
    }
    else if (flag == "--phantom")
    {
      phantom = value;
    }
    else if (flag == "--spacing")
    {
      spacing = std::stod(value);
    }
    else if (flag == "--work")
    {
      work = value;
    }
    else if (flag == "--keep")
    {
      keep = value;
    }
    else if (flag == "--module")
    {
      module = value;
    }
    else
    {
      return Usage();
    }
  }
  if (seeds.empty())
  {
    seeds.push_back(1);
  }
  gdcm::Trace::SetWarning(false);
  gdcm::Trace::SetError(false);

  const auto start = std::chrono::steady_clock::now();
  auto       made = itk::MakeCTAPhantom(itk::ParseCTAPhantomKind(phantom), spacing);
  made.Source->Update();
  fs::create_directories(work);
  DICOMCampaignSetup setup;
  setup.Module = module;
  setup.WorkFolder = (fs::path(work) / "run").string();
  setup.Volume = QuantizedCT(made.Source->GetOutput());
  setup.Centerlines = (fs::path(work) / "centerlines.vtp").string();
  vr::WriteCenterlines(made.Tree, setup.Centerlines);
  setup.ModuleArguments = { "--size", "128,256", "--iterations", "50", "--angle", "30" };
  DICOMCampaign campaign(setup);
  const auto    size = setup.Volume->GetLargestPossibleRegion().GetSize();
  std::cout << "DICOM fault campaign: the " << phantom << " phantom at " << spacing << " mm (" << size[0] << " x "
            << size[1] << " x " << size[2] << " voxels, whole HU), " << copies << " copies for each of " << seeds.size()
            << (seeds.size() == 1 ? " seed" : " seeds") << std::endl;

  std::map<std::string, std::map<std::string, unsigned int>> table;   // expected -> observed -> copies
  std::map<std::string, std::map<std::string, unsigned int>> byKind;  // fault kind (alone) -> observed -> copies
  std::map<std::string, std::string>                         example; // fault kind -> a message it gave alone
  std::vector<std::string>                                   wrong;
  unsigned int                                               total = 0;
  unsigned int                                               correct = 0;
  for (const std::uint64_t seed : seeds)
  {
    for (unsigned int copy = first; copy < first + copies; ++copy)
    {
      const DICOMCampaignRun run = campaign.Run(seed, copy);
      ++total;
      correct += run.Correct ? 1 : 0;
      ++table[ToString(run.Expected)][run.Observed];
      if (run.Faults.size() == 1)
      {
        ++byKind[run.Faults.front().Kind][run.Observed];
        if (run.Correct && run.Expected != DICOMOutcome::Identical && example.count(run.Faults.front().Kind) == 0)
        {
          example[run.Faults.front().Kind] = run.Faults.front().Detail + " -> " + run.Message;
        }
      }
      if (!run.Correct)
      {
        std::string faults;
        for (const DICOMFault & fault : run.Faults)
        {
          faults += (faults.empty() ? "" : "; ") + fault.Kind + " (" + fault.Detail + ")";
        }
        wrong.push_back("seed " + std::to_string(seed) + " copy " + std::to_string(copy) + " [" + run.Variant +
                        "]: " + faults + ": expected " + ToString(run.Expected) + ", got " + run.Observed + " " +
                        run.Finding + ": " + run.Message);
        if (!keep.empty())
        {
          const fs::path kept = fs::path(keep) / ("seed" + std::to_string(seed) + "-copy" + std::to_string(copy));
          fs::create_directories(kept.parent_path());
          fs::remove_all(kept);
          fs::copy(fs::path(setup.WorkFolder) / "copy", kept, fs::copy_options::recursive);
        }
      }
      if (total % 100 == 0)
      {
        std::cout << "  " << total << " copies, " << total - correct << " in a wrong class" << std::endl;
      }
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::cout << "\n"
            << total << " copies in " << std::fixed << std::setprecision(0) << seconds << " s; " << total - correct
            << " in a wrong class\n\n| expected | observed | copies |\n| --- | --- | --- |\n";
  for (const auto & [expected, observed] : table)
  {
    for (const auto & [name, count] : observed)
    {
      std::cout << "| " << expected << " | " << name << " | " << count << " |\n";
    }
  }
  std::cout << "\nCopies with one fault, by kind:\n\n| fault | expected | observed: copies |\n| --- | --- | --- |\n";
  for (const DICOMFaultKind & kind : DICOMFaultKinds())
  {
    std::string observed;
    for (const auto & [name, count] : byKind[kind.Name])
    {
      observed += (observed.empty() ? "" : ", ") + name + ": " + std::to_string(count);
    }
    std::cout << "| " << kind.Name << " | " << ToString(kind.Expected) << " | " << observed << " |\n";
  }
  std::cout << "\nOne message of each kind (the fault alone):\n\n";
  for (const DICOMFaultKind & kind : DICOMFaultKinds())
  {
    if (example.count(kind.Name) != 0)
    {
      std::cout << "- " << kind.Name << ": " << example[kind.Name] << "\n";
    }
  }
  if (!wrong.empty())
  {
    std::cout << "\nCopies in a wrong class:\n";
    for (const std::string & line : wrong)
    {
      std::cout << "- " << line << "\n";
    }
  }
  return wrong.empty() ? 0 : 1;
}
