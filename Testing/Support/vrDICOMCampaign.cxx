// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
#include "vrDICOMCampaign.h"

#include "vrImageIO.h"
#include "vrInputError.h"
#include "vrModuleRuns.h"
#include "vrVolumeIO.h"

#include "itkImageRegionConstIteratorWithIndex.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace vr::test
{
namespace
{
namespace fs = std::filesystem;

constexpr const char * Sentinel = "an earlier output that a refused run must leave";

std::string
ReadText(const fs::path & path)
{
  std::ifstream      file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

std::vector<float>
PixelsOf(const std::string & path)
{
  const DepthImageType::Pointer image = ReadDepthImage(path);
  const std::size_t             count = image->GetLargestPossibleRegion().GetNumberOfPixels();
  return std::vector<float>(image->GetBufferPointer(), image->GetBufferPointer() + count);
}

/** The lines of \a text that hold "warning: ". */
std::vector<std::string>
WarningLines(const std::string & text)
{
  std::vector<std::string> warnings;
  std::istringstream       lines(text);
  for (std::string line; std::getline(lines, line);)
  {
    if (line.find("warning: ") != std::string::npos)
    {
      warnings.push_back(line);
    }
  }
  return warnings;
}

bool
NamesOneOf(const std::string & text, const std::vector<std::string> & named)
{
  return std::any_of(
    named.begin(), named.end(), [&](const std::string & name) { return text.find(name) != std::string::npos; });
}
} // namespace

std::vector<unsigned int>
SlicesThatDiffer(const VolumeImageType * read, const VolumeImageType * reference, double tolerance)
{
  const auto                size = reference->GetLargestPossibleRegion().GetSize();
  std::vector<unsigned int> every(size[2]);
  for (unsigned int k = 0; k < size[2]; ++k)
  {
    every[k] = k;
  }
  if (read->GetLargestPossibleRegion().GetNumberOfPixels() != reference->GetLargestPossibleRegion().GetNumberOfPixels())
  {
    return every;
  }
  std::set<unsigned int> differ;
  const auto             region = read->GetLargestPossibleRegion();
  for (itk::ImageRegionConstIteratorWithIndex<VolumeImageType> it(read, region); !it.IsAtEnd(); ++it)
  {
    VolumeImageType::PointType point;
    read->TransformIndexToPhysicalPoint(it.GetIndex(), point);
    itk::ContinuousIndex<double, 3> at;
    reference->TransformPhysicalPointToContinuousIndex(point, at);
    VolumeImageType::IndexType index;
    for (unsigned int d = 0; d < 3; ++d)
    {
      index[d] = static_cast<itk::IndexValueType>(std::lround(at[d]));
      if (std::abs(at[d] - static_cast<double>(index[d])) > 1e-3)
      {
        return every;
      }
    }
    if (!reference->GetLargestPossibleRegion().IsInside(index))
    {
      return every;
    }
    if (!(std::abs(static_cast<double>(it.Get()) - static_cast<double>(reference->GetPixel(index))) <= tolerance))
    {
      differ.insert(static_cast<unsigned int>(index[2]));
    }
  }
  return std::vector<unsigned int>(differ.begin(), differ.end());
}

DICOMCampaign::DICOMCampaign(DICOMCampaignSetup setup)
  : m_Setup(std::move(setup))
{
  fs::remove_all(m_Setup.WorkFolder);
  fs::create_directories(m_Setup.WorkFolder);
  const fs::path reference = fs::path(m_Setup.WorkFolder) / "reference.nrrd";
  WriteVolume(m_Setup.Volume, reference.string());
  std::vector<std::string> arguments{ m_Setup.Module,
                                      reference.string(),
                                      m_Setup.Centerlines,
                                      (fs::path(m_Setup.WorkFolder) / "reference-cpr.nrrd").string() };
  arguments.insert(arguments.end(), m_Setup.ModuleArguments.begin(), m_Setup.ModuleArguments.end());
  const ModuleRun run = RunProgram(arguments, 600.0);
  if (run.ExitCode != 0)
  {
    throw std::runtime_error("the module fails on the reference volume: " + run.Err);
  }
  m_ReferenceCPR = PixelsOf((fs::path(m_Setup.WorkFolder) / "reference-cpr.nrrd").string());
}

DICOMCampaignRun
DICOMCampaign::Run(std::uint64_t seed, unsigned int copy)
{
  CampaignRandom    random(seed * 1000003ULL + copy);
  CTSeriesOptions   options;
  std::string       variant;
  const std::size_t encoding = random.Below(10);
  options.Encoding.ExplicitVR = encoding < 8;
  options.Encoding.BigEndian = encoding == 9;
  variant = encoding == 9 ? "explicit VR big-endian" : encoding == 8 ? "implicit VR" : "explicit VR";
  options.FeetFirst = random.Below(2) == 0;
  variant += options.FeetFirst ? ", feet first" : ", head first";
  options.Signed = random.Below(3) == 0;
  variant += options.Signed ? ", signed 16 bits" : ", unsigned 12 bits";
  if (random.Below(5) == 0)
  {
    // Each file its own rescale: slopes of 1, 1/2 and 1/4 keep the stored values whole (16 bits stored).
    const std::uint64_t pattern = random.Next();
    const bool          isSigned = options.Signed;
    options.Rescale = [pattern, isSigned](unsigned int slice) -> std::pair<double, double>
    {
      const double slopes[] = { 1.0, 0.5, 0.25 };
      const double slope = slopes[(pattern >> (slice % 32)) % 3];
      return { slope, (isSigned ? 0.0 : -1024.0) - static_cast<double>((pattern >> (2 * (slice % 16))) % 200) };
    };
    variant += ", rescale per file";
  }
  std::vector<DICOMTestFile> files = MakeCTSeries(m_Setup.Volume, options);
  std::vector<DICOMFault>    faults;
  std::set<std::string>      touched;
  const std::size_t          count = 1 + random.Below(3);
  const auto &               kinds = DICOMFaultKinds();
  for (std::size_t tries = 0; faults.size() < count && tries < 50; ++tries)
  {
    DICOMFault fault = ApplyDICOMFault(kinds[random.Below(kinds.size())].Name, files, random, touched);
    if (!fault.Kind.empty())
    {
      faults.push_back(fault);
    }
  }
  const fs::path folder = fs::path(m_Setup.WorkFolder) / "copy";
  fs::remove_all(folder);
  WriteDICOMTestFolder(folder.string(), files);
  DICOMCampaignRun run = Classify(folder.string(), faults, variant);
  run.Seed = seed;
  run.Copy = copy;
  return run;
}

DICOMCampaignRun
DICOMCampaign::Classify(const std::string & folder, const std::vector<DICOMFault> & faults, const std::string & variant)
{
  DICOMCampaignRun run;
  run.Variant = variant;
  run.Faults = faults;
  run.Expected = ExpectedOutcome(faults);
  const fs::path output = fs::path(m_Setup.WorkFolder) / "cpr.nrrd";
  {
    std::ofstream(output) << Sentinel;
  }
  std::vector<std::string> arguments{ m_Setup.Module, folder, m_Setup.Centerlines, output.string() };
  arguments.insert(arguments.end(), m_Setup.ModuleArguments.begin(), m_Setup.ModuleArguments.end());
  const auto      start = std::chrono::steady_clock::now();
  const ModuleRun module = RunProgram(arguments, 300.0);
  run.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::vector<std::string>        refusalNames;
  std::vector<const DICOMFault *> warningFaults;
  bool                            gap = false;
  std::set<std::string>           removed;
  for (const DICOMFault & fault : faults)
  {
    if (fault.Expected == DICOMOutcome::Refused)
    {
      refusalNames.insert(refusalNames.end(), fault.Named.begin(), fault.Named.end());
    }
    if (fault.Expected == DICOMOutcome::Warning)
    {
      warningFaults.push_back(&fault);
    }
    gap = gap || fault.Kind == "missing slice" || fault.Kind == "missing slices";
  }

  if (module.Crashed || module.TimedOut)
  {
    run.Observed = "crashed";
    run.Message = module.Err;
  }
  else if (module.ExitCode == 1)
  {
    run.Message = module.Err;
    if (ReadText(output) != Sentinel || fs::exists(fs::path(m_Setup.WorkFolder) / "cpr.nrrd.tmp"))
    {
      run.Observed = "refused-and-wrote";
    }
    else if (run.Expected == DICOMOutcome::Refused && !NamesOneOf(module.Err, refusalNames))
    {
      run.Observed = "refused-naming-nothing-at-fault";
    }
    else
    {
      run.Observed = "refused-naming-the-file";
    }
  }
  else if (module.ExitCode != 0)
  {
    run.Observed = "wrong";
    run.Message = "exit status " + std::to_string(module.ExitCode) + ": " + module.Err;
  }
  else
  {
    const std::vector<std::string> warnings = WarningLines(module.Err);
    for (const std::string & warning : warnings)
    {
      run.Message += (run.Message.empty() ? "" : "\n") + warning;
    }
    // The image: the CPR against the reference's, and the volume read here against the volume, point by point.
    bool               sameCPR = false;
    std::vector<float> cpr;
    try
    {
      cpr = PixelsOf(output.string());
    }
    catch (const std::exception &)
    {
    }
    if (cpr.size() == m_ReferenceCPR.size())
    {
      sameCPR = true;
      for (std::size_t k = 0; k < cpr.size() && sameCPR; ++k)
      {
        sameCPR = std::abs(cpr[k] - m_ReferenceCPR[k]) <= 1e-3f;
      }
    }
    std::vector<unsigned int> differ;
    try
    {
      VolumeReadReport report;
      differ = SlicesThatDiffer(ReadVolume(folder, VolumeReadOptions(), &report), m_Setup.Volume);
    }
    catch (const std::exception & error)
    {
      run.Finding = std::string("the volume read here failed: ") + error.what();
      differ = { 0 };
    }
    if (warnings.empty())
    {
      run.Observed = sameCPR && differ.empty() ? "read-identical" : "wrong";
      if (run.Observed == "wrong")
      {
        run.Finding += (sameCPR ? "" : "the CPR differs; ") + std::to_string(differ.size()) + " slices differ";
      }
    }
    else
    {
      run.Observed = "read-with-warning";
      // Each warning fault named; and the image the same as the sound one but at the slices of a gap.
      for (const DICOMFault * fault : warningFaults)
      {
        if (!NamesOneOf(run.Message, fault->Named))
        {
          run.Observed = "warning-naming-nothing-at-fault";
        }
      }
      if (!gap && !(sameCPR && differ.empty()))
      {
        run.Observed = "wrong";
        run.Finding += "a warning, but the image differs where no slice is missing";
      }
      if (gap)
      {
        // The interpolated slices are where files were removed: IMnnnn.dcm holds the reference's slice
        // (slices - n) head first, (n - 1) feet first (MakeCTSeries).
        std::set<unsigned int> allowed;
        const auto slices = static_cast<unsigned int>(m_Setup.Volume->GetLargestPossibleRegion().GetSize()[2]);
        for (const DICOMFault & fault : faults)
        {
          if (fault.Kind != "missing slice" && fault.Kind != "missing slices")
          {
            continue;
          }
          std::istringstream names(fault.Detail);
          for (std::string name; names >> name && name != "removed";)
          {
            const auto instance = static_cast<unsigned int>(std::stoul(name.substr(2, 4)));
            allowed.insert(variant.find("feet first") != std::string::npos ? instance - 1 : slices - instance);
          }
        }
        for (const unsigned int slice : differ)
        {
          if (allowed.count(slice) == 0)
          {
            run.Observed = "wrong";
            run.Finding += "slice " + std::to_string(slice) + " differs, and no file of it is missing; ";
          }
        }
      }
    }
  }
  run.Correct = run.Observed == ToString(run.Expected);
  return run;
}
} // namespace vr::test
