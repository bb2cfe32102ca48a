// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// Measures what the module logic's memory check predicts against what a reformation really allocates: the peak of
// the bytes allocated (counted by vrAllocationCounter, which replaces malloc) over one update of a W x H view of a
// phantom, after a small update has converted the inputs and warmed every filter (so the volume, the tree and the
// code are not counted). The growth of the peak resident memory is printed beside it.
//
//   MeasureReformationMemory W H jacobi|steady [surface|nosurface] [--phantom runoff|thorax|aorta] [--cubic]
//                            [--mode scanline|nearest|visibility] [--tolerance F]
//
// With --cubic the measured update interpolates cubically after a linear warm-up, so that it computes the B-spline
// coefficients of the volume in both resamplers, which the check counts besides the view (the volume itself is
// sampled where it lies and never copied).
// With --phantom aorta, the VMTK aorta MRA of VR_SHARED_DATA_DIR (real data). Prints the allocated and predicted
// bytes per view pixel, and for a steady update whether the solve started from the coarser grids (the thoracic
// phantom's does, the run-off phantom's and the aorta's do not; the prediction is the same for both paths, as the
// coarser grids lie in the image's grid's scratch arrays). With --tolerance, exits 1 when the prediction differs by
// more than the fraction F of the allocated bytes. Linux (glibc) only: the resident peak is VmHWM of
// /proc/self/status, reset through /proc/self/clear_refs.
#include "itkCTAPhantom.h"
#include "itkMultiThreaderBase.h"
#include "vrAllocationCounter.h"
#include "vrCenterlineIO.h"
#include "vrMemoryBudget.h"
#include "vrNodeConversion.h"
#include "vrVesselReformationLogic.h"
#include "vrVolumeIO.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
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
    std::cerr << "usage: MeasureReformationMemory W H jacobi|steady [surface|nosurface] [--phantom P] [--mode M] "
                 "[--tolerance F]\n";
    return 2;
  }
  const unsigned int width = static_cast<unsigned int>(std::atoi(argv[1]));
  const unsigned int height = static_cast<unsigned int>(std::atoi(argv[2]));
  const std::string  solver = argv[3];
  bool               surface = true;
  double             tolerance = -1.0;
  std::string        phantomName = "runoff";
  bool               cubic = false;
  itk::CPRDepthMode  mode = itk::CPRDepthMode::Scanline;
  for (int k = 4; k < argc; ++k)
  {
    const std::string argument = argv[k];
    if (argument == "nosurface")
    {
      surface = false;
    }
    else if (argument == "--mode" && k + 1 < argc)
    {
      mode = vr::ParseDepthMode(argv[++k], "--mode");
    }
    else if (argument == "--phantom" && k + 1 < argc)
    {
      phantomName = argv[++k];
    }
    else if (argument == "--cubic")
    {
      cubic = true;
    }
    else if (argument == "--tolerance" && k + 1 < argc)
    {
      tolerance = std::atof(argv[++k]);
    }
  }
  try
  {
    vr::VesselReformationLogic logic;
    vr::ReformationParameters  parameters;
    if (phantomName == "aorta")
    {
      // The VMTK aorta MRA (real data), its up direction chosen automatically as the benchmarks view it.
      const std::filesystem::path folder = std::filesystem::path(VR_SHARED_DATA_DIR) / "vmtk-aorta-mra";
      logic.SetVolumeNode(vr::ConvertItkImageToVolumeNode(vr::ReadVolume((folder / "aorta.mha").string()), "aorta"));
      logic.SetCenterlineNode(
        vr::ConvertTreeToCenterlineNode(vr::ReadCenterlines((folder / "aorta-centerline.vtp").string()), "centerline"));
      parameters.AutomaticUp = true;
    }
    else
    {
      auto phantom =
        itk::MakeCTAPhantom(itk::ParseCTAPhantomKind(phantomName), 3.0); // coarse: the volume is not measured
      phantom.Source->Update();
      logic.SetVolumeNode(vr::ConvertItkImageToVolumeNode(phantom.Source->GetOutput(), "phantom"));
      logic.SetCenterlineNode(vr::ConvertTreeToCenterlineNode(phantom.Tree, "centerlines"));
      parameters.AngleInDegrees = phantom.DesignAngleInDegrees;
    }
    logic.SetSurfaceEnabled(surface);
    parameters.Backend = vr::RelaxBackend::CPU;
    parameters.Solver =
      solver == "steady" ? itk::BilateralDepthRelaxSolver::Steady : itk::BilateralDepthRelaxSolver::Jacobi;
    parameters.Mode = mode;
    parameters.ImageSize[0] = 16;
    parameters.ImageSize[1] = 32;
    logic.SetParameters(parameters);
    logic.Update();

    parameters.ImageSize[0] = width;
    parameters.ImageSize[1] = height;
    if (cubic)
    {
      parameters.Interpolation = itk::CPRInterpolationMode::Cubic;
    }
    logic.SetParameters(parameters);
    const double    before = StatusBytes("VmRSS");
    const long long allocatedBefore = vr::test::AllocatedBytes();
    ResetPeak();
    vr::test::ResetAllocationPeak();
    logic.Update();
    const double resident = StatusBytes("VmHWM") - before;
    const double measured = static_cast<double>(vr::test::AllocationPeak() - allocatedBefore);
    itk::Size<2> size;
    size[0] = width;
    size[1] = height;
    // What the logic's check predicted before the update, from the relax filter it used (configured the same way).
    auto &       relax = *logic.GetRelaxFilter();
    const bool   coarserGrids = relax.GetSteadyReport().Grids > 1;
    const double voxels =
      static_cast<double>(logic.GetResampleFilter()->GetVolume()->GetBufferedRegion().GetNumberOfPixels());
    const double volumeSampling = vr::EstimateVolumeSamplingBytes(
      voxels, cubic ? itk::CPRInterpolationMode::Cubic : itk::CPRInterpolationMode::Linear);
    const double predicted =
      vr::EstimateReformationBytes(size, relax.GetWorkspaceBytes(size), surface, volumeSampling, mode);
    const double pixels = static_cast<double>(width) * height;
    auto         percent = [measured](double bytes) { return 100.0 * (bytes - measured) / measured; };
    std::cout << phantomName << " (" << vr::ToString(mode) << "), " << width << " x " << height << " " << solver
              << (surface ? " with surface" : " without surface") << ", "
              << itk::MultiThreaderBase::GetGlobalDefaultNumberOfThreads() << " threads: allocated at the peak "
              << measured / pixels << " B/pixel (peak resident growth " << resident / pixels << "); predicted "
              << predicted / pixels << " (" << percent(predicted) << " %), of it relaxation "
              << relax.GetWorkspaceBytes(size) / pixels << " (path taken: "
              << (solver == "steady" ? (coarserGrids ? "coarser grids" : "no coarser grid") : "Jacobi") << ")";
    if (cubic)
    {
      std::cout << "; cubic: of the prediction " << volumeSampling / pixels << " for the coefficients of " << voxels
                << " voxels";
    }
    std::cout << "\n";
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
