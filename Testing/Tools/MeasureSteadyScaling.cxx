// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Measurement, not a test: the steady solver from the input depths (as before issue 26) and with nested iteration,
// alternately, on the thoracic phantom, the run-off phantom and the VMTK aorta MRA at W x H, H = 2 W: median times of
// repeated solves, outer iterations on the image's grid and on the coarser ones, and the energy and residual of each
// result from the plain reference code (docs/measurements/2026-11-26-steady-nested-iteration.md). Beside the wall time,
// the process's CPU time (all threads): on a machine shared with other work, where wall time also counts the waits
// for a core, it tells what a solve cost. --jacobi also times the 500 Jacobi passes (the CPU filter, w = 1, the same J
// and threads) on the same map, alternately with the solves, and prints the ratio (issue 40).
//
//   MeasureSteadyScaling [--repeat N] [--threads T] [--anisotropy a] [--only nested|input] [--jacobi] case:W ...
//   (case thorax|runoff|aorta|aortailiacs|aorta@ANGLE (the aorta at ANGLE degrees), H = 2 W, or fullsize, W one of the
//   full-size views' widths (vr::benchmarks::FullSizeViews); runoff-repeated|runoff-subsampled, the run-off map at
//   half or twice the width resampled to W x 2W; a in mm^-2, default 1/9: J = 3 mm)
#include "PlainBilateralDepthRelax.h"
#include "vrBenchmarkScene.h"
#include "vrCenterlineIO.h"
#include "vrTestDepthMaps.h"
#include "vrVolumeIO.h"

#include "itkBilateralDepthRelaxFilter.h"
#include "itkBilateralDepthRelaxSteadySolver.h"
#include "itkCTAPhantom.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using Solver = itk::BilateralDepthRelaxSteadySolver;
double Anisotropy = 1.0 / 9.0; // J = 3 mm, the filter's default; --anisotropy a to change

using Map = vr::test::DepthMapBuffers;

Map
MapOf(const vr::test::PhantomDepthMap & map, unsigned int width, unsigned int height)
{
  return { vr::test::PixelsOf(map.Depth.GetPointer()), vr::test::PixelsOf(map.Fixed.GetPointer()), width, height };
}

/** The run-off phantom's map at W x 2W resampled to \a width x 2 \a width by nearest pixel: each pixel repeated
 * 2 x 2 (W = width / 2), or every other pixel taken (W = 2 width). The same content at another resolution, to tell
 * the solver's own scaling from what a finer map adds (docs/measurements/2026-11-29-steady-runoff-content.md). */
Map
RunoffResampled(unsigned int width, bool repeated)
{
  const unsigned int sourceWidth = repeated ? width / 2 : 2 * width;
  const Map          source = MapOf(
    vr::benchmarks::PhantomScene::Instance().GetDepthMap(sourceWidth, 2 * sourceWidth), sourceWidth, 2 * sourceWidth);
  const unsigned int height = 2 * width;
  Map                map{ std::vector<float>(std::size_t{ width } * height),
           std::vector<unsigned char>(std::size_t{ width } * height),
           width,
           height };
  for (std::size_t y = 0; y < height; ++y)
  {
    for (std::size_t x = 0; x < width; ++x)
    {
      const std::size_t from = repeated ? (y / 2) * sourceWidth + x / 2 : (2 * y) * sourceWidth + 2 * x;
      map.Depth[y * width + x] = source.Depth[from];
      map.Fixed[y * width + x] = source.Fixed[from];
    }
  }
  return map;
}

Map
MakeMap(const std::string & name, unsigned int width)
{
  const unsigned int height = 2 * width;
  if (name == "thorax")
  {
    return MapOf(vr::benchmarks::ThoraxDepthMap(width, height), width, height);
  }
  if (name == "runoff")
  {
    return MapOf(vr::benchmarks::PhantomScene::Instance().GetDepthMap(width, height), width, height);
  }
  if (name == "runoff-repeated" || name == "runoff-subsampled")
  {
    if (width < 2 || width % 2 != 0)
    {
      throw std::invalid_argument(name + " needs an even width, not " + std::to_string(width));
    }
    return RunoffResampled(width, name == "runoff-repeated");
  }
  if (name == "aorta")
  {
    return MapOf(vr::benchmarks::AortaDepthMap(width, height), width, height);
  }
  if (name.rfind("aorta@", 0) == 0)
  {
    const double angle = std::stod(name.substr(6));
    return MapOf(vr::benchmarks::AortaDepthMap(width, height, angle), width, height);
  }
  if (name == "aortailiacs")
  {
    return MapOf(vr::benchmarks::AortaDepthMap(width, height, vr::benchmarks::AortaIliacsOverlapAngle), width, height);
  }
  if (name == "fullsize")
  {
    for (const auto & view : vr::benchmarks::FullSizeViews())
    {
      if (view.Width == width)
      {
        return MapOf(vr::benchmarks::FullSizeDepthMap(view.Width, view.Height), view.Width, view.Height);
      }
    }
    throw std::invalid_argument("no full-size view is " + std::to_string(width) + " pixels wide");
  }
  throw std::invalid_argument("unknown case " + name +
                              " (thorax, runoff, runoff-repeated, runoff-subsampled, aorta, aortailiacs or fullsize)");
}

