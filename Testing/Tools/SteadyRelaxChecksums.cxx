// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Measurement, not a test: the steady solver's relaxed maps of both phantoms (and a random map, isotropic and not)
// written as raw float files into a folder, with each solve's report, so that a rework of the solver can show its
// results bit-identical before and after (md5sum the files). Usage: SteadyRelaxChecksums <folder> [threads]
#include "vrTestDepthMaps.h"

#include "itkBilateralDepthRelaxSteadySolver.h"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <random>
#include <string>
#include <vector>

namespace
{
using Map = vr::test::DepthMapBuffers;

/** Blocks of 20 x 20 pixels 50 mm apart in depth (weights between them vanish), with noise of 2 mm, fixed pixels in
 * the left half only: floating regions on the right, and a few isolated pixels. */
Map
BlockMap(unsigned int width, unsigned int height)
{
  std::mt19937                          generator(5);
  std::uniform_real_distribution<float> noise(0.0f, 2.0f);
  std::bernoulli_distribution           fixed(0.05);
  Map                                   map{ {}, {}, width, height };
  for (unsigned int y = 0; y < height; ++y)
  {
    for (unsigned int x = 0; x < width; ++x)
    {
      const bool isolated = (x * 7 + y * 13) % 997 == 0;
      map.Depth.push_back(50.0f * static_cast<float>((x / 20 + y / 20) % 3) + noise(generator) +
                          (isolated ? 25.0f : 0.0f));
      map.Fixed.push_back(x < width / 2 && fixed(generator) ? 1 : 0);
    }
  }
  return map;
}

void
Write(const std::string & folder, const std::string & name, const Map & map, double anisotropy, unsigned int threads)
{
  std::vector<float> relaxed(map.Depth.size());
  const auto         report =
    itk::BilateralDepthRelaxSteadySolver::Solve(map.Depth.data(),
                                                map.Fixed.data(),
                                                relaxed.data(),
                                                map.Width,
                                                map.Height,
                                                anisotropy,
                                                itk::BilateralDepthRelaxSteadySolver::DefaultTolerance,
                                                threads);
  std::ofstream out(folder + "/" + name + ".raw", std::ios::binary);
  out.write(reinterpret_cast<const char *>(relaxed.data()), static_cast<std::streamsize>(relaxed.size() * 4));
  std::cout << name << ": " << report.OuterIterations << " outer, " << report.Cycles << " cycles, "
            << report.HierarchyBuilds << " builds, " << report.FloatingPixels << " floating, residual "
            << report.Residual << std::endl;
}
} // namespace

int
main(int argc, char * argv[])
{
  if (argc < 2)
  {
    std::cerr << "Usage: SteadyRelaxChecksums <folder> [threads]" << std::endl;
    return 1;
  }
  const std::string  folder = argv[1];
  const unsigned int threads = argc > 2 ? static_cast<unsigned int>(std::stoul(argv[2])) : 4;
  constexpr double   Anisotropy = 1.0 / 9.0;
  Write(folder, "runoff-512x1024", vr::test::RunoffDepthMapBuffers(512, 1024), Anisotropy, threads);
  Write(folder, "thorax-512x1024", vr::test::ThoraxDepthMapBuffers(512, 1024), Anisotropy, threads);
  Write(folder, "thorax-128x256", vr::test::ThoraxDepthMapBuffers(128, 256), Anisotropy, threads);
  Write(folder, "random-97x61", vr::test::RandomDepthMapBuffers(97, 61, 8.0f, 0.05, 9), Anisotropy, threads);
  Write(folder, "random-97x61-isotropic", vr::test::RandomDepthMapBuffers(97, 61, 8.0f, 0.05, 9), 0.0, threads);
  Write(folder, "blocks-301x203", BlockMap(301, 203), Anisotropy, threads);
  return 0;
}
