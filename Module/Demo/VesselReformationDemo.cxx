// Copyright the VesselReformation developers. SPDX-License-Identifier: Apache-2.0
// The main job on a built-in default: a synthetic leg run-off CTA, reformatted as a multipath CPR with and
// without bilateral depth filtering, written as pictures (the paper's Figure 2 among them).
//
//   VesselReformationDemo [--output DIR] [--angle DEG] [--size W,H] [--iterations N] [--backend B]

#include "itkRunoffPhantomImageSource.h"
#include "vrFigure.h"
#include "vrImageIO.h"
#include "vrSurfaceIO.h"
#include "vrInputError.h"
#include "vrNodeConversion.h"
#include "vrVesselReformationLogic.h"

#include <CLI/CLI.hpp>

#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>

namespace
{
using DepthImage = itk::Image<float, 2>;
using Clock = std::chrono::steady_clock;

// A CTA window that shows contrast-filled lumen, soft tissue and bone at once.
constexpr double Window = 900.0;
constexpr double Level = 200.0;

double
Milliseconds(Clock::time_point start)
{
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

/** A relaxed depth map and the CPR sampled on it. */
struct Result
{
  DepthImage::Pointer Depth;
  DepthImage::Pointer CPR;
};

std::string
Parameters(double w, double a)
{
  std::ostringstream stream;
  stream << "w = " << w << ", a = " << a << " mm^-2";
  return stream.str();
}

void
PrintStages(const vr::ReformationOutputs & outputs, const vr::StageCounts & before, const vr::StageCounts & after)
{
  auto line = [](const char * stage, double seconds, unsigned int runs)
  {
    std::cout << "    " << std::left << std::setw(11) << stage << std::right
              << (runs ? std::to_string(static_cast<long>(std::lround(seconds * 1000.0))) + " ms" : "not rerun")
              << std::endl;
  };
  line("conversion", outputs.Times.Conversion, after.Conversion - before.Conversion);
  line("depth", outputs.Times.Depth, after.Depth - before.Depth);
  line("relax", outputs.Times.Relax, after.Relax - before.Relax);
  line("resample", outputs.Times.Resample, after.Resample - before.Resample);
  line("surface", outputs.Times.Surface, after.Surface - before.Surface);
}

int
RunDemo(int argc, char * argv[])
{
  CLI::App    app{ "VesselReformation demo: a synthetic leg run-off CTA, reformatted with and without bilateral "
                   "depth filtering (Kretschmer et al., EuroVis 2014) through the module logic. Writes PNG pictures, "
                   "NRRD images and the cut surface." };
  std::string output = "vessel-reformation-demo";
  double      angle = 30.0;
  std::vector<unsigned int> size = { 512, 1024 };
  long long                 iterations = 500;
  double                    spacing = 1.5;
  std::string               backendName = "auto";
  app.add_option("--output", output, "folder for the pictures")->capture_default_str();
  app.add_option("--angle", angle, "view angle about the patient's superior axis, degrees")->capture_default_str();
  app.add_option("--size", size, "CPR image size W,H in pixels")->delimiter(',')->expected(2)->capture_default_str();
  app.add_option("--iterations", iterations, "bilateral filter iterations")->capture_default_str();
  app.add_option("--phantomSpacing", spacing, "voxel spacing of the phantom, mm")->capture_default_str();
  app.add_option("--backend", backendName, "relax filter backend: auto, cpu or opencl")->capture_default_str();
  CLI11_PARSE(app, argc, argv);

  try
  {
    vr::ReformationParameters parameters;
    parameters.AngleInDegrees = angle;
    parameters.ImageSize[0] = size[0];
    parameters.ImageSize[1] = size[1];
    parameters.Iterations = iterations;
    parameters.Backend = vr::ParseRelaxBackend(backendName, "--backend");
    parameters.Relaxation = 1.0;
    parameters.Anisotropy = 0.0;
    parameters.Validate();
    std::filesystem::create_directories(output);
    std::cout << "VesselReformation demo: synthetic run-off CTA, view " << angle << " degrees about superior, "
              << size[0] << " x " << size[1] << " pixels" << std::endl;

    auto start = Clock::now();
    auto phantom = itk::RunoffPhantomImageSource::New();
    phantom->SetSpacing(spacing);
    phantom->Update();
    const auto volumeSize = phantom->GetOutput()->GetLargestPossibleRegion().GetSize();
    std::cout << "  phantom " << volumeSize[0] << " x " << volumeSize[1] << " x " << volumeSize[2] << " voxels at "
              << spacing << " mm, " << phantom->GetCenterlineTree().GetNumberOfBranches()
              << " arteries: " << std::lround(Milliseconds(start)) << " ms" << std::endl;

    // The platform's view of the data: a volume node and a centerline node in RAS, as a 3D Slicer scene holds them.
    vr::VesselReformationLogic logic;
    logic.SetVolumeNode(vr::ConvertItkImageToVolumeNode(phantom->GetOutput(), "RunoffPhantom"));
    logic.SetCenterlineNode(vr::ConvertTreeToCenterlineNode(phantom->GetCenterlineTree(), "RunoffCenterlines"));
    logic.SetWarningCallback([](const std::string & message, const std::string &)
                             { std::cout << "  warning: " << message << std::endl; });

    auto run = [&](double a)
    {
      parameters.Anisotropy = a;
      logic.SetParameters(parameters);
      const auto   before = logic.GetStageExecutionCounts();
      const auto & outputs = logic.Update();
      std::cout << "  " << (a == 0.0 ? "isotropic" : "bilateral") << " relaxation (" << Parameters(1.0, a) << ", "
                << iterations << " iterations, " << outputs.RelaxBackendUsed << "):" << std::endl;
      PrintStages(outputs, before, logic.GetStageExecutionCounts());
      return Result{ vr::ConvertVolumeNodeToDepthImage(outputs.RelaxedDepth),
                     vr::ConvertVolumeNodeToDepthImage(outputs.CPR) };
    };
    const Result isotropic = run(0.0);
    const Result bilateral = run(0.5); // a new a reruns relax and resample only (DESIGN 3.7)
    const auto & outputs = logic.GetOutputs();
    const Result unfiltered{ vr::ConvertVolumeNodeToDepthImage(outputs.Depth),
                             vr::ConvertVolumeNodeToDepthImage(outputs.UnfilteredCPR) };

    // One colour range for every depth map, so they compare.
    const auto * values = unfiltered.Depth->GetBufferPointer();
    const auto   count = unfiltered.Depth->GetBufferedRegion().GetNumberOfPixels();
    const double nearest = *std::min_element(values, values + count);
    const double farthest = *std::max_element(values, values + count);

    const auto path = [&](const char * name) { return (std::filesystem::path(output) / name).string(); };
    const auto unfilteredCPR = vr::RenderWindowLevel(unfiltered.CPR, Window, Level);
    const auto isotropicCPR = vr::RenderWindowLevel(isotropic.CPR, Window, Level);
    const auto bilateralCPR = vr::RenderWindowLevel(bilateral.CPR, Window, Level);
    const auto unfilteredDepth = vr::RenderDepth(unfiltered.Depth, nearest, farthest);
    const auto isotropicDepth = vr::RenderDepth(isotropic.Depth, nearest, farthest);
    const auto bilateralDepth = vr::RenderDepth(bilateral.Depth, nearest, farthest);
    vr::WriteRGBPNG(unfilteredCPR, path("cpr-unfiltered.png"));
    vr::WriteRGBPNG(bilateralCPR, path("cpr-filtered.png"));
    vr::WriteRGBPNG(unfilteredDepth, path("depth-unfiltered.png"));
    vr::WriteRGBPNG(bilateralDepth, path("depth-filtered.png"));
    vr::WriteImage2D(unfiltered.Depth, path("depth.nrrd"));
    vr::WriteImage2D(bilateral.Depth, path("depth-relaxed.nrrd"));
    vr::WriteImage2D(bilateral.CPR, path("cpr.nrrd"));
    vr::WriteImage2D(unfiltered.CPR, path("cpr-unfiltered.nrrd"));
    // As 3D Slicer writes models (LPS, the space recorded in the file), so Slicer loads it in place.
    vr::WriteSurface(outputs.Surface, path("cut-surface.vtp"), vr::CoordinateSpace::RAS, vr::CoordinateSpace::LPS);

    const std::string  unfilteredTitle = "unfiltered (w = 0)";
    const std::string  isotropicTitle = "isotropic (" + Parameters(1.0, 0.0) + ")";
    const std::string  bilateralTitle = "bilateral (" + Parameters(1.0, 0.5) + ")";
    std::ostringstream caption;
    caption << "Synthetic run-off CTA, mpCPR at " << angle << " degrees, " << iterations << " iterations. Top: CPR (W "
            << Window << " / L " << Level << " HU). Bottom: depth map.";
    // A detail of the patient's left thigh and knee (the screen's right half), magnified, with the depth in a
    // tight colour range: there the small seams are what the eye sees.
    const unsigned int detailX = static_cast<unsigned int>(0.50 * size[0]);
    const unsigned int detailY = static_cast<unsigned int>(0.35 * size[1]);
    const unsigned int detailWidth = static_cast<unsigned int>(0.30 * size[0]);
    const unsigned int detailHeight = static_cast<unsigned int>(0.30 * size[1]);
    const auto [detailNear, detailFar] =
      vr::RangeWithin(unfiltered.Depth, detailX, detailY, detailWidth, detailHeight, 0.05, 0.95);
    const unsigned int panelWidth = (3 * size[0] + 16) / 4;
    auto               detail = [&](const vr::RGBImageType * image)
    { return vr::Magnify(vr::Crop(image, detailX, detailY, detailWidth, detailHeight), panelWidth); };
    const auto figure = vr::ComposeFigure(
      { { { unfilteredCPR, unfilteredTitle }, { isotropicCPR, isotropicTitle }, { bilateralCPR, bilateralTitle } },
        { { unfilteredDepth, "depth, unfiltered" },
          { isotropicDepth, "depth, isotropic" },
          { bilateralDepth, "depth, bilateral" } },
        { { vr::RenderDepthColorBar(nearest, farthest, size[0]), "" } },
        { { detail(unfilteredCPR), "detail: left thigh, unfiltered" },
          { detail(bilateralCPR), "detail: bilateral" },
          { detail(vr::RenderDepthRelief(unfiltered.Depth, detailNear, detailFar)),
            "detail depth (relief), unfiltered" },
          { detail(vr::RenderDepthRelief(bilateral.Depth, detailNear, detailFar)),
            "detail depth (relief), bilateral" } },
        { { vr::RenderDepthColorBar(detailNear, detailFar, size[0]), "" } } },
      caption.str());
    vr::WriteRGBPNG(figure, path("figure2-comparison.png"));

    std::cout << "Wrote to " << std::filesystem::absolute(output).string() << ":" << std::endl
              << "  cpr-unfiltered.png, cpr-filtered.png     the CPR before and after bilateral filtering" << std::endl
              << "  depth-unfiltered.png, depth-filtered.png the depth maps (viridis: near dark, far yellow)"
              << std::endl
              << "  figure2-comparison.png                   unfiltered | isotropic | bilateral (the paper's Fig. 2)"
              << std::endl
              << "  depth.nrrd, depth-relaxed.nrrd, cpr.nrrd, cpr-unfiltered.nrrd  the images, view in their metadata"
              << std::endl
              << "  cut-surface.vtp                          the relaxed cut surface in 3D (RAS), coloured by HU"
              << std::endl;
    return EXIT_SUCCESS;
  }
  catch (const vr::InputError & error)
  {
    std::cerr << "error: " << error.what() << std::endl;
  }
  catch (const itk::ExceptionObject & error)
  {
    std::cerr << "error: " << error.GetDescription() << std::endl;
  }
  catch (const std::exception & error)
  {
    std::cerr << "error: " << error.what() << std::endl;
  }
  return EXIT_FAILURE;
}
} // namespace

int
main(int argc, char * argv[])
{
  try
  {
    return RunDemo(argc, argv);
  }
  catch (const std::exception & error) // outside RunDemo's own handlers: allocation, the output stream
  {
    std::cerr << "error: " << error.what() << std::endl;
  }
  catch (...)
  {
    std::cerr << "error: an unknown exception" << std::endl;
  }
  return EXIT_FAILURE;
}