struct Run
{
  Solver::Report      Report;
  double              Milliseconds;
  double              CPUMilliseconds;
  std::vector<double> Relaxed;
};

double
CPUMillisecondsSince(std::clock_t start)
{
  return 1000.0 * static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
}

/** The 500 Jacobi passes (w = 1, the same a) of the CPU filter on \a map with \a threads: wall and CPU ms. */
std::pair<double, double>
JacobiOnce(itk::BilateralDepthRelaxFilter<itk::Image<float, 2>> & filter)
{
  filter.Modified();
  const auto         start = std::chrono::steady_clock::now();
  const std::clock_t processStart = std::clock();
  filter.Update();
  return { std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count(),
           CPUMillisecondsSince(processStart) };
}

Run
SolveOnce(const Map & map, bool nested, unsigned int threads, Solver::Workspace & workspace)
{
  std::vector<float> relaxed(map.Depth.size());
  Solver::Settings   settings = Solver::DefaultSettings();
  settings.NestedIteration = nested;
  settings.MaximumOuterIterations = 1000;
  const auto         start = std::chrono::steady_clock::now();
  const std::clock_t processStart = std::clock();
  const auto         report = Solver::Solve(map.Depth.data(),
                                    map.Fixed.data(),
                                    relaxed.data(),
                                    map.Width,
                                    map.Height,
                                    Anisotropy,
                                    Solver::DefaultTolerance,
                                    threads,
                                    {},
                                    &workspace,
                                    settings);
  const double       milliseconds =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return {
    report, milliseconds, CPUMillisecondsSince(processStart), std::vector<double>(relaxed.begin(), relaxed.end())
  };
}

double
Median(std::vector<double> values)
{
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}
} // namespace

/** \a text as a positive whole number, or an error that names \a what and the text. */
unsigned int
PositiveCount(const std::string & text, const std::string & what)
{
  std::size_t   used = 0;
  unsigned long value = 0;
  try
  {
    value = std::stoul(text, &used);
  }
  catch (const std::exception &)
  {
    used = 0;
  }
  if (used == 0 || used != text.size() || value == 0 || value > 1000000)
  {
    throw std::invalid_argument(what + " must be a positive whole number, not '" + text + "'");
  }
  return static_cast<unsigned int>(value);
}

constexpr const char * Usage =
  "usage: MeasureSteadyScaling [--repeat N] [--threads T] [--anisotropy a] [--only nested|input] [--jacobi] case:W "
  "...\n"
  "  case: thorax, runoff, aorta, aortailiacs or aorta@ANGLE (degrees), at W x 2W pixels;\n"
  "        runoff-repeated (the run-off map at W/2 x W, each pixel 2 x 2) or runoff-subsampled (the map at\n"
  "        2W x 4W, every other pixel), at W x 2W, W even;\n"
  "        fullsize, with W one of the full-size views' widths (253, 505, 1010)\n"
  "  a: in mm^-2, default 1/9 (J = 3 mm)\n";

