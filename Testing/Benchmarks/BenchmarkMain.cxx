// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// VesselReformationBenchmarks: the paper's Table 1 on this machine (see benchmark_table.py). The context of the
// JSON output names the processor, the relax kernel's instruction set, the thread count, the build flags and the
// OpenCL devices. --opencl_devices prints those devices, one a line, and exits (scripts/device-report.sh).
#include "itkBilateralDepthRelaxKernel.h"
#include "itkMultiThreaderBase.h"

#include <benchmark/benchmark.h>

#ifdef VESSELREFORMATION_HAS_OPENCL
#include "vrOpenCLDevices.h"
#endif

#include <cstring>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace
{
/** "model name" of the first processor in /proc/cpuinfo, or "unknown". */
std::string
ProcessorModel()
{
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string   line;
  while (std::getline(cpuinfo, line))
  {
    if (line.rfind("model name", 0) == 0)
    {
      const auto colon = line.find(':');
      return colon == std::string::npos ? line : line.substr(line.find_first_not_of(' ', colon + 1));
    }
  }
  return "unknown";
}

/** The machine's OpenCL devices as the relax filter names them ("P:D name (platform, type)"), unusable ones with
 * the reason, one a line; or why there is none. */
std::string
OpenCLDevices()
{
#ifdef VESSELREFORMATION_HAS_OPENCL
  std::string problem;
  std::string lines;
  for (const auto & device : vr::ListOpenCLDevices(&problem))
  {
    lines += device.Label() + (device.Unusable.empty() ? "" : " [not usable: " + device.Unusable + "]") + "\n";
  }
  return lines.empty() ? "none: " + problem + "\n" : lines;
#else
  return "none: this build has no OpenCL support\n";
#endif
}
} // namespace

int
main(int argc, char ** argv)
{
  if (argc == 2 && std::strcmp(argv[1], "--opencl_devices") == 0)
  {
    std::cout << OpenCLDevices();
    return 0;
  }
  // Repetitions of all benchmarks run in random order by default, so that a slow spell of a shared machine
  // spreads over all figures instead of spoiling one (and the ratios between them). A later
  // --benchmark_enable_random_interleaving=false on the command line wins.
  std::vector<char *> arguments(argv, argv + argc);
  std::string         interleave = "--benchmark_enable_random_interleaving=true";
  arguments.insert(arguments.begin() + 1, interleave.data());
  int count = static_cast<int>(arguments.size());
  benchmark::Initialize(&count, arguments.data());
  argc = count;
  argv = arguments.data();
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
  {
    return 1;
  }
  benchmark::AddCustomContext("cpu_model", ProcessorModel());
  benchmark::AddCustomContext("relax_instruction_set", itk::BilateralDepthRelaxKernel::GetInstructionSet());
  benchmark::AddCustomContext("itk_threads", std::to_string(itk::MultiThreaderBase::GetGlobalDefaultNumberOfThreads()));
  benchmark::AddCustomContext("build_type", VR_BENCHMARK_BUILD_TYPE);
  benchmark::AddCustomContext("cxx_flags", VR_BENCHMARK_CXX_FLAGS);
  std::string devices = OpenCLDevices();
  devices.pop_back(); // the last line's end
  for (auto at = devices.find('\n'); at != std::string::npos; at = devices.find('\n', at))
  {
    devices.replace(at, 1, "; ");
  }
  benchmark::AddCustomContext("opencl_devices", devices);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
