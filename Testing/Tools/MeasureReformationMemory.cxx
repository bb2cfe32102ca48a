// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Measures what the module logic's memory check predicts against what a reformation really takes: the growth of the
// process's peak resident memory over one update of a W x H view of the run-off phantom, after a small update has
// converted the inputs and warmed every filter (so the volume, the tree and the code are not counted).
//
//   MeasureReformationMemory W H jacobi|steady [surface|nosurface] [--tolerance F]
//
// Prints predicted and measured bytes per view pixel; with --tolerance, exits 1 when they differ by more than the
// fraction F of the measured bytes. Linux only: the peak is VmHWM of /proc/self/status, reset through
// /proc/self/clear_refs.
#include "itkCTAPhantom.h"
#include "itkMultiThreaderBase.h"
#include "vrMemoryBudget.h"
#include "vrNodeConversion.h"
#include "vrVesselReformationLogic.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

namespace
{
/** A field of /proc/self/status in bytes (it is given in kB). */
double
StatusBytes(const std::string & field)
{
  std::ifstream status("/proc/self/status");
  std::string   key;
  while (status >> key)
  {
    if (key == field + ":")
    {
      double kibibytes = 0.0;
      status >> kibibytes;
      return kibibytes * 1024.0;
    }
    status.ignore(1 << 16, '\n');
  }
  throw std::runtime_error("no " + field + " in /proc/self/status");
}

void
ResetPeak()
{
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5"; // resets VmHWM to the current VmRSS (Linux 4.0 and later)
}
} // namespace

int
main(int argc, char ** argv)
{
  if (argc < 4)
  {
    std::cerr << "usage: MeasureReformationMemory W H jacobi|steady [surface|nosurface] [--tolerance F]\n";
    return 2;
  }
  const unsigned int width = static_cast<unsigned int>(std::atoi(argv[1]));
  const unsigned int height = static_cast<unsigned int>(std::atoi(argv[2]));
  const std::string  solver = argv[3];
  bool               surface = true;
  double             tolerance = -1.0;
  for (int k = 4; k < argc; ++k)
  {
    const std::string argument = argv[k];
    if (argument == "nosurface")
    {
      surface = false;
    }
    else if (argument == "--tolerance" && k + 1 < argc)
    {
      tolerance = std::atof(argv[++k]);
    }
  }
  try
  {
    auto phantom = itk::MakeCTAPhantom(itk::CTAPhantomKind::Runoff, 3.0); // coarse: the volume is not measured
    phantom.Source->Update();
    vr::VesselReformationLogic logic;
    logic.SetVolumeNode(vr::ConvertItkImageToVolumeNode(phantom.Source->GetOutput(), "phantom"));
    logic.SetCenterlineNode(vr::ConvertTreeToCenterlineNode(phantom.Tree, "centerlines"));
    logic.SetSurfaceEnabled(surface);
    vr::ReformationParameters parameters;
    parameters.AngleInDegrees = phantom.DesignAngleInDegrees;
    parameters.Backend = vr::RelaxBackend::CPU;
    parameters.Solver =
      solver == "steady" ? itk::BilateralDepthRelaxSolver::Steady : itk::BilateralDepthRelaxSolver::Jacobi;
    parameters.ImageSize[0] = 16;
    parameters.ImageSize[1] = 32;
    logic.SetParameters(parameters);
    logic.Update();

    parameters.ImageSize[0] = width;
    parameters.ImageSize[1] = height;
    logic.SetParameters(parameters);
    const double before = StatusBytes("VmRSS");
    ResetPeak();
    logic.Update();
    const double measured = StatusBytes("VmHWM") - before;
    itk::Size<2> size;
    size[0] = width;
    size[1] = height;
    const double predicted = vr::EstimateReformationBytes(size, parameters.Solver, surface);
    const double pixels = static_cast<double>(width) * height;
    std::cout << width << " x " << height << " " << solver << (surface ? " with surface" : " without surface") << ", "
              << itk::MultiThreaderBase::GetGlobalDefaultNumberOfThreads() << " threads: predicted "
              << predicted / pixels << " B/pixel, measured (peak resident growth) " << measured / pixels << " B/pixel, "
              << 100.0 * (predicted - measured) / measured << " %\n";
    if (tolerance >= 0.0 && std::abs(predicted - measured) > tolerance * measured)
    {
      std::cerr << "error: the prediction is off by more than " << 100.0 * tolerance << " %\n";
      return 1;
    }
  }
  catch (const std::exception & error)
  {
    std::cerr << "error: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