int
main(int argc, char * argv[])
{
  try
  {
    unsigned int             repeat = 5;
    unsigned int             threads = 2;
    std::string              only;
    bool                     jacobi = false;
    std::vector<std::string> cases;
    for (int k = 1; k < argc; ++k)
    {
      const std::string argument = argv[k];
      if (argument == "--repeat" && k + 1 < argc)
      {
        repeat = PositiveCount(argv[++k], "--repeat");
      }
      else if (argument == "--threads" && k + 1 < argc)
      {
        threads = PositiveCount(argv[++k], "--threads");
      }
      else if (argument == "--anisotropy" && k + 1 < argc)
      {
        Anisotropy = std::stod(argv[++k]);
      }
      else if (argument == "--only" && k + 1 < argc)
      {
        only = argv[++k];
      }
      else if (argument == "--jacobi")
      {
        jacobi = true;
      }
      else if (argument == "--help" || argument == "-h")
      {
        std::cout << Usage;
        return EXIT_SUCCESS;
      }
      else if (argument.rfind("-", 0) == 0 || argument.find(':') == std::string::npos)
      {
        std::cerr << "error: '" << argument << "' is neither an option nor a case:W\n" << Usage;
        return EXIT_FAILURE;
      }
      else
      {
        cases.push_back(argument);
      }
    }
    if (cases.empty())
    {
      std::cerr << "error: no case given\n" << Usage;
      return EXIT_FAILURE;
    }
    std::cout
      << "| case | W x H | start | median ms (n) | median CPU ms | fine outer | coarse outer | grids | V-cycles | "
         "energy mm^2 | plain residual mm |"
      << (jacobi ? " 500 passes: ms, CPU ms | x passes (CPU) |" : "")
      << "\n|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|" << (jacobi ? "---:|---:|" : "") << std::endl;
    for (const std::string & item : cases)
    {
      const auto          colon = item.find(':');
      const std::string   name = item.substr(0, colon);
      const unsigned int  width = PositiveCount(item.substr(colon + 1), "the width of " + item);
      const Map           map = MakeMap(name, width);
      Solver::Workspace   input, nested;
      std::vector<double> times[2];
      std::vector<double> cpuTimes[2];
      std::vector<double> jacobiTimes;
      std::vector<double> jacobiCPUTimes;
      Run                 last[2];
      auto                filter = itk::BilateralDepthRelaxFilter<itk::Image<float, 2>>::New();
      auto                depthImage = vr::test::MakeDepthImage(map.Width, map.Height, map.Depth);
      auto                maskImage = vr::test::MakeMaskImage(map.Width, map.Height, map.Fixed);
      filter->SetInput(depthImage);
      filter->SetFixedMask(maskImage);
      filter->SetRelaxation(1.0);
      filter->SetAnisotropy(Anisotropy);
      filter->SetNumberOfIterations(500);
      filter->SetNumberOfWorkUnits(threads);
      if (jacobi)
      {
        JacobiOnce(*filter); // its workspace, as the solves keep theirs
      }
      for (unsigned int r = 0; r < repeat; ++r)
      {
        if (jacobi)
        {
          const auto [wall, cpu] = JacobiOnce(*filter);
          jacobiTimes.push_back(wall);
          jacobiCPUTimes.push_back(cpu);
        }
        for (int n = 0; n < 2; ++n)
        {
          if ((only == "nested" && n == 0) || (only == "input" && n == 1))
          {
            continue;
          }
          last[n] = SolveOnce(map, n == 1, threads, n == 1 ? nested : input);
          times[n].push_back(last[n].Milliseconds);
          cpuTimes[n].push_back(last[n].CPUMilliseconds);
        }
      }
      for (int n = 0; n < 2; ++n)
      {
        if (times[n].empty())
        {
          continue;
        }
        const Run & run = last[n];
        std::cout << "| " << name << " | " << map.Width << " x " << map.Height << " | " << (n ? "nested" : "input")
                  << " | " << std::fixed << std::setprecision(1) << Median(times[n]) << " (" << times[n].size()
                  << ") | " << Median(cpuTimes[n]) << " | " << run.Report.OuterIterations << " | "
                  << run.Report.CoarseOuterIterations << " | " << run.Report.Grids << " | " << run.Report.Cycles
                  << " | " << std::setprecision(6)
                  << vr::test::PlainRelaxEnergy(run.Relaxed, map.Width, map.Height, Anisotropy) << " | "
                  << std::scientific << std::setprecision(2)
                  << vr::test::PlainFixedPointResidual(run.Relaxed, map.Fixed, map.Width, map.Height, Anisotropy)
                  << std::defaultfloat << (run.Report.Converged ? "" : " (stopped)") << " |";
        if (jacobi)
        {
          std::cout << std::fixed << std::setprecision(1) << " " << Median(jacobiTimes) << ", "
                    << Median(jacobiCPUTimes) << " | " << std::setprecision(2)
                    << Median(cpuTimes[n]) / Median(jacobiCPUTimes) << " |" << std::defaultfloat;
        }
        std::cout << std::endl;
      }
    }
    return EXIT_SUCCESS;
  }
  catch (const std::exception & error)
  {
    std::cerr << "error: " << error.what() << std::endl;
  }
  return EXIT_FAILURE;
}
